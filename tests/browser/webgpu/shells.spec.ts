import { expect, test, type Page } from '@playwright/test';
import { mkdirSync, writeFileSync } from 'node:fs';
import { PNG } from 'pngjs';
import { WEBGPU_BROWSER } from '../shared/webgpuBrowser';
import type { RendererStatus } from '../../../src/embed/fftOceanElement';

// The shells on three's WebGPURenderer: <fft-ocean renderer="webgpu"> and the app's
// ?renderer=webgpu, on SwiftShader's WebGPU adapter (--enable-unsafe-webgpu, ../shared/BROWSER.md)
// and, where a page has no navigator.gpu, on WebGPURenderer's WebGL2 backend.
test.use(WEBGPU_BROWSER);

/** What a page said: uncaught errors, console warnings and notes. */
interface PageLog {
  errors: string[];
  warnings: string[];
  infos: string[];
}

async function open(page: Page, url: string, withoutWebGPU = false): Promise<PageLog> {
  const log: PageLog = { errors: [], warnings: [], infos: [] };
  page.on('pageerror', (error) => log.errors.push(error.message));
  page.on('console', (message) => {
    if (message.type() === 'warning') log.warnings.push(message.text());
    if (message.type() === 'info') log.infos.push(message.text());
  });
  // A browser without WebGPU: Navigator has no gpu.
  if (withoutWebGPU) await page.addInitScript(() => delete (Navigator.prototype as { gpu?: unknown }).gpu);
  await page.goto(url);
  return log;
}

/**
 * Mean luma of rows [from, to) of an RGBA picture (rows from the top), and the mean over those rows
 * of the standard deviation along each row: waves vary along a row, a smooth gradient does not.
 */
function rows(png: InstanceType<typeof PNG>, from: number, to: number): { mean: number; spread: number } {
  let total = 0;
  let spreads = 0;
  for (let y = from; y < to; y++) {
    let sum = 0;
    let squares = 0;
    for (let x = 0; x < png.width; x++) {
      const i = 4 * (y * png.width + x);
      const luma = 0.2126 * png.data[i] + 0.7152 * png.data[i + 1] + 0.0722 * png.data[i + 2];
      sum += luma;
      squares += luma * luma;
    }
    const mean = sum / png.width;
    total += mean;
    spreads += Math.sqrt(Math.max(0, squares / png.width - mean * mean));
  }
  return { mean: total / (to - from), spread: spreads / (to - from) };
}

/**
 * Expects `png` to be a lit sky over darker water with waves: the top 30 % of rows against the
 * bottom 30 %; logs the figures under `label`.
 */
function expectSkyOverWaves(png: InstanceType<typeof PNG>, label: string): void {
  const sky = rows(png, 0, Math.round(png.height * 0.3));
  const sea = rows(png, Math.round(png.height * 0.7), png.height);
  console.log(`${label} ${png.width}×${png.height}: sky mean luma ${sky.mean.toFixed(1)}, sea mean ${sea.mean.toFixed(1)} spread ${sea.spread.toFixed(1)}`);
  expect(sky.mean).toBeGreaterThan(60); // a lit sky, not black
  expect(sea.mean).toBeGreaterThan(5);
  expect(sea.mean).toBeLessThan(sky.mean); // darker water under the sky
  expect(sea.spread).toBeGreaterThan(5); // waves along the rows, not a smooth gradient
}

/** An RGBA picture (rows from the top) as a PNG, saved under .tmp/ to be looked at. */
function picture(width: number, height: number, data: number[], name: string): InstanceType<typeof PNG> {
  const png = new PNG({ width, height });
  png.data.set(data);
  mkdirSync('.tmp', { recursive: true });
  writeFileSync(`.tmp/${name}.png`, PNG.sync.write(png));
  return png;
}

/**
 * In the embed test page: an <fft-ocean renderer="webgpu"> (N = 64, paused at t = 3) with `extra`
 * attributes; its status, and its view drawn into an 8-bit sRGB target and read back, rows from
 * the top. On screen the element draws its own frame first (its camera placed by the drifting
 * view). `belowTheFold`: the element sits just below the viewport, near enough to hold its
 * renderer and ocean but not drawing, and the camera is placed here, 8 m up looking at the
 * horizon: headless SwiftShader's WebGPU loses its device once a frame is presented to a canvas
 * (../shared/BROWSER.md), so on the WebGPU backend the picture comes from a target alone.
 */
async function webgpuElement(page: Page, extra: Record<string, string> = {}, belowTheFold = false): Promise<{ status: RendererStatus; width: number; height: number; data: number[]; framesDrawn: number }> {
  const { status, framesDrawn } = await page.evaluate(async ({ extra, belowTheFold }) => {
    if (belowTheFold) {
      const spacer = document.createElement('div');
      spacer.style.height = `${innerHeight + 20}px`;
      document.body.prepend(spacer);
    }
    const el = window.embed.create({ renderer: 'webgpu', resolution: '64', paused: '', ...extra });
    el.time = 3;
    const status = await new Promise<RendererStatus>((resolve, reject) => {
      el.addEventListener('fft-ocean-renderer', (event) => resolve((event as CustomEvent<RendererStatus>).detail));
      el.addEventListener('fft-ocean-error', (event) => reject(new Error((event as CustomEvent<{ message: string }>).detail.message)));
    });
    if (!belowTheFold) await window.embed.drawn(el, 1);
    return { status, framesDrawn: el.frameCount };
  }, { extra, belowTheFold });
  return { status, framesDrawn, ...(await elementView(page, belowTheFold)) };
}

/**
 * The view of the page's <fft-ocean renderer="webgpu"> drawn by its renderer into an 8-bit sRGB
 * target and read back, rows from the top; `placeCamera`: first 8 m up looking at the horizon,
 * the Ocean updated to the element's time (an element below the fold draws nothing itself).
 */
async function elementView(page: Page, placeCamera: boolean): Promise<{ width: number; height: number; data: number[] }> {
  return page.evaluate(async (placeCamera) => {
    const { RenderTarget, SRGBColorSpace } = window.embed;
    const el = document.querySelector('fft-ocean')!;
    if (placeCamera) {
      el.camera!.position.set(0, 8, 0);
      el.camera!.lookAt(0, 6, -100);
      el.webgpuOcean!.update(el.time);
    }
    const renderer = el.webgpuRenderer!;
    const [width, height] = [el.canvas!.width, el.canvas!.height];
    const target = new RenderTarget(width, height);
    target.texture.colorSpace = SRGBColorSpace;
    renderer.setRenderTarget(target);
    renderer.render(el.scene!, el.camera!);
    renderer.setRenderTarget(null);
    const pixels = (await renderer.readRenderTargetPixelsAsync(target, 0, 0, width, height)) as Uint8Array;
    target.dispose();
    const bottomFirst = el.rendererStatus!.backend === 'WebGL2'; // WebGL's rows come bottom first
    const data: number[] = [];
    for (let row = 0; row < height; row++) {
      const from = 4 * width * (bottomFirst ? height - 1 - row : row);
      data.push(...pixels.subarray(from, from + 4 * width));
    }
    return { width, height, data };
  }, placeCamera);
}

/** Removes every element from the page; whether the last one's ocean and renderer were freed. */
async function removeElement(page: Page): Promise<{ oceanDisposed: boolean; canvasGone: boolean; heldAfter: boolean; deviceLost: string | null }> {
  return page.evaluate(async () => {
    const el = document.querySelector('fft-ocean')!;
    const ocean = el.webgpuOcean!;
    const canvas = el.canvas!;
    const backend = el.webgpuRenderer!.backend as { device?: GPUDevice };
    const lost = backend.device?.lost.then((info) => info.reason) ?? Promise.resolve(null);
    await window.embed.reset();
    let oceanDisposed = false;
    try {
      void ocean.time;
    } catch (error) {
      oceanDisposed = (error as Error).name === 'DisposedError';
    }
    // The WebGPU backend destroys its device on dispose: its lost promise resolves with 'destroyed'.
    // 30 s only stops a hang: a device destroyed is lost within milliseconds, later under load.
    const deviceLost = await Promise.race([lost, new Promise<string>((resolve) => setTimeout(() => resolve('not lost within 30 s'), 30_000))]);
    return { oceanDisposed, canvasGone: !canvas.isConnected, heldAfter: el.webgpuRenderer !== null || el.webgpuOcean !== null, deviceLost };
  });
}

test('<fft-ocean renderer="webgpu"> holds WebGPURenderer on its WebGPU backend and its sea is sky over waves; removal frees it, destroying the device', async ({ page }) => {
  const log = await open(page, '/tests/browser/embed/embed.html');
  const view = await webgpuElement(page, {}, true);
  expect(view.status).toEqual({ renderer: 'webgpu', backend: 'WebGPU', fallback: null, notDrawn: [] });
  expect(view.framesDrawn).toBe(0); // below the fold: it holds its renderer and does not draw
  expectSkyOverWaves(picture(view.width, view.height, view.data, 'shells-element-webgpu'), 'element, WebGPU backend');
  const freed = await removeElement(page);
  expect(freed).toEqual({ oceanDisposed: true, canvasGone: true, heldAfter: false, deviceLost: 'destroyed' });
  expect(log.errors).toEqual([]);
});

for (const backend of ['WebGPU', 'WebGL2'] as const) {
  test(`<fft-ocean renderer="webgpu"> on the ${backend} backend whose device is lost says so, makes a new renderer and Ocean at the same time, and draws sky over waves again`, async ({ page }) => {
    const log = await open(page, '/tests/browser/embed/embed.html', backend === 'WebGL2');
    await expect(page).toHaveTitle('ready');
    // Below the fold on the WebGPU backend: headless, a WebGPU canvas loses its device once a frame is presented (../shared/BROWSER.md).
    const first = await webgpuElement(page, {}, backend === 'WebGPU');
    expect(first.status.backend).toBe(backend);
    const recovery = await page.evaluate(async () => {
      const el = document.querySelector('fft-ocean')!;
      const [renderer, ocean, canvas] = [el.webgpuRenderer!, el.webgpuOcean!, el.canvas!];
      const lost = new Promise((resolve) => el.addEventListener('fft-ocean-device-lost', (event) => resolve((event as CustomEvent).detail), { once: true }));
      const restarted = new Promise<RendererStatus>((resolve) => el.addEventListener('fft-ocean-renderer', (event) => resolve((event as CustomEvent<RendererStatus>).detail), { once: true }));
      const backend = renderer.backend as { isWebGPUBackend?: boolean; device?: GPUDevice };
      // What a browser does to a device it drops: here by hand (the WebGPU backend: destroy(); WebGL2: WEBGL_lose_context).
      if (backend.isWebGPUBackend) backend.device!.destroy();
      else (renderer.getContext() as WebGL2RenderingContext).getExtension('WEBGL_lose_context')!.loseContext();
      const loss = await lost;
      const status = await restarted;
      let oldOceanDisposed = false;
      try {
        void ocean.time;
      } catch (error) {
        oldOceanDisposed = (error as Error).name === 'DisposedError';
      }
      return {
        loss,
        status,
        newRenderer: el.webgpuRenderer !== null && el.webgpuRenderer !== renderer,
        newOcean: el.webgpuOcean !== null && el.webgpuOcean !== ocean,
        oldOceanDisposed,
        oldCanvasGone: !canvas.isConnected,
        canvases: el.shadowRoot!.querySelectorAll('canvas').length,
        time: el.time,
        message: el.shadowRoot!.textContent,
      };
    });
    console.log(`element, ${backend} backend, device lost: ${JSON.stringify(recovery)}`);
    expect(recovery).toMatchObject({ status: { renderer: 'webgpu', backend }, newRenderer: true, newOcean: true, oldOceanDisposed: true, oldCanvasGone: true, canvases: 1, time: 3 });
    expect(recovery.loss).toMatchObject(backend === 'WebGPU' ? { api: 'WebGPU', reason: 'destroyed' } : { api: 'WebGL2', reason: 'context lost' });
    expect(log.warnings.filter((text) => text.includes('was lost'))).toHaveLength(1);
    const again = await elementView(page, backend === 'WebGPU');
    expectSkyOverWaves(picture(again.width, again.height, again.data, `shells-element-recovered-${backend}`), `element, ${backend} backend, after a lost device`);
    const freed = await removeElement(page);
    expect(freed).toMatchObject({ oceanDisposed: true, canvasGone: true, heldAfter: false });
    expect(log.errors).toEqual([]);
  });
}

test('without WebGPU, <fft-ocean renderer="webgpu"> draws on the WebGL2 backend and says so; what it does not draw yet is left out with a warning', async ({ page }) => {
  const log = await open(page, '/tests/browser/embed/embed.html', true);
  await expect(page).toHaveTitle('ready');
  const view = await webgpuElement(page, { 'shading-mode': 'height', boat: '', 'wind-speed': '14', quality: 'low' });
  // QUALITY_STEPS.low on the WebGPU Ocean: N at most 64 (asked 64), the two largest cascades, render scale 0.5.
  const quality = await page.evaluate(() => {
    const el = document.querySelector('fft-ocean')!;
    return { cascades: el.webgpuOcean!.parameters.patchSizes.length, pixelRatio: el.webgpuRenderer!.getPixelRatio() / Math.min(devicePixelRatio || 1, 2) };
  });
  expect(quality).toEqual({ cascades: 2, pixelRatio: 0.5 });
  expect(view.status.renderer).toBe('webgpu');
  expect(view.status.backend).toBe('WebGL2');
  expect(view.status.fallback).toBe('this browser has no WebGPU (navigator.gpu is undefined)');
  expect(view.status.notDrawn.map(({ name }) => name)).toEqual(['shadingMode', 'boat']);
  expect(log.infos.filter((text) => text.includes('WebGL2 backend'))).toEqual(['three-fft-ocean/webgpu: this browser has no WebGPU (navigator.gpu is undefined): WebGPURenderer draws with its WebGL2 backend.']);
  expect(log.warnings.some((text) => text.startsWith('<fft-ocean renderer="webgpu">: left out') && text.includes('shadingMode') && text.includes('boat'))).toBe(true);
  expectSkyOverWaves(picture(view.width, view.height, view.data, 'shells-element-webgl2-backend'), 'element, WebGL2 backend');
  // The canvas itself shows it too (the WebGL2 backend presents to a canvas here).
  await page.locator('fft-ocean').screenshot({ path: '.tmp/shells-element-webgl2-canvas.png' });
  // A new wind speed makes a new Ocean, with another sea at the same time.
  const before = await page.evaluate(() => {
    const el = document.querySelector('fft-ocean')!;
    (window as unknown as { previousOcean: unknown }).previousOcean = el.webgpuOcean;
    const height = el.webgpuOcean!.heightAt(1, 2);
    el.setAttribute('wind-speed', '6');
    return height;
  });
  await page.waitForFunction(() => {
    const ocean = document.querySelector('fft-ocean')!.webgpuOcean;
    return ocean !== null && ocean !== (window as unknown as { previousOcean: unknown }).previousOcean;
  });
  const after = await page.evaluate(() => {
    const el = document.querySelector('fft-ocean')!;
    el.renderFrame(); // the new ocean at the same time (paused)
    return el.webgpuOcean!.heightAt(1, 2);
  });
  expect(after).not.toBe(before);
  const freed = await removeElement(page);
  expect(freed).toMatchObject({ oceanDisposed: true, canvasGone: true, heldAfter: false });
  expect(log.errors).toEqual([]);
});

test('a changed renderer attribute makes the renderer again: WebGL to WebGPURenderer (its WebGL2 backend here), the WebGL context given back; a bad value is refused by name', async ({ page }) => {
  const log = await open(page, '/tests/browser/embed/embed.html', true);
  await expect(page).toHaveTitle('ready');
  const result = await page.evaluate(async () => {
    const el = window.embed.create({ resolution: '64' });
    await window.embed.drawn(el, 1);
    const webglContext = el.renderer!.getContext();
    const started = new Promise<RendererStatus>((resolve) => el.addEventListener('fft-ocean-renderer', (event) => resolve((event as CustomEvent<RendererStatus>).detail)));
    el.setAttribute('renderer', 'webgpu');
    const status = await started;
    const framesBefore = el.frameCount;
    await window.embed.drawn(el, framesBefore + 2);
    el.setAttribute('renderer', 'vulkan');
    return {
      status,
      webglContextLost: webglContext.isContextLost(),
      webgl: el.renderer === null && el.ocean === null && el.output === null,
      webgpu: el.webgpuRenderer !== null && el.webgpuOcean !== null,
      canvases: el.shadowRoot!.querySelectorAll('canvas').length,
      statusAfterBadValue: el.rendererStatus?.renderer,
    };
  });
  expect(result).toEqual({
    status: { renderer: 'webgpu', backend: 'WebGL2', fallback: 'this browser has no WebGPU (navigator.gpu is undefined)', notDrawn: [] },
    webglContextLost: true,
    webgl: true,
    webgpu: true,
    canvases: 1,
    statusAfterBadValue: 'webgpu',
  });
  expect(log.warnings).toContain(`<fft-ocean>: ignoring renderer="vulkan": renderer must be 'webgl' or 'webgpu'; got "vulkan"; keeping webgpu`);
  expect(log.errors).toEqual([]);
});

test('the app with ?renderer=webgpu and no WebGPU draws the sea on the WebGL2 backend, says so, turns off what it cannot draw yet, and holds the quality level', async ({ page }) => {
  await page.setViewportSize({ width: 640, height: 360 });
  const log = await open(page, '/?renderer=webgpu&resolution=64&mode=height&buoys=1&paused=1&t=3&quality=lowest', true);
  await page.waitForFunction(() => (window.oceanAppWebGPU?.framesDrawn ?? 0) >= 2, undefined, { timeout: 60_000 });
  const app = await page.evaluate(() => ({
    backend: window.oceanAppWebGPU.backend,
    notDrawn: window.oceanAppWebGPU.notDrawn.map(({ name }) => name),
    status: document.querySelector('.status-line')!.textContent,
    notices: [...document.querySelectorAll('.notice')].map((notice) => (notice as HTMLElement).dataset.parameter),
    // QUALITY_STEPS.lowest: render scale 0.3, N at most 32, the two largest cascades, rings of 16 cells at least.
    quality: {
      pixelRatio: window.oceanAppWebGPU.renderer.getPixelRatio() / Math.min(devicePixelRatio, 2),
      resolution: window.oceanAppWebGPU.ocean.parameters.resolution,
      cascades: window.oceanAppWebGPU.ocean.parameters.patchSizes.length,
      fewestCellsPerRing: window.oceanAppWebGPU.ocean.fewestCellsPerRing,
    },
  }));
  expect(app.quality).toEqual({ pixelRatio: 0.3, resolution: 32, cascades: 2, fewestCellsPerRing: 16 });
  expect(app.backend).toBe('WebGL2');
  // The app's JS FFT runs in workers (its worker option's default).
  expect(app.status).toBe(
    "WebGPURenderer, WebGL2 backend (this browser has no WebGPU (navigator.gpu is undefined)) · three-fft-ocean/webgpu · FFT: JS in a worker (WebGPURenderer's WebGL2 backend runs no compute shaders) · quality lowest",
  );
  expect(app.notDrawn).toEqual(['shadingMode']);
  expect(app.notices).toEqual(['buoys', 'shadingMode']);
  await page.screenshot({ path: '.tmp/shells-app-webgl2-backend.png' });
  expectSkyOverWaves(PNG.sync.read(await page.locator('#app canvas').screenshot()), 'app, WebGL2 backend');
  expect(log.errors).toEqual([]);
});

test('the app with ?renderer=webgpu opens on the WebGPU backend without page errors', async ({ page }) => {
  const log = await open(page, '/?renderer=webgpu&resolution=64');
  await page.waitForFunction(() => (window.oceanAppWebGPU?.framesDrawn ?? 0) >= 1, undefined, { timeout: 60_000 });
  const app = await page.evaluate(() => ({ backend: window.oceanAppWebGPU.backend, notDrawn: window.oceanAppWebGPU.notDrawn, status: document.querySelector('.status-line')!.textContent }));
  // The quality level is 'auto''s, whichever it holds now.
  expect(app).toMatchObject({ backend: 'WebGPU', notDrawn: [] });
  // SwiftShader's WebGPU adapter is a software one: 'auto' takes the JS FFT there (computeSupport.ts).
  expect(app.status).toMatch(/^WebGPURenderer, WebGPU backend · three-fft-ocean\/webgpu · FFT: JS in a worker \(a software WebGPU adapter \(swiftshader\), where the JS FFT is faster; path 'gpu' runs the compute FFT\) · quality (high|medium|low|lowest) \(auto\)$/);
  expect(log.errors).toEqual([]);
});
