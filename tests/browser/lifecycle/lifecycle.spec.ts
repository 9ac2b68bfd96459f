import { expect, test, type Page } from '@playwright/test';
import type { WebGLRenderer } from 'three';
import type { FftOceanElement } from '../../../src/embed/fftOceanElement';
import { ALSO_ON_OLDEST_THREE } from '../shared/threeRange';

declare global {
  interface Window {
    /** Objects the tests below keep between page.evaluate calls. */
    lifecycle: { renderer: WebGLRenderer; canvas: HTMLCanvasElement; memory: () => Record<string, number>; cycle: (i: number) => boolean };
    removed: { el: FftOceanElement; renderer: WebGLRenderer; canvas: HTMLCanvasElement; gl: WebGL2RenderingContext };
  }
}

// Creating and freeing: Ocean objects on one renderer, <fft-ocean> taken out of and put back into
// the page, and a lost and restored WebGL context. GPU memory is read from renderer.info.memory
// (three.js's count of live geometries and textures); listeners from Chromium's DevTools protocol.

async function openPage(page: Page): Promise<string[]> {
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(error.message));
  await page.goto('/tests/browser/embed/embed.html');
  await expect(page).toHaveTitle('ready');
  return errors;
}

/** Event listeners on the object `expression` evaluates to (of one type, or all). */
async function listeners(page: Page, expression: string, type?: string): Promise<number> {
  const cdp = await page.context().newCDPSession(page);
  try {
    const { result } = await cdp.send('Runtime.evaluate', { expression });
    const { listeners } = await cdp.send('DOMDebugger.getEventListeners', { objectId: result.objectId! });
    return listeners.filter((listener) => type === undefined || listener.type === type).length;
  } finally {
    await cdp.detach();
  }
}

test('50 Ocean create/dispose cycles on one renderer (with their refraction captures) leave GPU memory and listeners at baseline', async ({ page }) => {
  const errors = await openPage(page);
  await page.evaluate(() => {
    const { Ocean, WebGLRenderer, Scene, PerspectiveCamera, Mesh, BoxGeometry, MeshBasicMaterial } = window.embed;
    const renderer = new WebGLRenderer();
    renderer.setSize(160, 90);
    document.body.append(renderer.domElement);
    const scene = new Scene();
    const camera = new PerspectiveCamera(50, 16 / 9, 0.5, 1e5);
    camera.position.set(0, 8, 0);
    camera.lookAt(50, 0, -50);
    // A box in the water: a scene of nothing but the sea draws no capture (sceneCapture.ts, holdsOnlySeas).
    const box = new Mesh(new BoxGeometry(4, 4, 4), new MeshBasicMaterial({ color: 0xff0000 }));
    box.position.set(30, 0, -30);
    scene.add(box);
    renderer.render(scene, camera); // the box alone: its geometry is in every count below
    const memory = () => ({ ...renderer.info.memory, programs: renderer.info.programs!.length });
    /**
     * One ocean's whole life, alternately on the GPU and the (synchronous) JS path, with its scene
     * capture for the refractions ('scene', the default); whether it drew the capture.
     */
    const cycle = (i: number) => {
      // The reflection's target has its own test below; left out here, it would add a render per frame.
      const ocean = new Ocean(renderer, { resolution: 32, seed: i, path: i % 2 ? 'js' : 'auto', worker: false, reflections: 'sky' });
      scene.add(ocean);
      // A hull that moves 3 m in the next half second: it makes waves and foam (hullFoam.ts).
      const hull = ocean.localWaves!.addPressure({ length: 8, beam: 2.6, draft: 0.6 }, { x: 0, z: -20, heading: 0 });
      ocean.update(1.5 + i);
      renderer.render(scene, camera);
      ocean.setParameters({ windSpeed: 10 + (i % 5) }); // rebuilds the simulation's textures
      ocean.setSun(20 + i, 40); // re-renders the sky cube
      hull.setPose(3, -20, 0);
      ocean.update(2 + i);
      renderer.render(scene, camera);
      ocean.heightAt(1, 2);
      const captured = ocean.surface.refraction.renderTarget !== null;
      scene.remove(ocean);
      ocean.dispose();
      return captured;
    };
    window.lifecycle = { renderer, memory, cycle, canvas: renderer.domElement };
  });
  const canvasListeners = await listeners(page, 'window.lifecycle.canvas');
  const result = await page.evaluate(() => {
    const { memory, cycle } = window.lifecycle;
    const empty = memory();
    // One warm-up cycle: the first render sets up three.js's own state.
    const captures = [cycle(0)];
    const baseline = memory();
    for (let i = 1; i <= 50; i++) captures.push(cycle(i));
    return { empty, baseline, after: memory(), captures };
  });
  // Every ocean drew its scene capture (a colour and a depth texture), and freed it with the rest.
  expect(result.captures.every((captured) => captured)).toBe(true);
  expect(result.empty).toMatchObject({ geometries: 1, textures: 0 });
  expect(result.baseline.geometries).toBeLessThanOrEqual(2);
  expect(result.baseline.textures).toBe(0);
  expect(result.after).toEqual(result.baseline);
  // Every listener the oceans added to the canvas (the sky's context-restore one) is gone.
  expect(await listeners(page, 'window.lifecycle.canvas')).toBe(canvasListeners);
  expect(errors).toEqual([]);
});

test('an Ocean reflecting the scene holds its reflection target while it reflects and frees it with the sea', async ({ page }) => {
  const errors = await openPage(page);
  const result = await page.evaluate(() => {
    const { Ocean, WebGLRenderer, Scene, PerspectiveCamera, Mesh, BoxGeometry, MeshBasicMaterial } = window.embed;
    const renderer = new WebGLRenderer();
    renderer.setSize(160, 90);
    const scene = new Scene();
    const camera = new PerspectiveCamera(50, 16 / 9, 0.5, 1e5);
    camera.position.set(0, 8, 0);
    camera.lookAt(0, 0, -50);
    const box = new Mesh(new BoxGeometry(4, 4, 4), new MeshBasicMaterial({ color: 0xff0000 }));
    box.position.set(0, 3, -40);
    scene.add(box);
    const textures = () => renderer.info.memory.textures;
    /** One sea's life: the textures it holds reflecting the box, and after its reflection is turned off. */
    const cycle = (i: number) => {
      const ocean = new Ocean(renderer, { resolution: 32, seed: i, localWaves: false, worker: false });
      scene.add(ocean);
      ocean.update(2 + i);
      renderer.render(scene, camera);
      const reflecting = textures();
      ocean.setShading({ reflections: 'sky' });
      renderer.render(scene, camera);
      const sky = textures();
      ocean.setShading({ reflections: 'scene' });
      renderer.render(scene, camera);
      scene.remove(ocean);
      ocean.dispose();
      return { reflecting, sky };
    };
    renderer.render(scene, camera); // the box alone
    const baseline = { ...renderer.info.memory };
    const lives = [0, 1, 2].map(cycle);
    const after = { ...renderer.info.memory };
    box.geometry.dispose();
    box.material.dispose();
    renderer.dispose();
    return { baseline, lives, after };
  });
  // The reflection's render target is two textures (its colour and its depth), freed when the sea
  // shows only its sky, and with the sea.
  for (const { reflecting, sky } of result.lives) expect(reflecting - sky).toBe(2);
  expect(result.after).toEqual(result.baseline);
  expect(errors).toEqual([]);
});

test('a parameter change reuses the compiled shaders, and what it replaced is freed after the next update', async ({ page }) => {
  const errors = await openPage(page);
  const result = await page.evaluate(() => {
    const { Ocean, WebGLRenderer, Scene, PerspectiveCamera } = window.embed;
    const renderer = new WebGLRenderer();
    renderer.setSize(160, 90);
    const scene = new Scene();
    const camera = new PerspectiveCamera(50, 16 / 9, 0.5, 1e5);
    camera.position.set(0, 8, 0);
    camera.lookAt(50, 0, -50);
    const ocean = new Ocean(renderer, { resolution: 64, seed: 3, path: 'gpu', localWaves: false });
    scene.add(ocean);
    let t = 4;
    const frame = () => {
      ocean.update((t += 0.1));
      renderer.render(scene, camera);
    };
    // The programs three.js holds (each compiled once), and the live textures and geometries.
    const state = () => ({ programs: renderer.info.programs!.map((program) => program.id).sort((a, b) => a - b), ...renderer.info.memory });
    frame();
    frame();
    const before = state();
    ocean.setParameters({ windSpeed: 14 }); // new spectra: new cascades and foam
    const replacedStillHeld = renderer.info.memory.textures;
    frame();
    const afterOne = state();
    // Two changes without an update between: the first one's cascades never drew.
    ocean.setParameters({ windSpeed: 9 });
    ocean.setParameters({ windSpeed: 11 });
    frame();
    const afterTwo = state();
    ocean.dispose();
    renderer.dispose();
    return { before, replacedStillHeld, afterOne, afterTwo };
  });
  // The same programs: none deleted and compiled again (three.js keeps one while a material uses it).
  expect(result.afterOne.programs).toEqual(result.before.programs);
  expect(result.afterTwo.programs).toEqual(result.before.programs);
  // Until the next update both seas' textures live; after it, as many as before.
  expect(result.replacedStillHeld).toBeGreaterThan(result.before.textures);
  expect(result.afterOne).toEqual(result.before);
  expect(result.afterTwo).toEqual(result.before);
  expect(errors).toEqual([]);
});

test('removing <fft-ocean> frees its renderer, context, canvas and listeners; putting it back starts again', async ({ page }) => {
  const errors = await openPage(page);
  const documentListeners = await listeners(page, 'document', 'visibilitychange');
  const running = await page.evaluate(async () => {
    const el = window.embed.create({ resolution: '64' });
    await window.embed.drawn(el, 3);
    window.removed = { el, renderer: el.renderer!, canvas: el.canvas!, gl: el.renderer!.getContext() as WebGL2RenderingContext };
    return { memory: { ...el.renderer!.info.memory } };
  });
  expect(running.memory.textures).toBeGreaterThan(0);
  expect(await listeners(page, 'document', 'visibilitychange')).toBe(documentListeners + 1);
  expect(await listeners(page, 'window.removed.canvas', 'webglcontextrestored')).toBe(4); // three.js, the sky, the GPU foam, the element

  const removed = await page.evaluate(async () => {
    const { el, renderer, canvas, gl } = window.removed;
    el.remove();
    await new Promise((resolve) => setTimeout(resolve, 50));
    const frames = el.frameCount;
    await new Promise((resolve) => setTimeout(resolve, 500));
    return {
      memory: { ...renderer.info.memory },
      contextLost: gl.isContextLost(),
      canvasInShadowRoot: el.shadowRoot!.querySelector('canvas') !== null,
      canvasConnected: canvas.isConnected,
      ocean: el.ocean,
      renderer: el.renderer,
      framesAfterRemoval: el.frameCount - frames,
      time: el.time,
    };
  });
  expect(removed.memory).toMatchObject({ geometries: 0, textures: 0 });
  expect(removed.contextLost).toBe(true); // given back at once, not at garbage collection
  expect(removed.canvasInShadowRoot).toBe(false);
  expect(removed.canvasConnected).toBe(false);
  expect(removed.ocean).toBeNull();
  expect(removed.renderer).toBeNull();
  expect(removed.framesAfterRemoval).toBe(0);
  expect(await listeners(page, 'document', 'visibilitychange')).toBe(documentListeners);
  expect(await listeners(page, 'window.removed.canvas')).toBe(0);

  const back = await page.evaluate(async () => {
    const { el, canvas } = window.removed;
    const timeAtRemoval = el.time;
    const putBack = performance.now();
    document.querySelector('#box')!.append(el);
    await window.embed.drawn(el, el.frameCount + 3);
    const rendererBeforeMove = el.renderer;
    // A move within the page (out and in within one task) keeps everything.
    el.parentElement!.append(document.createElement('p'), el);
    await window.embed.frames(2);
    return {
      newCanvas: el.canvas !== null && el.canvas !== canvas,
      canvases: el.shadowRoot!.querySelectorAll('canvas').length,
      // From where it was, by at most the real time since it came back (not the time it was away).
      timeContinued: el.time >= timeAtRemoval && el.time - timeAtRemoval <= (performance.now() - putBack) / 1000 + 1e-3,
      keptOnMove: el.renderer === rendererBeforeMove,
      pixels: window.embed.pixels(el),
    };
  });
  expect(back.newCanvas).toBe(true);
  expect(back.canvases).toBe(1);
  expect(back.timeContinued).toBe(true);
  expect(back.keptOnMove).toBe(true);
  expect(back.pixels.mean).toBeGreaterThan(40);
  expect(await listeners(page, 'document', 'visibilitychange')).toBe(documentListeners + 1);
  expect(errors).toEqual([]);
});

test('after a lost and restored WebGL context the same scene is drawn again at the same time', ALSO_ON_OLDEST_THREE, async ({ page }) => {
  const errors = await openPage(page);
  const result = await page.evaluate(async () => {
    const el = window.embed.create({ resolution: '64', paused: '' });
    el.time = 7.25;
    await window.embed.drawn(el);
    const before = window.embed.pixels(el);
    const canvas = el.canvas!;
    const lose = el.renderer!.getContext().getExtension('WEBGL_lose_context')!;
    const lost = new Promise((resolve) => canvas.addEventListener('webglcontextlost', resolve, { once: true }));
    lose.loseContext();
    await lost;
    // Chromium allows restoreContext() only once the lost event's dispatch is over (and a
    // listener, three.js's, called preventDefault on it).
    await new Promise((resolve) => setTimeout(resolve, 10));
    const whileLost = { active: el.active, drew: el.renderFrame() };
    const restored = new Promise((resolve) => canvas.addEventListener('webglcontextrestored', resolve, { once: true }));
    lose.restoreContext();
    await restored;
    await window.embed.frames(3);
    const after = window.embed.pixels(el);
    return { before, after, whileLost, time: el.time, sameCanvas: el.canvas === canvas };
  });
  expect(result.whileLost).toEqual({ active: false, drew: false });
  expect(result.time).toBe(7.25);
  expect(result.sameCanvas).toBe(true);
  const { before, after } = result;
  expect(after.mean).toBeGreaterThan(40); // not black
  // The sky (top rows, drawn from the re-rendered cube) is not black either.
  const top = after.samples.slice(after.samples.length - 16);
  expect(Math.min(...top)).toBeGreaterThan(100);
  // Same picture: every cell's mean within 1 level of 255 (the context restarts from scratch).
  const worst = Math.max(...before.samples.map((value, i) => Math.abs(value - after.samples[i])));
  expect(worst).toBeLessThan(1);
  expect(errors).toEqual([]);
});
