import { expect, test, type Page } from '@playwright/test';
import { mkdirSync } from 'node:fs';
import { WEBGPU_BROWSER } from '../shared/webgpuBrowser';
import { onePageForFile } from '../shared/sharedPages';
import { pictureDifference, savePicture, type Picture } from './pictureCompare';

// three-fft-ocean/webgpu seen from under the water, against the WebGL Ocean, and after its
// renderer lost its device; on WebGPURenderer's WebGL2 backend, then on its WebGPU backend
// (SwiftShader's adapter, ../shared/BROWSER.md), in the one Chromium of the WebGPU spec files.
test.use(WEBGPU_BROWSER);
test.describe.configure({ mode: 'serial' });

interface Pose {
  position: [number, number, number];
  target: [number, number, number];
}

mkdirSync('.tmp', { recursive: true });
let page: Page;
onePageForFile('/tests/browser/webgpu/underWater.html', (opened) => {
  page = opened;
}, { width: 320, height: 180 });

/** The share of pixels darker than 4 levels in every channel: black, which neither sky nor water is. */
function blackShare(png: Picture): number {
  let black = 0;
  for (let i = 0; i < png.data.length; i += 4) if (png.data[i] < 4 && png.data[i + 1] < 4 && png.data[i + 2] < 4) black++;
  return black / (png.width * png.height);
}

/** Mean blue level of rows [from, to): the deep water's colour is blue. */
function meanBlue(png: Picture, from: number, to: number): number {
  let sum = 0;
  for (let y = from; y < to; y++) for (let x = 0; x < png.width; x++) sum += png.data[4 * (y * png.width + x) + 2];
  return sum / ((to - from) * png.width);
}

const figures = (f: ReturnType<typeof pictureDifference>) =>
  `mean |Δ| ${f.mean.toFixed(2)} levels, ${(100 * f.within8).toFixed(3)} % of pixels within 8 levels (${(100 * f.greenBlueWithin8).toFixed(3)} % in green and blue), worst ${f.worst}`;

const T = 2;
/** The under-water views compared with the WebGL Ocean's, at 480×270. */
const UNDER_WATER: { name: string; file: string; pose: Pose; meanBound: number; within8Bound: number }[] = [
  // As the screenshots' "underwater" view (tests/browser/screenshots/scene.ts): 4 m under, looking up 50°: Snell's window.
  { name: "4 m under, looking up at Snell's window", file: 'up', pose: { position: [0, -4, 0], target: [-8, 6, -3] }, meanBound: 0.3, within8Bound: 0.999 },
  // 4 m under, looking along under the surface: the underside fading into the deep water, and the
  // deep water behind everything below the horizon, where the WebGL Ocean's background is dithered
  // (pictureDifference in pictureCompare.ts): that is the difference.
  { name: '4 m under, looking along the surface', file: 'along', pose: { position: [0, -4, 0], target: [0, -2, -40] }, meanBound: 1, within8Bound: 0.9 },
];
/**
 * A camera at the origin looking level (towards −z), lowered through the surface and raised again (the eye
 * at the surface: the near plane cuts the waves, each triangle tells the side by its face).
 */
const HEIGHTS = [1.5, 0.4, 0.1, -0.1, -0.4, -1.5, -0.4, -0.1, 0.1, 0.4, 1.5];
const levelPose = (y: number): Pose => ({ position: [0, y, 0], target: [0, y, -40] });
/** The heights once each, for the WebGL Ocean's pictures (each drawn alone: nothing carries over from one to the next). */
const REFERENCE_HEIGHTS = [...new Set(HEIGHTS)];
const CROSSING_SIZE = { width: 256, height: 144 };

/** The WebGL Ocean's pictures, made on the WebGL2 backend's page before any WebGPU device lives (webgpu.spec.ts says why). */
const references: { underWater?: Picture[]; crossing?: Picture[] } = {};

async function webglPictures(poses: Pose[], width: number, height: number, name: string): Promise<Picture[]> {
  const pictures = await page.evaluate(({ poses, t, width, height }) => window.underWater.drawWebGLPoses(poses, t, width, height), { poses, t: T, width, height });
  return pictures.map((picture, i) => savePicture(picture, `under-${name}-${i}-webgl-ocean`));
}

async function webgpuPictures(poses: Pose[], width: number, height: number, name: string): Promise<Picture[]> {
  const pictures = await page.evaluate(({ poses, t, width, height }) => window.underWater.drawPoses(poses, t, width, height), { poses, t: T, width, height });
  return pictures.map((picture) => savePicture(picture, name));
}

function backendTests(backend: 'webgl' | 'webgpu'): void {
  test.describe(`WebGPURenderer, ${backend === 'webgl' ? 'WebGL2 backend (forceWebGL)' : 'WebGPU backend'}`, () => {
    test('gets the backend asked for', async () => {
      const got = await page.evaluate((b) => window.webgpuOcean.open(b), backend);
      expect(got.isWebGPUBackend, got.reason).toBe(backend === 'webgpu');
    });

    test('under the water the picture is the WebGL Ocean\'s: the underside with Snell\'s window, the deep water behind', async () => {
      references.underWater ??= await webglPictures(UNDER_WATER.map((view) => view.pose), 480, 270, 'view');
      for (const [i, view] of UNDER_WATER.entries()) {
        const [drawn] = await webgpuPictures([view.pose], 480, 270, `under-view-${view.file}-webgpu-ocean-${backend}`);
        const difference = pictureDifference(drawn, references.underWater[i], `under-view-${view.file}-difference-${backend}`);
        console.log(`${backend}, ${view.name}: WebGPU Ocean against WebGL Ocean at 480×270, t = ${T} s: ${figures(difference)}; blue of the top and bottom fifths ${meanBlue(drawn, 0, 54).toFixed(0)}, ${meanBlue(drawn, 216, 270).toFixed(0)}`);
        expect(difference.mean).toBeLessThan(view.meanBound);
        expect(difference.within8).toBeGreaterThan(view.within8Bound);
        expect(difference.greenBlueWithin8).toBeGreaterThan(0.999);
        expect(blackShare(drawn)).toBe(0);
      }
    });

    for (const ior of [1.333, 1.5]) {
      test(`Snell's window: looking up from under a calm sea, the sky shows within asin(1/n) of the zenith (n = ${ior}, within 1°)`, async () => {
        // Snell's law at the water–air interface: light from the whole sky reaches the eye through a
        // cone of half-angle asin(n_air/n_water) (48.6° for water, 41.8° for n = 1.5); outside it the
        // surface reflects totally (Born & Wolf, "Principles of Optics", §1.5.4; Hecht, "Optics", §4.7.1).
        const { edgeAngles, centreRed, picture } = await page.evaluate((n) => window.underWater.snellWindow(n), ior);
        savePicture(picture, `under-snell-${ior}-${backend}`);
        const expected = (Math.asin(1 / ior) * 180) / Math.PI;
        console.log(`${backend}, Snell's window at n = ${ior}: edges at ${edgeAngles.map((a) => a.toFixed(2)).join(', ')}° (asin(1/n) = ${expected.toFixed(2)}°), red at the centre ${centreRed}`);
        // The sky straight up: its red (linear, about 0.04 at the zenith under a sun 30° up), which the deep water has none of.
        expect(centreRed).toBeGreaterThan(5);
        expect(edgeAngles).toHaveLength(4);
        for (const angle of edgeAngles) expect(Math.abs(angle - expected)).toBeLessThan(1);
      });
    }

    test('crossing the surface down and up, every frame is the WebGL Ocean\'s and none is black', async () => {
      test.setTimeout(300_000); // 17 pictures; under SwiftShader on a loaded machine this took 2.8 min at 320×180
      const { width, height } = CROSSING_SIZE;
      references.crossing ??= await webglPictures(REFERENCE_HEIGHTS.map(levelPose), width, height, 'crossing');
      const drawn = await page.evaluate(({ poses, t, width, height }) => window.underWater.drawPoses(poses, t, width, height), { poses: HEIGHTS.map(levelPose), t: T, width, height });
      const lines: string[] = [];
      for (const [i, frame] of drawn.entries()) {
        const png = savePicture(frame, `under-crossing-${i}-webgpu-ocean-${backend}`);
        const reference = references.crossing[REFERENCE_HEIGHTS.indexOf(HEIGHTS[i])];
        const difference = pictureDifference(png, reference, `under-crossing-${i}-difference-${backend}`);
        const black = blackShare(png);
        lines.push(`y = ${HEIGHTS[i]} m: ${figures(difference)}, black ${(100 * black).toFixed(2)} %, blue ${meanBlue(png, 0, height).toFixed(0)}`);
        expect(black, `frame ${i} (eye at y = ${HEIGHTS[i]} m)`).toBe(0);
        // The background's dither shows in the red of the deep water below the horizon (pictureDifference).
        expect(difference.mean, `frame ${i} (eye at y = ${HEIGHTS[i]} m)`).toBeLessThan(1.5);
        expect(difference.within8, `frame ${i} (eye at y = ${HEIGHTS[i]} m)`).toBeGreaterThan(0.9);
        expect(difference.greenBlueWithin8, `frame ${i} (eye at y = ${HEIGHTS[i]} m)`).toBeGreaterThan(0.999);
      }
      console.log(`${backend}, crossing the surface:\n  ${lines.join('\n  ')}`);
    });

    test('a lost device: the Ocean dispatches devicelost once and update() then throws an UnsupportedError naming it', async () => {
      const result = await page.evaluate(() => window.underWater.loseDevice());
      console.log(`${backend}: ${JSON.stringify(result)}`);
      const api = backend === 'webgpu' ? 'WebGPU' : 'WebGL2';
      expect(result.event).toMatchObject({ api, reason: backend === 'webgpu' ? 'destroyed' : 'context lost' });
      expect(result.deviceLost).toEqual(result.event);
      expect(result.update[0]).toBe('UnsupportedError');
      expect(result.update[1]).toContain(`Ocean.update: the renderer's ${backend === 'webgpu' ? 'WebGPU device' : 'WebGL2 context'} was lost`);
      expect(result.disposed).toBe(true);
    });
  });
}

backendTests('webgl');
backendTests('webgpu');
