/**
 * The app (index.html, src/app/): fly controls, panel, URL state, status line, time and resize,
 * in real Chromium. Small viewports and a small FFT keep each test to a few seconds under
 * SwiftShader; pixels are read by the app right after its render (oceanApp.capturePixels).
 */
import { expect, test, type Browser, type Page } from '@playwright/test';
import { MAX_STEP_SECONDS } from '../../../src/app/flyControls';
import { DEFAULT_PARAMETERS } from '../../../src/parameters/parameters';
import { beaufortPreset, presetCloudCover, SEA_PRESETS } from '../../../src/spectrum/presets';
import { seaState } from '../../../src/spectrum/seaState';
import { boatWake } from '../shared/boatWake';
import { sharedPages } from '../shared/sharedPages';
import { slowFrames, slowFramesUntil } from '../shared/slowFrames';
import { withHiddenCapabilities } from '../shared/hiddenCapabilities';
import { withoutWebGL2 } from '../shared/withoutWebGL2';
import { ALSO_ON_OLDEST_THREE } from '../shared/threeRange';

type Vec3 = [number, number, number];

/** What a page said: its uncaught errors, and those with the console's errors. */
interface PageLog {
  uncaught: string[];
  errors: string[];
}

function listen(page: Page, log: PageLog): void {
  page.on('pageerror', (error) => {
    log.uncaught.push(error.message);
    log.errors.push(error.message);
  });
  page.on('console', (message) => {
    if (message.type() === 'error') log.errors.push(message.text());
  });
}

// A fixed quality level unless the test is about it: 'auto' would lower the render scale and the
// grid within seconds under SwiftShader, and the tests compare pictures and fields over longer.
const appQuery = (query: string) => (/(^|&)quality=/.test(query) ? query : [query, 'quality=high'].filter(Boolean).join('&'));
const SIZE = { width: 480, height: 270 };

/** Sets the panel open or closed (narrow viewports, fast under SwiftShader, start with it closed) and waits two frames. */
async function settle(page: Page, openPanel: boolean): Promise<void> {
  await page.evaluate((open) => window.oceanApp.panel.gui.open(open), openPanel);
  await frames(page, 2);
}

/** Loads the app with `query` into `page`. */
async function loadApp(page: Page, query: string): Promise<void> {
  await page.goto(`/?${appQuery(query)}`);
  await page.waitForFunction(() => window.oceanApp !== undefined);
}

/** Opens the app with `query` on a page of its own; returns the console errors and page errors it collects. */
async function openApp(page: Page, query = '', size = SIZE, openPanel = true): Promise<string[]> {
  const log: PageLog = { uncaught: [], errors: [] };
  listen(page, log);
  await page.setViewportSize(size);
  await loadApp(page, query);
  await settle(page, openPanel);
  return log.errors;
}

// One page for the tests that need none of their own (an init script, hidden capabilities, the
// page's first load): the first to take it loads the app with its query, the others open the app
// in it again from theirs (oceanApp.reopen disposes the running app and starts it anew from the
// URL, as a load would, without loading the modules again).
const sharedLog: PageLog = { uncaught: [], errors: [] };
const sharedAppPage = sharedPages(
  async (page) => listen(page, sharedLog),
  async () => {
    sharedLog.uncaught.length = 0;
    sharedLog.errors.length = 0;
  },
);
/** The shared page while a test (or a beforeAll) holds it. */
let heldPage: Page | null = null;

/**
 * Stops the shared page's app until the next test opens it again, so that it does not draw beside
 * the tests on other pages; then no uncaught error may have reached the page.
 */
async function releaseSharedPage(): Promise<void> {
  const page = heldPage;
  heldPage = null;
  if (!page) return;
  if (!page.isClosed()) await page.evaluate(() => window.oceanApp.dispose());
  expect(sharedLog.uncaught, 'uncaught errors on the shared page').toEqual([]);
}
test.afterEach(releaseSharedPage);

/** The shared page with the app opened again from `query`, and what the page says from now on. */
async function reopenApp(browser: Browser, query = '', size = SIZE, openPanel = true): Promise<{ page: Page; errors: string[] }> {
  const page = await sharedAppPage(browser);
  heldPage = page;
  await page.setViewportSize(size);
  if (page.url() === 'about:blank') await loadApp(page, query);
  else await page.evaluate((query) => window.oceanApp.reopen(query), appQuery(query));
  await settle(page, openPanel);
  return { page, errors: sharedLog.errors };
}

/** Waits until the app has drawn `count` more frames. */
async function frames(page: Page, count = 1): Promise<void> {
  await page.evaluate(async (count) => {
    for (let i = 0; i < count; i++) await new Promise((resolve) => requestAnimationFrame(resolve));
  }, count);
}

/** The canvas right after the app's next render, as raw RGBA bytes. */
async function pixels(page: Page): Promise<Buffer> {
  const base64 = await page.evaluate(async () => {
    const { data } = await window.oceanApp.capturePixels();
    let text = '';
    for (let i = 0; i < data.length; i += 8192) text += String.fromCharCode(...data.subarray(i, i + 8192));
    return btoa(text);
  });
  return Buffer.from(base64, 'base64');
}

function meanAbsDifference(a: Buffer, b: Buffer): number {
  expect(a.length).toBe(b.length);
  let sum = 0;
  for (let i = 0; i < a.length; i++) sum += Math.abs(a[i] - b[i]);
  return sum / a.length;
}

const pose = (page: Page) => page.evaluate(() => window.oceanApp.controls.pose);

/** The sea state as the status line and the panel's "Hs, Tp" line start: "Hs 2.14 m, Tp 6.2 s (simulated Hs 2.22 m)". */
const SEA_STATE_TEXT = String.raw`Hs \d+\.\d\d m, Tp \d+\.\d s \(simulated Hs \d+\.\d\d m\)`;

/** What the status line and the panel say for `options` (seaState.ts) and the simulated 4·RMS height. */
function seaStateText(options: Parameters<typeof seaState>[0], simulatedHs: number): string {
  const { significantWaveHeight, peakPeriod } = seaState(options);
  return `Hs ${significantWaveHeight.toFixed(2)} m, Tp ${peakPeriod.toFixed(1)} s (simulated Hs ${simulatedHs.toFixed(2)} m)`;
}

const escapeRegExp = (text: string) => text.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');

/** v = (cos φ cos θ, sin θ, sin φ cos θ) (course report §2.6). */
function viewDirection(yawDeg: number, pitchDeg: number): Vec3 {
  const phi = (yawDeg * Math.PI) / 180;
  const theta = (pitchDeg * Math.PI) / 180;
  return [Math.cos(phi) * Math.cos(theta), Math.sin(theta), Math.sin(phi) * Math.cos(theta)];
}
const sub = (a: Vec3, b: Vec3): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a: Vec3, b: Vec3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const length = (a: Vec3) => Math.hypot(...a);

/**
 * Holds `key` until the frames drawn while it was down add up to `ms` or more, and returns those
 * frames' time, seconds: what the fly controls moved for (each frame's real step, at most
 * MAX_STEP_SECONDS), whatever the frame rate. A frame sees the key as its listeners left it, the
 * same for the controls' update and the count here (both run in the frame's callbacks, after its
 * input events).
 */
async function holdKey(page: Page, key: string, ms: number): Promise<number> {
  await page.evaluate(async (maxStep) => {
    const record = { down: false, last: 0, seconds: 0, running: true };
    Object.assign(window, { keyRecord: record });
    window.addEventListener('keydown', () => (record.down = true), { capture: true, once: true });
    window.addEventListener('keyup', () => (record.down = false), { capture: true, once: true });
    // The first frame only sets where the next one's step starts: it is over before keydown.
    await new Promise<void>((resolve) => {
      const tick = (now: number) => {
        if (record.down) record.seconds += Math.min((now - record.last) / 1000, maxStep);
        record.last = now;
        resolve();
        if (record.running) requestAnimationFrame(tick);
      };
      requestAnimationFrame(tick);
    });
  }, MAX_STEP_SECONDS);
  await page.keyboard.down(key);
  await page.waitForFunction((seconds) => (window as unknown as { keyRecord: { seconds: number } }).keyRecord.seconds >= seconds, ms / 1000);
  await page.keyboard.up(key);
  await frames(page, 2); // the frame after keyup applies nothing more
  return page.evaluate(() => {
    const record = (window as unknown as { keyRecord: { seconds: number; running: boolean } }).keyRecord;
    record.running = false;
    return record.seconds;
  });
}

test.describe('the app', () => {
  test('loads without console errors and shows the FFT path, CPU timings and the keys', async ({ page }) => {
    const errors = await openApp(page, 'resolution=64');
    const status = page.locator('#status .status-line');
    await expect(status).toHaveText(
      new RegExp(`^${SEA_STATE_TEXT} · FFT: (GPU RGBA32F|GPU RGBA16F|JS in a worker|JS) · \\d+ fps · quality high(, frame \\d+ ms)?: render scale 1, 4× MSAA, 3 cascades of 64² · CPU time: sim \\d+\\.\\d ms, render \\d+\\.\\d ms$`),
    );
    await expect(page.locator('#status .status-time')).toHaveText(/^t = \d+\.\d\d s · camera speed 20 m\/s$/);
    const path = await page.evaluate(() => window.oceanApp.ocean.simulation.path);
    const label = { 'gpu-rgba32f': 'GPU RGBA32F', 'gpu-rgba16f': 'GPU RGBA16F', 'js-worker': 'JS in a worker', js: 'JS' }[path];
    await expect(status).toContainText(`FFT: ${label} ·`);
    await expect(page.locator('#status .status-help')).toContainText('Move: W A S D');
    await expect(page.locator('[data-key="running"] input')).toHaveValue(label);

    // Switching the path in the panel shows in the status and in the panel's read-only line.
    await page.locator('[data-key="path"] select').selectOption('js');
    await expect(status).toContainText('FFT: JS in a worker ·');
    await expect(page.locator('[data-key="running"] input')).toHaveValue('JS in a worker');
    expect(await page.evaluate(() => window.oceanApp.ocean.simulation.pathPreference)).toBe('js');
    expect(errors).toEqual([]);
  });

  test.describe('fly controls and the canvas size', () => {
    /**
     * The app at one view, paused, in a small viewport, for the tests of the fly controls and of the
     * canvas's size: one page load for them all (a load costs more than most of these tests take),
     * the camera, the panel (closed) and the viewport set back before each.
     */
    const FLY_START = { position: [0, 10, 0] as Vec3, yaw: 30, pitch: -10 };
    const FLY_SIZE = { width: 320, height: 180 };
    const flyPage = sharedPages(
      async (page) => void (await openApp(page, 'resolution=32&paused=1&cam=0,10,0,30,-10', FLY_SIZE, false)),
      async (page) => {
        if (page.viewportSize()?.width !== FLY_SIZE.width || page.viewportSize()?.height !== FLY_SIZE.height) await page.setViewportSize(FLY_SIZE);
        await page.evaluate((start) => {
          window.oceanApp.controls.pose = start;
          window.oceanApp.panel.gui.open(false);
        }, FLY_START);
        await frames(page, 2);
      },
    );

    test('W moves along v by speed × time; A moves along l = u × v, left on screen; Shift goes down, through the surface', async ({ browser }) => {
      const page = await flyPage(browser);
      await page.evaluate(() => (window.oceanApp.controls.speed = 10));

      const before = await pose(page);
      const forward = await holdKey(page, 'w', 1500);
      const afterW = await pose(page);
      const moved = sub(afterW.position, before.position);
      const v = viewDirection(30, -10);
      expect(dot(moved, v) / length(moved)).toBeGreaterThan(0.99999);
      // Speed × the time of the frames that saw the key down.
      expect(length(moved)).toBeCloseTo(10 * forward, 6);
      expect(afterW.yaw).toBe(30);
      expect(afterW.pitch).toBe(-10);

      const sideways = await holdKey(page, 'a', 800);
      const afterA = await pose(page);
      const left = sub(afterA.position, afterW.position);
      expect(length(left)).toBeCloseTo(10 * sideways, 6);
      const l: Vec3 = [v[2], 0, -v[0]]; // u × v with u = (0, 1, 0)
      expect(dot(left, l) / (length(left) * length(l))).toBeGreaterThan(0.99999);
      expect(Math.abs(left[1])).toBeLessThan(1e-9);
      // Left on screen: the camera's own x axis (its right) points the other way.
      const rightAxis = await page.evaluate(() => window.oceanApp.camera.matrixWorld.elements.slice(0, 3) as [number, number, number]);
      expect(dot(left, rightAxis) / length(left)).toBeLessThan(-0.99999);

      const up = await holdKey(page, 'Space', 500);
      const high = (await pose(page)).position[1];
      expect(high - afterA.position[1]).toBeCloseTo(10 * up, 6);
      const down = await holdKey(page, 'Shift', 2000); // 10 m/s down for 2 s or more from ~13 m: under the water
      const low = (await pose(page)).position[1];
      // The camera dives (down to 200 m: flyControls.ts MIN_HEIGHT), by speed × time.
      expect(low).toBeLessThan(0);
      expect(high - low).toBeCloseTo(10 * down, 6);
    });

    test('dragging turns the view: right increases yaw, up increases pitch, pitch clamps at ±89°', async ({ browser }) => {
      const page = await flyPage(browser);
      const start = await pose(page);
      await page.mouse.move(100, 120);
      await page.mouse.down();
      await page.mouse.move(150, 100, { steps: 5 }); // 50 px right, 20 px up
      await page.mouse.up();
      const turned = await pose(page);
      expect(turned.yaw).toBeCloseTo(start.yaw + 50 * 0.15, 6);
      expect(turned.pitch).toBeCloseTo(start.pitch + 20 * 0.15, 6);
      expect(turned.position).toEqual(start.position);
      // The new view leans to the old right (−l) and up.
      const oldView = viewDirection(start.yaw, start.pitch);
      const newView = viewDirection(turned.yaw, turned.pitch);
      const oldLeft: Vec3 = [oldView[2], 0, -oldView[0]];
      expect(dot(newView, oldLeft)).toBeLessThan(0);
      expect(newView[1]).toBeGreaterThan(oldView[1]);
      // And the camera really looks there.
      const cameraForward = await page.evaluate(() => {
        const e = window.oceanApp.camera.matrixWorld.elements;
        return [-e[8], -e[9], -e[10]] as [number, number, number];
      });
      expect(dot(cameraForward, newView)).toBeGreaterThan(0.99999);

      for (const [pitch, dy, limit] of [
        [80, -100, 89], // 80° + 15° up stops at 89°
        [-80, 100, -89],
      ]) {
        await page.evaluate((pitch) => (window.oceanApp.controls.pose = { position: [0, 10, 0], yaw: 30, pitch }), pitch);
        const y = dy < 0 ? 150 : 30;
        await page.mouse.move(100, y);
        await page.mouse.down();
        await page.mouse.move(100, y + dy, { steps: 5 });
        await page.mouse.up();
        expect((await pose(page)).pitch).toBe(limit);
      }
    });

    test('touch: one finger turns, two fingers dragged up move forward', async ({ browser }) => {
      const page = await flyPage(browser);
      const result = await page.evaluate(() => {
        const { controls, renderer } = window.oceanApp;
        const canvas = renderer.domElement;
        const touch = (type: string, pointerId: number, x: number, y: number) =>
          canvas.dispatchEvent(new PointerEvent(type, { pointerId, pointerType: 'touch', clientX: x, clientY: y, bubbles: true }));
        touch('pointerdown', 1, 100, 100);
        touch('pointermove', 1, 140, 100); // one finger 40 px right
        touch('pointerup', 1, 140, 100);
        const turned = controls.pose;
        touch('pointerdown', 1, 100, 120);
        touch('pointerdown', 2, 160, 120);
        touch('pointermove', 1, 100, 70); // both fingers 50 px up
        touch('pointermove', 2, 160, 70);
        touch('pointerup', 1, 100, 70);
        touch('pointerup', 2, 160, 70);
        return { turned, moved: controls.pose, speed: controls.speed };
      });
      expect(result.turned.yaw).toBeCloseTo(30 + 40 * 0.25, 6);
      expect(result.turned.pitch).toBe(-10);
      const moved = sub(result.moved.position, result.turned.position);
      const v = viewDirection(result.turned.yaw, result.turned.pitch);
      expect(dot(moved, v) / length(moved)).toBeGreaterThan(0.99999);
      expect(length(moved)).toBeCloseTo((50 * result.speed) / 100, 6); // speed/100 metres per pixel
    });

    test('resizing the viewport resizes the canvas and the camera aspect', async ({ browser }) => {
      const page = await flyPage(browser);
      await page.setViewportSize({ width: 400, height: 300 });
      await expect
        .poll(() =>
          page.evaluate(() => {
            const { renderer, camera } = window.oceanApp;
            const canvas = renderer.domElement;
            return [canvas.clientWidth, canvas.clientHeight, canvas.width / devicePixelRatio, canvas.height / devicePixelRatio, camera.aspect];
          }),
        )
        .toEqual([400, 300, 400, 300, 400 / 300]);
    });
  });

  test('URL → scene and panel; panel → URL; reload → the same scene and picture', async ({ browser }) => {
    const query = 'windSpeed=7.5&resolution=64&depth=35&seed=9&mode=fresnel&sunElevation=15&absorption=0.5,0.1,0.05&paused=1&t=3.5&cam=5,8,-3,20,-12';
    const { page, errors } = await reopenApp(browser, query);
    const scene = await page.evaluate(() => {
      const { ocean, state, controls } = window.oceanApp;
      return { parameters: ocean.parameters, shading: ocean.shading, sun: ocean.sky.sunElevation, t: state.t, pose: controls.pose };
    });
    expect(scene.parameters).toMatchObject({ windSpeed: 7.5, resolution: 64, depth: 35, seed: 9 });
    expect(scene.shading.shadingMode).toBe('fresnel');
    expect(scene.shading.absorption.map((c) => Number(c.toFixed(6)))).toEqual([0.5, 0.1, 0.05]);
    expect(scene.sun).toBe(15);
    expect(scene.t).toBe(3.5);
    expect(scene.pose).toEqual({ position: [5, 8, -3], yaw: 20, pitch: -12 });
    await expect(page.locator('[data-key="windSpeed"] input')).toHaveValue('7.5');
    await expect(page.locator('[data-key="resolution"] select')).toHaveValue('64');
    await expect(page.locator('[data-key="depth.deep"] input')).not.toBeChecked();
    await expect(page.locator('[data-key="depth"] input')).toHaveValue('35');
    await expect(page.locator('[data-key="seed"] input')).toHaveValue('9');
    await expect(page.locator('[data-key="paused"] input')).toBeChecked();

    // Change values in the panel: they reach the ocean and, shortly after, the URL.
    await page.locator('[data-key="windSpeed"] input').fill('9.5');
    await page.locator('[data-key="resolution"] select').selectOption('128');
    await page.locator('[data-key="depth.deep"] input').check();
    expect(await page.evaluate(() => window.oceanApp.ocean.parameters)).toMatchObject({ windSpeed: 9.5, resolution: 128, depth: Infinity });
    const urlParams = () => new URL(page.url()).searchParams;
    // Deep water is the default, so depth leaves the URL.
    await expect.poll(() => [urlParams().get('windSpeed'), urlParams().get('resolution'), urlParams().has('depth')]).toEqual(['9.5', '128', false]);
    const url = new URL(page.url());
    expect(url.searchParams.get('mode')).toBe('fresnel');
    expect(url.searchParams.get('t')).toBe('3.5');
    const picture = await pixels(page);

    await page.reload();
    await page.waitForFunction(() => window.oceanApp !== undefined);
    await frames(page, 2);
    expect(await page.evaluate(() => window.oceanApp.ocean.parameters)).toMatchObject({
      windSpeed: 9.5,
      resolution: 128,
      depth: Infinity,
      seed: 9,
    });
    expect(await pose(page)).toEqual({ position: [5, 8, -3], yaw: 20, pitch: -12 });
    expect(meanAbsDifference(picture, await pixels(page))).toBeLessThan(0.01);
    expect(errors).toEqual([]);
  });

  test('an invalid URL value shows a warning naming it, and the default is used', async ({ browser }) => {
    const { page } = await reopenApp(browser, 'windSpeed=abc&resolution=100&mode=shiny&seed=5');
    const warnings = page.locator('#status .notice.warning');
    await expect(warnings).toHaveCount(3);
    await expect(warnings.nth(0)).toBeVisible();
    await expect(warnings.nth(0)).toContainText('windSpeed must be');
    await expect(warnings.nth(1)).toContainText('resolution must be a power of two');
    await expect(warnings.nth(2)).toContainText('mode must be one of');
    await expect(warnings.nth(0)).toContainText(`using the default ${DEFAULT_PARAMETERS.windSpeed}`);
    await expect(warnings.nth(1)).toContainText(`using the default ${DEFAULT_PARAMETERS.resolution}`);
    const { parameters, mode } = await page.evaluate(() => ({
      parameters: window.oceanApp.ocean.parameters,
      mode: window.oceanApp.ocean.shading.shadingMode,
    }));
    expect(parameters).toMatchObject({ windSpeed: DEFAULT_PARAMETERS.windSpeed, resolution: DEFAULT_PARAMETERS.resolution, seed: 5 });
    expect(mode).toBe('full');
    // The URL now holds what runs; a warning can be dismissed.
    expect(page.url()).not.toContain('abc');
    expect(page.url()).toContain('seed=5');
    await warnings.nth(0).getByRole('button', { name: 'Dismiss' }).click();
    await expect(warnings).toHaveCount(2);
  });

  test('a bad panel value shows a warning naming it and the ocean keeps its last good value', async ({ browser }) => {
    const { page } = await reopenApp(browser, 'resolution=32&seed=3');
    const seed = page.locator('[data-key="seed"] input');
    await seed.fill('-5');
    const warning = page.locator('#status .notice.warning[data-parameter="seed"]');
    await expect(warning).toBeVisible();
    await expect(warning).toContainText('seed must be an integer');
    await expect(warning).toContainText('keeping seed 3');
    expect(await page.evaluate(() => window.oceanApp.ocean.parameters.seed)).toBe(3);
    await seed.blur();
    await expect(seed).toHaveValue('3');
    // A good value clears the warning.
    await seed.fill('4');
    await expect(warning).toHaveCount(0);
    expect(await page.evaluate(() => window.oceanApp.ocean.parameters.seed)).toBe(4);

    // Presets and "new seed" go through the same path.
    await page.locator('[data-key="preset"] select').selectOption('storm');
    expect(await page.evaluate(() => window.oceanApp.ocean.parameters)).toMatchObject({ ...SEA_PRESETS.storm, seed: 4 });
    await expect(page.locator('[data-key="windSpeed"] input')).toHaveValue(String(SEA_PRESETS.storm.windSpeed));
    await page.locator('[data-key="newSeed"] button').click();
    expect(await page.evaluate(() => window.oceanApp.ocean.parameters.seed)).not.toBe(4);
    await expect.poll(() => new URL(page.url()).searchParams.get('windSpeed')).toBe(String(SEA_PRESETS.storm.windSpeed));
  });

  test('the status line and the panel\'s "Hs, Tp" line show the sea state the parameters describe', async ({ browser }) => {
    const { page, errors } = await reopenApp(browser, 'windSpeed=17&fetch=300&resolution=64');
    const status = page.locator('#status .status-line');
    const panelLine = page.locator('[data-key="seaState"] input');
    for (const sea of [{ windSpeed: 17, fetch: 300 }, { windSpeed: 6, fetch: 300 }]) {
      if (sea.windSpeed !== 17) await page.locator('[data-key="windSpeed"] input').fill(String(sea.windSpeed));
      expect(await page.evaluate(() => window.oceanApp.ocean.parameters)).toMatchObject(sea);
      const heightRms = await page.evaluate(() => window.oceanApp.ocean.heightRms);
      // The cascades hold nearly all of this spectrum, so what they simulate is near its Hs, but
      // a random sample of it: at 17 m/s only a few wave vectors carry the peak, and over seeds
      // 1–12 the simulated Hs ranges from 0.73 to 1.27 times the spectrum's (mean 0.99).
      const { significantWaveHeight } = seaState(sea);
      expect(4 * heightRms).toBeGreaterThan(0.6 * significantWaveHeight);
      expect(4 * heightRms).toBeLessThan(1.4 * significantWaveHeight);
      const expected = seaStateText(sea, 4 * heightRms);
      await expect(status).toHaveText(new RegExp(`^${escapeRegExp(expected)} · FFT: `));
      await expect(panelLine).toHaveValue(expected);
    }
    expect(errors).toEqual([]);
  });

  test('choosing a preset in the dropdown applies its whole sea state, cascade sizes included', async ({ browser }) => {
    const { page, errors } = await reopenApp(browser, 'resolution=32&seed=3&swellHeight=2&depth=20&choppiness=1.3');
    const menu = page.locator('[data-key="preset"] select');
    const beaufort = Array.from({ length: 13 }, (_, force) => `Beaufort ${force}`);
    expect(await menu.locator('option').allTextContents()).toEqual(['', ...Object.keys(SEA_PRESETS), ...beaufort]);
    const urlParams = () => new URL(page.url()).searchParams;
    for (const [name, preset] of [
      ['storm', SEA_PRESETS.storm],
      ['Beaufort 3', beaufortPreset(3)],
      ['shallow bay', SEA_PRESETS['shallow bay']],
    ] as const) {
      await menu.selectOption(name);
      const applied = await page.evaluate(() => {
        const { ocean } = window.oceanApp;
        return { parameters: ocean.parameters, cascades: ocean.simulation.cascades.map((layer) => layer.spectrum.patchSize), heightRms: ocean.heightRms, cloudCover: ocean.sky.cloudCover };
      });
      // The sky it goes with: the storm overcast, the others clear (presetCloudCover).
      expect(applied.cloudCover).toBe(presetCloudCover(preset));
      // Every sea-state value of the preset (the swell and the depth of the URL are reset), and the
      // cascades it asks for; the grid's resolution, the seed and the choppiness stay.
      expect(applied.parameters).toMatchObject({ ...preset, resolution: 32, seed: 3, choppiness: 1.3 });
      expect(applied.parameters.patchSizes).toEqual(preset.patchSizes);
      expect(applied.cascades).toEqual(preset.patchSizes);
      await expect(page.locator('[data-key="windSpeed"] input')).toHaveValue(String(preset.windSpeed));
      await expect(page.locator('[data-key="patchSizes"] input')).toHaveValue(preset.patchSizes!.join(','));
      await expect(menu).toHaveValue(''); // the menu is an action, not a state
      await expect(page.locator('#status .status-line')).toHaveText(new RegExp(`^${escapeRegExp(seaStateText(preset, 4 * applied.heightRms))} · `));
      await expect.poll(() => [urlParams().get('windSpeed'), urlParams().get('patchSizes')]).toEqual([String(preset.windSpeed), preset.patchSizes!.join(',')]);
    }
    await expect(page.locator('#status .notice.warning')).toHaveCount(0);
    expect(errors).toEqual([]);
  });

  test('switching the shading mode in the panel changes the picture', async ({ browser }) => {
    const { page } = await reopenApp(browser, 'resolution=64&paused=1&t=2');
    const full = await pixels(page);
    await page.getByText('Sun & shading').click(); // the folder starts closed
    await page.locator('[data-key="mode"] select').selectOption('height');
    await expect(page.locator('#status .notice.warning')).toHaveCount(0); // the ocean took it
    expect(await page.evaluate(() => window.oceanApp.ocean.shading.shadingMode)).toBe('height');
    const height = await pixels(page);
    expect(meanAbsDifference(full, height)).toBeGreaterThan(10);
    await expect.poll(() => new URL(page.url()).searchParams.get('mode')).toBe('height');
    // Wireframe too reaches the material.
    await page.locator('[data-key="wireframe"] input').check();
    expect(await page.evaluate(() => window.oceanApp.ocean.surface.material.wireframe)).toBe(true);
  });

  test('the caustics mode under a low sun says why it is dark, and the hint goes once the sun is high', async ({ browser }) => {
    const { page } = await reopenApp(browser, 'resolution=64&paused=1&t=2&mode=caustics&sunElevation=30');
    const hint = page.locator('#status .notice.warning[data-parameter="caustics"]');
    await expect(hint).toContainText('raise the sun above 60°');
    await page.locator('.lil-title', { hasText: 'Sun & shading' }).click(); // the folder starts closed
    await page.locator('[data-key="sunElevation"] input').fill('75');
    await expect(hint).toHaveCount(0);
    const bright = await pixels(page);
    // The pattern now shows: a good part of the sea is lit in this term.
    let lit = 0;
    for (let i = 0; i < bright.length; i += 4) if (bright[i] > 60) lit++;
    expect(lit / (bright.length / 4)).toBeGreaterThan(0.05);
    await page.locator('[data-key="mode"] select').selectOption('full');
    await page.locator('[data-key="sunElevation"] input').fill('20');
    await expect(hint).toHaveCount(0); // only in the caustics mode
  });

  test('time: paused keeps t; slow frames advance t by real time × time scale; a stall over a second counts as one frame and the status shows the ratio', async ({ browser }) => {
    const { page } = await reopenApp(browser, 'resolution=32&paused=1&t=5', { width: 320, height: 180 });
    await page.waitForTimeout(300);
    expect(await page.evaluate(() => window.oceanApp.state.t)).toBe(5);
    const timeLine = page.locator('#status .status-time');
    await page.evaluate(() => window.oceanApp.set({ paused: false, timeScale: 2 }));
    const { simulated, real } = await slowFrames(page, 'app'); // the old clock, at most 0.1 s a frame, ran at 0.4×
    expect(real).toBeGreaterThan(1);
    expect(simulated / real).toBeCloseTo(2, 1);
    await expect(timeLine).not.toContainText('time ×'); // time runs as asked

    // Every text the time status shows from here on, recorded as it changes: the ratio shows for
    // about a second of frames, which a check polled from the test can miss on a loaded machine.
    await page.evaluate(() => {
      const shown: string[] = [];
      (window as unknown as { timeTextsShown: string[] }).timeTextsShown = shown;
      const line = document.querySelector('#status .status-time')!;
      new MutationObserver(() => shown.push(line.textContent ?? '')).observe(line, { subtree: true, childList: true, characterData: true });
    });
    const stalled = await page.evaluate(async () => {
      const app = window.oceanApp;
      await app.capturePixels();
      // The frames' lengths as this machine draws them now, from requestAnimationFrame's
      // timestamps (the app's clock sees the same): the longest of five.
      const longestFrame = await new Promise<number>((resolve) => {
        const stamps: number[] = [];
        const frame = (now: number) => {
          stamps.push(now);
          if (stamps.length < 6) requestAnimationFrame(frame);
          else resolve(Math.max(...stamps.slice(1).map((stamp, i) => stamp - stamps[i])));
        };
        requestAnimationFrame(frame);
      });
      // The main thread stalls for 1.5 s, or 8 of the longest frames if longer: a gap is over a
      // second and over 4 times the frame before it, or over 10 s (src/runtime/simulationClock.ts).
      const stall = Math.min(10_500, Math.max(1500, 8 * longestFrame));
      const before = app.state.t;
      const end = performance.now() + stall;
      while (performance.now() < end) {
        // busy
      }
      await app.capturePixels();
      return { gained: app.state.t - before, stall: stall / 1000 };
    });
    // One ordinary frame (plus at most the one before the stall) at 2×, not the 2 × stall it would be.
    expect(stalled.gained).toBeGreaterThan(0);
    expect(stalled.gained).toBeLessThan(stalled.stall);
    // The second that held the stall ran slower than asked, and the status says so, then not.
    const ratioShown = /^t = \d+\.\d\d s · time ×0\.\d+ \(time scale 2\) · camera speed /;
    await expect
      .poll(() => page.evaluate(() => (window as unknown as { timeTextsShown: string[] }).timeTextsShown), { timeout: 30_000 })
      .toContainEqual(expect.stringMatching(ratioShown));
    await expect(timeLine).not.toContainText('time ×', { timeout: 30_000 });
  });

  test('time far ahead: from t = 10^16 s (where t += dt stands still) the sea moves, as at t mod its repeat period', async ({ browser }) => {
    const { page } = await reopenApp(browser, 'resolution=32&t=1e16', { width: 320, height: 180 });
    const times = await page.evaluate(async () => {
      const app = window.oceanApp;
      await app.capturePixels();
      const first = app.state.t;
      await new Promise((resolve) => setTimeout(resolve, 1500));
      await app.capturePixels();
      return { first, later: app.state.t, period: app.ocean.repeatPeriod };
    });
    console.log(`from t = 1e16: t = ${times.first} then ${times.later} s 1.5 s later (repeat period ${times.period} s)`);
    expect(times.first).toBeLessThan(times.period + 1); // wrapped, where a double still resolves milliseconds
    expect(times.later - times.first).toBeGreaterThan(1); // and it moves with real time
  });

  test("quality 'auto' lowers the render scale, MSAA, the grid and the cascades until the frames hold the target, and the status line says so; a fixed level stays", async ({ page }) => {
    test.setTimeout(120_000);
    // Each quality the status line names, in turn, from the app's first frame on (an observer set
    // up before the page's scripts run): the level 'auto' starts at is read there, however far it
    // has come down by the time the test looks (under SwiftShader it comes down by itself).
    await page.addInitScript(() => {
      const shown: string[] = [];
      (window as unknown as { qualitiesShown: string[] }).qualitiesShown = shown;
      new MutationObserver(() => {
        const quality = /quality \w+ \(auto, for \d+ fps/.exec(document.querySelector('#status .status-line')?.textContent ?? '')?.[0];
        if (quality !== undefined && quality !== shown[shown.length - 1]) shown.push(quality);
      }).observe(document, { subtree: true, childList: true, characterData: true });
    });
    await openApp(page, 'quality=auto&targetFps=60', { width: 640, height: 360 }, false);
    // Frames of 250 ms (by their timestamps) until 'auto' is at the lowest level, a window (2 s) a
    // step: 60 fps is then out of reach on any machine, not only under SwiftShader.
    const slowed = await slowFramesUntil(page, 'app', 'lowest');
    console.log(`quality auto for 60 fps: lowest after ${slowed.frames} frames of 250 ms`);
    const status = page.locator('#status .status-line');
    await expect(status).toContainText(/quality lowest \(auto, for 60 fps, frame \d+ ms\): render scale 0\.3, no MSAA, 2 cascades of 32² · /);
    expect(await page.evaluate(() => (window as unknown as { qualitiesShown: string[] }).qualitiesShown)).toEqual(
      ['high', 'medium', 'low', 'lowest'].map((level) => `quality ${level} (auto, for 60 fps`),
    );
    const lowest = await page.evaluate(() => ({
      pixelRatio: window.oceanApp.renderer.getPixelRatio(),
      resolution: window.oceanApp.ocean.parameters.resolution,
      asked: window.oceanApp.state.resolution,
      msaa: window.oceanApp.output.msaa,
      msaaTarget: window.oceanApp.output.multisampleTarget !== null,
      cascades: window.oceanApp.ocean.simulation.cascades.map((layer) => layer.spectrum.patchSize),
      askedPatchSizes: window.oceanApp.state.patchSizes,
      frameMs: window.oceanApp.quality.medianFrameMs,
      fewestGridCells: window.oceanApp.ocean.surface.fewestCellsPerRing,
      gridVertices: window.oceanApp.ocean.surface.geometry.getAttribute('position').count,
    }));
    console.log(`quality auto at 640x360 for 60 fps: lowest level, pixel ratio ${lowest.pixelRatio}, N ${lowest.resolution} (asked ${lowest.asked}), cascades ${lowest.cascades}, median frame ${lowest.frameMs?.toFixed(0)} ms`);
    expect(lowest.pixelRatio).toBeCloseTo(0.3, 6);
    expect(lowest.resolution).toBe(32);
    expect(lowest.asked).toBe(256); // the URL and the panel keep what was asked for
    expect(lowest.msaa).toBe(false);
    expect(lowest.msaaTarget).toBe(false); // freed
    expect(lowest.cascades).toEqual([79.3, 457]); // the two largest patches: the longest waves stay
    expect(lowest.askedPatchSizes).toEqual([13.7, 79.3, 457]);
    expect(lowest.fewestGridCells).toBe(16); // a 108-pixel-high picture: 16 cells a ring

    // A fixed level is put in force at once and kept, whatever the frames: over a window of slow
    // ones, which 'auto' would have come down on.
    await page.evaluate(() => window.oceanApp.set({ quality: 'medium' }));
    await slowFramesUntil(page, 'app', 'a window measured');
    const medium = await page.evaluate(() => ({
      level: window.oceanApp.quality.level,
      frameMs: window.oceanApp.quality.medianFrameMs,
      pixelRatio: window.oceanApp.renderer.getPixelRatio(),
      resolution: window.oceanApp.ocean.parameters.resolution,
      msaa: window.oceanApp.output.msaa,
      cascades: window.oceanApp.ocean.simulation.cascades.length,
      fewestGridCells: window.oceanApp.ocean.surface.fewestCellsPerRing,
      gridVertices: window.oceanApp.ocean.surface.geometry.getAttribute('position').count,
    }));
    expect(medium).toMatchObject({ level: 'medium', pixelRatio: 0.75, resolution: 128, msaa: false, cascades: 3, fewestGridCells: 32 });
    expect(medium.frameMs).toBeGreaterThan(1.2 * (1000 / 60)); // a window slower than 60 fps by more than 'auto' lowers at
    expect(medium.gridVertices).toBeGreaterThan(3 * lowest.gridVertices);
    // Patch sizes changed in the panel run within the level's cascades; the URL keeps all of them.
    await page.evaluate(() => window.oceanApp.set({ quality: 'low', patchSizes: [10, 50, 250, 1250] }));
    const low = await page.evaluate(() => ({
      cascades: window.oceanApp.ocean.simulation.cascades.map((layer) => layer.spectrum.patchSize),
      resolution: window.oceanApp.ocean.parameters.resolution,
    }));
    expect(low).toEqual({ cascades: [250, 1250], resolution: 64 });
    await expect.poll(() => new URL(page.url()).searchParams.get('patchSizes')).toBe('10,50,250,1250');
    await page.evaluate(() => window.oceanApp.set({ quality: 'medium' }));
    await expect.poll(() => new URL(page.url()).searchParams.get('quality')).toBe('medium');
  });

  // Also on the oldest three.js: the render target is drawn like the canvas through a three.js internal (drawLikeCanvas).
  test('quality high multisamples (4x) through its render target onto a canvas without antialiasing: the picture differs from the one without MSAA at edges only', ALSO_ON_OLDEST_THREE, async ({ browser }) => {
    const { page } = await reopenApp(browser, 'resolution=32&paused=1&t=3&quality=high', { width: 480, height: 270 });
    const target = await page.evaluate(async () => {
      await window.oceanApp.capturePixels();
      const target = window.oceanApp.output.multisampleTarget;
      return { samples: target?.samples, width: target?.width, canvasAntialias: window.oceanApp.renderer.getContextAttributes()!.antialias };
    });
    expect(target).toEqual({ samples: 4, width: 480, canvasAntialias: false });
    const withMsaa = await pixels(page);
    await page.evaluate(() => (window.oceanApp.output.msaa = false));
    const without = await pixels(page);
    await page.evaluate(() => (window.oceanApp.output.msaa = true));
    const again = await pixels(page);
    let differing = 0;
    for (let i = 0; i < without.length; i += 4) if (Math.abs(without[i] - withMsaa[i]) + Math.abs(without[i + 1] - withMsaa[i + 1]) + Math.abs(without[i + 2] - withMsaa[i + 2]) > 6) differing++;
    const share = differing / (without.length / 4);
    console.log(`MSAA on and off: ${(100 * share).toFixed(2)} % of pixels differ by more than 6 levels, mean difference ${meanAbsDifference(without, withMsaa).toFixed(3)}`);
    expect(share).toBeGreaterThan(0.001); // the edges (the horizon, crests against the sky) change
    expect(meanAbsDifference(without, withMsaa)).toBeLessThan(2); // and nothing else: tone mapping and sRGB as on the canvas
    expect(meanAbsDifference(again, withMsaa)).toBe(0);
  });

  test('copy link: without a clipboard the link is shown in a visible field', async ({ page }) => {
    await page.addInitScript(() => {
      Object.defineProperty(navigator, 'clipboard', { value: { writeText: () => Promise.reject(new Error('denied')) } });
    });
    await openApp(page, 'resolution=32&seed=12');
    await page.locator('[data-key="copyLink"] button').click();
    const field = page.locator('#status .notice.link input');
    await expect(field).toBeVisible();
    await expect(page.locator('#status .notice.link')).toContainText('clipboard is unavailable');
    expect(await field.inputValue()).toBe(page.url());
    expect(page.url()).toContain('seed=12');
  });

  test('?buoys=1 drops floating buoys ahead of the camera; they ride the water, and the panel takes them away', async ({ browser }) => {
    const { page } = await reopenApp(browser, 'resolution=64&windSpeed=12&buoys=1');
    const afloat = () =>
      page.evaluate(async () => {
        const { buoys, ocean, state } = window.oceanApp;
        const t0 = state.t;
        while (window.oceanApp.state.t < t0 + 1) await new Promise((resolve) => requestAnimationFrame(resolve));
        // Each float is 0.6 m high; its centre is where the water is, give or take the float's motion.
        return buoys!.children
          .filter((child) => child.type === 'Mesh')
          .map((buoy) => ({ y: buoy.position.y, water: ocean.heightAt(buoy.position.x, buoy.position.z), tilt: Math.acos(1 - 2 * (buoy.quaternion.x ** 2 + buoy.quaternion.z ** 2)) })); // the mast's angle from vertical
      });
    const first = await afloat();
    expect(first).toHaveLength(5);
    for (const { y, water, tilt } of first) {
      expect(Math.abs(y - water)).toBeLessThan(0.6);
      expect(tilt).toBeLessThan(0.7); // upright (it is stable), rocking with the waves (a turn about the vertical is free)
    }
    const second = await afloat();
    expect(second.some((buoy, i) => Math.abs(buoy.y - first[i].y) > 1e-3)).toBe(true); // they move
    await page.locator('[data-key="buoys"] input').uncheck();
    expect(await page.evaluate(() => window.oceanApp.buoys === null && !window.oceanApp.scene.getObjectByName('buoys'))).toBe(true);
  });

  test('a click on the sea drops a stone there: rings spread from the clicked point, and the picture shows them', async ({ browser }) => {
    // A calm sea seen from 20 m looking down 60°, so that the rings stand out.
    const { page } = await reopenApp(browser, 'resolution=64&windSpeed=2&cam=0,20,0,0,-60', { width: 480, height: 270 }, false);
    const before = await pixels(page);
    await page.mouse.click(240, 150);
    // Where the click's ray meets the sea, and the local waves there a few seconds on.
    const result = await page.evaluate(async () => {
      const { ocean, camera, state, renderer } = window.oceanApp;
      const t0 = state.t;
      while (window.oceanApp.state.t < t0 + 3) await new Promise((resolve) => requestAnimationFrame(resolve));
      const waves = ocean.localWaves!;
      const { size, origin, resolution } = waves.frame;
      const { displacement } = waves.fieldsOnCpu(state.t);
      // The centre of the rings: the centroid of h² (the energy), in world metres.
      let [sum, x, z, largest] = [0, 0, 0, 0];
      for (let j = 0; j < resolution; j++) {
        for (let i = 0; i < resolution; i++) {
          const h = displacement[4 * (j * resolution + i) + 1];
          const energy = h * h;
          [sum, x, z, largest] = [sum + energy, x + energy * (origin[0] + (i * size) / resolution), z + energy * (origin[1] + (j * size) / resolution), Math.max(largest, Math.abs(h))];
        }
      }
      // The clicked point: the ray through the pixel (240, 150) of the 480 × 270 canvas.
      const bounds = renderer.domElement.getBoundingClientRect();
      const ndc = [((240 - bounds.left) / bounds.width) * 2 - 1, 1 - ((150 - bounds.top) / bounds.height) * 2];
      const direction = camera.position.clone().set(ndc[0], ndc[1], 0.5).unproject(camera).sub(camera.position).normalize();
      const along = -camera.position.y / direction.y;
      return { largest, centre: [x / sum, z / sum], clicked: [camera.position.x + along * direction.x, camera.position.z + along * direction.z], active: waves.active };
    });
    expect(result.active).toBe(true);
    expect(result.largest).toBeGreaterThan(0.02); // a 0.8 m deep dip 1.2 m wide leaves rings of several centimetres
    expect(Math.hypot(result.centre[0] - result.clicked[0], result.centre[1] - result.clicked[1])).toBeLessThan(1);
    // The rings change the picture where they are (measured: a mean difference of several levels).
    expect(meanAbsDifference(before, await pixels(page))).toBeGreaterThan(1);
  });

  test('?boat=1 runs a boat round its course; it leaves a wake on the local waves behind it, and the panel takes it away', async ({ browser }) => {
    const { page } = await reopenApp(browser, 'resolution=64&windSpeed=2&boat=1');
    await page.evaluate(async () => {
      const t0 = window.oceanApp.state.t;
      while (window.oceanApp.state.t < t0 + 8) await new Promise((resolve) => requestAnimationFrame(resolve));
    });
    const wake = await boatWake(page, 'app');
    expect(wake.onCourse).toBeLessThan(3); // where its course puts it (a frame behind at most)
    expect(wake.astern).toBeGreaterThan(0.02);
    expect(wake.astern).toBeGreaterThan(3 * wake.ahead); // waves behind, calm water ahead
    // And foam along its track, none ahead (hullFoam.ts): 12 m from its centre is 8 m astern, foam
    // 1.6 s old at 5 m/s, e^(−1.6/3) = 0.59 of its full coverage (Froude number 0.56: full).
    expect(wake.foamAstern).toBeGreaterThan(0.4);
    expect(wake.foamAhead).toBe(0);
    await page.evaluate(() => window.oceanApp.panel.gui.open(true));
    await page.locator('[data-key="boat"] input').uncheck();
    expect(await page.evaluate(() => window.oceanApp.boat === null && !window.oceanApp.scene.getObjectByName('boat'))).toBe(true);
  });
});

/**
 * Compares the inspector's height tile with the texture of the cascade it shows: returns the
 * worst difference of 6 × 6 samples from the GL-style bilinear sample of the field, and their spread.
 */
async function compareHeightTile(page: Page): Promise<{ cascade: number; cells: number; worst: number; spread: number }> {
  return page.evaluate(async () => {
    const { ocean, inspector } = window.oceanApp;
    const cascade = inspector!.shownCascade;
    const heightTile = 3; // P(k), Re h̃0, Im h̃0, height h, …
    const view = inspector!.tiles[heightTile].view as unknown as { material: { uniforms: { scale: { value: number } } } };
    const scale = view.material.uniforms.scale.value;
    const { width, data } = await window.oceanApp.capturePixels();
    // Read the field after the await: the worker path swaps arrays between frames, and the one
    // the texture no longer holds is transferred to the worker (detached). Paused, every frame
    // carries the same field.
    const field = (ocean.simulation.cascades[cascade].textures.displacement.value as unknown as { image: { data: Float32Array } }).image.data.slice();
    const n = 32;
    // The strip's square cells: the field tiles, then the S(ω) plot (Inspector.CELL_COUNT).
    const cells = (inspector!.constructor as unknown as { CELL_COUNT: number }).CELL_COUNT;
    const size = Math.floor(width / cells);
    // GL-style bilinear sample of h (channel 1) with REPEAT at uv.
    const sample = (u: number, v: number) => {
      const x = u * n - 0.5;
      const y = v * n - 0.5;
      const x0 = Math.floor(x);
      const y0 = Math.floor(y);
      const at = (i: number, j: number) => field[4 * (((j + n) % n) * n + ((i + n) % n)) + 1];
      const fx = x - x0;
      const fy = y - y0;
      return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) + fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
    };
    let worst = 0;
    const greys: number[] = [];
    for (let j = 0; j < 6; j++) {
      for (let i = 0; i < 6; i++) {
        const px = heightTile * size + Math.floor(((i + 0.5) / 6) * size);
        const py = Math.floor(((j + 0.5) / 6) * size); // rows from the bottom, as readPixels gives them
        const grey = data[4 * (py * width + px)] / 255;
        const expected = 0.5 + 0.5 * Math.max(-1, Math.min(1, sample((px - heightTile * size + 0.5) / size, (py + 0.5) / size) / scale));
        worst = Math.max(worst, Math.abs(grey - expected));
        greys.push(grey);
      }
    }
    const mean = greys.reduce((a, b) => a + b, 0) / greys.length;
    const spread = Math.sqrt(greys.reduce((a, b) => a + (b - mean) ** 2, 0) / greys.length);
    return { cascade, cells, worst, spread };
  });
}

/**
 * The inspector's spectrum tiles and labels as drawn: for each of Ψ, Re h̃0 and Im h̃0, the spread
 * (standard deviation) of the relative luminance over its tile; for each label, its text and the
 * least WCAG contrast ratio between its text colour and its band, the band composited over every
 * canvas pixel under the label (over a pale tile the band must still keep the text readable).
 */
async function inspectorLegibility(page: Page): Promise<{ spreads: { title: string; spread: number }[]; labels: { text: string; contrast: number }[] }> {
  return page.evaluate(async () => {
    const { inspector, renderer } = window.oceanApp;
    const { width, height, data } = await window.oceanApp.capturePixels();
    const cells = (inspector!.constructor as unknown as { CELL_COUNT: number }).CELL_COUNT;
    const size = Math.floor(width / cells);
    const linear = (c: number) => (c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4);
    /** Relative luminance (WCAG 2) of an sRGB colour with channels 0–255. */
    const luminance = (rgb: number[]) => 0.2126 * linear(rgb[0] / 255) + 0.7152 * linear(rgb[1] / 255) + 0.0722 * linear(rgb[2] / 255);
    /** A pixel of the canvas, (x, y) from its top left, as [r, g, b]. */
    const pixel = (x: number, y: number) => [0, 1, 2].map((c) => data[4 * ((height - 1 - y) * width + x) + c]);
    const spreads = [0, 1, 2].map((index) => {
      const values: number[] = [];
      for (let y = height - size; y < height; y++) for (let x = index * size; x < (index + 1) * size; x++) values.push(luminance(pixel(x, y)));
      const mean = values.reduce((a, b) => a + b, 0) / values.length;
      return { title: inspector!.tiles[index].title, spread: Math.sqrt(values.reduce((a, b) => a + (b - mean) ** 2, 0) / values.length) };
    });
    const canvas = renderer.domElement.getBoundingClientRect();
    const rgba = (css: string) => css.match(/[\d.]+/g)!.map(Number);
    const labels = inspector!.tiles.map(({ label }) => {
      const style = getComputedStyle(label);
      const text = rgba(style.color);
      const [br, bg, bb, alpha = 1] = rgba(style.backgroundColor);
      const box = label.getBoundingClientRect();
      let contrast = Infinity;
      for (let y = Math.ceil(box.top - canvas.top); y < Math.floor(box.bottom - canvas.top); y++) {
        for (let x = Math.ceil(box.left - canvas.left); x < Math.floor(box.right - canvas.left); x++) {
          const under = pixel(x, y);
          const band = [br, bg, bb].map((c, i) => alpha * c + (1 - alpha) * under[i]);
          const [light, dark] = [luminance(text), luminance(band)].sort((a, b) => b - a);
          contrast = Math.min(contrast, (light + 0.05) / (dark + 0.05));
        }
      }
      return { text: label.textContent ?? '', contrast };
    });
    return { spreads, labels };
  });
}

test('?inspector=1 shows the inspector, which draws the real height field (a tile matches the texture it shows); the panel takes it away', async ({ browser }) => {
  // The JS path keeps the field in a DataTexture the test can read; paused, so it stays put.
  const { page } = await reopenApp(browser, 'resolution=32&path=js&paused=1&t=7.5&inspector=1', { width: 720, height: 405 }, false);
  await expect.poll(() => page.evaluate(() => window.oceanApp.ocean.simulation.path)).toBe('js-worker');
  await frames(page, 10);
  const cascades = await page.evaluate(() => window.oceanApp.ocean.simulation.cascades.length);
  expect(cascades).toBe(DEFAULT_PARAMETERS.patchSizes.length);
  // By default the tiles show the largest cascade.
  const largest = await compareHeightTile(page);
  expect(largest.cascade).toBe(cascades - 1);
  expect(largest.cells).toBe(11); // ten field tiles and the S(ω) plot
  expect(largest.spread).toBeGreaterThan(0.03); // not a blank or uniform tile
  expect(largest.worst).toBeLessThan(0.03); // 8-bit output and float32 filtering: ~0.005

  // The spectrum tiles show their content (the h̃0 tiles were almost blank, scaled to the single
  // largest mode), and every label is readable on its band over whatever tile lies under it.
  const { spreads, labels } = await inspectorLegibility(page);
  console.log(`inspector: luminance spread ${spreads.map(({ title, spread }) => `${title} ${spread.toFixed(3)}`).join(', ')}; least label contrast ${Math.min(...labels.map((l) => l.contrast)).toFixed(2)}:1`);
  for (const { title, spread } of spreads) expect(spread, `${title} tile`).toBeGreaterThan(0.02);
  expect(labels).toHaveLength(10);
  // WCAG 2 asks 4.5:1 for normal text (its 1.4.3 "Contrast (Minimum)"); white on white was 1:1.
  for (const { text, contrast } of labels) expect(contrast, text).toBeGreaterThanOrEqual(4.5);

  // C shows the next cascade (after the last, the first): the tile then matches that one's texture.
  await page.keyboard.press('c');
  await frames(page, 3); // the tiles' scales follow the shown cascade's spectrum at the next render
  const finest = await compareHeightTile(page);
  expect(finest.cascade).toBe(0);
  expect(finest.spread).toBeGreaterThan(0.03);
  expect(finest.worst).toBeLessThan(0.03);

  // The panel takes it away: its tiles and labels go, and the URL no longer asks for it.
  await expect(page.locator('.inspector-labels > div')).toHaveCount(10);
  await page.evaluate(() => window.oceanApp.panel.gui.open(true));
  await page.locator('[data-key="inspector"] input').uncheck();
  await expect(page.locator('.inspector-labels')).toHaveCount(0);
  expect(await page.evaluate(() => window.oceanApp.inspector)).toBeNull();
  await expect.poll(() => new URL(page.url()).searchParams.has('inspector')).toBe(false);
});

test.describe('under water', () => {
  /** Mean (r, g, b) of the rows [from, to) of the canvas (its top row first), from raw RGBA read bottom-up. */
  function rowsMean(data: Buffer, width: number, height: number, from: number, to: number): number[] {
    const sum = [0, 0, 0];
    for (let y = from; y < to; y++) {
      const row = height - 1 - y;
      for (let x = 0; x < width; x++) for (let c = 0; c < 3; c++) sum[c] += data[4 * (row * width + x) + c];
    }
    return sum.map((v) => v / ((to - from) * width));
  }

  // One page for both (the same sea, paused at t = 5): the first reads the camera the URL put under
  // water, the second sets its own.
  const underWaterPage = sharedPages(
    async (page) => void (await openApp(page, 'resolution=64&windSpeed=8&paused=1&t=5&cam=0,-6,0,0,0', { width: 320, height: 180 }, false)),
    async () => {},
  );

  test('the camera dives; 6 m down looking level, the view is the water\'s own colour, darker and greener-blue than the sky, never the sky', async ({ browser }) => {
    const page = await underWaterPage(browser);
    const eye = await page.evaluate(() => window.oceanApp.camera.position.y);
    expect(eye).toBe(-6); // not pushed back above the water
    const data = await pixels(page);
    // Below the horizon: deep water, the sea's scatterColor tone-mapped (about (0, 47, 61)); no pixel
    // there is as bright as the sky (whose every row is above 120 in blue).
    const [r, g, b] = rowsMean(data, 320, 180, 100, 180);
    expect(r).toBeLessThan(15);
    expect(b).toBeGreaterThan(g);
    expect(b).toBeLessThan(110);
  });

  test('at the surface, the waterline: sky above, water below, one boundary across the picture', async ({ browser }) => {
    const page = await underWaterPage(browser);
    // The eye exactly at the water's height under it: the near plane crosses the surface.
    await page.evaluate(() => {
      const { ocean, controls } = window.oceanApp;
      controls.pose = { position: [0, ocean.heightAt(0, 0), 0], yaw: 0, pitch: 0 };
    });
    await frames(page, 2);
    const data = await pixels(page);
    const top = rowsMean(data, 320, 180, 0, 40);
    const bottom = rowsMean(data, 320, 180, 140, 180);
    expect(top[2]).toBeGreaterThan(150); // the sky
    expect(bottom[2]).toBeLessThan(110); // the water, from inside it
    // In every column, once the water begins (8 dark pixels in a row) it does not end: no band of
    // sky colour under the waterline. (Above it the sea seen from above may have dark troughs.)
    let columnsWithOneBoundary = 0;
    for (let x = 0; x < 320; x += 8) {
      const dark = (y: number) => data[4 * ((179 - y) * 320 + x) + 2] < 130;
      let start = -1;
      for (let y = 0; y + 8 <= 180 && start < 0; y++) if ([0, 1, 2, 3, 4, 5, 6, 7].every((d) => dark(y + d))) start = y;
      let clean = start > 0;
      for (let y = start; clean && y < 180; y++) clean = dark(y);
      if (clean) columnsWithOneBoundary++;
    }
    expect(columnsWithOneBoundary).toBeGreaterThanOrEqual(36); // of 40
  });
});

test.describe('failures the app explains', () => {
  // The skybox tests are about what is fetched and said: the smallest viewport and FFT do (the
  // default 1280×720 window at N = 256 took seconds a load under SwiftShader).
  const SMALL = 'resolution=32&quality=high';
  const SMALL_SIZE = { width: 320, height: 180 };

  test('a skybox that fails to load shows a warning naming it, and the generated sky stays', async ({ browser }) => {
    const { page } = await reopenApp(browser, `skybox=/no-such-skybox/&${SMALL}`, SMALL_SIZE, false);
    await expect(page.locator('.notice.warning', { hasText: 'skybox' })).toBeVisible({ timeout: 30_000 });
    await expect(page.locator('.notice.warning', { hasText: 'skybox' })).toContainText('/no-such-skybox/px.png');
    const generated = await page.evaluate(() => !window.oceanApp.ocean.sky.usingFaces);
    expect(generated).toBe(true);
    await expect.poll(() => new URL(page.url()).searchParams.has('skybox')).toBe(false); // a copied link does not carry it on
  });

  test('a skybox on another origin is refused before anything is fetched, unless the page trusts that origin', async ({ page }) => {
    const requested: string[] = [];
    page.on('request', (request) => {
      if (!request.url().startsWith('http://127.0.0.1')) requested.push(request.url());
    });
    // One page load: the first folder through the URL (the warning, the sky, the URL that drops it),
    // the others through the same function the app loads its URL's skybox with (appView.ts).
    const [first, ...others] = ['https://tracker.example/sky/', '//tracker.example/sky/', 'data:image/png;base64,AAAA/'];
    await page.setViewportSize(SMALL_SIZE);
    await page.goto(`/?skybox=${encodeURIComponent(first)}&${SMALL}`);
    await page.waitForFunction(() => window.oceanApp !== undefined);
    const refusal = `skybox must be a folder URL on ${new URL(page.url()).origin}`;
    const warning = page.locator('.notice.warning', { hasText: 'skybox' });
    await expect(warning).toContainText(refusal);
    await expect(warning).toContainText('fft-ocean-skybox-origins');
    expect(await page.evaluate(() => window.oceanApp.ocean.sky.usingFaces)).toBe(false);
    await expect.poll(() => new URL(page.url()).searchParams.has('skybox')).toBe(false);
    const load = (skybox: string, trusted?: string) =>
      page.evaluate(
        async ({ skybox, trusted }) => {
          const appView = '/src/app/appView.ts'; // from the dev server, as the app loads it
          const { loadAppSkybox, trustedSkyboxOrigins } = (await import(appView)) as typeof import('../../../src/app/appView');
          if (trusted !== undefined) {
            const meta = Object.assign(document.createElement('meta'), { name: 'fft-ocean-skybox-origins', content: trusted });
            document.head.append(meta);
            if (trustedSkyboxOrigins().join(' ') !== `${location.origin} ${trusted.split(/\s+/).join(' ')}`) return { parameter: 'meta not read', message: '' };
          }
          try {
            await loadAppSkybox(window.oceanApp.ocean, skybox);
            return { parameter: 'loaded', message: '' };
          } catch (error) {
            return { parameter: (error as { parameter?: string }).parameter ?? 'none', message: (error as Error).message };
          }
        },
        { skybox, trusted },
      );
    for (const skybox of others) {
      const refused = await load(skybox);
      expect(refused.parameter, skybox).toBe('skybox');
      expect(refused.message, skybox).toContain(refusal);
      expect(refused.message, skybox).toContain('fft-ocean-skybox-origins');
      expect(await page.evaluate(() => window.oceanApp.ocean.sky.usingFaces)).toBe(false);
    }
    expect(requested).toEqual([]);

    // The page's own list: an origin it names is tried (here it does not answer: the load fails, after a request).
    const trusted = await load('https://sky.example/faces/', 'https://cdn.example  https://sky.example');
    expect(trusted.message).toContain('could not load https://sky.example/faces/px.png');
    expect(requested).toContain('https://sky.example/faces/px.png');
  });

  test('the shipped skybox loads from the URL', async ({ browser }) => {
    const { page } = await reopenApp(browser, `skybox=/skybox/clear-afternoon/&${SMALL}`, SMALL_SIZE, false);
    await expect.poll(() => page.evaluate(() => window.oceanApp.ocean.sky.usingFaces), { timeout: 30_000 }).toBe(true);
    await expect(page.locator('.notice.warning', { hasText: 'skybox' })).toHaveCount(0);
  });

  // The picture of the full GPU path all the weaker devices are compared with: the same for each.
  const FALLBACK_QUERY = 'resolution=64&paused=1&t=7.5';
  let reference: Buffer;
  test.beforeAll(async ({ browser }) => {
    const { page } = await reopenApp(browser, FALLBACK_QUERY, SMALL_SIZE, false);
    await frames(page, 3);
    reference = await pixels(page);
    await releaseSharedPage();
  });

  for (const [device, hidden, running, reason] of [
    ['MAX_DRAW_BUFFERS of 4 (all WebGL2 promises)', { maxDrawBuffers: 4 }, /^js/, /MAX_DRAW_BUFFERS is 4/],
    ['no EXT_color_buffer_float', { extensions: ['EXT_color_buffer_float'] }, /^gpu-rgba16f$/, /no EXT_color_buffer_float: half floats/],
    ['no float render targets at all', { extensions: ['EXT_color_buffer_float', 'EXT_color_buffer_half_float'] }, /^js/, /no float render targets/],
    // Found when the GPU path is built, not at its first update: 'auto' can still fall back then.
    ['framebuffers of several attachments unsupported', { layeredFramebuffers: false }, /^js/, /the GPU path failed: GPU FFT: the layered framebuffer is incomplete \(status 0x8cdd\)/],
    // A three.js newer than the newest tested whose internals moved: the peer range is open above.
    ['a three.js without the internals the GPU FFT uses', { rendererMethods: ['setRenderTargetFramebuffer'] }, /^js/, /three\.js r\d+ has no WebGLRenderer\.setRenderTargetFramebuffer, which the GPU FFT needs/],
  ] as const) {
    test(`on a device with ${device} the sea falls back, says why, and looks the same`, async ({ page }) => {
      const weaker = page;
      await withHiddenCapabilities(weaker, hidden);
      await openApp(weaker, FALLBACK_QUERY, SMALL_SIZE, false);
      await frames(weaker, 6); // the JS worker's fields arrive a frame or two later
      const report = await weaker.evaluate(() => window.oceanApp.ocean.path);
      expect(report.preference).toBe('auto');
      expect(report.running).toMatch(running);
      expect(report.reason).toMatch(reason);
      await expect(weaker.locator('#status')).toContainText(report.reason);
      // The same sea: the paths agree to 1e-6 of the heights (RGBA16F to half-float precision).
      const difference = meanAbsDifference(reference, await pixels(weaker));
      console.log(`${device}: ${report.running} (${report.reason}), mean difference from RGBA32F ${difference.toFixed(3)} levels`);
      expect(difference).toBeLessThan(1);
    });
  }

  test('without WebGL2 the page explains instead of showing a blank canvas', async ({ page }) => {
    await withoutWebGL2(page);
    const errors: string[] = [];
    page.on('pageerror', (error) => errors.push(error.message));
    await page.goto('/');
    await expect(page.locator('.no-webgl')).toContainText('needs WebGL2');
    await expect(page.locator('canvas')).toHaveCount(0);
    expect(errors).toEqual([]);
  });
});
