import { expect, test } from '@playwright/test';
import { WEBGPU_BROWSER } from '../shared/webgpuBrowser';

// The compute FFT (src/fft/computeFft.ts) on SwiftShader's WebGPU adapter, which Chromium gives
// localhost pages with --enable-unsafe-webgpu (../shared/BROWSER.md): its fields equal the JS FFT's
// within 1e-5 of their RMS (issue 23), and the exact answers (a plane wave in one field, the
// term-by-term DFT of all at small N) too, so that an error both FFTs shared would still show. Then
// what is built on it: a cascade's fields (ComputeWaveFields) against the JS path's, and the WebGPU
// Ocean on path 'gpu' against path 'js'.
test.use(WEBGPU_BROWSER);

const SIZES = [16, 32, 64, 128, 256, 512];
/** Sizes also checked against the term-by-term DFT (N⁴ operations per field). */
const NAIVE_SIZES = [16, 32];
const BOUND = 1e-5;

test('the compute FFT, and the cascade fields made with it, equal the JS path within 1e-5 of RMS at N = 16 to 512; so does the WebGPU Ocean on path gpu', async ({ page }) => {
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(error.message));
  await page.goto('/tests/browser/fft/computeFft.html');
  await expect(page).toHaveTitle('ready');
  const noWebGPU = await page.evaluate(() => window.computeFft.open());
  expect(noWebGPU, 'a WebGPU backend').toBeNull();
  const before = await page.evaluate(() => window.computeFft.gpuMemory());
  for (const n of SIZES) {
    const result = await page.evaluate(([size, naive]) => window.computeFft.compare(size, naive), [n, NAIVE_SIZES.includes(n)] as const);
    const naive = result.naive === null ? '' : `, vs naive DFT ${result.naive.toExponential(2)}`;
    console.log(`compute FFT N = ${n}: vs JS FFT ${result.js.toExponential(2)}, vs plane wave ${result.planeWave.toExponential(2)}${naive} (relative RMS, worst of 4 fields); ${result.ms.toFixed(1)} ms with upload and read-back`);
    expect(result.js, `N = ${n} vs the JS FFT`).toBeLessThan(BOUND);
    expect(result.planeWave, `N = ${n} vs the plane wave`).toBeLessThan(BOUND);
    if (result.naive !== null) expect(result.naive, `N = ${n} vs the naive DFT`).toBeLessThan(BOUND);
  }
  for (const n of SIZES) {
    const error = await page.evaluate((size) => window.computeFft.cascadeFields(size, 12.5), n);
    console.log(`cascade fields N = ${n}: compute FFT vs JS path ${error.toExponential(2)} (relative RMS, worst of 8 fields)`);
    expect(error, `cascade fields at N = ${n}`).toBeLessThan(BOUND);
  }
  const paths = await page.evaluate(() => window.computeFft.oceanPaths(3.7));
  console.log(`WebGPU Ocean, path 'gpu' vs 'js' (N = 64): picture ${paths.meanLevels.toFixed(3)} levels on average, ${paths.maxLevels} at most; heightAt ${paths.heights.toExponential(2)} m at most`);
  expect(paths.meanLevels).toBeLessThan(0.05);
  expect(paths.heights).toBe(0); // the queries compute their own fields in JS on both paths
  // compare(), cascadeFields() and oceanPaths() dispose what they make: its buffers and textures are gone from the renderer.
  expect(await page.evaluate(() => window.computeFft.gpuMemory())).toEqual(before);
  expect(errors).toEqual([]);
});
