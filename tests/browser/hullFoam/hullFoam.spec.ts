import { expect, test, type Page } from '@playwright/test';
import { onePageForFile } from '../shared/sharedPages';

// The foam of a hull under way (src/layers/hullFoam.ts), drawn by the real surface in Chromium: a
// hull given to the local waves runs along +x, seen straight down from 50 m. Foam pixels are told
// by their brightness (the calm water under the sky is dark blue, the hull's box dark red). One page
// for the file; the moving hull's Ocean, then a hull at rest.

test.describe.configure({ mode: 'serial' });

let page: Page;
const WIDTH = 480;
const HEIGHT = 270;
const HULL = { length: 8, beam: 2.6 };
const SPEED = 5; // m/s: Froude number 5/√(9.81·8) = 0.56, above the hull speed's 0.40: full foam
const STOP_AT = 10; // s: the hull is at x = 0 from then on
const TAU = 3; // s, foamPersistence's default (the whitecaps' decay, Callaghan et al. 2012)
/** tan 19.47°, the Kelvin wedge's half-angle arcsin(1/3) (Thomson 1887, "On ship waves"). */
const WEDGE = Math.tan(Math.asin(1 / 3));

let ground: number[] = [];

onePageForFile('/tests/browser/hullFoam/hullFoam.html', async (opened) => {
  page = opened;
  await page.evaluate(([w, h, speed, stopAt]) => window.hullFoamHarness.setup(w, h, speed, stopAt), [WIDTH, HEIGHT, SPEED, STOP_AT]);
  ground = await page.evaluate(() => window.hullFoamHarness.ground());
});

/** Where a world point lies against a hull whose bow is at x = bow on z = 0 heading +x. */
function place(x: number, z: number, bow: number): 'ahead' | 'wake' | 'outside' | 'edge' {
  const behindBow = bow - x;
  if (behindBow < -1.5) return 'ahead';
  // The wedge from the bow's shoulders, with 1.5 m for the field's soft edge and the texels' filtering.
  const edge = HULL.beam / 2 + Math.max(0, behindBow) * WEDGE;
  if (Math.abs(z) < edge - 0.5 && behindBow > 0.5) return 'wake';
  if (Math.abs(z) > edge + 1.5) return 'outside';
  return 'edge';
}

/** Counts of pixels and foam pixels in each place, and in bands behind the bow. */
async function drawAndCount(t: number): Promise<{ bow: number; counts: Record<string, { pixels: number; foam: number }>; beside: number; behind: number[] }> {
  const drawn = await page.evaluate((t) => window.hullFoamHarness.draw(t), t);
  const [pixels, bow] = [Buffer.from(drawn.pixels, 'base64'), drawn.bow];
  const counts: Record<string, { pixels: number; foam: number }> = { ahead: { pixels: 0, foam: 0 }, wake: { pixels: 0, foam: 0 }, outside: { pixels: 0, foam: 0 }, edge: { pixels: 0, foam: 0 } };
  const band = (from: number, to: number) => ({ from, to, pixels: 0, foam: 0 });
  // Beside the hull's after half (outside its sides), and behind its stern at 0–10, 10–20, 20–30 m.
  const besideBand = band(HULL.length / 2, HULL.length);
  const behindBands = [band(HULL.length, HULL.length + 10), band(HULL.length + 10, HULL.length + 20), band(HULL.length + 20, HULL.length + 30)];
  for (let p = 0; p < WIDTH * HEIGHT; p++) {
    const [x, z] = [ground[2 * p], ground[2 * p + 1]];
    const [r, g, b] = [pixels[4 * p], pixels[4 * p + 1], pixels[4 * p + 2]];
    // The water's darkest channel stays under 10 (of 255), the foam's is 20 to 150 (grey-blue, its
    // bubbles' gaps let water through); the box is red (r ≫ b).
    const foam = Math.min(r, g, b) > 40 && b > r - 10;
    const where = place(x, z, bow);
    counts[where].pixels++;
    if (foam) counts[where].foam++;
    if (where !== 'wake') continue;
    const behindBow = bow - x;
    if (behindBow > besideBand.from && behindBow < besideBand.to && Math.abs(z) > HULL.beam / 2 + 0.3) {
      besideBand.pixels++;
      if (foam) besideBand.foam++;
    }
    for (const b of behindBands) {
      if (behindBow > b.from && behindBow < b.to) {
        b.pixels++;
        if (foam) b.foam++;
      }
    }
  }
  return { bow, counts, beside: besideBand.foam / besideBand.pixels, behind: behindBands.map((b) => b.foam / b.pixels) };
}

test('a hull at 5 m/s leaves foam along its sides and behind it, within the Kelvin wedge, none ahead', async () => {
  await page.evaluate(() => window.hullFoamHarness.advance(8));
  const { bow, counts, beside, behind } = await drawAndCount(8 + 1 / 30);
  await page.locator('canvas').screenshot({ path: test.info().outputPath('moving.png') });
  console.log(`bow at x = ${bow.toFixed(2)} m; foam pixels: ${JSON.stringify(counts)}; beside ${beside.toFixed(3)}, behind ${behind.map((f) => f.toFixed(3)).join(', ')}`);
  expect(bow).toBeCloseTo(SPEED * (8 + 1 / 30 - STOP_AT) + HULL.length / 2, 5);
  // Ahead of the bow and outside the wedge: none (the sea is too calm for whitecaps).
  expect(counts.ahead.pixels).toBeGreaterThan(10_000);
  expect(counts.ahead.foam).toBe(0);
  expect(counts.outside.foam).toBe(0);
  // Beside the hull the zone is full (coverage 1: white but for its bubbles' gaps).
  expect(beside).toBeGreaterThan(0.8);
  // Behind, the white share falls as the foam ages (below).
  expect(behind[0]).toBeGreaterThan(0.4);
  expect(behind[0]).toBeGreaterThan(behind[1]);
  expect(behind[1]).toBeGreaterThan(behind[2]);
  // The field behind the stern on the centre line is as old as the time since the stern passed,
  // d/U: e^(−d/(U·τ)), the whitecaps' fading (foamModel.ts).
  const stern = bow - HULL.length;
  for (const d of [5, 10, 20]) {
    const { coverage, age } = await fieldAt(stern - d, 0, stern);
    console.log(`${d} m behind the stern: coverage ${coverage.toFixed(3)}, e^(−age/τ) ${Math.exp(-age / TAU).toFixed(3)}`);
    expect(Math.abs(coverage - Math.exp(-age / TAU))).toBeLessThan(0.05 * Math.exp(-age / TAU) + 0.02);
  }
});

/** The hull foam field at the texel nearest (x, z), and the age there, the time since a stern at `stern` (moving at SPEED) passed its x. */
async function fieldAt(x: number, z: number, stern: number): Promise<{ coverage: number; age: number }> {
  const field = await page.evaluate(() => window.hullFoamHarness.field());
  const i = Math.round((x - field.origin[0]) / field.cellSize);
  const j = Math.round((z - field.origin[1]) / field.cellSize);
  const texelX = field.origin[0] + i * field.cellSize;
  return { coverage: field.coverage[j * field.resolution + i], age: (stern - texelX) / SPEED };
}

test('after the hull stops its foam fades as e^(−Δt/τ), and the white pixels with it', async () => {
  // Stops at x = 0 at STOP_AT; then 2 s in steps of 0.5 s.
  const stopped = await drawAndCount(STOP_AT);
  const points: [number, number][] = [[-2, 2.5], [-8, 0], [-14, 0]];
  const before = await Promise.all(points.map(([x, z]) => fieldAt(x, z, 0)));
  for (const t of [0.5, 1, 1.5]) await page.evaluate((t) => window.hullFoamHarness.advance(t), STOP_AT + t);
  const faded = await drawAndCount(STOP_AT + 2);
  await page.locator('canvas').screenshot({ path: test.info().outputPath('stopped-2s.png') });
  const after = await Promise.all(points.map(([x, z]) => fieldAt(x, z, 0)));
  points.forEach((point, k) => {
    console.log(`(${point}): ${before[k].coverage.toFixed(3)} → ${after[k].coverage.toFixed(3)}, ratio ${(after[k].coverage / before[k].coverage).toFixed(4)}, e^(−2/τ) = ${Math.exp(-2 / TAU).toFixed(4)}`);
    expect(before[k].coverage).toBeGreaterThan(0.2);
    expect(after[k].coverage / before[k].coverage).toBeCloseTo(Math.exp(-2 / TAU), 3);
  });
  const white = (c: typeof stopped) => c.counts.wake.foam + c.counts.edge.foam;
  console.log(`white pixels: ${white(stopped)} at the stop, ${white(faded)} 2 s later`);
  expect(white(faded)).toBeLessThan(0.8 * white(stopped));
  expect(faded.counts.outside.foam + faded.counts.ahead.foam).toBe(0);
});

test('a hull at rest makes no foam; the Ocean frees the foam texture', async () => {
  const freed = await page.evaluate(() => window.hullFoamHarness.dispose());
  expect(freed.after).toBe(freed.before);
  await page.evaluate(([w, h]) => window.hullFoamHarness.setup(w, h, 0, 0), [WIDTH, HEIGHT]);
  for (const t of [8, 8.5]) await page.evaluate((t) => window.hullFoamHarness.advance(t), t);
  const { counts } = await drawAndCount(9);
  const field = await page.evaluate(() => window.hullFoamHarness.field());
  expect(Math.max(...field.coverage)).toBe(0);
  expect(counts.ahead.foam + counts.wake.foam + counts.edge.foam + counts.outside.foam).toBe(0);
  const last = await page.evaluate(() => window.hullFoamHarness.dispose());
  expect(last.after).toBe(last.before);
});
