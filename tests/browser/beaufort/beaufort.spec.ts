import { expect, test, type Page } from '@playwright/test';
import { mkdirSync, writeFileSync } from 'node:fs';
import type { BeaufortPicture, BeaufortView } from './beaufort';
import { beaufortWindSpeed } from '../../../src/spectrum/presets';
import { beaufortAppearance } from '../../../src/render/beaufortAppearance';

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

test('foam streaks along the wind from force 7, isotropic foam at force 5, a white sea at force 10', async ({ page }) => {
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(error.message));
  await page.goto('/tests/browser/beaufort/beaufort.html');
  await expect(page).toHaveTitle('ready');

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
  expect(errors).toEqual([]);
});
