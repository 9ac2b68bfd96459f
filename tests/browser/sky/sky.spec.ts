import { expect, test, type Page } from '@playwright/test';
import type { Vec3, ViewOptions, ViewSummary } from './sky';
import { ALSO_ON_OLDEST_THREE } from '../shared/threeRange';

test.beforeEach(async ({ page }) => {
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(error.message));
  await page.goto('/tests/browser/sky/sky.html');
  await expect(page).toHaveTitle('ready');
  expect(errors).toEqual([]);
});

const luminance = ([r, g, b]: Vec3): number => 0.2126 * r + 0.7152 * g + 0.0722 * b;

async function view(page: Page, direction: Vec3, options: ViewOptions = {}): Promise<ViewSummary> {
  return page.evaluate(([d, o]) => window.skyHarness.view(d, o), [direction, options] as const);
}

/** The sun is at the centre of a narrow view along `direction`, and HDR. */
async function expectSunAtCentre(page: Page, direction: Vec3): Promise<void> {
  const { brightest } = await view(page, direction, { fov: 10, size: 33 }); // 0.3° per pixel
  expect(Math.hypot(brightest.dx, brightest.dy)).toBeLessThanOrEqual(1.5);
  expect(luminance(brightest.value)).toBeGreaterThan(10);
}

/** Straight down is the deep-water colour (relative to its own size: it is dark). */
async function expectDeepWaterBelow(page: Page, tolerance: number): Promise<void> {
  const water = await page.evaluate(() => window.skyHarness.deepWaterColor());
  const { mean } = await view(page, [0, -1, 0], { fov: 60 });
  for (let c = 0; c < 3; c++) expect(Math.abs(mean[c] - water[c])).toBeLessThan(tolerance * water[2]);
  expect(mean[2]).toBeGreaterThan(mean[0]); // blue, not grey or black
}

// The shoulder scripts/make-skybox-faces.mjs applies before writing 8-bit sRGB.
const KNEE = 0.8;

/**
 * The cube holds the analytic sky: views of it (through SkyBackground and through
 * environmentLookup.glsl) equal views of the analytic sky shader itself. 0.31° per pixel, about
 * one cube texel; compared in 4×4 blocks of 16×16 pixels after the faces' tone-map shoulder, which
 * brings the sun disk (several hundred, clipped at the RGBM range of 32) to about 1 either way.
 * Left: bilinear filtering of 0.35° texels, and RGBM's 8 bits relative to each texel (~0.4%).
 */
async function expectCubeMatchesAnalyticSky(page: Page, directions: Vec3[]): Promise<void> {
  const options: ViewOptions = { fov: 20, size: 64, blocks: 4, toneMapKnee: KNEE };
  for (const direction of directions) {
    const analytic = await view(page, direction, { ...options, via: 'analytic' });
    for (const via of ['background', 'lookup'] as const) {
      const cube = await view(page, direction, { ...options, via });
      cube.blocks.forEach((value, i) => expect(Math.abs(value - analytic.blocks[i])).toBeLessThan(0.002 + 0.02 * analytic.blocks[i]));
    }
  }
}

test('the generated sky: not black, the sun where sunDirection points, deep water straight down', ALSO_ON_OLDEST_THREE, async ({ page }) => {
  await page.evaluate(() => window.skyHarness.create());
  const sun = await page.evaluate(() => window.skyHarness.sunDirection());
  expect(sun).toEqual((await page.evaluate(() => window.skyHarness.directionFromAngles(30, 40))).map((v) => expect.closeTo(v, 6)));
  await expectSunAtCentre(page, sun);
  await expectDeepWaterBelow(page, 0.02);

  const zenith = (await view(page, [0, 1, 0])).mean;
  const horizon = (await view(page, [-sun[0], 0.05, -sun[2]])).mean; // 3° up, away from the sun
  expect(zenith[2]).toBeGreaterThan(0.1); // not black
  expect(zenith[2]).toBeGreaterThan(1.5 * zenith[0]); // blue
  expect(luminance(horizon)).toBeGreaterThan(1.5 * luminance(zenith)); // brighter horizon haze

  // Moving the sun moves it in the cube too (setSun re-renders).
  expect(await page.evaluate(() => window.skyHarness.setSun(65, -120))).toBeNull();
  const moved = await page.evaluate(() => window.skyHarness.sunDirection());
  expect(moved).toEqual((await page.evaluate(() => window.skyHarness.directionFromAngles(65, -120))).map((v) => expect.closeTo(v, 6)));
  await expectSunAtCentre(page, moved);
  const { brightest } = await view(page, sun, { fov: 10, size: 33 });
  expect(luminance(brightest.value)).toBeLessThan(5); // the old position is just sky now
});

test('the 8-bit RGBM cube, seen through SkyBackground and environmentLookup.glsl, holds the analytic sky', ALSO_ON_OLDEST_THREE, async ({ page }) => {
  await page.evaluate(() => window.skyHarness.create());
  const sun = await page.evaluate(() => window.skyHarness.sunDirection());
  await expectCubeMatchesAnalyticSky(page, [sun, [1, 0.1, 0], [-0.3, 0.02, -1], [0, 1, 0], [0.2, -1, 0.1]]);
});

test('loadFaces with the shipped set: a loaded six-image CubeTexture that matches the generated sky', async ({ page }) => {
  const { shipped, shippedUrls } = await page.evaluate(() => window.skyHarness);
  await page.evaluate(({ sunElevation, sunAzimuth }) => window.skyHarness.create({ sunElevation, sunAzimuth }), shipped);

  // Directions on and across every face and edge: the axes, the cube's corners, the horizon all
  // round (just above and below), so a face that is mirrored, rotated or swapped shows up.
  const directions: Vec3[] = [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]];
  for (const x of [-1, 1]) for (const y of [-1, 1]) for (const z of [-1, 1]) directions.push([x, y, z]);
  for (let azimuth = 0; azimuth < 360; azimuth += 45) {
    const a = (azimuth * Math.PI) / 180;
    directions.push([Math.cos(a), 0.05, Math.sin(a)], [Math.cos(a), -0.03, Math.sin(a)]);
  }
  // 0.31° per pixel, about one cube texel, so both views sample mip 0: tone mapping (concave
  // above the knee) and mip filtering only commute there. Compared in 4×4 blocks of 16×16 pixels.
  const options: ViewOptions = { fov: 20, size: 64, blocks: 4 };
  const generated = await page.evaluate(
    ([ds, o]) => ds.map((d) => window.skyHarness.view(d, o).blocks),
    [directions, { ...options, toneMapKnee: KNEE }] as const,
  );

  const { error, environment } = await page.evaluate((urls) => window.skyHarness.loadFaces(urls), shippedUrls);
  expect(error).toBeNull();
  // The faces are copied into the same cube render target that everything samples.
  expect(environment.environmentIsRenderTarget).toBe(true);
  expect(environment.usingFaces).toBe(true);
  expect(environment.faces?.isCubeTexture).toBe(true);
  expect(environment.faces?.colorSpace).toBe('srgb');
  expect(environment.faces?.images).toHaveLength(6);
  for (const image of environment.faces?.images ?? []) {
    expect(image.complete).toBe(true);
    expect(image.width).toBe(256);
  }

  const faces = await page.evaluate(([ds, o]) => ds.map((d) => window.skyHarness.view(d, o).blocks), [directions, options] as const);
  let worst = 0;
  for (let i = 0; i < directions.length; i++) {
    const [expected, actual] = [generated[i], faces[i]];
    for (let j = 0; j < expected.length; j++) {
      // 8-bit sRGB steps give about 0.1 here; a mirrored, rotated or flipped face 25–50 (tried).
      worst = Math.max(worst, Math.abs(actual[j] - expected[j]) / (0.02 + 0.05 * expected[j]));
    }
  }
  expect(worst).toBeLessThan(1);

  // The sun: saturated at the centre of a view towards it, not where a mirrored set would put it.
  const sun = await page.evaluate(() => window.skyHarness.sunDirection());
  const towards = await view(page, sun, { fov: 10, size: 33 });
  expect(Math.min(...towards.pixels.slice(3 * (16 * 33 + 16), 3 * (16 * 33 + 16) + 3))).toBeGreaterThan(0.95);
  const mirrored = await view(page, [-sun[0], sun[1], sun[2]], { fov: 10, size: 33 });
  expect(luminance(mirrored.brightest.value)).toBeLessThan(0.5);
  await expectDeepWaterBelow(page, 0.1); // 8-bit sRGB is coarse this dark

  // Materials that sample the cube themselves see the loaded faces too.
  const lookup = await view(page, sun, { fov: 10, size: 33, via: 'lookup' });
  expect(Math.min(...lookup.pixels.slice(3 * (16 * 33 + 16), 3 * (16 * 33 + 16) + 3))).toBeGreaterThan(0.95);

  // Back to the generated sky: the cube is redrawn from the analytic shader.
  await page.evaluate(() => window.skyHarness.useGeneratedSky());
  const back = await page.evaluate(() => window.skyHarness.describe());
  expect(back.usingFaces).toBe(false);
  expect(back.faces).toBeNull();
  await expectCubeMatchesAnalyticSky(page, [sun, [-0.3, 0.02, -1]]);
});

test('loadFaces that fails rejects naming the URL, and the generated sky stays in use', async ({ page }) => {
  const { shippedUrls } = await page.evaluate(() => window.skyHarness);
  await page.evaluate(() => window.skyHarness.create());
  const missing = '/skybox/no-such-set/nx.png';
  const notAnImage = '/tests/browser/sky/sky.html';
  for (const [face, url] of [['nx', missing], ['pz', notAnImage]] as const) {
    const { error, environment } = await page.evaluate((urls) => window.skyHarness.loadFaces(urls), { ...shippedUrls, [face]: url });
    expect(error).toMatch(/^ParameterError on urls: SkyEnvironment.loadFaces: could not load /);
    expect(error).toContain(url);
    expect(error).toContain('generated sky stays in use');
    expect(environment.usingFaces).toBe(false);
    expect((await view(page, [0, 1, 0])).mean[2]).toBeGreaterThan(0.1); // still a sky, not black
  }

  // A load overtaken by useGeneratedSky does not switch when it completes late.
  const overtaken = await page.evaluate((urls) => window.skyHarness.loadFaces(urls, 'useGeneratedSky'), shippedUrls);
  expect(overtaken.error).toMatch(/^ParameterError on urls: SkyEnvironment.loadFaces: superseded by a later/);
  expect(overtaken.environment.usingFaces).toBe(false);
});

test('setSun with invalid values throws naming the parameter and keeps the sun', async ({ page }) => {
  await page.evaluate(() => window.skyHarness.create({ sunElevation: 20, sunAzimuth: 100 }));
  const before = await page.evaluate(() => window.skyHarness.sunDirection());
  // The rules are SUN_OPTIONS' (src/parameters/sceneOptions.ts); the message quotes the bad value.
  const allowed = {
    sunElevation: 'a number of degrees from -90 to 90',
    sunAzimuth: 'a finite angle in degrees (at most 1e6 in size)',
  };
  for (const [elevation, azimuth, parameter, got] of [
    [NaN, 0, 'sunElevation', 'NaN'],
    [91, 0, 'sunElevation', '91'],
    [-90.5, 0, 'sunElevation', '-90.5'],
    [-Infinity, 0, 'sunElevation', '-Infinity'],
    [10, NaN, 'sunAzimuth', 'NaN'],
    [10, Infinity, 'sunAzimuth', 'Infinity'],
    [10, 2e6, 'sunAzimuth', '2000000'],
  ] as const) {
    const error = await page.evaluate(([e, a]) => window.skyHarness.setSun(e, a), [elevation, azimuth]);
    expect(error).toBe(`ParameterError: ${parameter} must be ${allowed[parameter]}; got ${got}`);
    expect(await page.evaluate(() => window.skyHarness.sunDirection())).toEqual(before);
  }
  await expectSunAtCentre(page, before); // the cube was not re-rendered with a bad sun either
  await expect(page.evaluate(() => window.skyHarness.create({ sunElevation: NaN }))).rejects.toThrow(/sunElevation/);
});

test('dispose returns the renderer to its texture and geometry counts from before construction', async ({ page }) => {
  const { shippedUrls } = await page.evaluate(() => window.skyHarness);
  const baseline = await page.evaluate(() => window.skyHarness.memory());
  await page.evaluate(() => window.skyHarness.create());
  await page.evaluate(() => window.skyHarness.setSun(10, 200));
  expect((await page.evaluate((urls) => window.skyHarness.loadFaces(urls), shippedUrls)).error).toBeNull();
  expect((await page.evaluate((urls) => window.skyHarness.loadFaces(urls), shippedUrls)).error).toBeNull(); // replaces the first set
  const during = await page.evaluate(() => window.skyHarness.memory());
  expect(during.textures).toBe(baseline.textures + 2); // the generated cube and one loaded set
  expect(during.geometries).toBe(baseline.geometries + 1); // the sky box
  await page.evaluate(() => window.skyHarness.dispose());
  expect(await page.evaluate(() => window.skyHarness.memory())).toEqual(baseline);

  // A load still in flight when dispose() runs is dropped, not leaked.
  await page.evaluate(() => window.skyHarness.create());
  const late = await page.evaluate((urls) => window.skyHarness.loadFaces(urls, 'dispose'), shippedUrls);
  expect(late.error).toMatch(/^ParameterError on urls: SkyEnvironment.loadFaces: the environment was disposed before/);
  expect(await page.evaluate(() => window.skyHarness.memory())).toEqual(baseline);
});
