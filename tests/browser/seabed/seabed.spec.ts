/**
 * Shores on the real GPU path (src/layers/shore.ts, shaders/surface/shoaling.glsl): over a 1:50
 * plane beach the surface the vertex shader draws is the one the queries describe (heightAt at each
 * displaced vertex, within 2 cm, against 2 mm without a seabed as a control of the method), and the drawn
 * waterline lies where the queried surface meets the beach, within one cell of the grid. The shoaling
 * and breaking laws themselves are proven on the queries (tests/unit/shoaling.test.ts). A seabed
 * from meshes is drawn from above and read back; bad seabeds are refused and the last good one
 * stays. The picture of the beach is written to test-results-<port>/seabed/ for a person to look at.
 */
import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { expect, test } from '@playwright/test';

const PORT = Number(process.env.TEST_PORT ?? 5173);
const OUTPUT = join(PORT === 5173 ? 'test-results' : `test-results-${PORT}`, 'seabed');

test('the drawn surface over a beach is the queried one, and so is its waterline', async ({ page }) => {
  await page.goto('/tests/browser/seabed/seabed.html');
  await expect(page).toHaveTitle('ready');
  // Over the surf zone, looking along the shore.
  const view = { position: [-40, 25, -120], target: [60, 0, 40] };
  const result = await page.evaluate((view) => {
    const h = window.seabed;
    // One cascade, no local waves: its factor alone scales each vertex.
    const single = { patchSizes: [79.3], localWaves: false };
    h.setup(false, 11.3, view.position, view.target, single);
    const plain = h.capture();
    h.setup(true, 11.3, view.position, view.target, single);
    const formula = h.shoreFormula(plain, h.capture());
    h.setup(true, 11.3, view.position, view.target);
    const offsets = h.waterline(h.capture());
    return { formula, offsets, picture: h.picture() };
  }, view);
  mkdirSync(OUTPUT, { recursive: true });
  writeFileSync(join(OUTPUT, 'beach.png'), Buffer.from(result.picture.split(',')[1], 'base64'));
  const { formula, offsets } = result;
  const worstShore = Math.max(...offsets);
  console.log(
    `shore formula over ${formula.compared} vertices: worst ${(1000 * formula.worst).toFixed(2)} mm (RMS height ${formula.rms.toFixed(3)} m); ` +
      `${offsets.length} waterline crossings, worst ${worstShore.toFixed(2)} cells from the queried waterline`,
  );
  expect(formula.compared).toBeGreaterThan(1000);
  expect(formula.worst).toBeLessThan(2e-3);
  expect(offsets.length).toBeGreaterThan(20);
  expect(worstShore).toBeLessThanOrEqual(1);
});

test('a seabed from meshes is drawn from above; bad seabeds are refused and the last good one stays; its textures are freed', async ({ page }) => {
  await page.goto('/tests/browser/seabed/seabed.html');
  await expect(page).toHaveTitle('ready');
  const result = await page.evaluate(() => {
    const h = window.seabed;
    h.setup(true, 0, [0, 30, 0], [100, 0, 0]);
    const depths = h.meshSeabed([[-200, 0], [0, 300], [500, -500], [2000, 100]]);
    const bad = ['nan', 'noGeometry', 'noArea'].map((kind) => h.badSeabed(kind));
    return { depths, bad, memory: h.memoryCycle() };
  });
  // Every texture the seabeds made (depth maps, shoaling tables) is freed with the Ocean.
  expect(result.memory.after).toEqual(result.memory.before);
  // The plane y = −x/50: depth x/50 (within a millimetre: float32 heights, bilinear over a plane).
  [-200, 0, 500, 2000].forEach((x, i) => expect(Math.abs(result.depths[i] - x / 50)).toBeLessThan(1e-3));
  expect(result.bad.map((b) => b.parameter)).toEqual(['seabed.depthAt', 'seabed.meshes[0]', 'seabed.bounds']);
  for (const b of result.bad) expect(b.depthAfter).toBeCloseTo(20, 3);
});
