import { expect, test, type Page } from '@playwright/test';
import { mkdirSync, writeFileSync } from 'node:fs';
import { PNG } from 'pngjs';
import { WEBGPU_BROWSER } from '../shared/webgpuBrowser';
import { onePageForFile } from '../shared/sharedPages';
import type { Vec3, View } from './sceneLight';
import { bounds, fresnelReflectance, rayMeetsBox, redderPixels as redder } from '../shared/sceneProofs';

// The scene in the WebGPU Ocean's sea (reflections and refractions 'scene', src/webgpu/sceneLightNodes.ts)
// on both of WebGPURenderer's backends, by the methods of the WebGL Ocean's proofs
// (tests/browser/reflections, tests/browser/refractions), and against the WebGL Ocean's pictures
// of the same scenes. Pictures under .tmp/scene-light-*.png.
test.use(WEBGPU_BROWSER);
test.describe.configure({ mode: 'serial' });

const W = 960;
const H = 540;
mkdirSync('.tmp', { recursive: true });
let page: Page;
onePageForFile('/tests/browser/webgpu/sceneLight.html', (opened) => {
  page = opened;
}, { width: 320, height: 180 });

type Pixels = Buffer;

async function render(view: View): Promise<Pixels> {
  return Buffer.from(await page.evaluate((v) => window.sceneLight.render(v), view), 'base64');
}

/** RGB of pixel (x, y), y from the top. */
function rgb(pixels: Pixels, x: number, y: number): Vec3 {
  const i = 4 * (y * W + x);
  return [pixels[i], pixels[i + 1], pixels[i + 2]];
}

function save(name: string, pixels: Pixels): void {
  const png = new PNG({ width: W, height: H });
  pixels.copy(png.data);
  for (let i = 3; i < png.data.length; i += 4) png.data[i] = 255;
  writeFileSync(`.tmp/scene-light-${name}.png`, PNG.sync.write(png));
}

/** Pixels whose red rose against the other picture by more than `threshold` over their green and blue (reflections.spec.ts's measure). */
function redderPixels(scene: Pixels, sky: Pixels, threshold: number): [number, number][] {
  return redder((x, y) => rgb(scene, x, y), (x, y) => rgb(sky, x, y), W, H, threshold);
}

/** Mean |Δ| of the RGB levels and the share of pixels whose every channel is within 8 levels. */
function difference(a: Pixels, b: Pixels): { mean: number; within8: number } {
  let sum = 0;
  let within = 0;
  for (let p = 0; p < W * H; p++) {
    let largest = 0;
    for (let c = 0; c < 3; c++) {
      const d = Math.abs(a[4 * p + c] - b[4 * p + c]);
      sum += d;
      largest = Math.max(largest, d);
    }
    if (largest <= 8) within++;
  }
  return { mean: sum / (3 * W * H), within8: within / (W * H) };
}

// No wind: a level sea, the plane mirror of the law of reflection (as reflections.spec.ts's CALM).
const CALM: View = { windSpeed: 0, reflections: 'scene', refractions: 'sky', box: { centre: [1, 1.5, -25], size: [3, 2, 3] }, eye: [0, 2, 0], target: [0, 0.3, -30], fov: 40, t: 3 };

const N_WATER = 1.333; // the ior option's default
const ABSORPTION: Vec3 = [0.45, 0.07, 0.04]; // σ, 1/m: the absorption option's default
// Calm water seen 45° down (as refractions.spec.ts's PLATE_SETUP), the sun behind the eye, no caustics (the page's SEA).
const PLATE: View = { windSpeed: 0, reflections: 'sky', refractions: 'scene', plate: { depth: 1, grey: 1 }, eye: [0, 3, 0], target: [0, 0, -3], fov: 50, t: 1 };
/** Pixels [x, y] from the top left: near (steep), centre, far (grazing). */
const PLATE_PIXELS: [number, number][] = [
  [480, 460],
  [480, 270],
  [480, 140],
];

/**
 * What a plate of radiance 1 more than another (white against black) adds to a pixel over flat
 * water `depth` metres above it, seen along `ray`: the transmitted fraction T = 1 − R of its light (R: Fresnel, ../shared/sceneProofs.ts)
 * after the refracted path L = depth/cos θt (Snell: sin θt = sin θi/n), which Beer–Lambert dims by
 * e^{−σL} per channel (Mobley, "Light and Water", 1994, §3.2). The sky's reflection, the water's
 * in-scattered light and the glint are the same over both plates and cancel.
 */
function expectedTransmitted(ray: Vec3, depth: number): { colour: Vec3; path: number } {
  const cosI = -ray[1];
  const transmittance = 1 - fresnelReflectance(cosI, N_WATER);
  const sinT = Math.sqrt(1 - cosI * cosI) / N_WATER;
  const path = depth / Math.sqrt(1 - sinT * sinT);
  return { colour: ABSORPTION.map((sigma) => transmittance * Math.exp(-sigma * path)) as Vec3, path };
}

/** The WebGL Ocean's pictures of the compared scenes, drawn first: a WebGLRenderer made beside a live WebGPU device drops it (webgpu.spec.ts). */
const COMPARED: Record<string, View> = { 'red box over calm water': CALM, 'white plate 1 m under calm water': PLATE };
const webglPictures: Record<string, Pixels> = {};

test('the WebGL Ocean draws the compared scenes (before any WebGPU device)', async () => {
  for (const [name, view] of Object.entries(COMPARED)) {
    webglPictures[name] = Buffer.from(await page.evaluate((v) => window.sceneLight.renderWebGL(v), view), 'base64');
    save(`webgl-ocean-${name.replaceAll(' ', '-')}`, webglPictures[name]);
  }
});

function backendTests(backend: 'webgl' | 'webgpu'): void {
  test.describe(`WebGPURenderer, ${backend === 'webgl' ? 'WebGL2 backend (forceWebGL)' : 'WebGPU backend'}`, () => {
    test('gets the backend asked for', async () => {
      expect(await page.evaluate((b) => window.sceneLight.open(b), backend)).toBe(backend === 'webgpu');
    });

    test('a red box above calm water is reflected at its mirror image with scene, not with sky', async () => {
      const scene = await render(CALM);
      const sky = await render({ ...CALM, reflections: 'sky' });
      save(`${backend}-calm-scene`, scene);
      save(`${backend}-calm-sky`, sky);
      // The law of reflection: on a level surface a point (x, y, z) is seen where its image (x, −y, z)
      // would be (Hecht, Optics, 5th ed., §4.3 and §5.4: the plane mirror's virtual image).
      const { centre, size } = CALM.box!;
      const corners: Vec3[] = [];
      for (const dx of [-0.5, 0.5]) for (const dy of [-0.5, 0.5]) for (const dz of [-0.5, 0.5]) corners.push([centre[0] + dx * size[0], -(centre[1] + dy * size[1]), centre[2] + dz * size[2]]);
      const image = bounds(await page.evaluate(([v, c]) => window.sceneLight.project(v, c), [CALM, corners] as const));
      // Its edges are where half of the reflection's typical strength shows (a pixel half covered by the image).
      const strong = redderPixels(scene, sky, 8);
      expect(strong.length).toBeGreaterThan(100);
      const contrast = strong.map(([x, y]) => rgb(scene, x, y)[0] - rgb(sky, x, y)[0]).sort((a, b) => a - b)[Math.floor(strong.length / 2)];
      const reflection = bounds(redderPixels(scene, sky, contrast / 2));
      console.log(`${backend}: mirror image ${JSON.stringify(image)}, reflection ${JSON.stringify(reflection)}`);
      expect(Math.abs(reflection.left - image.left)).toBeLessThanOrEqual(2);
      expect(Math.abs(reflection.right + 1 - image.right)).toBeLessThanOrEqual(2);
      expect(Math.abs(reflection.top - image.top)).toBeLessThanOrEqual(2);
      expect(Math.abs(reflection.bottom + 1 - image.bottom)).toBeLessThanOrEqual(2);
      // With 'sky' the sea reflects nothing of the box: the same sea as without the box.
      const skyWithoutBox = await render({ ...CALM, reflections: 'sky', box: undefined });
      expect(redderPixels(sky, skyWithoutBox, 8).filter(([, y]) => y > image.top - 3)).toEqual([]);
      // Over a scene of seas alone 'scene' draws exactly what 'sky' draws: no capture is made.
      expect(Buffer.compare(await render({ ...CALM, box: undefined }), skyWithoutBox)).toBe(0);
    });

    test('on a 20 m/s sea no reflection pixel lies above the drawn surface, and each shows the box along its reflected ray', async () => {
      const rough: View = { windSpeed: 20, reflections: 'scene', refractions: 'sky', eye: [0, 9, 0], target: [0, 0, -40], fov: 40, t: 7 };
      const waterline = await page.evaluate((v) => window.sceneLight.heightAt(v, 0, -30), rough);
      rough.box = { centre: [0, waterline, -30], size: [4, 4, 4] };
      const scene = await render(rough);
      const sky = await render({ ...rough, reflections: 'sky' });
      save(`${backend}-rough-scene`, scene);
      const reflection = redderPixels(scene, sky, 8);
      // Where the sea is drawn: what changes when the surface is left out, and not the box itself.
      const noSurface = await render({ ...rough, reflections: 'sky', hideSurface: true });
      const noBox = await render({ ...rough, reflections: 'sky', box: undefined });
      const differs = (a: Pixels, b: Pixels, [x, y]: [number, number]) => rgb(a, x, y).some((v, c) => v !== rgb(b, x, y)[c]);
      const offSea = reflection.filter((p) => !differs(sky, noSurface, p) || differs(sky, noBox, p));
      // Each reflection pixel shows the box along the ray the law of reflection sends from the drawn
      // surface point (r = d − 2(d·n)n, Hecht §4.3; mirrored upwards as ocean.frag does), the point
      // where the pixel's view ray meets Ocean.heightAt's surface and its normal from Ocean.normalAt:
      // the reflection rides on the displaced surface (reflections.spec.ts's method, with the surface
      // found by the queries, as the WebGPU Ocean has no height shading mode). Within half a metre
      // of the box, as there: the drawn normal is filtered over its texels.
      const sample = reflection.filter((_, i) => i % Math.ceil(reflection.length / 400) === 0);
      const surface = await page.evaluate(([v, p]) => window.sceneLight.surfacePoints(v, p), [rough, sample] as const);
      const hits = surface.filter((found) => {
        if (found === null) return false;
        const { point, normal: n, ray: d } = found;
        const dn = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
        const reflected: Vec3 = [d[0] - 2 * dn * n[0], Math.abs(d[1] - 2 * dn * n[1]), d[2] - 2 * dn * n[2]];
        return rayMeetsBox(point, reflected, rough.box!.centre, rough.box!.size, 0.5);
      });
      console.log(`${backend}: 20 m/s, ${reflection.length} reflection pixels, ${offSea.length} off the drawn sea; ${hits.length} of ${sample.length} sampled meet the box`);
      expect(reflection.length).toBeGreaterThan(50);
      expect(offSea).toEqual([]);
      expect(hits.length / sample.length).toBeGreaterThan(0.8);
    });

    test('a white plate 1 m and 4 m under calm water: each channel follows Fresnel transmittance × e^{−σL} over the refracted path', async () => {
      const rays = await page.evaluate(([v, p]) => p.map(([x, y]) => window.sceneLight.pixelRay(v, x, y)), [PLATE, PLATE_PIXELS] as const);
      const measured: Record<number, Vec3[]> = {};
      for (const depth of [1, 4]) {
        const white = await page.evaluate(([v, p]) => window.sceneLight.linearPixels(v, p), [{ ...PLATE, plate: { depth, grey: 1 } }, PLATE_PIXELS] as const);
        const black = await page.evaluate(([v, p]) => window.sceneLight.linearPixels(v, p), [{ ...PLATE, plate: { depth, grey: 0 } }, PLATE_PIXELS] as const);
        measured[depth] = white.map((colour, i) => colour.map((v, c) => v - black[i][c]) as Vec3);
        measured[depth].forEach((colour, i) => {
          const { colour: expected, path } = expectedTransmitted(rays[i], depth);
          console.log(`${backend}: plate ${depth} m, pixel ${PLATE_PIXELS[i].join(',')}: path ${path.toFixed(2)} m, white − black ${colour.map((v) => v.toFixed(4))}, expected ${expected.map((v) => v.toFixed(4))}`);
          for (let c = 0; c < 3; c++) expect(Math.abs(colour[c] - expected[c])).toBeLessThan(0.1 * expected[c]);
        });
      }
      // Red fades faster with depth than blue (σ_red = 0.45/m against 0.04/m).
      PLATE_PIXELS.forEach((_pixel, i) => expect(measured[4][i][0] / measured[1][i][0]).toBeLessThan(0.6 * (measured[4][i][2] / measured[1][i][2])));
      // With refractions 'sky' the plate is not seen.
      const sky = await page.evaluate(([v, p]) => window.sceneLight.linearPixels(v, p), [{ ...PLATE, refractions: 'sky' }, PLATE_PIXELS] as const);
      const skyBlack = await page.evaluate(([v, p]) => window.sceneLight.linearPixels(v, p), [{ ...PLATE, refractions: 'sky', plate: { depth: 1, grey: 0 } }, PLATE_PIXELS] as const);
      expect(sky).toEqual(skyBlack);
    });

    for (const [name, view] of Object.entries(COMPARED)) {
      test(`draws the ${name} as the WebGL Ocean draws it`, async () => {
        const drawn = await render(view);
        save(`${backend}-${name.replaceAll(' ', '-')}`, drawn);
        const { mean, within8 } = difference(drawn, webglPictures[name]);
        console.log(`${backend}, ${name}: WebGPU Ocean against WebGL Ocean at ${W}×${H}: mean |Δ| ${mean.toFixed(2)} levels, ${(100 * within8).toFixed(3)} % of pixels within 8 levels`);
        expect(mean).toBeLessThan(1);
        expect(within8).toBeGreaterThan(0.99);
      });
    }

    test('dispose returns renderer.info.memory to its baseline', async () => {
      const { before, during, after } = await page.evaluate((views) => window.sceneLight.memoryCycle(views), [CALM, PLATE]);
      console.log(`${backend}: memory before ${JSON.stringify(before)}, drawing ${JSON.stringify(during)}, after dispose ${JSON.stringify(after)}`);
      expect(during.textures).toBeGreaterThan(before.textures);
      expect(after).toEqual(before);
    });
  });
}

backendTests('webgl');

test('reflections and refractions take scene or sky; anything else is a ParameterError naming it', async () => {
  const [reflections, refractions] = await page.evaluate(() => [window.sceneLight.construct({ reflections: 'mirror' }), window.sceneLight.construct({ refractions: 'glass' })]);
  expect(reflections[0]).toBe('ParameterError');
  expect(reflections[1]).toContain('reflections');
  expect(refractions[0]).toBe('ParameterError');
  expect(refractions[1]).toContain('refractions');
});

backendTests('webgpu');
