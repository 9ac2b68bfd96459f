import { expect, test, type Page, type TestInfo } from '@playwright/test';
import { writeFileSync } from 'node:fs';
import { PNG } from 'pngjs';
import type { Vec3, View } from './reflections';

// The scene's objects reflected in the sea (src/render/sceneReflection.ts,
// shaders/surface/sceneReflection.glsl), drawn at 960×540 in real WebGL2 and read back.

const W = 960;
const H = 540;

test.describe.configure({ mode: 'serial' });
let page: Page;
test.beforeAll(async ({ browser }) => {
  page = await browser.newPage();
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(error.message));
  await page.goto('/tests/browser/reflections/reflections.html');
  await expect(page).toHaveTitle('ready');
  expect(errors).toEqual([]);
});
test.afterAll(async () => page.close());

type Pixels = Buffer;

async function render(view: View): Promise<Pixels> {
  return Buffer.from(await page.evaluate((v) => window.reflections.render(v), view), 'base64');
}

/** RGB of pixel (x, y), y from the top. */
function rgb(pixels: Pixels, x: number, y: number): Vec3 {
  const i = 4 * ((H - 1 - y) * W + x);
  return [pixels[i], pixels[i + 1], pixels[i + 2]];
}

/** Saves the picture beside the test's results (looked at by hand). */
function save(info: TestInfo, name: string, pixels: Pixels): void {
  const png = new PNG({ width: W, height: H });
  for (let y = 0; y < H; y++) pixels.copy(png.data, 4 * y * W, 4 * (H - 1 - y) * W, 4 * (H - y) * W);
  for (let i = 3; i < png.data.length; i += 4) png.data[i] = 255;
  writeFileSync(info.outputPath(`${name}.png`), PNG.sync.write(png));
}

/** Pixels whose red rose against the other render by more than `threshold` over their green and blue. */
function redderPixels(scene: Pixels, sky: Pixels, threshold: number): [number, number][] {
  const found: [number, number][] = [];
  for (let y = 0; y < H; y++) {
    for (let x = 0; x < W; x++) {
      const a = rgb(scene, x, y);
      const b = rgb(sky, x, y);
      if (a[0] - b[0] - Math.max(a[1] - b[1], a[2] - b[2], 0) > threshold) found.push([x, y]);
    }
  }
  return found;
}

function bounds(points: [number, number][]): { left: number; right: number; top: number; bottom: number } {
  const xs = points.map((p) => p[0]);
  const ys = points.map((p) => p[1]);
  return { left: Math.min(...xs), right: Math.max(...xs), top: Math.min(...ys), bottom: Math.max(...ys) };
}

// No wind: a level sea (the spectrum is 0), the plane mirror of the law of reflection.
const CALM: View = {
  windSpeed: 0,
  reflections: 'scene',
  centre: [1, 1.5, -25],
  size: [3, 2, 3],
  eye: [0, 2, 0],
  target: [0, 0.3, -30],
  t: 3,
};

test('a red box above calm water is reflected at its mirror image with scene, not with sky', async ({ browserName: _ }, info) => {
  const scene = await render(CALM);
  const sky = await render({ ...CALM, reflections: 'sky' });
  save(info, 'calm-scene', scene);
  save(info, 'calm-sky', sky);
  // The law of reflection: on a level surface a point (x, y, z) is seen where its image (x, −y, z)
  // would be (Hecht, Optics, 5th ed., §4.3 and §5.4: the plane mirror's virtual image).
  const [cx, cy, cz] = CALM.centre;
  const [sx, sy, sz] = CALM.size;
  const corners: Vec3[] = [];
  for (const dx of [-0.5, 0.5]) for (const dy of [-0.5, 0.5]) for (const dz of [-0.5, 0.5]) corners.push([cx + dx * sx, -(cy + dy * sy), cz + dz * sz]);
  const image = bounds(await page.evaluate(([v, c]) => window.reflections.project(v, c), [CALM, corners] as const));
  // The reflection's strength: Fresnel's reflectance R of the water (Hecht §4.6.2) times the box's
  // red; its edges are where half of it shows (a pixel half covered by the image).
  const strong = redderPixels(scene, sky, 8);
  expect(strong.length).toBeGreaterThan(100);
  const contrast = strong.map(([x, y]) => rgb(scene, x, y)[0] - rgb(sky, x, y)[0]).sort((a, b) => a - b)[Math.floor(strong.length / 2)];
  const reflection = bounds(redderPixels(scene, sky, contrast / 2));
  console.log(JSON.stringify({ image, reflection, contrast }));
  expect(Math.abs(reflection.left - image.left)).toBeLessThanOrEqual(2);
  expect(Math.abs(reflection.right + 1 - image.right)).toBeLessThanOrEqual(2);
  expect(Math.abs(reflection.top - image.top)).toBeLessThanOrEqual(2);
  expect(Math.abs(reflection.bottom + 1 - image.bottom)).toBeLessThanOrEqual(2);
  // With 'sky' the sea reflects nothing of the box: the same picture without the box.
  const skyWithoutBox = await render({ ...CALM, reflections: 'sky', hideBox: true });
  expect(redderPixels(sky, skyWithoutBox, 8).filter(([, y]) => y > image.top - 3)).toEqual([]);
});
