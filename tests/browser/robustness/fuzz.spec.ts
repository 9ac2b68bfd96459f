import { openRobustnessPage as openPage } from './robustnessPage';
import { expect, test } from '@playwright/test';
import { sharedPages } from '../shared/sharedPages';

// Hostile input, generated in the page (fast-check; tests/browser/robustness/robustness.ts) against the
// real Ocean and <fft-ocean> in WebGL2: every call either works or is refused with a ParameterError
// (the element: a console warning) that names what was wrong, and the sea keeps finite texels,
// uniforms and heights. Seeded, so every run repeats the same cases; a failure prints fast-check's
// report (seed, counterexample) and the error. Runs are few: SwiftShader takes ~0.2 s for each.
// The URL parser and the option tables get many more runs in Node (tests/unit/fuzz.test.ts).

const SEED = 20261124;

// The runs share one page: each makes its own renderer and Oceans or elements and frees them
// (robustness.ts), so nothing of one reaches the next. `problems`: the page's errors since it loaded.
let problems: string[] = [];
const sharedPage = sharedPages(
  async (page) => {
    problems = await openPage(page);
  },
  () => Promise.resolve(),
);

/** Per kind of call: made, and refused (a ParameterError or a warning). */
type Tally = Record<string, { calls: number; refused: number }>;

function describeTally(tally: Tally): string {
  return Object.entries(tally)
    .map(([kind, { calls, refused }]) => `${kind} ${calls} (${refused} refused)`)
    .join(', ');
}

for (const path of ['gpu', 'js'] as const) {
  test(`Ocean's setters on the ${path} path: hostile calls work or throw a ParameterError naming the option, and the sea stays finite`, async ({ browser }) => {
    const page = await sharedPage(browser);
    const runs = 100;
    const started = Date.now();
    const report = await page.evaluate(([path, runs, seed]) => window.robustness.fuzzOcean(path, runs, seed), [path, runs, SEED] as const);
    console.log(`Ocean on the ${path} path: ${report.runs} runs in ${((Date.now() - started) / 1000).toFixed(1)} s: ${describeTally(report.tally)}`);
    expect(report.failure).toBeNull();
    expect(report.runs).toBe(runs);
    // Every method was called, with values it took and values it refused.
    for (const method of ['setParameters', 'setShading', 'setSun', 'setPath', 'update', 'heightAt']) {
      const { calls, refused } = report.tally[method];
      expect(refused, method).toBeGreaterThan(0);
      expect(calls - refused, method).toBeGreaterThan(0);
    }
    expect(problems).toEqual([]);
  });
}

test('<fft-ocean>: hostile attributes and times are taken or refused with a warning naming them, and the sea stays finite', async ({ browser }) => {
  const page = await sharedPage(browser);
  const runs = 60;
  const started = Date.now();
  const report = await page.evaluate(([runs, seed]) => window.robustness.fuzzElement(runs, seed), [runs, SEED] as const);
  console.log(`<fft-ocean>: ${report.runs} runs in ${((Date.now() - started) / 1000).toFixed(1)} s: ${describeTally(report.tally)}`);
  expect(report.failure).toBeNull();
  expect(report.runs).toBe(runs);
  const read = report.tally['attribute the element reads'];
  expect(read.refused).toBeGreaterThan(0);
  expect(read.calls - read.refused).toBeGreaterThan(0);
  expect(report.tally.time.calls).toBeGreaterThan(0);
  expect(report.tally['other attribute'].refused).toBe(0); // an attribute it does not read is no concern of it
  expect(problems).toEqual([]);
});
