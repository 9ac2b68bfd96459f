import { expect, test } from '@playwright/test';

test.beforeEach(async ({ page }) => {
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(error.message));
  await page.goto('/tests/browser/pages/simulation.html');
  await expect(page).toHaveTitle('ready');
  expect(errors).toEqual([]);
});

test('the context offers float32 render targets (SwiftShader WebGL2)', async ({ page }) => {
  expect(await page.evaluate(() => window.harness.supportedPrecision())).toBe('float32');
});

for (const resolution of [64, 256, 512]) {
  test(`GPU fields equal JS fields at N = ${resolution} (RGBA32F, two times)`, async ({ page }) => {
    const { results, passCount } = await page.evaluate(
      (n) => window.harness.compareGpuWithJs({ resolution: n, seed: 7, windSpeed: 14 }, [3.25, 117.5]),
      resolution,
    );
    expect(passCount).toBe(1 + 2 * Math.ceil(Math.log2(resolution) / 2));
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
