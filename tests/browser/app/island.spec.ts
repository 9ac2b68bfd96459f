/**
 * The app's island (?scene=island, the panel's "scene"; src/app/sceneChoice.ts, src/objects/island.ts)
 * in real Chromium: the island stands in the sea where the view from offshore of its beach shows
 * its sand, grass and rock; the URL keeps the choice across a reload; the panel takes it away and
 * brings it back with the camera at its beach; the cliff's reflection in the surf has no lone sky
 * pixels; an unknown scene is the app's usual warning.
 */
import { expect, test, type Page } from '@playwright/test';
import { BEACH_FACING, ISLAND_VIEW, islandSeabed } from '../../../src/objects/island';

/** A calm sea (1 m waves would hide a beach 200 m off from 5 m up), a fixed time and quality. */
const CALM = 'resolution=64&windSpeed=4&t=5&paused=1&quality=high';

async function openApp(page: Page, query: string, size = { width: 480, height: 270 }): Promise<string[]> {
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(error.message));
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(message.text());
  });
  await page.setViewportSize(size);
  await page.goto(`/?${query}`);
  await page.waitForFunction(() => window.oceanApp !== undefined);
  await rendered(page);
  return errors;
}

/** Waits until the app has drawn two more frames. */
async function rendered(page: Page): Promise<void> {
  await page.evaluate(async () => {
    for (let i = 0; i < 2; i++) await new Promise((resolve) => requestAnimationFrame(resolve));
  });
}

/** A point of the ground at distance `offshore` from the beach's waterline (negative: inland), on its facing. */
function beachPoint(offshore: number): [number, number, number] {
  const { depthAt } = islandSeabed();
  const [cos, sin] = [Math.cos(BEACH_FACING), Math.sin(BEACH_FACING)];
  let land = 0;
  let sea = 400;
  for (let i = 0; i < 50; i++) {
    const r = (land + sea) / 2;
    if (depthAt(r * cos, r * sin) < 0) land = r;
    else sea = r;
  }
  const [x, z] = [(land + offshore) * cos, (land + offshore) * sin];
  return [x, -depthAt(x, z), z];
}

/** The mean colour (0–255) of the 3×3 pixels where each world point is drawn, read right after a render. */
async function coloursAt(page: Page, points: [number, number, number][]): Promise<{ rgb: number[]; pixel: number[] }[]> {
  return page.evaluate(async (points) => {
    const { camera, capturePixels } = window.oceanApp;
    const { width, height, data } = await capturePixels();
    const Vector = camera.position.constructor as new (x: number, y: number, z: number) => typeof camera.position;
    return points.map(([x, y, z]) => {
      const ndc = new Vector(x, y, z).project(camera);
      const px = Math.round(((ndc.x + 1) / 2) * width);
      const py = Math.round(((ndc.y + 1) / 2) * height); // rows bottom first, as readPixels gives them
      const rgb = [0, 0, 0];
      for (let dy = -1; dy <= 1; dy++) {
        for (let dx = -1; dx <= 1; dx++) for (let c = 0; c < 3; c++) rgb[c] += data[4 * ((py + dy) * width + px + dx) + c] / 9;
      }
      return { rgb, pixel: [px, py] };
    });
  }, points);
}

test('?scene=island: the island stands offshore of the camera, sand on its beach and grass on its hill; the URL keeps it; the panel takes it away', async ({ page }) => {
  const errors = await openApp(page, `${CALM}&scene=island`);
  const start = await page.evaluate(() => ({
    island: window.oceanApp.island !== null && window.oceanApp.scene.getObjectByName('island') === window.oceanApp.island,
    position: window.oceanApp.camera.position.toArray(),
    cam: window.oceanApp.state.cam,
  }));
  expect(start.island).toBe(true);
  // No camera in the URL: the view from a boat offshore of the beach.
  start.position.forEach((value, i) => expect(value).toBeCloseTo(ISLAND_VIEW.position[i], 6));

  // Sand 40 m up the beach from the water, grass on the slope 90 m inland, the sea in front of
  // the beach: each where the camera projects it.
  const sand = beachPoint(-40);
  const hill = beachPoint(-90);
  const sea = beachPoint(120);
  sea[1] = 0;
  const [sandColour, hillColour, seaColour] = await coloursAt(page, [sand, hill, sea]);
  const [sr, sg, sb] = sandColour.rgb;
  const [gr, gg, gb] = hillColour.rgb;
  const [wr, , wb] = seaColour.rgb;
  expect(sr, `sand at ${sandColour.pixel}: ${sandColour.rgb}`).toBeGreaterThan(sb + 25); // warm, unlike sea and sky
  expect(sg, `sand at ${sandColour.pixel}`).toBeGreaterThan(sb);
  expect(sr + sg + sb, `sand at ${sandColour.pixel}`).toBeGreaterThan(200); // lighter than the sea
  expect(gg, `grass at ${hillColour.pixel}: ${hillColour.rgb}`).toBeGreaterThan(gr);
  expect(gg, `grass at ${hillColour.pixel}`).toBeGreaterThan(gb + 15);
  expect(wb, `sea at ${seaColour.pixel}: ${seaColour.rgb}`).toBeGreaterThan(wr); // the sea is still blue in front of it

  // The URL round-trips the choice and the camera: a reload shows the island from the same place.
  await page.evaluate(() => window.oceanApp.writeUrl());
  expect(new URL(page.url()).searchParams.get('scene')).toBe('island');
  await page.reload();
  await page.waitForFunction(() => window.oceanApp !== undefined);
  await rendered(page);
  const reloaded = await page.evaluate(() => ({ island: window.oceanApp.island !== null, position: window.oceanApp.camera.position.toArray() }));
  expect(reloaded.island).toBe(true);
  reloaded.position.forEach((value, i) => expect(value).toBeCloseTo(ISLAND_VIEW.position[i], 2));

  // The panel: the open sea takes the island away (and out of the URL); the island brings it back
  // with the camera at its beach, from wherever it was.
  const memory = () => page.evaluate(() => window.oceanApp.renderer.info.memory.geometries);
  const withIsland = await memory();
  await page.evaluate(() => window.oceanApp.panel.gui.open(true));
  await page.locator('[data-key="scene"] select').selectOption({ label: 'open sea' });
  await rendered(page);
  const open = await page.evaluate(() => {
    window.oceanApp.writeUrl();
    return { island: window.oceanApp.island, named: window.oceanApp.scene.getObjectByName('island') ?? null, scene: window.oceanApp.state.scene };
  });
  const withoutIsland = await memory();
  expect(open).toEqual({ island: null, named: null, scene: 'sea' });
  expect(new URL(page.url()).searchParams.has('scene')).toBe(false);
  const [openSand] = await coloursAt(page, [sand]);
  expect(openSand.rgb[0], `no sand at ${openSand.pixel} on the open sea: ${openSand.rgb}`).toBeLessThan(openSand.rgb[2]);
  await page.evaluate(() => {
    window.oceanApp.controls.pose = { position: [0, 12, 0], yaw: 0, pitch: 0 };
  });
  await page.locator('[data-key="scene"] select').selectOption({ label: 'island' });
  await rendered(page);
  const back = await page.evaluate(() => ({ island: window.oceanApp.island !== null, position: window.oceanApp.camera.position.toArray() }));
  expect(back.island).toBe(true);
  back.position.forEach((value, i) => expect(value).toBeCloseTo(ISLAND_VIEW.position[i], 6));
  // Its GPU geometries (terrain, posts, planks, hull, cabin) go with it, each time.
  expect(await memory()).toBe(withIsland);
  await page.locator('[data-key="scene"] select').selectOption({ label: 'open sea' });
  await rendered(page);
  expect(await memory()).toBe(withoutIsland);
  expect(withIsland - withoutIsland).toBeGreaterThanOrEqual(5);
  expect(errors).toEqual([]);
});

/**
 * Pixels brighter (r + g + b) by more than 75 than each of the 16 pixels two away (the ring around
 * the 3×3 block): lone specks, which no picture of the sea has but where a single pixel's shading
 * differs from its neighbours'. `data` is RGBA, rows bottom first or top first alike.
 */
function loneBrightPixels({ width, height, data }: { width: number; height: number; data: ArrayLike<number> }): number {
  const sum = (x: number, y: number) => data[4 * (y * width + x)] + data[4 * (y * width + x) + 1] + data[4 * (y * width + x) + 2];
  let count = 0;
  for (let y = 2; y < height - 2; y++) {
    for (let x = 2; x < width - 2; x++) {
      const centre = sum(x, y) - 75;
      let lone = true;
      for (let d = -2; d <= 2 && lone; d++) lone = centre > sum(x + d, y - 2) && centre > sum(x + d, y + 2) && centre > sum(x - 2, y + d) && centre > sum(x + 2, y + d);
      if (lone) count++;
    }
  }
  return count;
}

test('the cliff reflected in a 12 m/s surf: no lone sky pixels where rays from the troughs meet its foot', async ({ page }) => {
  // The view of docs/shores.md, from (−20, 10, 215) towards (−10, 0, 150): the cliff on the right.
  const view = 'scene=island&windSpeed=12&t=12&paused=1&quality=high&cam=-20,10,215,-81.25,-8.65';
  const count = async (reflections: string) => {
    await openApp(page, `${view}&reflections=${reflections}`, { width: 960, height: 540 });
    return loneBrightPixels(await page.evaluate(() => window.oceanApp.capturePixels()));
  };
  const sky = await count('sky');
  const scene = await count('scene');
  console.log(`lone bright pixels: ${scene} with reflections 'scene', ${sky} with 'sky'`);
  // Measured: 'scene' 50 with the mirror render cut at y = 0 (its cut base left no coverage for
  // rays from the troughs: sceneReflection.ts), 27 cut one RMS height down (10 three down); 'sky' 4.
  expect(scene).toBeLessThan(35);
  expect(sky).toBeLessThan(10);
});

test('?scene=volcano shows a warning naming scene and what it may be, and the open sea is used', async ({ page }) => {
  await openApp(page, 'resolution=32&scene=volcano');
  const warning = page.locator('#status .notice.warning');
  await expect(warning).toHaveCount(1);
  await expect(warning).toContainText('scene must be "sea" or "island"; got "volcano"');
  await expect(warning).toContainText('using the default sea');
  expect(await page.evaluate(() => ({ island: window.oceanApp.island, scene: window.oceanApp.state.scene }))).toEqual({ island: null, scene: 'sea' });
  expect(page.url()).not.toContain('volcano');
});
