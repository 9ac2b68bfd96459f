import { expect, test, type Locator, type Page } from '@playwright/test';
import { join, resolve } from 'node:path';
import { PNG } from 'pngjs';
import type { DataTexture } from 'three';
import { ensureBuiltApp } from '../../../scripts/shot.mjs';
import { serveDirectory } from '../../../scripts/static-server.mjs';

// The built app and example pages (dist/app, built by `vite build` as `npm run shot` builds it,
// when older than the sources) served as plain files with a strict Content-Security-Policy: no
// inline styles or scripts, no data: fonts, workers only from the site. Any violation fails, and
// every page must still draw its sea.

const CSP = "default-src 'self'; script-src 'self'; style-src 'self'; img-src 'self' data: blob:; worker-src 'self'";

let server: { url: string; close: () => Promise<void> };

test.beforeAll(async () => {
  test.setTimeout(180_000); // a build takes a few seconds, more on a busy machine
  ensureBuiltApp({ log: () => {} });
  server = await serveDirectory(join(resolve(import.meta.dirname, '../../..'), 'dist/app'), { headers: { 'content-security-policy': CSP } });
});
test.afterAll(() => server?.close());

/**
 * Opens `path` of the build. Returns a function that lists what has gone wrong on the page since:
 * CSP violations (securitypolicyviolation events, listened to before the page's first byte is
 * parsed), console errors (where Chromium reports a blocked style, font or script) and page errors.
 */
async function open(page: Page, path: string): Promise<() => Promise<string[]>> {
  const problems: string[] = [];
  page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
  page.on('console', (message) => {
    if (message.type() === 'error') problems.push(`console: ${message.text()}`);
  });
  await page.addInitScript(() => {
    const violations: string[] = [];
    document.addEventListener('securitypolicyviolation', (event) => {
      violations.push(`${event.effectiveDirective} blocked ${event.blockedURI || 'inline'} at ${event.sourceFile}:${event.lineNumber}`);
    });
    Object.assign(window, { cspViolations: violations });
  });
  const response = await page.goto(`${server.url}${path}`);
  expect(response?.headers()['content-security-policy']).toBe(CSP);
  return async () => {
    const violations = await page.evaluate(() => (window as unknown as { cspViolations: string[] }).cspViolations);
    return [...violations.map((text) => `violation: ${text}`), ...problems];
  };
}

interface Picture {
  width: number;
  height: number;
  /** RGBA, top row first. */
  data: Uint8Array;
}

/** A sky above a sea: no black, a bright top tenth, and variation across the picture (waves, the horizon). */
function expectSea({ width, height, data }: Picture): void {
  let black = 0;
  let top = 0;
  let sum = 0;
  let sumSquares = 0;
  const topRows = Math.ceil(height / 10);
  for (let i = 0; i < width * height; i++) {
    const [r, g, b] = data.subarray(4 * i, 4 * i + 3);
    const value = (r + g + b) / 3;
    if (Math.max(r, g, b) < 8) black++;
    if (i < topRows * width) top += value;
    sum += value;
    sumSquares += value * value;
  }
  const count = width * height;
  expect(black / count, 'black pixels').toBeLessThan(0.01);
  expect(top / (topRows * width), 'the sky at the top').toBeGreaterThan(100);
  expect(Math.sqrt(sumSquares / count - (sum / count) ** 2), 'variation across the picture').toBeGreaterThan(10);
}

/** What a canvas shows on screen (a screenshot: what was composited, whatever its drawing buffer's settings). */
async function screenshot(canvas: Locator): Promise<Picture> {
  const png = PNG.sync.read(await canvas.screenshot());
  return { width: png.width, height: png.height, data: new Uint8Array(png.data) };
}

test('the app: panel, inspector, the JS path in its worker and the skybox faces, with no CSP violation', async ({ page }) => {
  await page.setViewportSize({ width: 480, height: 270 });
  const problems = await open(page, '/?path=js&inspector=1&resolution=64&skybox=/skybox/clear-afternoon/');
  await page.waitForFunction(() => window.oceanApp !== undefined);
  await page.evaluate(() => window.oceanApp.panel.gui.open()); // a narrow page starts with it closed: draw its icons too
  // The worker runs (its fields reach the textures) and the six faces are loaded.
  await expect
    .poll(() =>
      page.evaluate(() => {
        const { ocean } = window.oceanApp;
        const field = (ocean.simulation.cascades[0].textures.displacement.value as DataTexture).image.data as Float32Array;
        return { path: ocean.simulation.path, moving: field.some((value) => value !== 0), faces: ocean.sky.usingFaces };
      }),
    )
    .toEqual({ path: 'js-worker', moving: true, faces: true });
  // The canvas right after the app's render (the panel and the status line cover a screenshot of
  // it), above the inspector's tiles along its bottom (as high as their labels' strip).
  const { width, height, data, tiles } = await page.evaluate(async () => {
    const { width, height, data } = await window.oceanApp.capturePixels();
    return { width, height, data: [...data], tiles: document.querySelector('.inspector-labels')!.clientHeight };
  });
  expect(tiles).toBeGreaterThan(0);
  const rows = height - tiles; // pixel ratio 1
  const flipped = new Uint8Array(4 * width * rows); // readPixels gives the bottom row first
  for (let y = 0; y < rows; y++) flipped.set(data.slice(4 * width * (height - 1 - y), 4 * width * (height - y)), 4 * width * y);
  expectSea({ width, height: rows, data: flipped });
  expect(await problems()).toEqual([]);
});

test('element.html: <fft-ocean> styles its shadow root and draws, with no CSP violation', async ({ page }) => {
  await page.setViewportSize({ width: 640, height: 600 });
  const problems = await open(page, '/examples/element.html');
  // The first element is on screen (the others, below, are made and styled but do not draw).
  await page.waitForFunction(() => document.querySelector('fft-ocean')!.frameCount >= 2, null, { timeout: 60_000 });
  // Its stylesheet applies: 16:9 of the column's width without a height from the page.
  const box = (await page.locator('#hero').boundingBox())!;
  expect(box.height).toBeCloseTo((box.width * 9) / 16, 0);
  expectSea(await screenshot(page.locator('#hero canvas')));
  expect(await problems()).toEqual([]);
});

test('three-scene.html draws with no CSP violation', async ({ page }) => {
  await page.setViewportSize({ width: 480, height: 270 });
  const problems = await open(page, '/examples/three-scene.html');
  await page.waitForFunction(() => window.example?.frames() > 2, null, { timeout: 60_000 });
  expectSea(await screenshot(page.locator('canvas')));
  expect(await problems()).toEqual([]);
});

test('the shot page (npm run shot) draws with no CSP violation', async ({ page }) => {
  await page.setViewportSize({ width: 480, height: 270 });
  const problems = await open(page, '/examples/shot.html?width=480&height=270&time=3');
  await expect(page).toHaveTitle('ready', { timeout: 60_000 });
  expectSea(await screenshot(page.locator('canvas')));
  expect(await problems()).toEqual([]);
});
