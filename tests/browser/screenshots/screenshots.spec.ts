import { expect, test } from '@playwright/test';
import { ALSO_ON_OLDEST_THREE } from '../shared/threeRange';

// Deterministic pictures: fixed seed and time from the URL, compared with committed baselines
// (tests/browser/screenshots/screenshots.spec.ts-snapshots/, each looked at before it was committed). The
// tolerance absorbs rasterization differences between Chromium builds, not wrong pictures: a
// black frame, a missing sky or a different sea changes far more than 1% of the pixels.
const TOLERANCE = { maxDiffPixelRatio: 0.01, threshold: 0.15 };

async function shot(page: import('@playwright/test').Page, query: string, width: number, height: number): Promise<Buffer> {
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(error.message));
  await page.setViewportSize({ width, height });
  await page.goto(`/tests/browser/screenshots/scene.html?seed=7&t=12.5&width=${width}&height=${height}&${query}`);
  await expect(page).toHaveTitle('rendered');
  expect(errors).toEqual([]);
  return page.locator('canvas').screenshot();
}

for (const [width, height] of [
  [1280, 720],
  [400, 225],
]) {
  for (const view of ['default', 'horizon', 'high']) {
    test(`${view} view at ${width}x${height}`, width === 400 ? ALSO_ON_OLDEST_THREE : {}, async ({ page }) => {
      await shot(page, `view=${view}`, width, height);
      await expect(page.locator('canvas')).toHaveScreenshot(`${view}-${width}x${height}.png`, TOLERANCE);
    });
  }
}

test('under water at 400x225', ALSO_ON_OLDEST_THREE, async ({ page }) => {
  await shot(page, 'view=underwater', 400, 225);
  await expect(page.locator('canvas')).toHaveScreenshot('underwater-400x225.png', TOLERANCE);
});

// The debug modes that reproduce the course report's figures.
for (const [name, query] of [
  ['fresnel (report Figure 7)', 'mode=fresnel'],
  ['reflection (report Figure 10, left)', 'mode=reflection'],
  ['refraction (report Figure 10, middle)', 'mode=refraction'],
  // Guardado's term follows a vertical ray, so it shows caustics only under a high sun.
  ['caustics (report Figure 9, left)', 'mode=caustics&sunElevation=75'],
  ['height (report Figure 3)', 'mode=height'],
  ['wireframe (report Figure 4)', 'wireframe=1&mode=height'],
]) {
  test(`debug mode ${name} at 400x225`, async ({ page }) => {
    await shot(page, `view=default&${query}`, 400, 225);
    const file = `${query.replace(/[=&]/g, '-')}-400x225.png`;
    await expect(page.locator('canvas')).toHaveScreenshot(file, TOLERANCE);
  });
}
