import { expect, test } from '@playwright/test';
import { openRobustnessPage } from './robustnessPage';

// A long run (tests/browser/robustness/robustness.ts, soak): 10 000 frames of an Ocean with a setting
// changed every 100 frames, and what the page holds (three.js's geometries, textures and programs,
// WebGL framebuffers, live Web Workers) each time the settings are back to the first ones. Frames
// are simulated (ocean.update at 1/60 s steps) and every tenth is drawn: SwiftShader takes ~30 ms
// a draw, and all ten thousand would take five minutes.

test('soak: 10 000 frames, a setting changed every 100; memory, programs, framebuffers and workers stay flat', async ({ page }) => {
  test.setTimeout(240_000);
  const problems = await openRobustnessPage(page);
  const report = await page.evaluate(() => window.robustness.soak(10_000, 100, 10));
  const holdings = ({ frame, ...held }: { frame: number }) => `frame ${frame}: ${JSON.stringify(held)}`;
  console.log(
    `soak: ${report.changes} changes (${report.cycles} cycles through ${report.settings.join(', ')}), ${report.draws} draws in ${report.seconds.toFixed(1)} s; ` +
      `workers: ${report.workersMade} made, at most ${report.mostWorkers} at once; paths ${report.paths.join(' → ')}\n` +
      [...report.atFirstSettings, report.last].map(holdings).join('\n'),
  );
  expect(report.changes).toBe(100);
  expect(report.cycles).toBe(5); // so the last change brought back the first settings
  // The first time round every setting is new: each material keeps a program for every variant
  // of its shaders it has drawn (three.js's cache, until the material is disposed), the surface's
  // for 'fresnel' and for two cascades among them. From then on nothing grows.
  const [first, baseline, ...later] = report.atFirstSettings;
  expect(later).toHaveLength(3);
  for (const sample of [...later, report.last]) expect({ ...sample, frame: 0 }).toEqual({ ...baseline, frame: 0 });
  expect({ ...first, frame: 0, programs: 0 }).toEqual({ ...baseline, frame: 0, programs: 0 });
  expect(first.programs).toBeLessThanOrEqual(baseline.programs);
  // No workers on the GPU path; on the JS path at most one per cascade (three), replaced, not
  // added to, as the settings change.
  expect(baseline.workers).toBe(0);
  expect(report.mostWorkers).toBeGreaterThan(0);
  expect(report.mostWorkers).toBeLessThanOrEqual(3);
  expect(report.problems).toEqual([]);
  expect(Number.isFinite(report.height)).toBe(true);
  expect(problems).toEqual([]);
});
