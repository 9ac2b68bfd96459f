import { expect, test, type Page } from '@playwright/test';
import { mkdirSync, writeFileSync } from 'node:fs';
import type { BeaufortPicture, BeaufortView } from './beaufort';
import { beaufortWindSpeed } from '../../../src/spectrum/presets';
import { beaufortAppearance, sprayVisibility } from '../../../src/render/beaufortAppearance';
import { onePageForFile } from '../shared/sharedPages';

/**
 * The WMO Beaufort scale's descriptions of the sea (WMO-No. 306; the Met Office's "Beaufort wind force
 * scale"), in pictures: force 7 "foam from breaking waves begins to be blown in streaks along the
 * direction of the wind", force 8 "well-marked streaks", force 10 "on the whole the surface of the
 * sea takes on a white appearance". Seen straight down, the wind towards +x (the picture's x).
 */

const luma = (p: number[], i: number): number => 0.2126 * p[i] + 0.7152 * p[i + 1] + 0.0722 * p[i + 2];

/** Foam pixels: brighter than FOAM_LUMA (8-bit; the sea under an overcast sky is below 100, foam above 170). */
const FOAM_LUMA = 140;

function foamMask({ pixels }: BeaufortPicture, width: number, height: number): Float64Array {
  const mask = new Float64Array(width * height);
  for (let i = 0; i < width * height; i++) mask[i] = luma(pixels, 4 * i) > FOAM_LUMA ? 1 : 0;
  return mask;
}

/**
 * The lag (pixels, linearly interpolated) at which the mask's autocorrelation along (dx, dy) falls
 * to 1/e of its value at 0: the foam's correlation length in that direction.
 */
function correlationLength(mask: Float64Array, width: number, height: number, dx: number, dy: number): number {
  let mean = 0;
  for (const m of mask) mean += m;
  mean /= mask.length;
  const autocorrelation = (lag: number): number => {
    let sum = 0;
    let count = 0;
    for (let y = 0; y + lag * dy < height; y++) {
      for (let x = 0; x + lag * dx < width; x++) {
        sum += (mask[y * width + x] - mean) * (mask[(y + lag * dy) * width + x + lag * dx] - mean);
        count++;
      }
    }
    return sum / count;
  };
  const zero = autocorrelation(0);
  let previous = 1;
  for (let lag = 1; lag < Math.min(width, height) / 2; lag++) {
    const c = autocorrelation(lag) / zero;
    if (c < 1 / Math.E) return lag - 1 + (previous - 1 / Math.E) / (previous - c);
    previous = c;
  }
  return Math.min(width, height) / 2;
}

const SIZE = 256;
/** 70 m up, 50° wide: 0.25 m a pixel, where foam.glsl still draws the foam's pattern. */
const DOWN: Omit<BeaufortView, 'force'> = { width: SIZE, height: SIZE, eyeHeight: 70, pitch: 90, yaw: 0, fov: 50, time: 20 };

async function picture(page: Page, view: BeaufortView, name: string): Promise<BeaufortPicture> {
  const shot = await page.evaluate((v) => window.beaufortHarness.render(v), { ...view, png: true });
  mkdirSync('test-results/beaufort', { recursive: true });
  writeFileSync(`test-results/beaufort/${name}.png`, Buffer.from(shot.png!.split(',')[1], 'base64'));
  return shot;
}

/** Mean luma of rows [from, to) over columns [x0, x1), and the mean over the rows of each row's standard deviation. */
function rowsLuma({ pixels }: BeaufortPicture, width: number, from: number, to: number, x0 = 0, x1 = width): { mean: number; deviation: number } {
  let [total, deviations] = [0, 0];
  for (let y = from; y < to; y++) {
    let [sum, squares] = [0, 0];
    for (let x = x0; x < x1; x++) {
      const l = luma(pixels, 4 * (y * width + x));
      [sum, squares] = [sum + l, squares + l * l];
    }
    const mean = sum / (x1 - x0);
    total += mean;
    deviations += Math.sqrt(Math.max(0, squares / (x1 - x0) - mean * mean));
  }
  return { mean: total / (to - from), deviation: deviations / (to - from) };
}

// One page for the file: each test renders its own seas on it.
test.describe.configure({ mode: 'serial' });
let page: Page;
onePageForFile('/tests/browser/beaufort/beaufort.html', (opened) => {
  page = opened;
});

test('foam streaks along the wind from force 7, isotropic foam at force 5, a white sea at force 10', async () => {
  const measure = async (force: number, foamAmount: number) => {
    const shot = await picture(page, { ...DOWN, force, foamAmount }, `force-${force}-down`);
    const mask = foamMask(shot, SIZE, SIZE);
    const along = correlationLength(mask, SIZE, SIZE, 1, 0);
    const across = correlationLength(mask, SIZE, SIZE, 0, 1);
    const white = mask.reduce((sum, m) => sum + m, 0) / mask.length;
    console.log(`force ${force} (${beaufortWindSpeed(force)} m/s, streaked share ${beaufortAppearance(beaufortWindSpeed(force), 0).streakShare.toFixed(2)}, foamAmount ${foamAmount}): foam pixels ${(100 * white).toFixed(1)} %, correlation length along the wind ${along.toFixed(2)} px, across ${across.toFixed(2)} px, ratio ${(along / across).toFixed(2)}`);
    return { along, across, white };
  };
  // Force 5 has few whitecaps (Monahan: 0.8 %); ten times the foam gives the shape enough pixels
  // without changing it (the amount scales the foam made, not where).
  const five = await measure(5, 10);
  const eight = await measure(8, 1);
  const ten = await measure(10, 1);
  expect(five.white).toBeGreaterThan(0.01);
  expect(Math.abs(five.along / five.across - 1)).toBeLessThan(0.35);
  expect(eight.along / eight.across).toBeGreaterThan(3);
  expect(ten.white).toBeGreaterThan(0.5);
});

// 25 m up, looking at the horizon, 30° high: a row is 0.11°; the horizon's dip is 0.16°.
const [WIDE, HIGH] = [480, 270];
const HORIZON: Omit<BeaufortView, 'force'> = { width: WIDE, height: HIGH, eyeHeight: 25, pitch: 0, yaw: 200, fov: 30, time: 20 };

test('the overcast sky has no bands: its rows brighten smoothly towards the zenith', async () => {
  // The sky up to 15° above the horizon under the overcast of force 8, in the middle 32 columns,
  // where its contours (circles about the zenith) are level.
  const shot = await picture(page, { ...HORIZON, force: 8 }, 'force-8-horizon');
  const x0 = WIDE / 2 - 16;
  const top = HIGH / 2 - 10;
  const rows = Array.from({ length: top }, (_, y) => rowsLuma(shot, WIDE, y, y + 1, x0, x0 + 32).mean);
  // The overcast sky is smooth (Moon & Spencer: L ∝ 1 + 2 cos θ): each row within a fraction of a
  // level of the mean of its 9 neighbours. Without dither 8-bit levels step by 1 every few rows, and
  // the RGBM cube's filtering drew lines a level brighter along the contours (rgbm.glsl).
  let [worst, worstRow] = [0, 0];
  for (let y = 4; y < top - 4; y++) {
    const departure = Math.abs(rows[y] - rows.slice(y - 4, y + 5).reduce((sum, r) => sum + r, 0) / 9);
    if (departure > worst) [worst, worstRow] = [departure, y];
  }
  const largestStep = Math.max(...rows.slice(1).map((r, y) => Math.abs(r - rows[y])));
  console.log(`overcast sky, middle 32 columns: luma ${rows[0].toFixed(1)} (15° up) to ${rows[top - 1].toFixed(1)} (1° up); largest step between rows ${largestStep.toFixed(2)} levels; largest departure from the 9-row mean ${worst.toFixed(2)} levels (row ${worstRow})`);
  expect(largestStep).toBeLessThan(0.8);
  expect(worst).toBeLessThan(0.35);
});

test('spray from force 9: at force 11 the sea 1.5–2.8 km away fades into the horizon sky (visibility 1.5 km)', async () => {
  // Rows 6 to 10 below the middle: 0.51° to 0.95° below the horizon, the sea 2.8 to 1.5 km away.
  const band = async (force: number) => {
    const shot = await picture(page, { ...HORIZON, force }, `force-${force}-horizon`);
    const sea = rowsLuma(shot, WIDE, HIGH / 2 + 6, HIGH / 2 + 10);
    const sky = rowsLuma(shot, WIDE, HIGH / 2 - 10, HIGH / 2 - 6).mean;
    const visibility = sprayVisibility(beaufortWindSpeed(force));
    console.log(`force ${force}: the sea 1.5–2.8 km away, luma ${sea.mean.toFixed(1)} ± ${sea.deviation.toFixed(2)}; the sky 0.6°–1.1° up ${sky.toFixed(1)} (visibility ${Number.isFinite(visibility) ? `${(visibility / 1000).toFixed(2)} km` : 'unlimited'})`);
    return { ...sea, sky };
  };
  const clear = await band(8);
  const spray = await band(11);
  // Koschmieder / MOR: beyond 1.5 km in a 1.5 km visibility the sea keeps at most e^(−2.996) = 5 %
  // of its contrast: its waves and foam fade into the spray's haze, which has the horizon sky's light.
  // The force-8 sea there shows its waves (a standard deviation of 1.9 levels, 2.2 with modes
  // weighed by Ψ at their centres and the 3-point slope taps), or the comparison would prove little.
  expect(clear.deviation).toBeGreaterThan(1.5);
  expect(spray.deviation).toBeLessThan(0.3 * clear.deviation);
  expect(Math.abs(spray.mean - spray.sky)).toBeLessThan(3);
});
