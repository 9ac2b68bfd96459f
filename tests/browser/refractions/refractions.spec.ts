import { expect, test, type Page, type TestInfo } from '@playwright/test';
import { writeFileSync } from 'node:fs';
import { PNG } from 'pngjs';
import type { SetupOptions, Vec3 } from './refractions';
import { ALSO_ON_OLDEST_THREE } from '../shared/threeRange';
import { onePageForFile } from '../shared/sharedPages';
import { fresnelReflectance } from '../shared/sceneProofs';

// The scene seen through the water (refractions: 'scene'): a white plate under calm water, drawn
// without tone mapping in linear RGB, against the optics it should follow. One page and one Ocean
// for the whole file (a new Ocean compiles its shaders again).

test.describe.configure({ mode: 'serial' });

let page: Page;
onePageForFile('/tests/browser/refractions/refractions.html', (opened) => {
  page = opened;
});

const N_WATER = 1.333; // the ior option's default
const ABSORPTION: Vec3 = [0.45, 0.07, 0.04]; // σ, 1/m: the absorption option's default
const SCATTER: Vec3 = [0.0, 0.035, 0.06]; // the scatterColor option's default (linear)
const SKY_GREY = 200; // the sky's faces, sRGB

/**
 * The sky's radiance: its faces' sRGB level decoded to linear (IEC 61966-2-1:
 * c ≤ 0.04045 ? c/12.92 : ((c + 0.055)/1.055)^2.4).
 */
const skyRadiance = ((c) => (c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4))(SKY_GREY / 255);

/**
 * What a pixel over flat water shows with a white plate (radiance 1) `depth` metres under it, seen
 * along `ray` (unit, downwards): the sky reflected, R·S, plus the transmitted fraction T = 1 − R of
 * the plate's light after the refracted path L = depth/cos θt (Snell: sin θt = sin θi/n) through the
 * water, which Beer–Lambert dims by e^{−σL} per channel (Mobley, "Light and Water", 1994, §3.2)
 * and the water's own in-scattered light fills in, scatter·(1 − e^{−σL}) (full daylight: the sun
 * above the horizon, src/render/daylight.ts). No caustics (causticColor 0) and no glint (the sun
 * behind the eye).
 */
function expectedPixel(ray: Vec3, depth: number): { colour: Vec3; path: number } {
  const cosI = -ray[1];
  const reflectance = fresnelReflectance(cosI, N_WATER);
  const sinT = Math.sqrt(1 - cosI * cosI) / N_WATER;
  const path = depth / Math.sqrt(1 - sinT * sinT);
  const colour = ABSORPTION.map((sigma, c) => {
    const transmittance = Math.exp(-sigma * path);
    return reflectance * skyRadiance + (1 - reflectance) * (transmittance + SCATTER[c] * (1 - transmittance));
  }) as Vec3;
  return { colour, path };
}

const PLATE_SETUP: SetupOptions = {
  // Calm water (no wind: a flat surface), no caustics, the sun at 30° behind the eye.
  ocean: { windSpeed: 0, resolution: 32, causticColor: [0, 0, 0], sunElevation: 30, sunAzimuth: 90 },
  skyGrey: SKY_GREY,
  output: 'linear',
  content: 'plate',
  width: 480,
  height: 270,
  // 45° down towards −z: the rows below see the water from 20° to 70° off the vertical.
  camera: { position: [0, 3, 0], lookAt: [0, 0, -3], fov: 50 },
};
/** Pixels [x, y] from the bottom left: near (steep), centre, far (grazing). */
const PIXELS: [number, number][] = [
  [240, 40],
  [240, 135],
  [240, 200],
];

async function draw(depth: number, pixels = PIXELS) {
  return page.evaluate(([d, p]) => window.refractionHarness.draw(d, p), [depth, pixels] as const);
}

test('a white plate 1 m and 4 m under calm water: each channel is R·sky + T·(e^{−σL} + scatter·(1 − e^{−σL})) over the refracted path', ALSO_ON_OLDEST_THREE, async () => {
  await page.evaluate((options) => window.refractionHarness.setup(options), PLATE_SETUP);
  const measured: Record<number, Vec3[]> = {};
  for (const depth of [1, 4]) {
    const { colours, rays, captured } = await draw(depth);
    expect(captured).toBe(true);
    measured[depth] = colours;
    colours.forEach((colour, i) => {
      const { colour: expected, path } = expectedPixel(rays[i], depth);
      console.log(`plate ${depth} m, pixel ${PIXELS[i].join(',')}: path ${path.toFixed(2)} m, measured ${colour.map((v) => v.toFixed(3))} expected ${expected.map((v) => v.toFixed(3))}`);
      for (let c = 0; c < 3; c++) expect(Math.abs(colour[c] - expected[c])).toBeLessThan(0.1 * expected[c]);
    });
  }
  // Red fades faster with depth than blue (σ_red = 0.45/m against 0.04/m).
  PIXELS.forEach((_pixel, i) => {
    const red = measured[4][i][0] / measured[1][i][0];
    const blue = measured[4][i][2] / measured[1][i][2];
    expect(red).toBeLessThan(0.6 * blue);
  });
});

test("with refractions 'sky' the plate is not seen: the same pixels at 1 m and 4 m, no capture drawn", async () => {
  const withScene = await draw(1);
  expect(await page.evaluate(() => window.refractionHarness.setShading({ refractions: 'sky' }))).toEqual({ error: null, refractions: 'sky' });
  const shallow = await draw(1);
  const deep = await draw(4);
  expect(shallow.captured).toBe(false);
  expect(shallow.colours).toEqual(deep.colours);
  // Only the sky through the water: far darker than the plate 1 m down.
  shallow.colours.forEach((colour, i) => expect(colour[0]).toBeLessThan(0.5 * withScene.colours[i][0]));
  await page.evaluate(() => window.refractionHarness.setShading({ refractions: 'scene' }));
  expect((await draw(1)).colours).toEqual(withScene.colours);
});

test("refractions: 'glass' is a ParameterError naming refractions, and the last good value stays", async () => {
  const { error, refractions } = await page.evaluate(() => window.refractionHarness.setShading({ refractions: 'glass' }));
  expect(error?.parameter).toBe('refractions');
  expect(error?.message).toContain('one of scene, sky');
  expect(refractions).toBe('scene');
  const fromConstructor = await page.evaluate(() => window.refractionHarness.construct({ refractions: 'glass' }));
  expect(fromConstructor?.parameter).toBe('refractions');
});

test('where a box pierces calm water, a line of foam forms within 0.3 m of it, and none farther out', async () => {
  await page.evaluate(
    (options) => window.refractionHarness.setup(options),
    { ...PLATE_SETUP, content: 'box', camera: { position: [0, 2, 0], lookAt: [0, 0, -6], fov: 50 } } satisfies SetupOptions,
  );
  // On the water 5 cm and 1 m in front of the box's face (z = −5), in the middle of it.
  const pixels = await page.evaluate(() => [window.refractionHarness.pixelOf([0, 0, -4.95]), window.refractionHarness.pixelOf([0, 0, -4])]);
  const withScene = await draw(1, pixels);
  await page.evaluate(() => window.refractionHarness.setShading({ refractions: 'sky' }));
  const skyOnly = await draw(1, pixels);
  await page.evaluate(() => window.refractionHarness.setShading({ refractions: 'scene' }));
  const [atEdge, farther] = withScene.colours;
  console.log(`box edge: at 5 cm ${atEdge.map((v) => v.toFixed(3))}, at 1 m ${farther.map((v) => v.toFixed(3))}; sky only ${skyOnly.colours[0].map((v) => v.toFixed(3))}`);
  // Foam is white (a diffuse surface of albedo 0.8 under the sky, foam.glsl): every channel far
  // above the water's, whose red the water absorbs.
  expect(Math.min(...atEdge)).toBeGreaterThan(0.4);
  expect(atEdge[0]).toBeGreaterThan(3 * skyOnly.colours[0][0]);
  // 1 m out, water without foam: its red absorbed (foam's is as bright as its blue).
  expect(farther[0]).toBeLessThan(0.2);
  expect(farther[0]).toBeLessThan(0.5 * farther[2]);
});

/** Pictures compared pixel for pixel: 480×270, a 6 m/s sea under the generated sky, tone-mapped. */
const OPEN_SEA: SetupOptions = {
  ocean: { windSpeed: 6, resolution: 32, seed: 3, localWaves: false },
  output: 'display',
  content: 'none',
  width: 480,
  height: 270,
  camera: { position: [0, 4, 0], lookAt: [0, 0, -20], fov: 50 },
};

test('over a scene of nothing but seas no capture is drawn, and the picture is the one drawn over empty captures, pixel for pixel', async () => {
  await page.evaluate((options) => window.refractionHarness.setup(options), OPEN_SEA);
  const skipped = await page.evaluate(() => window.refractionHarness.picture(2));
  // An object neither the camera nor the captures draw: both captures are drawn, and are empty.
  await page.evaluate(() => window.refractionHarness.withUnseenObject(true));
  const empty = await page.evaluate(() => window.refractionHarness.picture(2));
  await page.evaluate(() => window.refractionHarness.withUnseenObject(false));
  expect(skipped.captured).toBe(false);
  expect(empty.captured).toBe(true);
  expect(Buffer.from(skipped.pixels, 'base64').equals(Buffer.from(empty.pixels, 'base64'))).toBe(true);
});

test("two Oceans in one scene: one sea's capture hides the other sea, as its own (the same picture with the second sea as without)", async () => {
  await page.evaluate((options) => window.refractionHarness.setup(options), { ...OPEN_SEA, content: 'box', camera: { position: [0, 2, 0], lookAt: [0, 0, -6], fov: 50 } } satisfies SetupOptions);
  const alone = await page.evaluate(() => window.refractionHarness.withSecondSea(false, 2));
  const withSecond = await page.evaluate(() => window.refractionHarness.withSecondSea(true, 2));
  expect(alone.captured).toBe(true);
  expect(withSecond.captured).toBe(true);
  const [a, b] = [alone, withSecond].map((p) => Buffer.from(p.pixels, 'base64'));
  let differing = 0;
  for (let i = 0; i < a.length; i += 4) if (a[i] !== b[i] || a[i + 1] !== b[i + 1] || a[i + 2] !== b[i + 2]) differing++;
  expect(differing).toBe(0);
});

/**
 * The refracted ray from the eye through a pixel into calm water (y = 0): the view ray d meets the
 * surface at P, and goes on along t = η·d + (η·cos θi − cos θt)·n, η = n_a/n_w (Snell's law in vector
 * form, Hecht, "Optics", 5th ed., §4.4; GLSL's refract()), cos θt = √(1 − η²(1 − cos² θi)).
 */
function refractedRay(eye: Vec3, d: Vec3): { from: Vec3; along: Vec3 } | null {
  if (d[1] >= 0) return null;
  const s = -eye[1] / d[1];
  const from: Vec3 = [eye[0] + s * d[0], 0, eye[2] + s * d[2]];
  const eta = 1 / N_WATER;
  const cosI = -d[1];
  const cosT = Math.sqrt(1 - eta * eta * (1 - cosI * cosI));
  return { from, along: [eta * d[0], eta * d[1] + (eta * cosI - cosT), eta * d[2]] };
}

/** Whether the ray from + s·along (s > 0) meets the box [low, high] (slabs). */
function rayMeetsBox(from: Vec3, along: Vec3, low: Vec3, high: Vec3): boolean {
  let near = 0;
  let far = Infinity;
  for (let a = 0; a < 3; a++) {
    const t1 = (low[a] - from[a]) / along[a];
    const t2 = (high[a] - from[a]) / along[a];
    near = Math.max(near, Math.min(t1, t2));
    far = Math.min(far, Math.max(t1, t2));
  }
  return near <= far;
}

/** Saves a picture (RGBA rows from the bottom, base64) of width × height beside the test's results (looked at by hand). */
function save(info: TestInfo, name: string, pixels: string, width: number, height: number): void {
  const data = Buffer.from(pixels, 'base64');
  const png = new PNG({ width, height });
  for (let y = 0; y < height; y++) data.copy(png.data, 4 * y * width, 4 * (height - 1 - y) * width, 4 * (height - y) * width);
  for (let i = 3; i < png.data.length; i += 4) png.data[i] = 255;
  writeFileSync(info.outputPath(`${name}.png`), PNG.sync.write(png));
}

test('a red box under calm water shows only where the refracted rays meet it: no halo of its colour on the water beyond its far edge', async ({ browserName: _ }, info) => {
  await page.evaluate(
    (options) => window.refractionHarness.setup(options),
    { ...PLATE_SETUP, content: 'sunk', camera: { position: [0, 3, 0], lookAt: [0, -1.5, -6], fov: 50 } } satisfies SetupOptions,
  );
  const column = Array.from({ length: 270 }, (_, y): [number, number] => [240, y]);
  const { colours, rays, eye } = await draw(1, column);
  save(info, 'sunk-box', (await page.evaluate(() => window.refractionHarness.picture(1))).pixels, 480, 270);
  // The box: 2 m, centred at (0, −1.5, −6) (refractions.ts).
  const meets = rays.map((d) => {
    const ray = refractedRay(eye, d);
    return ray === null ? null : rayMeetsBox(ray.from, ray.along, [-1, -2.5, -7], [1, -0.5, -5]);
  });
  // Rows whose ray and both neighbours' on either side agree (the edge's pixels are partly covered).
  const sure = (y: number) => [-2, -1, 1, 2].every((dy) => meets[y + dy] === meets[y]);
  const shown = colours.map((c) => c[0] > 0.1 && c[0] > 2 * c[2]);
  const onBox = column.filter(([, y]) => meets[y] === true && sure(y));
  const offBox = column.filter(([, y]) => meets[y] === false && sure(y));
  const halo = offBox.filter(([, y]) => shown[y]).map(([, y]) => y);
  const missing = onBox.filter(([, y]) => !shown[y]).map(([, y]) => y);
  console.log(`sunk box: rays meeting it in rows ${onBox[0]?.[1]}..${onBox[onBox.length - 1]?.[1]}, red shown in rows ${shown.flatMap((s, y) => (s ? [y] : [])).join(',')}`);
  expect(onBox.length).toBeGreaterThan(20);
  // Measured: the rays of rows 111..195 meet it, red shows in 108..187 (without the check of the
  // sample's side in sceneRefraction.glsl, in 108..232: 37 rows of halo beyond it). The top's far
  // rows show the water: their screen-space search starts from the empty picture straight behind
  // and finds only the box's near face, which it must refuse.
  expect(missing.length).toBeLessThan(0.15 * onBox.length);
  expect(halo.filter((y) => y > onBox[onBox.length - 1][1])).toEqual([]);
});

test("from under calm water a red box above it is seen in Snell's window, where the refracted rays meet it, and nothing of it outside the window", async ({ browserName: _ }, info) => {
  const [W, H, FOV] = [480, 270, 70];
  const eye: Vec3 = [0, -2, 0];
  const target: Vec3 = [2, 0, 0];
  await page.evaluate(
    (options) => window.refractionHarness.setup(options),
    { ...PLATE_SETUP, content: 'raised', width: W, height: H, camera: { position: eye, lookAt: target, fov: FOV } } satisfies SetupOptions,
  );
  const { pixels } = await page.evaluate(() => window.refractionHarness.picture(1));
  save(info, 'snell-window', pixels, W, H);
  const data = Buffer.from(pixels, 'base64');
  // The camera's frame (three's lookAt with up = +y) and each pixel's ray through its centre.
  const sub = (a: Vec3, b: Vec3): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
  const cross = (a: Vec3, b: Vec3): Vec3 => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const unit = (a: Vec3): Vec3 => ((l) => [a[0] / l, a[1] / l, a[2] / l] as Vec3)(Math.hypot(...a));
  const back = unit(sub(eye, target));
  const right = unit(cross([0, 1, 0], back));
  const up = cross(back, right);
  const tanHalf = Math.tan((FOV / 2) * (Math.PI / 180));
  const rayOf = (x: number, y: number): Vec3 => {
    const u = (((x + 0.5) / W) * 2 - 1) * tanHalf * (W / H);
    const v = (((y + 0.5) / H) * 2 - 1) * tanHalf;
    return unit([0, 1, 2].map((a) => -back[a] + u * right[a] + v * up[a]) as Vec3);
  };
  // Water to air at the level surface: Snell's law n_w·sin θi = n_a·sin θt in vector form (GLSL
  // refract(d, N, η) with N = −y facing the eye, η = n_w/n_a); none beyond the critical angle
  // asin(n_a/n_w) = 48.6°, where k = 1 − η²(1 − cos² θi) < 0 (total internal reflection). With
  // N = −y: t = η·d − (η·(N·d) + √k)·N = (η·dx, √k, η·dz).
  const intoAir = (d: Vec3): { from: Vec3; along: Vec3 } | null => {
    if (d[1] <= 0) return null;
    const s = -eye[1] / d[1];
    const eta = N_WATER;
    const k = 1 - eta * eta * (1 - d[1] * d[1]);
    if (k < 0) return null;
    return { from: [eye[0] + s * d[0], 0, eye[2] + s * d[2]], along: [eta * d[0], Math.sqrt(k), eta * d[2]] };
  };
  const predicted: [number, number][] = [];
  const red: [number, number][] = [];
  const outsideWindow: [number, number][] = [];
  for (let y = 0; y < H; y++) {
    for (let x = 0; x < W; x++) {
      const d = rayOf(x, y);
      const ray = intoAir(d);
      // The box: 1 m, centred at (3, 1.5, 0) (refractions.ts).
      if (ray !== null && rayMeetsBox(ray.from, ray.along, [2.5, 1, -0.5], [3.5, 2, 0.5])) predicted.push([x, y]);
      const i = 4 * (y * W + x);
      const [r, g, b] = [data[i] / 255, data[i + 1] / 255, data[i + 2] / 255];
      if (r > 0.1 && r > 2 * g && r > 2 * b) {
        red.push([x, y]);
        if (ray === null) outsideWindow.push([x, y]);
      }
    }
  }
  const bounds = (points: [number, number][]) => ({
    left: Math.min(...points.map((p) => p[0])),
    right: Math.max(...points.map((p) => p[0])),
    bottom: Math.min(...points.map((p) => p[1])),
    top: Math.max(...points.map((p) => p[1])),
  });
  console.log(`Snell's window: predicted ${predicted.length} px ${JSON.stringify(bounds(predicted))}, red ${red.length} px ${red.length ? JSON.stringify(bounds(red)) : ''}, red outside the window ${outsideWindow.length}`);
  expect(predicted.length).toBeGreaterThan(100);
  expect(red.length).toBeGreaterThan(0.8 * predicted.length);
  const [p, m] = [bounds(predicted), bounds(red)];
  for (const side of ['left', 'right', 'bottom', 'top'] as const) expect(Math.abs(p[side] - m[side])).toBeLessThanOrEqual(3);
  expect(outsideWindow).toEqual([]);
});
