import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { expect, test, type Page } from '@playwright/test';
import { validateParameters } from '../../../src/parameters/parameters';
import { createCascadeSpectra } from '../../../src/spectrum/initialSpectrum';
import { sharedPages } from '../shared/sharedPages';
import { ALSO_ON_OLDEST_THREE } from '../shared/threeRange';

// One page for the file: the page holds a renderer and nothing else between tests (each test's
// simulations are made and disposed in its own call), so there is nothing to set back.
const simulationPage = sharedPages(
  async (page: Page) => {
    const errors: string[] = [];
    page.on('pageerror', (error) => errors.push(error.message));
    await page.goto('/tests/browser/simulation/simulation.html');
    await expect(page).toHaveTitle('ready');
    expect(errors).toEqual([]);
  },
  async () => {},
);

test('the page runs the three.js release the dev server was given (THREE_FFT_OCEAN_THREE, else the devDependency)', ALSO_ON_OLDEST_THREE, async ({ browser }) => {
  const page = await simulationPage(browser);
  // So a run against another release cannot pass on a server or a cached bundle of the devDependency.
  const servedThree = process.env.THREE_FFT_OCEAN_THREE ?? resolve(import.meta.dirname, '../../../node_modules/three');
  const { version } = JSON.parse(readFileSync(resolve(servedThree, 'package.json'), 'utf8')) as { version: string };
  expect(await page.evaluate(() => window.harness.threeRevision)).toBe(version.split('.')[1]);
});

test('the context offers float32 render targets (SwiftShader WebGL2)', async ({ browser }) => {
  const page = await simulationPage(browser);
  expect(await page.evaluate(() => window.harness.supportedPrecision())).toBe('float32');
});

for (const resolution of [16, 32, 64, 256, 512]) {
  test(`GPU fields equal JS fields at N = ${resolution}, every cascade (RGBA32F, two times)`, resolution === 256 ? ALSO_ON_OLDEST_THREE : {}, async ({ browser }) => {
    const page = await simulationPage(browser);
    const { results, passCount } = await page.evaluate(
      (n) => window.harness.compareGpuWithJs({ resolution: n, seed: 7, windSpeed: 14 }, [3.25, 117.5]),
      resolution,
    );
    // Evolution, FFT (radix 4; along x a first radix-2 stage is fused into the evolution), copy out.
    expect(passCount).toBe(2 + 2 * Math.ceil(Math.log2(resolution) / 2) - (Math.log2(resolution) % 2));
    expect(new Set(results.map(({ cascade }) => cascade)).size).toBe(3); // the default cascades
    for (const { displacement, derivatives } of results) {
      for (const channel of [...displacement, ...derivatives]) {
        // Both paths hold float32 and read twiddles and phases computed in double precision; the
        // remaining difference is float32 rounding over log2(N) stages, ~1e-6 of the RMS. 1e-4 is
        // the bound; a wrong twiddle, index or sign gives errors of order 1.
        expect(channel.rms).toBeGreaterThan(0);
        expect(channel.relativeMaxError).toBeLessThan(1e-4);
      }
    }
  });
}

test('GPU fields in half floats (RGBA16F) follow the JS fields within half-float precision', ALSO_ON_OLDEST_THREE, async ({ browser }) => {
  const page = await simulationPage(browser);
  const { results } = await page.evaluate(() => window.harness.compareGpuWithJs({ resolution: 256, seed: 7 }, [3.25], 'float16'));
  for (const channel of results.flatMap(({ displacement, derivatives }) => [...displacement, ...derivatives])) {
    // Half floats keep 11 significant bits (relative step 4.9e-4) through 9 passes; the field that
    // shares a complex transform with a 10× larger one (∂Dx/∂z beside Dz) sees ~2e-2 of its RMS.
    expect(channel.relativeMaxError).toBeLessThan(0.05);
  }
});

for (const [name, changes] of [
  ['no wind', { windSpeed: 0 }],
  ['a 60 m/s wind', { windSpeed: 60 }],
  ['N = 1024', { resolution: 1024 }],
  // Issue "Real seas without seams": the extremes of the sea state.
  ['a fetch of 1 m', { resolution: 64, fetch: 0.001 }],
  ['a fetch of 10 000 km and a 30 m swell', { resolution: 64, fetch: 1e4, swellHeight: 30, swellPeriod: 40 }],
  ['TMA at a depth of 0.1 m', { resolution: 64, spectrum: 'tma', depth: 0.1, windSpeed: 60 }],
  ['Phillips at 60 m/s with Donelan–Banner spreading requested', { resolution: 64, spectrum: 'phillips', windSpeed: 60, spreading: 'donelan-banner' }],
] as const) {
  test(`no NaN or Infinity reaches the GPU field textures with ${name}`, async ({ browser }) => {
    const page = await simulationPage(browser);
    expect(await page.evaluate((c) => window.harness.gpuNonFiniteCount(c, 17.5), changes)).toBe(0);
  });
}

test('the whitecap foam on the GPU equals the JS foam, through a warm-up and frame steps', ALSO_ON_OLDEST_THREE, async ({ browser }) => {
  const page = await simulationPage(browser);
  // 20 m/s at N = 128: coverage of a few per cent. The first time is a jump (warm-up from nothing
  // over 3τ, twelve FFT updates), the next three are frame steps, the last a jump back in time.
  const results = await page.evaluate(() =>
    window.harness.compareFoamGpuWithJs({ windSpeed: 20, resolution: 128, seed: 3 }, [30, 30.05, 30.1, 30.4, 12]),
  );
  for (const { meanCoverage, maxDifference } of results) {
    expect(meanCoverage).toBeGreaterThan(0.01);
    // Both paths sum float32 fields in the same order and step the same model (measured: at most
    // 5e-5 apart). A wrong texel index, threshold or step gives differences of order the coverage.
    expect(maxDifference).toBeLessThan(1e-4);
  }
});

test('the local waves on the GPU equal the JS solver, through a stone, a turning hull and a moving grid, in open water and by a beach', ALSO_ON_OLDEST_THREE, async ({ browser }) => {
  const page = await simulationPage(browser);
  const open = await page.evaluate(() => window.harness.compareLocalWavesGpuWithJs(12));
  // By a beach (docs/shores.md): the dispersion's depth and the land held at zero change as the grid moves.
  const beach = await page.evaluate(() => window.harness.compareLocalWavesGpuWithJs(12, true));
  for (const { maxHeight, heightError, slopeError } of [...open, ...beach]) {
    expect(maxHeight).toBeGreaterThan(0.01);
    // Same step on both paths, float32 on the GPU against double in JS (measured: at most 1.3e-5 of
    // the largest height over 12 steps; with GLSL's own sin/cos it was 1e-3). A wrong twiddle,
    // shift or sign gives errors of order 1.
    expect(heightError).toBeLessThan(5e-5);
    expect(slopeError).toBeLessThan(5e-5);
  }
});

test('a hull on a path: after a jump in time its wake is run up to the time, the same bits whatever came before', async ({ browser }) => {
  const page = await simulationPage(browser);
  const result = await page.evaluate(() => window.harness.localWavesAfterJumps(30));
  expect(result.finite).toBe(true);
  expect(result.maxHeight).toBeGreaterThan(0.02); // a wake, not a calm sea
  expect(result.identical).toBe(true);
});

test('bad input to the local waves raises errors naming it; a drop off the grid is ignored; nothing NaN', async ({ browser }) => {
  const page = await simulationPage(browser);
  const { messages, droppedOutside, finite } = await page.evaluate(() => window.harness.localWavesBadInput());
  expect(messages).toEqual([
    expect.stringMatching(/^drop\(x, z\) must be finite coordinates in metres; got \[NaN, 0\]$/),
    expect.stringMatching(/^drop radius must be metres from 0.1 to 20; got 0$/),
    expect.stringMatching(/^drop depth must be metres from 0 to 5; got -1$/),
    expect.stringMatching(/^hull length must be metres from 0.2 to 400; got -1$/),
    expect.stringMatching(/^hull pose must be finite x, z \(m\) and heading \(radians\); got \[0, Infinity, 0\]$/),
    expect.stringMatching(/^hull draft must be metres from 0 to 20; got -2$/),
    expect.stringMatching(/^follow\(x, z\) must be finite coordinates/),
    expect.stringMatching(/^localWaves.resolution must be a power of two from 16 to 1024; got 100$/),
    expect.stringMatching(/^localWaves.cellSize must be metres per texel from 0.05 to 10; got 0$/),
  ]);
  expect(droppedOutside).toBe(false);
  expect(finite).toBe(true);
});

test('the JS path in a Web Worker uploads the same fields as CpuWaveFields', async ({ browser }) => {
  const page = await simulationPage(browser);
  const result = await page.evaluate(() => window.harness.workerAgainstDirect({ resolution: 64, seed: 5 }, 42.5));
  expect(result.path).toBe('js-worker');
  expect(result.rms).toBeGreaterThan(0);
  // Same code, same float32 arithmetic in another thread: identical.
  expect(result.maxDifference).toBe(0);
});

test('bad parameters raise errors naming them, and the simulation keeps its last good values', async ({ browser }) => {
  const page = await simulationPage(browser);
  const { messages, unchanged, nonFinite } = await page.evaluate(() => window.harness.badInput());
  expect(messages).toEqual([
    expect.stringMatching(/^windSpeed must be a speed in m\/s from 0 to 60; got NaN$/),
    expect.stringMatching(/^resolution must be a power of two from 16 to 1024; got 100$/),
    expect.stringMatching(/^patchSizes must be .*ascending, each at least twice the one before; got \[-1\]$/),
    expect.stringMatching(/^patchSizes must be .*ascending.*; got \[100, 50\]$/),
    expect.stringMatching(/^patchSizes must be .*at least twice the one before; got \[50, 60\]$/),
    expect.stringMatching(/^spectrum must be one of phillips, pierson-moskowitz, jonswap, tma; got "bretschneider"$/),
    expect.stringMatching(/^spreading must be one of cos-2s, mitsuyasu, hasselmann, donelan-banner; got "cosine"$/),
    expect.stringMatching(/^fetch must be a distance in km > 0 and at most 100000; got 0$/),
    expect.stringMatching(/^swellPeriod must be a period in seconds > 0 and at most 40; got -3$/),
    expect.stringMatching(/^amplitude must be a number from 0 to 1; got -0.000001$/),
    expect.stringMatching(/^repeatPeriod must be .*> 0 and at most 100000; got 0$/),
    expect.stringMatching(/^depth must be .*; got 0$/),
    expect.stringMatching(/^time must be a finite number of seconds; got NaN$/),
  ]);
  expect(unchanged).toBe(true);
  expect(nonFinite).toBe(0);
});

test('a shader-only parameter (choppiness) rebuilds nothing; a spectrum parameter (wind) rebuilds the cascades', async ({ browser }) => {
  const page = await simulationPage(browser);
  const result = await page.evaluate(() => window.harness.layersKeptAcross());
  expect(result).toEqual({ choppiness: true, windSpeed: false, choppinessApplied: 2.5 });
});

test('every GPU resource a simulation makes is freed by dispose (memory back to its baseline)', ALSO_ON_OLDEST_THREE, async ({ browser }) => {
  const page = await simulationPage(browser);
  const { before, during, after } = await page.evaluate(() => window.harness.memoryAfterCycles(12));
  // The GPU path's framebuffers (three.js's and the FFT's own layered ones) exist while it runs…
  expect(during).toBeGreaterThan((before as { framebuffers: number }).framebuffers + 4);
  // …and textures, geometries and framebuffers all go with dispose.
  expect(after).toEqual(before);
});

test('the initial spectrum is bit-identical in Node and in the browser for the same seed', async ({ browser }) => {
  const page = await simulationPage(browser);
  const changes = { resolution: 64, seed: 7, windDirection: 33.3 };
  const inNode = createCascadeSpectra(validateParameters(changes)).flatMap((spectrum) => Array.from(new Uint32Array(spectrum.amplitudes.buffer)));
  const inBrowser = await page.evaluate((c) => window.harness.spectrumBits(c), changes);
  expect(inBrowser.length).toBe(inNode.length);
  expect(inBrowser).toEqual(inNode);
  // And another seed gives another sea.
  const otherSeed = await page.evaluate((c) => window.harness.spectrumBits({ ...c, seed: 8 }), changes);
  expect(otherSeed).not.toEqual(inNode);
});
