import { expect, test, type Page } from '@playwright/test';
import { writeFileSync } from 'node:fs';
import { PNG } from 'pngjs';
import { WEBGPU_BROWSER } from '../shared/webgpuBrowser';

// The compute FFT (src/fft/computeFft.ts) on SwiftShader's WebGPU adapter, which Chromium gives
// localhost pages with --enable-unsafe-webgpu (../shared/BROWSER.md): its fields equal the JS FFT's
// within 1e-5 of their RMS (issue 23), and the exact answers (a plane wave in one field, the
// term-by-term DFT of all at small N) too, so that an error both FFTs shared would still show. Then
// what is built on it: the spectra evolved in a compute shader (ComputeSpectrumEvolution) and a
// cascade's fields (ComputeWaveFields) against the JS path's, also a day and a month into the scene
// (the phases from dispersion.ts' table, reduced in double precision), the whitecap foam made from
// them in a compute shader (ComputeFoam), and the WebGPU Ocean on path 'gpu' against path 'js'.
test.use(WEBGPU_BROWSER);

const SIZES = [16, 32, 64, 128, 256, 512];
/** Sizes also checked against the term-by-term DFT (N⁴ operations per field). */
const NAIVE_SIZES = [16, 32];
const BOUND = 1e-5;
/**
 * Times (s) the evolved spectra and the fields are compared at: a day and a month in, a float32
 * ω·t would be off by radians (ulp(2.6e6 s) = 0.25 s against periods of seconds).
 */
const TIMES = [0, 12.5, 86_400.3, 2_592_000.7];

/** Opens the test page on a WebGPU backend (failing, saying why, where there is none); the page's errors collect in the array returned. */
async function openPage(page: Page): Promise<string[]> {
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(error.message));
  await page.goto('/tests/browser/fft/computeFft.html');
  await expect(page).toHaveTitle('ready');
  expect(await page.evaluate(() => window.computeFft.open()), 'a WebGPU backend').toBeNull();
  return errors;
}

test('the compute FFT, the spectra evolved in a compute shader and the cascade fields made with them equal the JS path within 1e-5 of RMS at N = 16 to 512, at large times too', async ({ page }) => {
  const errors = await openPage(page);
  const before = await page.evaluate(() => window.computeFft.gpuMemory());
  for (const n of SIZES) {
    const result = await page.evaluate(([size, naive]) => window.computeFft.compare(size, naive), [n, NAIVE_SIZES.includes(n)] as const);
    const naive = result.naive === null ? '' : `, vs naive DFT ${result.naive.toExponential(2)}`;
    console.log(`compute FFT N = ${n}: vs JS FFT ${result.js.toExponential(2)}, vs plane wave ${result.planeWave.toExponential(2)}${naive} (relative RMS, worst of 4 fields); ${result.ms.toFixed(1)} ms with upload and read-back`);
    expect(result.js, `N = ${n} vs the JS FFT`).toBeLessThan(BOUND);
    expect(result.planeWave, `N = ${n} vs the plane wave`).toBeLessThan(BOUND);
    if (result.naive !== null) expect(result.naive, `N = ${n} vs the naive DFT`).toBeLessThan(BOUND);
  }
  // The finest cascade in deep water at every size, and the largest in water 5 m deep at one: its
  // long waves feel the bottom, ω = √(g·k·tanh(k·d)) (Tessendorf 2001, eq. 15), so other m per mode.
  for (const [n, depth, cascade] of [...SIZES.map((size) => [size, Infinity, 0]), [64, 5, -1]]) {
    const errors = await page.evaluate(([size, d, c, times]) => window.computeFft.evolvedSpectra(size, times, d, c), [n, depth, cascade, TIMES] as const);
    console.log(`evolved spectra N = ${n}, cascade ${cascade}, depth ${depth} m: compute shader vs JS at t = ${TIMES.join(', ')} s: ${errors.map((e) => e.toExponential(2)).join(', ')} (relative RMS, worst of 4 spectra)`);
    for (const [i, error] of errors.entries()) expect(error, `evolved spectra at N = ${n}, depth ${depth} m, t = ${TIMES[i]} s`).toBeLessThan(BOUND);
  }
  for (const n of SIZES) {
    for (const t of [12.5, TIMES[TIMES.length - 1]]) {
      const error = await page.evaluate(([size, time]) => window.computeFft.cascadeFields(size, time), [n, t] as const);
      console.log(`cascade fields N = ${n}, t = ${t} s: compute shaders vs JS path ${error.toExponential(2)} (relative RMS, worst of 8 fields)`);
      expect(error, `cascade fields at N = ${n}, t = ${t} s`).toBeLessThan(BOUND);
    }
  }
  // compare(), evolvedSpectra() and cascadeFields() dispose what they make: its buffers and textures are gone from the renderer.
  expect(await page.evaluate(() => window.computeFft.gpuMemory())).toEqual(before);
  expect(errors).toEqual([]);
});

test("the whitecap foam of path 'gpu', a compute shader over the compute FFT's fields, equals the JS path's through a warm-up and frame steps; the WebGPU Ocean draws path 'gpu' as path 'js', and runs no JS FFT per frame on it", async ({ page }) => {
  const errors = await openPage(page);
  const before = await page.evaluate(() => window.computeFft.gpuMemory());
  // As the WebGL GPU foam's test (tests/browser/simulation): 20 m/s at N = 128, coverage near 10 %.
  // The first time is a jump (a warm-up from nothing over 3τ, twelve FFT updates), the next three
  // are frame steps, the last a jump back in time.
  const times = [30, 30.05, 30.1, 30.4, 12];
  const results = await page.evaluate((t) => window.computeFft.foamPaths({ windSpeed: 20, resolution: 128, seed: 3 }, t), times);
  for (const [i, { meanCoverage, maxDifference }] of results.entries()) {
    console.log(`foam at t = ${times[i]} s: mean coverage ${meanCoverage.toFixed(4)} (JS), compute shader vs JS at most ${maxDifference.toExponential(2)}`);
    expect(meanCoverage).toBeGreaterThan(0.01);
    // Both sum float32 fields in the same order and step the same model; the fields differ by ~2e-7
    // of their RMS (the first test). A wrong texel index, threshold or step gives differences of
    // order the coverage. The WebGL GPU foam is held to the same bound.
    expect(maxDifference).toBeLessThan(1e-4);
  }
  // Ten frames after the first update, foam on, no queries: the JS path (on this thread) runs its
  // FFT for every cascade each frame; path 'gpu' none (its cascades and foam are compute shaders).
  const calls = await page.evaluate(() => ({ gpu: window.computeFft.jsFftCallsPerFrames('gpu', true, 10), js: window.computeFft.jsFftCallsPerFrames('js', false, 10) }));
  console.log(`JS FFT calls on this thread over 10 frames: path 'gpu' ${calls.gpu}, path 'js' (no worker) ${calls.js}`);
  expect(calls.js).toBeGreaterThanOrEqual(30); // three cascades a frame: the counter counts
  expect(calls.gpu).toBe(0);
  const paths = await page.evaluate(() => window.computeFft.oceanPaths(3.7));
  const png = new PNG({ width: 160, height: 90 });
  png.data.set(paths.picture);
  writeFileSync(test.info().outputPath('ocean-path-gpu.png'), PNG.sync.write(png)); // to be looked at
  console.log(`WebGPU Ocean, path 'gpu' vs 'js' (N = 64, force 7 with whitecaps): picture ${paths.meanLevels.toFixed(3)} levels on average, ${paths.maxLevels} at most; heightAt ${paths.heights.toExponential(2)} m at most`);
  expect(paths.meanLevels).toBeLessThan(0.05);
  expect(paths.heights).toBe(0); // the queries compute their own fields in JS on both paths
  expect(await page.evaluate(() => window.computeFft.gpuMemory())).toEqual(before);
  expect(errors).toEqual([]);
});
