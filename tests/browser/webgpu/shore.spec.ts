/**
 * The WebGPU Ocean's shore (src/webgpu/shoreNodes.ts) against the WebGL Ocean's, on both of
 * WebGPURenderer's backends: the queries over the same seabed give the same numbers (the same JS,
 * src/layers/shore.ts and surfaceQuery.ts); the surface drawn over a 1:50 beach is where heightAt
 * puts it (the real vertex node read back, as webgpu.spec.ts does without a seabed); the island's
 * shore looks as the WebGL Ocean draws it; bad seabeds throw as the WebGL Ocean's do and the last
 * good one stays; dispose frees what the seabeds made. The shoaling and breaking laws themselves
 * are proven on the queries (tests/unit/shoaling.test.ts) and on the WebGL Ocean's drawn surface
 * (tests/browser/seabed). Pictures go to test-results-<port>/webgpu-shore/ for a person to look at.
 */
import { expect, test, type Page } from '@playwright/test';
import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { PNG } from 'pngjs';
import { WEBGPU_BROWSER } from '../shared/webgpuBrowser';
import { onePageForFile } from '../shared/sharedPages';

test.use(WEBGPU_BROWSER);
test.describe.configure({ mode: 'serial' });

const PORT = Number(process.env.TEST_PORT ?? 5173);
const OUTPUT = join(PORT === 5173 ? 'test-results' : `test-results-${PORT}`, 'webgpu-shore');

mkdirSync(OUTPUT, { recursive: true });
let page: Page;
onePageForFile('/tests/browser/webgpu/shore.html', (opened) => {
  page = opened;
}, { width: 320, height: 180 });

type Picture = { width: number; height: number; data: number[] };

/** Writes a picture as a PNG under OUTPUT. */
function save(picture: Picture, name: string): void {
  const png = new PNG({ width: picture.width, height: picture.height });
  png.data.set(picture.data);
  writeFileSync(join(OUTPUT, `${name}.png`), PNG.sync.write(png));
}

/** Mean |Δ| of the RGB levels of `a` against `b` and the share of pixels whose every channel is within 8 levels; writes |a − b| × 8. */
function difference(a: Picture, b: Picture, name: string): { mean: number; within8: number } {
  const shown: Picture = { width: a.width, height: a.height, data: Array.from({ length: a.data.length }, (_, i) => (i % 4 === 3 ? 255 : Math.min(255, 8 * Math.abs(a.data[i] - b.data[i])))) };
  save(shown, name);
  let sum = 0;
  let within = 0;
  const pixels = a.width * a.height;
  for (let p = 0; p < pixels; p++) {
    const channels = [0, 1, 2].map((c) => Math.abs(a.data[4 * p + c] - b.data[4 * p + c]));
    sum += channels[0] + channels[1] + channels[2];
    if (Math.max(...channels) <= 8) within++;
  }
  return { mean: sum / (3 * pixels), within8: within / pixels };
}

/** Mean RGB of rows [from, to) of a picture. */
function meanColour(picture: Picture, from: number, to: number): number[] {
  const rgb = [0, 0, 0];
  for (let p = from * picture.width; p < to * picture.width; p++) for (let c = 0; c < 3; c++) rgb[c] += picture.data[4 * p + c] / ((to - from) * picture.width);
  return rgb;
}

/** The island's beach from offshore: 25 m up at (−50, 230), looking north (−z) down over the surf to the beach (src/objects/island.ts). */
/** The beach of shore.ts: depth x/50. */
const BEACH_SLOPE = 1 / 50;

const ISLAND_PICTURE = { t: 3, width: 480, height: 270, view: { at: [-50, 230] as [number, number], altitude: 25 } };
let islandReference: Picture | null = null;

function backendTests(backend: 'webgl' | 'webgpu'): void {
  test.describe(`WebGPURenderer, ${backend === 'webgl' ? 'WebGL2 backend (forceWebGL)' : 'WebGPU backend'}`, () => {
    test('gets the backend asked for', async () => {
      const got = await page.evaluate((b) => window.webgpuOcean.open(b), backend);
      expect(got.isWebGPUBackend, got.reason).toBe(backend === 'webgpu');
    });

    test("draws the island's shore as the WebGL Ocean draws it", async () => {
      const { t, width, height } = ISLAND_PICTURE;
      // The WebGL Ocean's picture, made once, on the WebGL2 backend's page: a WebGLRenderer made beside a live WebGPU device would drop it.
      islandReference ??= await page.evaluate(({ t, width, height, view }) => window.webgpuOcean.drawWebGLView(t, width, height, { ...view, seabed: window.webgpuShore.seabed('island') }), ISLAND_PICTURE);
      save(islandReference, 'island-webgl-ocean');
      const drawn = await page.evaluate(({ t, width, height, view }) => window.webgpuOcean.drawView(t, width, height, { ...view, seabed: window.webgpuShore.seabed('island') }), ISLAND_PICTURE);
      save(drawn, `island-webgpu-ocean-${backend}`);
      const open = await page.evaluate(({ t, width, height, view }) => window.webgpuOcean.drawView(t, width, height, view), ISLAND_PICTURE);
      save(open, `island-without-seabed-webgpu-ocean-${backend}`);
      const against = difference(drawn, islandReference, `island-difference-${backend}`);
      // A control: the same view without the seabed (open sea) against the WebGL Ocean's shore.
      const control = difference(open, islandReference, `island-difference-without-seabed-${backend}`);
      // The surf: the rows between the horizon and the camera's feet, where the shore's foam whitens the sea.
      const [surf, openSea] = [meanColour(drawn, 140, 200), meanColour(open, 140, 200)];
      console.log(
        `${backend}, the island's shore at ${width}×${height}, t = ${t} s: WebGPU Ocean against WebGL Ocean mean |Δ| ${against.mean.toFixed(2)} levels, ` +
          `${(100 * against.within8).toFixed(2)} % of pixels within 8 levels; control (no seabed) ${control.mean.toFixed(2)} levels, ${(100 * control.within8).toFixed(2)} %; ` +
          `rows 140–199 mean RGB ${surf.map((c) => c.toFixed(0))} with the seabed, ${openSea.map((c) => c.toFixed(0))} without`,
      );
      expect(against.mean).toBeLessThan(1);
      expect(against.within8).toBeGreaterThan(0.99);
      expect(control.mean).toBeGreaterThan(5 * against.mean);
    });

    test('draws the surface over a 1:50 beach where heightAt puts it', async () => {
      // As webgpu.spec.ts's test without a seabed: 2.5 m up, the rings' finest cells are the finest
      // texel, so the drawn surface differs from heightAt only by the linear interpolation between
      // vertices (interpolationBound, webgpu.ts). Two squares: the waterline (land, swash, surf) and
      // 1.2 m deep in the surf zone.
      const rms = (values: number[]) => Math.sqrt(values.reduce((s, v) => s + v * v, 0) / values.length);
      for (const cx of [4, 60]) {
        const now = await page.evaluate((x) => window.webgpuOcean.heightAgreement(x, 0, 16, 2, { patchSizes: [40, 231, 1337], seabed: window.webgpuShore.seabed('beach') }), cx);
        const difference = now.drawn.map((y, i) => y - now.queried[i]);
        // Where heightAt lies under the beach (y < −x/50) the water is drawn under the ground, which
        // hides it, at ζ + max(D, −LAND_DROP) (src/spectrum/shoaling.ts): kinks, with no second
        // derivative for the bound to hold. The bound is checked on the water above the ground.
        const visible = now.queried.map((h, i) => h > -now.xs[i] * BEACH_SLOPE);
        const outside = difference.filter((d, i) => visible[i] && Math.abs(d) > now.bound[i] + 1e-3).length;
        const underGround = visible.filter((shown) => !shown).length;
        // A control: the open sea's surface (no seabed) against the queries over the beach.
        const open = await page.evaluate((x) => window.webgpuOcean.heightAgreement(x, 0, 16, 2, { patchSizes: [40, 231, 1337] }), cx);
        const control = rms(open.drawn.map((y, i) => y - now.queried[i]));
        console.log(
          `${backend}, beach square at x = ${cx} m: ${now.drawn.length} pixels, height RMS ${now.heightRms.toFixed(3)} m, drawn − heightAt RMS ${rms(difference).toExponential(2)} m, ` +
            `worst ${Math.max(...difference.map(Math.abs)).toExponential(2)} m, interpolation bound RMS ${rms(now.bound).toExponential(2)} m, ${outside} pixels of ${now.drawn.length - underGround} above the ground beyond it ` +
            `(${underGround} under the ground left out); control (no seabed) ${control.toFixed(3)} m`,
        );
        expect(now.drawn.length).toBeGreaterThan(0.95 * 64 * 64);
        expect(now.drawn.length - underGround).toBeGreaterThan(0.5 * 64 * 64);
        expect(outside).toBe(0);
        expect(control).toBeGreaterThan(10 * rms(difference));
      }
    });

    test('dispose returns renderer.info.memory to its baseline, seabeds too', async () => {
      const { before, during, after } = await page.evaluate(() => window.webgpuShore.memoryCycle());
      console.log(`${backend}: memory before ${JSON.stringify(before)}, drawing over a seabed ${JSON.stringify(during)}, after dispose ${JSON.stringify(after)}`);
      expect(during.textures).toBeGreaterThan(before.textures);
      expect(after).toEqual(before);
    });
  });
}

backendTests('webgl');

// On the WebGL2 backend's page, before the WebGPU backend: a WebGLRenderer beside a live WebGPU device drops it (webgpu.spec.ts).
test.describe('three-fft-ocean/webgpu over a seabed', () => {
  test("heightAt, normalAt and depthAt equal the WebGL Ocean's for the same options, seabed and time, also after setSeabed", async () => {
    const points: [number, number][] = [[-2, 0], [3.3, -7.1], [40, 12], [150, -30], [-51, 160], [-80, 200], [3000, 0]];
    const { webgpu, webgl } = await page.evaluate((p) => window.webgpuShore.sameQueriesAsWebGL(p, 3.7, 'beach', 'island'), points);
    // Five numbers a point (height, normal, depth), seven points, two seabeds.
    const heights = (values: number[]) => values.filter((_, i) => i % 5 === 0).map((h) => h.toFixed(4));
    console.log(`heightAt over the beach then the island: WebGPU Ocean ${heights(webgpu)}, WebGL Ocean ${heights(webgl)}`);
    // Exactly: the same JS on the same float32 depth maps and tables.
    expect(webgpu).toEqual(webgl);
    expect(new Set(heights(webgpu)).size).toBeGreaterThan(points.length); // a real sea that the seabed shapes
  });

  test("bad seabeds throw as the WebGL Ocean's do, and the last good one stays", async () => {
    const { thrown, depthAfter, constructed } = await page.evaluate(() => window.webgpuShore.badSeabeds());
    console.log(thrown.map(([name, parameter, message]) => `${name} ${parameter}: ${message}`).join('\n'));
    expect(thrown.map(([name, parameter]) => [name, parameter])).toEqual([
      ['ParameterError', 'seabed.depthAt'],
      ['ParameterError', 'seabed.bounds'],
      ['ParameterError', 'seabed.depthAt'],
      ['ParameterError', 'seabed.depths'],
      ['UnsupportedError', 'seabed.meshes'],
      ['ParameterError', 'seabed'],
    ]);
    expect(thrown[4][2]).toContain('depthAt(x, z)'); // what to give instead
    for (const depth of depthAfter) expect(depth).toBeCloseTo(20, 3); // the beach's x/50 at x = 1000
    expect(constructed).toEqual(['ParameterError', 'seabed.depthAt']);
  });
});

backendTests('webgpu');
