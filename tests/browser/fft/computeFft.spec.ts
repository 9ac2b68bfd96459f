import { expect, test } from '@playwright/test';
import { BROWSER_ARGS, findBrowser } from '../../../scripts/browser.mjs';

// The compute FFT (src/fft/computeFft.ts) on SwiftShader's WebGPU adapter, which Chromium gives
// localhost pages with --enable-unsafe-webgpu (../shared/BROWSER.md): its fields equal the JS FFT's
// within 1e-5 of their RMS (issue 23), and the exact answers (a plane wave in one field, the
// term-by-term DFT of all at small N) too, so that an error both FFTs shared would still show.
test.use({ launchOptions: { executablePath: findBrowser() ?? undefined, args: [...BROWSER_ARGS, '--enable-unsafe-webgpu'] } });

const SIZES = [16, 32, 64, 128, 256, 512];
/** Sizes also checked against the term-by-term DFT (N⁴ operations per field). */
const NAIVE_SIZES = [16, 32];
const BOUND = 1e-5;

test('the compute FFT equals the JS FFT and the exact transforms within 1e-5 of RMS at N = 16 to 512', async ({ page }) => {
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(error.message));
  await page.goto('/tests/browser/fft/computeFft.html');
  await expect(page).toHaveTitle('ready');
  const noWebGPU = await page.evaluate(() => window.computeFft.open());
  expect(noWebGPU, 'a WebGPU backend').toBeNull();
  const before = await page.evaluate(() => window.computeFft.storageBuffers());
  for (const n of SIZES) {
    const result = await page.evaluate(([size, naive]) => window.computeFft.compare(size, naive), [n, NAIVE_SIZES.includes(n)] as const);
    const naive = result.naive === null ? '' : `, vs naive DFT ${result.naive.toExponential(2)}`;
    console.log(`compute FFT N = ${n}: vs JS FFT ${result.js.toExponential(2)}, vs plane wave ${result.planeWave.toExponential(2)}${naive} (relative RMS, worst of 4 fields); ${result.ms.toFixed(1)} ms with upload and read-back`);
    expect(result.js, `N = ${n} vs the JS FFT`).toBeLessThan(BOUND);
    expect(result.planeWave, `N = ${n} vs the plane wave`).toBeLessThan(BOUND);
    if (result.naive !== null) expect(result.naive, `N = ${n} vs the naive DFT`).toBeLessThan(BOUND);
  }
  // compare() disposes each FFT: its buffers are gone from the renderer.
  expect(await page.evaluate(() => window.computeFft.storageBuffers())).toEqual(before);
  expect(errors).toEqual([]);
});
