import { expect, test, type Page } from '@playwright/test';
import { existsSync, readdirSync, readFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import type { DataTexture, WebGLRenderer } from 'three';
import type { FftOceanElement } from '../../../src/embed/fftOceanElement';
import type { Ocean } from '../../../src/ocean';
import { DEFAULT_PARAMETERS } from '../../../src/parameters/parameters';
import { PNG } from 'pngjs';
import { serveDirectory } from '../../../scripts/static-server.mjs';
import { ensureBuiltLibrary } from '../shared/builtLibrary';

// The example pages (served by Vite, as in the app build) and the built library (dist/lib)
// loaded by a plain page through an import map.

declare global {
  interface Window {
    lib: { Ocean: typeof Ocean; FftOceanElement: typeof FftOceanElement; WebGLRenderer: typeof WebGLRenderer; defined: boolean };
  }
}

function collectErrors(page: Page): string[] {
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(error.message));
  page.on('console', (message) => {
    // Resource 404s (e.g. a favicon) are not the page's fault; everything else is.
    if (message.type() === 'error' && !message.text().startsWith('Failed to load resource')) errors.push(message.text());
  });
  return errors;
}

/** Opens the gallery and follows its link to `name`, as a visitor does. */
async function openFromGallery(page: Page, name: string): Promise<void> {
  await page.goto('/examples/index.html');
  await page.click(`.gallery a[href="./${name}"]`);
  await page.waitForURL(`**/examples/${name}`);
}

/** Whether an RGBA picture is drawn: not black (a mean above 30 of 255) and not one flat colour (a spread above 30). */
function drawnPicture({ width, height, data }: { width: number; height: number; data: Buffer }): { mean: boolean; varied: boolean } {
  let sum = 0;
  let min = 255;
  let max = 0;
  for (let i = 0; i < width * height; i++) {
    const value = (data[4 * i] + data[4 * i + 1] + data[4 * i + 2]) / 3;
    sum += value;
    min = Math.min(min, value);
    max = Math.max(max, value);
  }
  return { mean: sum / (width * height) > 30, varied: max - min > 30 };
}

/** A canvas's picture as the page encodes it (canvas.toDataURL), decoded. */
const decodeDataUrl = (dataUrl: string) => PNG.sync.read(Buffer.from(dataUrl.slice(dataUrl.indexOf(',') + 1), 'base64'));

/** Waits until the page's first canvas shows a picture: neither black nor one flat colour. */
async function expectAPicture(page: Page, name: string): Promise<void> {
  const canvas = page.locator('canvas').first();
  await canvas.waitFor({ timeout: 60_000 });
  await expect
    .poll(async () => drawnPicture(PNG.sync.read(await canvas.screenshot())), { timeout: 60_000, message: `${name}: a picture, not a black or flat canvas` })
    .toEqual({ mean: true, varied: true });
}

/**
 * The example pages whose own tests below open them from the gallery and check their first
 * canvas's picture as the gallery's test of the other pages does (drawnPicture, here of the canvas
 * right after a render: a screenshot of three live seas at 1000×1400 took a minute under load).
 * The gallery's loop leaves them out: each load of an example compiles its shaders again under
 * SwiftShader, seconds a page.
 */
const OPENED_BY_OWN_TEST = ['element.html', 'three-scene.html'];

test('element.html, opened from the gallery: three <fft-ocean>s among page content, sized by the page, all drawing', async ({ page }) => {
  const errors = collectErrors(page);
  await page.setViewportSize({ width: 1000, height: 1400 }); // all three on screen
  await openFromGallery(page, 'element.html');
  const result = await page.evaluate(async () => {
    await customElements.whenDefined('fft-ocean');
    const elements = [...document.querySelectorAll('fft-ocean')];
    const start = performance.now();
    while (elements.some((el) => el.frameCount < 2) && performance.now() - start < 60_000) {
      await new Promise((resolve) => requestAnimationFrame(resolve));
    }
    const main = document.querySelector('main')!;
    const style = getComputedStyle(main);
    const contentRight = main.getBoundingClientRect().right - parseFloat(style.paddingRight);
    return {
      contentWidth: main.clientWidth - parseFloat(style.paddingLeft) - parseFloat(style.paddingRight),
      contentRight,
      elements: elements.map((el) => {
        const box = el.getBoundingClientRect();
        el.renderFrame();
        const gl = el.renderer!.getContext();
        const pixel = new Uint8Array(4);
        // A pixel of sky (near the top) and one of sea (near the bottom).
        gl.readPixels(gl.drawingBufferWidth >> 1, gl.drawingBufferHeight - 5, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
        const sky = [...pixel];
        gl.readPixels(gl.drawingBufferWidth >> 1, 5, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
        return { id: el.id, width: box.width, height: box.height, right: box.right, frames: el.frameCount, wind: el.ocean!.parameters.windSpeed, sky, sea: [...pixel] };
      }),
      // The first canvas (the hero's) right after its render above, as the gallery's test reads a page.
      firstCanvas: elements[0].shadowRoot!.querySelector('canvas')!.toDataURL('image/png'),
    };
  });
  const [hero, calm, storm] = result.elements;
  expect(result.elements.map((el) => el.id)).toEqual(['hero', 'calm', 'storm']);
  // No size given: the column's width at 16:9.
  expect(hero.width).toBeCloseTo(result.contentWidth, 0);
  expect(hero.height).toBeCloseTo((result.contentWidth * 9) / 16, 0);
  // 220 px high side by side, inside the column.
  for (const el of [calm, storm]) {
    expect(el.height).toBe(220);
    expect(el.width).toBeLessThan(result.contentWidth / 2);
    expect(el.right).toBeLessThanOrEqual(result.contentRight + 0.5);
  }
  expect([hero.wind, calm.wind, storm.wind]).toEqual([DEFAULT_PARAMETERS.windSpeed, 4, 26]); // the hero has no attributes
  for (const el of result.elements) {
    expect(el.frames, el.id).toBeGreaterThanOrEqual(2);
    expect(Math.max(...el.sky.slice(0, 3)), `${el.id} sky`).toBeGreaterThan(120); // a bright sky, not a black box
    expect(Math.min(...el.sea.slice(0, 3)), `${el.id} sea`).toBeLessThan(Math.max(...el.sky.slice(0, 3)));
  }
  expect(drawnPicture(decodeDataUrl(result.firstCanvas)), 'element.html: a picture, not a black or flat canvas').toEqual({ mean: true, varied: true });
  expect(errors).toEqual([]);
});

test('three-scene.html, opened from the gallery: the ocean in a plain three.js scene, a crate floating on it (FloatingBody over heightAt)', async ({ page }) => {
  const errors = collectErrors(page);
  await page.setViewportSize({ width: 480, height: 270 });
  await openFromGallery(page, 'three-scene.html');
  await page.waitForFunction(() => window.example?.frames() > 2, null, { timeout: 60_000 });
  const result = await page.evaluate(async () => {
    const { ocean, crate, crateBody, scene, renderer, camera } = window.example;
    const samples: { t: number; y: number; draft: number; restingDraft: number; tilt: number }[] = [];
    for (let i = 0; i < 2; i++) {
      await new Promise((resolve) => setTimeout(resolve, 700));
      await new Promise((resolve) => requestAnimationFrame(resolve));
      // The crate was moved in this frame's loop, at the ocean's time of this frame; its bottom is 0.5 m below its centre.
      const draft = ocean.heightAt(crate.position.x, crate.position.z) - (crate.position.y - 0.5);
      samples.push({ t: ocean.time, y: crate.position.y, draft, restingDraft: crateBody.restingDraft, tilt: 2 * Math.acos(Math.min(1, Math.abs(crate.quaternion.w))) });
    }
    renderer.render(scene, camera);
    const gl = renderer.getContext();
    const pixel = new Uint8Array(4);
    gl.readPixels(gl.drawingBufferWidth >> 1, gl.drawingBufferHeight - 3, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
    const picture = renderer.domElement.toDataURL('image/png'); // right after the render: the drawing buffer is still there
    return { samples, background: ocean.skyBackground.parent === ocean && ocean.parent === scene, sky: [...pixel], picture };
  });
  for (const { draft, restingDraft, tilt } of result.samples) {
    // Afloat: the water stands part way up its 1 m side, neither under it nor over it. (At rest the
    // draft is 0.24 m; the waves and the crate's lag behind them move it.)
    expect(restingDraft).toBeCloseTo(1000 / (1025 * 4), 12);
    expect(draft).toBeGreaterThan(0);
    expect(draft).toBeLessThan(1);
    expect(tilt).toBeGreaterThan(0); // tilted with the slope
    expect(tilt).toBeLessThan(0.6);
  }
  const [a, b] = result.samples;
  expect(b.t).toBeGreaterThan(a.t);
  expect(Math.abs(b.y - a.y)).toBeGreaterThan(1e-3); // it bobs
  expect(result.background).toBe(true);
  expect(Math.max(...result.sky.slice(0, 3))).toBeGreaterThan(120);
  expect(drawnPicture(decodeDataUrl(result.picture)), 'three-scene.html: a picture, not a black or flat canvas').toEqual({ mean: true, varied: true });
  expect(errors).toEqual([]);
});

test.describe('the gallery (examples/index.html)', () => {
  const examples = resolve(import.meta.dirname, '../../../examples');
  /** Every example page: each examples/*.html but the gallery itself. */
  const pages = readdirSync(examples)
    .filter((name) => name.endsWith('.html') && name !== 'index.html')
    .sort();

  test('lists every example page, each with its thumbnail (320×180, loaded)', async ({ page }) => {
    const errors = collectErrors(page);
    await page.goto('/examples/index.html');
    await page.waitForFunction(() => [...document.images].every((image) => image.complete));
    const cards = await page.evaluate(() =>
      [...document.querySelectorAll('.gallery li')].map((card) => {
        const image = card.querySelector('img')!;
        return {
          href: card.querySelector('a')?.getAttribute('href') ?? null,
          src: image.getAttribute('src')!,
          size: [image.naturalWidth, image.naturalHeight],
          text: card.querySelector('p')!.textContent!.trim(),
        };
      }),
    );
    const linked = cards.flatMap((card) => (card.href ? [card.href.replace(/^\.\//, '')] : []));
    expect(linked.sort(), 'the pages the gallery links to').toEqual(pages);
    // Every card (the react-three-fiber one too, which is not served here) has a picture and a sentence.
    expect(cards.length).toBeGreaterThanOrEqual(pages.length);
    for (const card of cards) {
      expect(card.src, card.href ?? card.src).toMatch(/^\.\/thumbnails\/[\w-]+\.png$/);
      expect(existsSync(join(examples, card.src)), card.src).toBe(true);
      expect(card.size, `${card.src} loaded at its size`).toEqual([320, 180]);
      expect(card.text.length, `${card.src}: a sentence`).toBeGreaterThan(40);
    }
    expect(errors).toEqual([]);
  });

  test("the app's Examples link opens the gallery", async ({ page }) => {
    const errors = collectErrors(page);
    // The smallest sea the app draws (its default of N = 256 at 640×360 took seconds to load under
    // SwiftShader): the test is about the link.
    await page.setViewportSize({ width: 320, height: 180 });
    await page.goto('/?resolution=32&quality=high');
    await page.click('#status .status-links a');
    await page.waitForURL('**/examples/index.html');
    await expect(page).toHaveTitle(/^Examples/);
    expect(errors).toEqual([]);
  });

  // Each page the gallery links to, opened from it, is drawn: here, or in its own test above.
  for (const name of pages.filter((page) => !OPENED_BY_OWN_TEST.includes(page))) {
    test(`${name}, opened from the gallery, draws a picture without errors`, async ({ page }) => {
      const errors = collectErrors(page);
      await page.setViewportSize({ width: 480, height: 270 });
      await openFromGallery(page, name);
      await expectAPicture(page, name);
      expect(errors).toEqual([]);
    });
  }
  test('the pages with their own test are example pages the gallery links to', () => {
    for (const name of OPENED_BY_OWN_TEST) expect(pages).toContain(name);
  });
});

test.describe('the built library (dist/lib) in a page without a bundler', () => {
  const root = resolve(import.meta.dirname, '../../..');

  test.beforeAll(() => {
    // This part tests build output, so it builds the library first when it is missing or stale.
    ensureBuiltLibrary();
  });

  test('the bundle keeps three.js external and carries the shaders, the worker and the types', () => {
    const files = readdirSync(join(root, 'dist/lib')).filter((name) => name.endsWith('.js'));
    const code = files.map((name) => readFileSync(join(root, 'dist/lib', name), 'utf8')).join('\n');
    expect(code).toMatch(/from "three"/);
    expect(code).not.toContain('REVISION = '); // three.js itself is not bundled
    expect(code).toContain('void main'); // GLSL sources as strings
    expect(code).toMatch(/new URL\("assets\/waveFieldWorker-[\w-]+\.js", import\.meta\.url\)/); // relative, not site-root
    const pkg = JSON.parse(readFileSync(join(root, 'package.json'), 'utf8'));
    for (const entry of Object.values(pkg.exports as Record<string, string | Record<string, string>>)) {
      for (const file of typeof entry === 'string' ? [entry] : Object.values(entry)) expect(existsSync(join(root, file)), file).toBe(true);
    }
    expect(pkg.peerDependencies.three).toBeTruthy();
  });

  test('imported through an import map, <fft-ocean> and Ocean render, and the JS worker path runs', async ({ page }) => {
    const server = await serveDirectory(root);
    try {
      const errors = collectErrors(page);
      await page.goto(`${server.url}/tests/browser/examples/lib-import-map.html`);
      await expect(page).toHaveTitle('ready');
      const result = await page.evaluate(async () => {
        const el = document.querySelector('fft-ocean')!;
        const start = performance.now();
        while (el.frameCount < 2 && performance.now() - start < 30_000) await new Promise((resolve) => requestAnimationFrame(resolve));
        el.renderFrame();
        const gl = el.renderer!.getContext();
        const pixel = new Uint8Array(4);
        gl.readPixels(gl.drawingBufferWidth >> 1, gl.drawingBufferHeight - 5, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);

        // The JS path in its Web Worker, loaded from dist/lib/assets next to the bundle.
        const renderer = new window.lib.WebGLRenderer();
        const ocean = new window.lib.Ocean(renderer, { resolution: 32, path: 'js', worker: true });
        const field = () => (ocean.simulation.cascades[0].textures.displacement.value as DataTexture).image.data as Float32Array;
        // Updates until fields are in, however long the worker takes to start here: the ocean gives
        // up on a worker silent for 20 s (fieldWorker.ts) and computes them itself, and the path
        // is then not 'js-worker'.
        let workerResult = false;
        for (let i = 0; !workerResult; i++) {
          ocean.update(3 + i * 0.01);
          await new Promise((resolve) => setTimeout(resolve, 50));
          workerResult = field().some((value) => value !== 0);
        }
        const path = ocean.simulation.path;
        ocean.dispose();
        renderer.dispose();
        return { defined: window.lib.defined, frames: el.frameCount, sky: [...pixel], path, workerResult };
      });
      expect(result.defined).toBe(true);
      expect(result.frames).toBeGreaterThanOrEqual(2);
      expect(Math.max(...result.sky.slice(0, 3))).toBeGreaterThan(120);
      expect(result.path).toBe('js-worker');
      expect(result.workerResult).toBe(true);
      expect(errors).toEqual([]);
    } finally {
      await server.close();
    }
  });
});
