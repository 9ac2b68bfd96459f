/**
 * "From altitude no tiling is visible": the rendered sea, seen from 1 km and 4 km up, straight down
 * and 45° down, has no repeating pattern. Measured by the picture's 2D autocorrelation
 * (Wiener–Khinchin: R = F⁻¹|F(f)|², f the luminance with its mean removed; e.g. Bracewell, "The
 * Fourier Transform and its Applications", ch. 6), normalised so that R(0) = 1 and, lag by lag,
 * by the number of overlapping pixels (the unbiased estimate). A sea made of copies of one patch
 * has R ≈ 1 at the patch's period. The default sea sums three cascades whose sizes are not whole
 * ratios of each other (13.7, 79.3, 457 m), but from a few km up only the largest one is resolved
 * and its period showed (R = 0.63 at 457 m from 4 km); drawing it as a slowly varying blend of two
 * shifted copies (src/layers/patchBlend.ts) decorrelates its repeats, and R at each period must
 * stay below 0.4. A control renders a single 250 m patch without the blend and must show R above
 * 0.4 at its period: the measurement can fail.
 *
 * The frames are written to test-results-<port>/tiling/ (PNG) for a person to look at.
 */
import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { expect, test, type Page } from '@playwright/test';
import { PNG } from 'pngjs';
import { fft2d } from '../../referenceFft';

const SIZE = 512;
const PORT = Number(process.env.TEST_PORT ?? 5173);
const OUTPUT = join(PORT === 5173 ? 'test-results' : `test-results-${PORT}`, 'tiling');
const THRESHOLD = 0.4;

/** Luminance (Rec. 709 weights on linear RGB) of a decoded RGBA 8-bit picture. */
function luminance(png: { width: number; height: number; data: Buffer }): Float64Array {
  const linear = (v: number) => {
    const c = v / 255;
    return c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4;
  };
  const out = new Float64Array(png.width * png.height);
  for (let q = 0; q < out.length; q++) {
    out[q] = 0.2126 * linear(png.data[4 * q]) + 0.7152 * linear(png.data[4 * q + 1]) + 0.0722 * linear(png.data[4 * q + 2]);
  }
  return out;
}

/** Box mean of an n×n picture over a (2r + 1)² window (clamped at the edges), by running sums. */
function boxMean(picture: Float64Array, n: number, r: number): Float64Array {
  const pass = (input: Float64Array, horizontal: boolean) => {
    const out = new Float64Array(n * n);
    for (let line = 0; line < n; line++) {
      const at = (i: number) => (horizontal ? line * n + i : i * n + line);
      let sum = 0;
      let count = 0;
      for (let i = 0; i <= Math.min(r, n - 1); i++, count++) sum += input[at(i)];
      for (let i = 0; i < n; i++) {
        out[at(i)] = sum / count;
        if (i + r + 1 < n) {
          sum += input[at(i + r + 1)];
          count++;
        }
        if (i - r >= 0) {
          sum -= input[at(i - r)];
          count--;
        }
      }
    }
    return out;
  };
  return pass(pass(picture, true), false);
}

/**
 * The picture's texture: luminance minus its local mean, divided by its local standard deviation
 * (windows of 2·HIGH_PASS_RADIUS + 1 px). The slow variation of brightness across the frame (the
 * sun's glitter lobe, Fresnel reflectance growing towards the horizon) is not a pattern that
 * repeats, but it would dominate the autocorrelation at every lag; a tiled sea repeats its small
 * features, which this keeps.
 */
const HIGH_PASS_RADIUS = 24;
function texture(picture: Float64Array, n: number): Float64Array {
  const mean = boxMean(picture, n, HIGH_PASS_RADIUS);
  const detail = picture.map((v, q) => v - mean[q]);
  const power = boxMean(
    detail.map((v) => v * v),
    n,
    HIGH_PASS_RADIUS,
  );
  const floor = 1e-12 + 1e-3 * power.reduce((a, b) => a + b, 0) / power.length;
  return detail.map((v, q) => v / Math.sqrt(power[q] + floor));
}

/**
 * Autocorrelation R(dx, dy) of an n×n picture for |dx|, |dy| ≤ n/2, by FFT with zero padding to 2n
 * (no wrap-around): Σ f(x)·f(x + d) / ((n − |dx|)·(n − |dy|)) / var f. Returned as a function of the lag.
 */
function autocorrelation(picture: Float64Array, n: number): (dx: number, dy: number) => number {
  const mean = picture.reduce((a, b) => a + b, 0) / picture.length;
  return autocorrelationOf(
    picture.map((v) => v - mean),
    n,
    n,
  );
}

/** The same for the first `rows` rows of an n-wide picture whose mean is already removed. */
function autocorrelationOf(picture: Float64Array, n: number, rows: number): (dx: number, dy: number) => number {
  let variance = 0;
  for (let q = 0; q < n * rows; q++) variance += picture[q] ** 2;
  variance /= n * rows;
  const m = 2 * n;
  const re = new Float64Array(m * m);
  const im = new Float64Array(m * m);
  for (let y = 0; y < rows; y++) for (let x = 0; x < n; x++) re[y * m + x] = picture[y * n + x];
  fft2d(re, im, m, -1);
  for (let q = 0; q < m * m; q++) {
    re[q] = re[q] * re[q] + im[q] * im[q];
    im[q] = 0;
  }
  fft2d(re, im, m, 1); // Σ_x f(x)·f(x + d) · m² at lag d (mod m)
  return (dx, dy) => {
    const q = ((dy + m) % m) * m + ((dx + m) % m);
    return re[q] / (m * m) / ((n - Math.abs(dx)) * (rows - Math.abs(dy))) / variance;
  };
}

interface Measurement {
  /** Radius (px) where the largest |R| over the ring first drops below the threshold. */
  centralRadius: number;
  /** Largest R outside the central radius (|dx|, |dy| ≤ n/2), and where. */
  maxOffCentre: number;
  maxAt: [number, number];
  /** For each patch period: its lag in px and the largest R within ±2 px of (±P, 0), (0, ±P), (±P, ±P). */
  periods: { patchSize: number; lag: number; peak: number | null }[];
}

function measure(picture: Float64Array, n: number, patchSizes: number[], metresPerPixel: [number, number] | null): Measurement {
  const r = autocorrelation(texture(picture, n), n);
  const half = n / 2;
  let centralRadius = half;
  for (let radius = 1; radius < half; radius++) {
    let ringMax = 0;
    for (let a = 0; a < 8 * radius; a++) {
      const angle = (2 * Math.PI * a) / (8 * radius);
      ringMax = Math.max(ringMax, Math.abs(r(Math.round(radius * Math.cos(angle)), Math.round(radius * Math.sin(angle)))));
    }
    if (ringMax < THRESHOLD) {
      centralRadius = radius;
      break;
    }
  }
  let maxOffCentre = -Infinity;
  let maxAt: [number, number] = [0, 0];
  for (let dy = -half; dy <= half; dy++) {
    for (let dx = -half; dx <= half; dx++) {
      if (dx * dx + dy * dy < centralRadius * centralRadius) continue;
      const value = r(dx, dy);
      if (value > maxOffCentre) [maxOffCentre, maxAt] = [value, [dx, dy]];
    }
  }
  const periods = patchSizes.map((patchSize) => {
    if (!metresPerPixel) return { patchSize, lag: NaN, peak: null };
    const [lx, ly] = [patchSize / metresPerPixel[0], patchSize / metresPerPixel[1]];
    const lag = Math.min(lx, ly);
    // Measurable only outside the central lobe and within half the picture.
    if (lag < centralRadius + 3 || Math.max(lx, ly) > half - 3) return { patchSize, lag, peak: null };
    let peak = -Infinity;
    for (const [sx, sy] of [[1, 0], [0, 1], [1, 1], [1, -1]]) {
      const [cx, cy] = [Math.round(sx * lx), Math.round(sy * ly)];
      for (let dy = -2; dy <= 2; dy++) for (let dx = -2; dx <= 2; dx++) peak = Math.max(peak, r(cx + dx, cy + dy));
    }
    return { patchSize, lag, peak };
  });
  return { centralRadius, maxOffCentre, maxAt, periods };
}

const STRIP = 32;

/**
 * For an oblique view: the autocorrelation of a strip of `rows` rows (texture as above) at lags
 * (dx, dy) with |dy| ≤ 3, and the largest R at |dx| ≥ MIN_LAG (outside the central lobe) and near each
 * patch's period along the rows, patchSize / metresPerPixel.
 */
const MIN_LAG = 12;
function measureStrip(strip: Float64Array, n: number, rows: number, patchSizes: number[], metresPerPixel: number): Measurement {
  // Autocorrelate the strip padded to an n×n picture: lags with |dy| ≤ 3 only use strip rows.
  const padded = new Float64Array(n * n);
  const square = new Float64Array(n * n);
  square.set(strip);
  // Rows below the strip repeat it, so the local statistics near its lower edge are not skewed.
  for (let y = rows; y < n; y++) square.set(strip.subarray(((y - rows) % rows) * n, ((y - rows) % rows + 1) * n), y * n);
  const t = texture(square, n);
  padded.set(t.subarray(0, n * rows));
  // Each row's own mean removed: the 8-bit picture quantizes the slow brightness change down the
  // view into bands one level high and a row wide, which would otherwise correlate along every row.
  for (let y = 0; y < rows; y++) {
    const row = padded.subarray(y * n, (y + 1) * n);
    const mean = row.reduce((a, b) => a + b, 0) / n;
    for (let x = 0; x < n; x++) row[x] -= mean;
  }
  const r = autocorrelationOf(padded, n, rows);
  let maxOffCentre = -Infinity;
  let maxAt: [number, number] = [0, 0];
  for (let dy = -3; dy <= 3; dy++) {
    for (let dx = -n / 2; dx <= n / 2; dx++) {
      if (Math.abs(dx) < MIN_LAG) continue;
      const value = r(dx, dy);
      if (value > maxOffCentre) [maxOffCentre, maxAt] = [value, [dx, dy]];
    }
  }
  const periods = patchSizes.map((patchSize) => {
    const lag = patchSize / metresPerPixel;
    if (lag < MIN_LAG || lag > n / 2 - 4) return { patchSize, lag, peak: null };
    let peak = -Infinity;
    for (let dy = -3; dy <= 3; dy++) for (let dx = -4; dx <= 4; dx++) peak = Math.max(peak, r(Math.round(lag) + dx, dy));
    return { patchSize, lag, peak };
  });
  return { centralRadius: MIN_LAG, maxOffCentre, maxAt, periods };
}

async function openPage(page: Page): Promise<void> {
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(error.message));
  await page.goto(`/tests/browser/tiling/tiling.html?size=${SIZE}`);
  await expect(page).toHaveTitle('ready');
  expect(errors).toEqual([]);
}

interface View {
  name: string;
  height: number;
  /** Degrees below the horizontal. */
  pitch: number;
}

/** Renders one view and returns its measurement (and saves the frame). */
async function renderAndMeasure(page: Page, file: string, view: View, patchSizes: number[]): Promise<Measurement> {
  // Far from the origin of every patch, so the view is not centred on a patch corner.
  const [x0, z0] = [3137.4, -1821.9];
  const pitch = (view.pitch * Math.PI) / 180;
  const reach = view.pitch === 90 ? 0 : view.height / Math.tan(pitch);
  const result = await page.evaluate(
    ([position, target, up]) => window.tiling.render(14.5, position, target, up),
    [
      [x0, view.height, z0],
      // Straight down: up is −z, so the picture's x is world x and its y (downwards) world z.
      // Oblique: looking along +z, so the picture's rows run along world x, a lattice direction.
      view.pitch === 90 ? [x0, 0, z0] : [x0, 0, z0 + reach],
      view.pitch === 90 ? [0, 0, -1] : [0, 1, 0],
    ] as [[number, number, number], [number, number, number], [number, number, number]],
  );
  expect(result.far).toBeGreaterThanOrEqual(result.horizonDistance);
  const buffer = Buffer.from(result.png.replace(/^data:image\/png;base64,/, ''), 'base64');
  writeFileSync(join(OUTPUT, file), buffer);
  const png = PNG.sync.read(buffer);
  expect([png.width, png.height]).toEqual([SIZE, SIZE]);
  // Metres per pixel at the picture's centre: the distance to the sea there times the angle per
  // pixel (2·tan(fov/2)/size); only straight down is the scale the same everywhere.
  const fov = (55 * Math.PI) / 180;
  const distance = view.height / Math.sin(pitch);
  const across = (2 * distance * Math.tan(fov / 2)) / SIZE;
  let m: Measurement;
  if (view.pitch === 90) {
    m = measure(luminance(png), SIZE, patchSizes, [across, across]);
  } else {
    // Oblique: the scale changes down the picture, so only a strip of rows about the centre
    // (±STRIP/2 = ±16 rows, where it changes by less than ±5 %) is measured, at lags along its rows.
    const full = luminance(png);
    const strip = full.slice(((SIZE - STRIP) / 2) * SIZE, ((SIZE + STRIP) / 2) * SIZE);
    m = measureStrip(strip, SIZE, STRIP, patchSizes, across);
  }
  console.log(
    `${view.name}: central radius ${m.centralRadius} px, largest R outside it ${m.maxOffCentre.toFixed(3)} at (${m.maxAt.join(', ')}) px; ` +
      m.periods.map((p) => `${p.patchSize} m → ${p.lag.toFixed(1)} px: ${p.peak === null ? 'not measurable' : `R = ${p.peak.toFixed(3)}`}`).join('; '),
  );
  return m;
}

test.describe('from altitude no tiling is visible', () => {
  test.beforeAll(() => mkdirSync(OUTPUT, { recursive: true }));

  // A known failure, kept as one so that it is seen (test.fail: it fails the run once it passes).
  // Since the glint became Cox–Munk's lobe (seaLighting.glsl), the sun's glitter reaches into the
  // view from 4 km straight down, and there the largest cascade's slopes show as brightness: the
  // picture's autocorrelation at the 457 m patch period is R = 0.594 (1 km: 0.040). The glitter
  // covers a few patches only, over which the blend's angle θ (patchBlend.ts) changes too little to
  // decorrelate them; larger blend amplitudes (×1.8) did not help (R = 0.711). A likely reason
  // (not proven): the blend makes the slopes at x + L cos Δθ·S(x) plus an uncorrelated part, and
  // what depends on the slope evenly (Δθ = π gives −S(x)) correlates as E[cos² Δθ], about ½ for
  // any broad spread of Δθ, whatever the amplitudes. Measured once, not kept: with the largest
  // cascade's slopes left out of the normal, R at 457 m is 0.387 and the 79.3 m patch shows
  // instead (R = 0.729); fading every cascade's slopes into σ² where the largest patch spans
  // 16–128 pixels gave 0.534 here and flattened the 45° view from 4 km. Four copies, weights
  // uniform on the 3-sphere (E[ρ²] = 0.25 over this view, against 0.50 for two; computed from the
  // weights of patchBlend.ts), measured 0.527 here (one copy 0.901, two 0.594; the 457 m cascade
  // alone: two 0.645, four 0.543) and 0.446 45° down from 4 km (two: 0.389): the periodic part of
  // the picture does not follow E[ρ²], so it is not (only) the blend's cos² Δθ. Branch
  // tiling4k-fourcopies keeps that code. What does remove it (session 19, branch tiling4k-stripes):
  // with fixed offsets the sea at x and x + L is made of the same two values P(x), P(x + o), so
  // what the light makes of them correlates whatever the weights; two copies whose offsets in the
  // patch change stripe by stripe where their weight is zero (ψ = κ·e·x + θ, stripes L/2 wide along
  // 56°, offsets from the R2 sequence; Heitz & Neyret 2018's variance-preserving blend) measured
  // R = 0.171–0.183 at 457 m here, largest off-centre 0.328–0.347, 1 km 0.081–0.088, 45° 0.05–0.18,
  // the control 0.946. Not merged: the realisation near the origin then depends on the ramp's phase,
  // and of eight phases tried (0 to 2.6 rad) each failed one of the seabed spec's checks (the foam
  // band's ratio 2.5 ± 10 %: 1.96–3.05; the drawn waterline within a cell of heightAt's: 1.02–1.18)
  // or the lighting spec's (quality levels within 3 levels near the eye: 3.4–4.5; the crest glow).
  // Issue 26.
  const GLITTER_TILES = 'from 4 km the glitter shows the 457 m patch (R = 0.594): issue 26';
  const groups: [string, View[], string?][] = [
    ['1 km up, straight down', [{ name: '1 km up, straight down', height: 1000, pitch: 90 }]],
    ['4 km up, straight down', [{ name: '4 km up, straight down', height: 4000, pitch: 90 }], GLITTER_TILES],
    ['1 and 4 km up, 45° down', [
      { name: '1 km up, 45° down', height: 1000, pitch: 45 },
      { name: '4 km up, 45° down', height: 4000, pitch: 45 },
    ]],
  ];
  for (const [group, views, knownFailure] of groups) {
    test(`the default sea (three cascades), ${group}: no autocorrelation peak at any patch period`, async ({ page }) => {
      test.fail(knownFailure !== undefined, knownFailure);
      await openPage(page);
      await page.evaluate(() => window.tiling.setup({}));
      for (const view of views) {
        const m = await renderAndMeasure(page, `default-${view.height}m-${view.pitch}deg.png`, view, [13.7, 79.3, 457]);
        // Soft: every view is measured and reported even when one fails.
        expect.soft(m.centralRadius, view.name).toBeLessThan(SIZE / 4); // texture, not a blank or a gradient
        // The largest patch's period is measurable from every one of these views.
        expect.soft(m.periods[2].peak, view.name).not.toBeNull();
        for (const { patchSize, peak } of m.periods) if (peak !== null) expect.soft(peak, `${view.name}, ${patchSize} m`).toBeLessThan(THRESHOLD);
        expect.soft(m.maxOffCentre, view.name).toBeLessThan(THRESHOLD);
      }
    });
  }

  test('control: one 250 m patch without the blend tiles visibly, and the measurement sees it', async ({ page }) => {
    await openPage(page);
    await page.evaluate(() => window.tiling.setup({ patchSizes: [250] }, false));
    for (const view of [
      { name: 'control, one 250 m patch, 1.5 km up, straight down', height: 1500, pitch: 90 },
      { name: 'control, one 250 m patch, 1.5 km up, 45° down', height: 1500, pitch: 45 },
    ]) {
      const m = await renderAndMeasure(page, `control-250m-${view.height}m-${view.pitch}deg.png`, view, [250]);
      expect.soft(m.periods[0].peak, view.name).not.toBeNull();
      expect.soft(m.periods[0].peak!, view.name).toBeGreaterThan(THRESHOLD);
      expect.soft(m.maxOffCentre, view.name).toBeGreaterThan(THRESHOLD);
    }
  });
});

test('looking 45° down exactly along ±z draws the same sea as 1 mrad off it', async ({ page }) => {
  // Found while writing the oblique views above: with the view direction exactly in the yz plane
  // the sky (then a box drawn at z = w) was clipped into a shape that covered the sea; 1 mrad to the
  // side it was a normal sea. The sky is now a clip-space triangle (shaders/sky/background.vert).
  await openPage(page);
  await page.evaluate(() => window.tiling.setup({}));
  const frames: Float64Array[] = [];
  for (const dx of [0, 1]) {
    const result = await page.evaluate((dx) => window.tiling.render(14.5, [3137.4, 1000, -1821.9], [3137.4 + dx, 0, -821.9]), dx);
    const buffer = Buffer.from(result.png.replace(/^data:image\/png;base64,/, ''), 'base64');
    writeFileSync(join(OUTPUT, `along-z-${dx}.png`), buffer);
    frames.push(luminance(PNG.sync.read(buffer)));
  }
  let difference = 0;
  for (let q = 0; q < frames[0].length; q++) difference += Math.abs(frames[0][q] - frames[1][q]);
  difference /= frames[0].length;
  console.log(`mean |Δ luminance| between exactly along +z and 1 mrad off: ${difference.toFixed(4)}`);
  expect(difference).toBeLessThan(0.01);
});
