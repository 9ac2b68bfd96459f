import { expect, test, type Page } from '@playwright/test';
import { mkdirSync, writeFileSync } from 'node:fs';
import type { ViewRequest, ViewResult } from '../lighting/lighting';
import { whitecapFraction } from '../../../src/layers/foamModel';
import { onePageForFile } from '../shared/sharedPages';
import { QUALITY_LEVELS } from '../../../src/runtime/adaptiveQuality';

/**
 * Whitecaps seen from altitude (shaders/surface/foamCells.glsl): straight down from hundreds of
 * metres a pixel spans metres of sea, and the whitecaps must still show as white pixels, about as
 * many as the foam model covers, not as a faint veil over the whole picture. Real pictures of a
 * whole Ocean on the lighting test page (tests/browser/lighting/lighting.ts), 480×270, the app's
 * field of view and sun.
 */

let page: Page;
test.describe.configure({ mode: 'default' });
onePageForFile('/tests/browser/lighting/lighting.html', (opened) => {
  page = opened;
});

const WIND = 10;
const DOWN: ViewRequest = {
  windSpeed: WIND,
  quality: 'high',
  width: 480,
  height: 270,
  eyeHeight: 1000,
  pitch: 89.9,
  yaw: 0,
  fov: 55,
  sunElevation: 30,
  sunAzimuth: 40,
  time: 3,
};

/** A pixel is a whitecap where its mean over R, G and B is more than this many levels above the same pixel with the foam off. */
const WHITECAP_LIFT = 10;

async function view(changes: Partial<ViewRequest>): Promise<ViewResult> {
  return page.evaluate((request) => window.lightingHarness.render(request), { ...DOWN, ...changes });
}

function keep(name: string, result: ViewResult): void {
  if (!result.png) return;
  mkdirSync('test-results/altitude', { recursive: true });
  writeFileSync(`test-results/altitude/${name}.png`, Buffer.from(result.png.split(',')[1], 'base64'));
}

/** Per pixel, the mean over R, G, B of `a` less `b` (8-bit levels). */
function lift(a: ViewResult, b: ViewResult): number[] {
  return Array.from({ length: a.width * a.height }, (_, i) => {
    let sum = 0;
    for (let c = 0; c < 3; c++) sum += a.pixels[4 * i + c] - b.pixels[4 * i + c];
    return sum / 3;
  });
}

for (const quality of QUALITY_LEVELS) test(`straight down from 1 km at ${WIND} m/s, quality ${quality}: the whitecap pixels' share is within 3× of Monahan's coverage, bright, and the same the next frame`, async () => {
  // Monahan & O'Muircheartaigh (1980), "Optimal power-law description of oceanic whitecap coverage
  // dependence on wind speed", J. Phys. Oceanogr. 10: 2094–2099, eq. 5: W = 3.84·10⁻⁶·U10^3.41,
  // the share of the sea whitecaps cover; the foam model is calibrated to it (foamModel.ts).
  const monahan = 3.84e-6 * WIND ** 3.41;
  expect(whitecapFraction(WIND)).toBeCloseTo(monahan, 12);
  const off = await view({ quality, foamAmount: 0 });
  const on = await view({ quality, png: true });
  keep(`down-1km-${quality}`, on);
  // The next frame at 30 fps, the foam stepped on by 1/30 s; against the same picture without foam
  // (from 1 km the waves alone change 0.01 % of the pixels by more than WHITECAP_LIFT in 1/30 s).
  const next = await view({ quality, time: DOWN.time + 1 / 30 });
  const lifted = lift(on, off);
  const whitecaps = lifted.flatMap((l, i) => (l > WHITECAP_LIFT ? [i] : []));
  const share = whitecaps.length / lifted.length;
  const meanLift = whitecaps.reduce((sum, i) => sum + lifted[i], 0) / Math.max(whitecaps.length, 1);
  const nextLifted = lift(next, off);
  const kept = whitecaps.filter((i) => nextLifted[i] > WHITECAP_LIFT).length / Math.max(whitecaps.length, 1);
  const appeared = nextLifted.filter((l, i) => l > WHITECAP_LIFT && lifted[i] <= WHITECAP_LIFT).length / Math.max(whitecaps.length, 1);
  console.log(
    `1 km, ${quality}: whitecap pixels ${(100 * share).toFixed(3)} % (Monahan ${(100 * monahan).toFixed(3)} %, ratio ${(share / monahan).toFixed(2)}), ` +
      `their mean lift ${meanLift.toFixed(0)} levels; the next frame keeps ${(100 * kept).toFixed(1)} % of them, ${(100 * appeared).toFixed(1)} % more appear`,
  );
  expect(share / monahan).toBeGreaterThan(1 / 3);
  expect(share / monahan).toBeLessThan(3);
  // Each is white like a whitecap close up, not a faint speck: on average far above the threshold.
  expect(meanLift).toBeGreaterThan(5 * WHITECAP_LIFT);
  // Fixed on the sea: no shimmer from one frame to the next.
  expect(kept).toBeGreaterThan(0.9);
  expect(appeared).toBeLessThan(0.1);
});

test('straight down from 1 km at 16 m/s (force 7, streaks), quality high (MSAA): no lines of faint foam along the grid’s edges', async () => {
  // With multisampling a pixel on a triangle's edge evaluates centroid-sampled inputs off its
  // centre; the foam's footprint taken from such an input drew one-pixel lines of faint foam along
  // the grid's edges (ocean.frag takes it from the largest layer's coordinates). Foam here is
  // whitecap cells, white or not: a pixel lifted a little, neither water nor whitecap, is a line's.
  const windy = { windSpeed: 16, quality: 'high' as const, msaa: true };
  const off = await view({ ...windy, foamAmount: 0 });
  const on = await view({ ...windy, png: true });
  keep('down-1km-16ms-high', on);
  const lifted = lift(on, off);
  const faint = lifted.filter((l) => l > 2 && l <= WHITECAP_LIFT).length / lifted.length;
  const white = lifted.filter((l) => l > WHITECAP_LIFT).length / lifted.length;
  console.log(`1 km, 16 m/s, high: faint foam ${(100 * faint).toFixed(3)} % of the pixels, whitecaps ${(100 * white).toFixed(3)} %`);
  expect(white).toBeGreaterThan(0.01); // the foam is drawn: the check below is not met by an empty picture
  expect(faint).toBeLessThan(0.004); // 0.14 % measured; 0.85 % with the centroid input's derivatives
});
