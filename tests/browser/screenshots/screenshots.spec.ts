import { expect, test, type Browser, type Page } from '@playwright/test';
import { sharedPages } from '../shared/sharedPages';
import { ALSO_ON_OLDEST_THREE } from '../shared/threeRange';

// Deterministic pictures: fixed seed and time, compared with committed baselines
// (tests/browser/screenshots/screenshots.spec.ts-snapshots/, each looked at before it was committed). The
// tolerance absorbs rasterization differences between Chromium builds, not wrong pictures: a
// black frame, a missing sky or a different sea changes far more than 1% of the pixels.
const TOLERANCE = { maxDiffPixelRatio: 0.01, threshold: 0.15 };

// One page per canvas size (sharedPages), each scene drawn in it by a new Ocean
// (window.screenshotScene.draw): a page load costs more than a frame. After each test no uncaught
// error may have reached the page.
const pageErrors = new WeakMap<Page, string[]>();
const scenePage = sharedPages(
  async (page, size) => {
    const [width, height] = size.split('x').map(Number);
    const errors: string[] = [];
    pageErrors.set(page, errors);
    page.on('pageerror', (error) => errors.push(error.message));
    await page.setViewportSize({ width, height });
    await page.goto(`/tests/browser/screenshots/scene.html?width=${width}&height=${height}`);
    await expect(page).toHaveTitle('rendered');
  },
  async () => {},
);

/** The page of this canvas size, showing the scene of seed 7 at t = 12.5 s with `query`'s view and shading. */
async function shot(browser: Browser, query: string, width: number, height: number): Promise<Page> {
  const page = await scenePage(browser, `${width}x${height}`);
  await page.evaluate((query) => window.screenshotScene.draw(query), `seed=7&t=12.5&${query}`);
  expect(pageErrors.get(page)).toEqual([]);
  return page;
}

for (const [width, height] of [
  [1280, 720],
  [400, 225],
]) {
  for (const view of ['default', 'horizon', 'high']) {
    test(`${view} view at ${width}x${height}`, width === 400 ? ALSO_ON_OLDEST_THREE : {}, async ({ browser }) => {
      const page = await shot(browser, `view=${view}`, width, height);
      await expect(page.locator('canvas')).toHaveScreenshot(`${view}-${width}x${height}.png`, TOLERANCE);
    });
  }
}

test('under water at 400x225', ALSO_ON_OLDEST_THREE, async ({ browser }) => {
  const page = await shot(browser, 'view=underwater', 400, 225);
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
  test(`debug mode ${name} at 400x225`, async ({ browser }) => {
    const page = await shot(browser, `view=default&${query}`, 400, 225);
    const file = `${query.replace(/[=&]/g, '-')}-400x225.png`;
    await expect(page.locator('canvas')).toHaveScreenshot(file, TOLERANCE);
  });
}
