import { expect, test, type Page } from '@playwright/test';
import { mkdirSync, writeFileSync } from 'node:fs';
import type { ViewRequest, ViewResult } from './lighting';
import { onePageForFile } from '../shared/sharedPages';

/**
 * The sea's light from the slopes the grid does not show (src/render/seaLighting.ts,
 * shaders/surface/seaLighting.glsl), in real pictures of a whole Ocean: the glitter's width against
 * Cox & Munk, the same brightness at every quality level, and the far sea as bright as a
 * supersampled picture of it. One page for the file; small canvases.
 */

let page: Page;
test.describe.configure({ mode: 'default' });
onePageForFile('/tests/browser/lighting/lighting.html', (opened) => {
  page = opened;
});

const BASE: ViewRequest = {
  windSpeed: 10,
  quality: 'high',
  width: 320,
  height: 180,
  eyeHeight: 10,
  pitch: 10,
  yaw: 0,
  fov: 40,
  sunElevation: 30,
  sunAzimuth: 0,
  time: 3,
};

async function view(changes: Partial<ViewRequest>): Promise<ViewResult> {
  return page.evaluate((request) => window.lightingHarness.render(request), { ...BASE, ...changes });
}

/** Keeps a picture under test-results for a look (the spec's pictures are described in the report). */
function keep(name: string, result: ViewResult): void {
  if (!result.png) return;
  mkdirSync('test-results/lighting', { recursive: true });
  writeFileSync(`test-results/lighting/${name}.png`, Buffer.from(result.png.split(',')[1], 'base64'));
}

type Vec3 = [number, number, number];
const normalize = (v: Vec3): Vec3 => {
  const l = Math.hypot(...v);
  return [v[0] / l, v[1] / l, v[2] / l];
};
const cross = (a: Vec3, b: Vec3): Vec3 => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];

/** The direction through the centre of pixel (x, y) (rows from the top) of the harness's camera. */
function pixelRay(request: ViewRequest, x: number, y: number): Vec3 {
  const pitch = (request.pitch * Math.PI) / 180;
  const yaw = (request.yaw * Math.PI) / 180;
  const forward: Vec3 = [Math.cos(pitch) * Math.cos(yaw), -Math.sin(pitch), Math.cos(pitch) * Math.sin(yaw)];
  const right = normalize(cross(forward, [0, 1, 0]));
  const up = cross(right, forward);
  const tan = Math.tan((request.fov * Math.PI) / 360);
  const u = ((2 * (x + 0.5)) / request.width - 1) * tan * (request.width / request.height);
  const v = (1 - (2 * (y + 0.5)) / request.height) * tan;
  return normalize([0, 1, 2].map((c) => forward[c] + u * right[c] + v * up[c]) as Vec3);
}

/** Mean of channel c over the pixels whose ray meets the flat sea between `near` and `far` metres. */
function bandMean(result: ViewResult, request: ViewRequest, near: number, far: number): { mean: Vec3; count: number } {
  const sum: Vec3 = [0, 0, 0];
  let count = 0;
  for (let y = 0; y < result.height; y++) {
    for (let x = 0; x < result.width; x++) {
      const d = pixelRay(request, x, y);
      if (d[1] >= 0) continue;
      const distance = (request.eyeHeight / -d[1]) * Math.hypot(d[0], d[2]);
      if (distance < near || distance > far) continue;
      for (let c = 0; c < 3; c++) sum[c] += result.pixels[4 * (y * result.width + x) + c];
      count++;
    }
  }
  return { mean: sum.map((s) => s / count) as Vec3, count };
}

test('the glitter towards a sun 30° high widens with the wind as Cox & Munk’s σ (5, 10, 15 m/s)', async () => {
  // Cox & Munk (1954), "Measurement of the roughness of the sea surface from photographs of the
  // sun's glitter", J. Opt. Soc. Am. 44: 838–850: the glitter is the sun reflected by facets whose
  // slopes are Gaussian with mean square σ² = 0.003 + 5.12·10⁻³·U (clean surface). From 200 m, looking
  // down at the glitter with a 100° view, each pixel's ray needs a facet of slope ζ (the half
  // vector of the ray and the sun, over the flat sea) to show the sun; the glint's radiance (the
  // picture less the same picture without the sun's light on the water) divided by
  // F·/(4·cos θv·cos⁴ θh) is then ∝ p(ζ) = exp(−|ζ|²/σ²)/(πσ²), and ln of it against |ζ|² is a line
  // of slope −1/σ², fitted where |ζ|² < 2σ² (iterated from σ² = 0.03), weighted by the density.
  const sun: Vec3 = [Math.cos(Math.PI / 6), Math.sin(Math.PI / 6), 0];
  const measured: { windSpeed: number; sigma: number; coxMunk: number }[] = [];
  for (const windSpeed of [5, 10, 15]) {
    const request: ViewRequest = { ...BASE, windSpeed, eyeHeight: 200, pitch: 45, fov: 100, width: 160, height: 120, linear: true, time: 7 };
    const lit = await view(request);
    const unlit = await view({ ...request, sunlit: false });
    const samples: { slope2: number; density: number }[] = [];
    for (let y = 0; y < request.height; y++) {
      for (let x = 0; x < request.width; x++) {
        const d = pixelRay(request, x, y);
        if (d[1] > -0.05) continue;
        const h = normalize([sun[0] - d[0], sun[1] - d[1], sun[2] - d[2]]);
        const cosView = -d[1];
        const cosHalf = h[1];
        const cosIncident = sun[0] * h[0] + sun[1] * h[1] + sun[2] * h[2];
        const glint = lit.pixels[4 * (y * request.width + x) + 1] - unlit.pixels[4 * (y * request.width + x) + 1];
        samples.push({ slope2: (1 - cosHalf * cosHalf) / (cosHalf * cosHalf), density: (glint * 4 * cosView * cosHalf ** 4) / fresnel(cosIncident) });
      }
    }
    let variance = 0.03;
    for (let iteration = 0; iteration < 6; iteration++) variance = fitVariance(samples, 2 * variance);
    const coxMunk = 0.003 + 5.12e-3 * windSpeed;
    measured.push({ windSpeed, sigma: Math.sqrt(variance), coxMunk: Math.sqrt(coxMunk) });
  }
  console.log(measured.map((m) => `U = ${m.windSpeed} m/s: glitter σ ${m.sigma.toFixed(3)}, Cox–Munk σ ${m.coxMunk.toFixed(3)}, ratio ${(m.sigma / m.coxMunk).toFixed(3)}`).join('\n'));
  for (const m of measured) expect(Math.abs(m.sigma / m.coxMunk - 1), `${m.windSpeed} m/s`).toBeLessThan(0.2);
  measured.slice(1).forEach((m, i) => expect(m.sigma).toBeGreaterThan(measured[i].sigma));
});

test('backlit crests glow in the scatter colour, and not without it (Atlas, GDC 2019)', async () => {
  // seaLighting.glsl's crestGlow, after Mihelich & Tcheblokov, "Wakes, Explosions and Lighting:
  // Interactive Water Simulation in Atlas" (GDC 2019): sunlight crosses the thin tops of the waves
  // and leaves them in the colour the water scatters, towards an eye that looks at a low sun. A
  // sun 5° high, 30° to the right of the view, out of the picture (its glitter too); the sun's own
  // light on the water is the picture less the same picture without it, in linear radiance,
  // projected on the scatter colour's direction. Crest pixels (the highest tenth of the near
  // band's displaced heights, read in the 'height' mode) must show more of it than trough pixels
  // (the lower half), by at least 4 % of what the troughs show along that direction; with the
  // scatter colour black the difference must go (below a tenth of it), and what the scatter adds
  // there must have no red, as the scatter colour has none.
  const request: ViewRequest = { ...BASE, eyeHeight: 6, pitch: 6, yaw: 0, sunElevation: 5, sunAzimuth: 50, linear: true, time: 5 };
  const heights = await view({ ...request, shadingMode: 'height' });
  const near: number[] = [];
  for (let y = 0; y < request.height; y++) {
    for (let x = 0; x < request.width; x++) {
      const d = pixelRay(request, x, y);
      if (d[1] >= 0) continue;
      const distance = (request.eyeHeight / -d[1]) * Math.hypot(d[0], d[2]);
      if (distance >= 10 && distance <= 100) near.push(y * request.width + x);
    }
  }
  const sorted = near.map((i) => heights.pixels[4 * i]).sort((a, b) => a - b);
  const [trough, crest] = [sorted[Math.floor(0.5 * sorted.length)], sorted[Math.floor(0.9 * sorted.length)]];
  const scatter: Vec3 = [0.0, 0.035, 0.06];
  const along = normalize(scatter);
  const sunsLight = async (scatterColor: Vec3) => {
    const [lit, unlit] = [await view({ ...request, scatterColor }), await view({ ...request, scatterColor, sunlit: false })];
    const sums = { crest: [0, 0, 0, 0], trough: [0, 0, 0, 0], troughSeen: [0, 0, 0] };
    for (const i of near) {
      const height = heights.pixels[4 * i];
      const group = height >= crest ? sums.crest : height <= trough ? sums.trough : null;
      if (!group) continue;
      for (let c = 0; c < 3; c++) group[c] += lit.pixels[4 * i + c] - unlit.pixels[4 * i + c];
      group[3]++;
      if (group === sums.trough) for (let c = 0; c < 3; c++) sums.troughSeen[c] += lit.pixels[4 * i + c];
    }
    const mean = (g: number[]) => [0, 1, 2].map((c) => g[c] / g[3]) as Vec3;
    const [crestLight, troughLight] = [mean(sums.crest), mean(sums.trough)];
    const difference = [0, 1, 2].map((c) => crestLight[c] - troughLight[c]) as Vec3;
    const seen = mean([...sums.troughSeen, sums.trough[3]]);
    const project = (v: Vec3) => v[0] * along[0] + v[1] * along[1] + v[2] * along[2];
    return { difference, alongScatter: project(difference), troughAlong: project(seen), counts: [sums.crest[3], sums.trough[3]] };
  };
  const glowing = await sunsLight(scatter);
  keep('crests', await view({ ...request, linear: false, png: true }));
  const black = await sunsLight([0, 0, 0]);
  const added = [0, 1, 2].map((c) => glowing.difference[c] - black.difference[c]);
  console.log(
    `crest − trough of the sun's light on the water (linear RGB), ${glowing.counts[0]} crest and ${glowing.counts[1]} trough pixels:\n` +
      `  scatter ${scatter.join(', ')}: ${glowing.difference.map((c) => c.toExponential(2)).join(', ')} (along the scatter colour ${glowing.alongScatter.toExponential(2)}, ${((100 * glowing.alongScatter) / glowing.troughAlong).toFixed(1)} % of the troughs' whole radiance along it)\n` +
      `  scatter 0: ${black.difference.map((c) => c.toExponential(2)).join(', ')} (along it ${black.alongScatter.toExponential(2)})`,
  );
  expect(glowing.counts[0]).toBeGreaterThan(100);
  // Measured: 7.7 % of the troughs' radiance along the scatter colour (scatter 0: −0.4 %).
  expect(glowing.alongScatter).toBeGreaterThan(0.04 * glowing.troughAlong);
  expect(Math.abs(black.alongScatter)).toBeLessThan(0.1 * glowing.alongScatter);
  expect(Math.abs(added[0])).toBeLessThan(0.05 * added[2]);
});

test('every quality level shows the sea as bright as \'high\' does, near and far within 3 levels', async () => {
  // The levels' grids (adaptiveQuality.ts: N 1024 … 32, 3 or 2 cascades) and render scales
  // (1 … 0.3) differ; the slopes a grid leaves out are in the light (resolved + unresolved =
  // Cox–Munk), so the mean colour of a band of the sea must not move with them (the bound,
  // 3 levels). The sun 30° high, 120° to the left: no glitter in view, the sky's reflection and the
  // water's colour. Near, the slopes of a coarse grid or a small render scale are mostly in the
  // Gaussian taps of slopeTaps.glsl rather than in the pixels' normals, and the taps' mean
  // reflectance is what they must get right: with a 3-point rule 'low' measured 3.7 levels darker
  // in red than 'high' (3.4 with the cells' variance of the spectrum kept at N = 64), with the
  // 5-point rule ≤ 1.4 in every channel.
  const request: Partial<ViewRequest> = { eyeHeight: 20, pitch: 4, yaw: 120, png: true };
  const bands = [] as { level: string; near: Vec3; far: Vec3 }[];
  for (const quality of ['high', 'medium', 'low', 'lowest'] as const) {
    const result = await view({ ...request, quality });
    keep(`quality-${quality}`, result);
    const full = { ...BASE, ...request, quality };
    bands.push({ level: quality, near: bandMean(result, full, 40, 150).mean, far: bandMean(result, full, 1000, 5000).mean });
  }
  console.log(bands.map((b) => `${b.level}: near ${b.near.map((c) => c.toFixed(1)).join(', ')}; far ${b.far.map((c) => c.toFixed(1)).join(', ')}`).join('\n'));
  for (const band of bands.slice(1)) {
    for (let c = 0; c < 3; c++) {
      expect(Math.abs(band.near[c] - bands[0].near[c]), `${band.level} near, channel ${c}`).toBeLessThanOrEqual(3);
      expect(Math.abs(band.far[c] - bands[0].far[c]), `${band.level} far, channel ${c}`).toBeLessThanOrEqual(3);
    }
  }
});

test('the far sea (1–5 km) has the mean colour of a 4×4-supersampled picture of it (within 2 levels)', async () => {
  // Far away a pixel spans many waves: mip-mapping averages their slopes out of the normal and
  // seaLighting.ts puts their variance back into the light. A picture rendered at 4× the size and
  // box-averaged 4×4 down resolves them (16 rays a pixel) and is the reference.
  const request: ViewRequest = { ...BASE, eyeHeight: 40, pitch: 1.5, fov: 12, yaw: 120, png: true };
  const one = await view(request);
  const supersampled = await view({ ...request, supersample: 4, png: false });
  keep('far', one);
  const [far, reference] = [one, supersampled].map((result) => bandMean(result, request, 1000, 5000));
  console.log(`far band (${far.count} pixels): ${far.mean.map((c) => c.toFixed(1)).join(', ')}; 4×4 supersampled: ${reference.mean.map((c) => c.toFixed(1)).join(', ')}`);
  expect(far.count).toBeGreaterThan(1000);
  for (let c = 0; c < 3; c++) expect(Math.abs(far.mean[c] - reference.mean[c]), `channel ${c}`).toBeLessThanOrEqual(2);
});

test('the far sea (1–5 km) does not flicker from frame to frame at 30 fps, with the filtered slopes in its light or without', async () => {
  // A far pixel spans many waves; its normal is the mip-filtered mean of their slopes and the light
  // takes the variance filtered out (Bruneton, Neyret & Holzschuch 2010, §4). Measured: the mean
  // absolute difference of the 8-bit channels between two frames 1/30 s apart in the band 1–5 km
  // away, and, as the control that shows the measurement sees the sea move, in the band
  // 300 m–1 km; the reference is the same view with the filtered slopes left out of the light (both
  // here, the figures in the log). A quarter of a level on average is far below what shows.
  const request: ViewRequest = { ...BASE, eyeHeight: 40, pitch: 1.5, fov: 12, yaw: 120 };
  const flicker = async (changes: Partial<ViewRequest>): Promise<{ near: number; far: number }> => {
    const [first, next] = [await view({ ...request, ...changes }), await view({ ...request, ...changes, time: request.time + 1 / 30 })];
    const sums = { near: [0, 0], far: [0, 0] };
    for (let y = 0; y < first.height; y++) {
      for (let x = 0; x < first.width; x++) {
        const d = pixelRay(request, x, y);
        if (d[1] >= 0) continue;
        const distance = (request.eyeHeight / -d[1]) * Math.hypot(d[0], d[2]);
        const band = distance >= 300 && distance < 1000 ? sums.near : distance >= 1000 && distance <= 5000 ? sums.far : null;
        if (!band) continue;
        for (let c = 0; c < 3; c++) band[0] += Math.abs(first.pixels[4 * (y * first.width + x) + c] - next.pixels[4 * (y * first.width + x) + c]);
        band[1] += 3;
      }
    }
    expect(Math.min(sums.near[1], sums.far[1])).toBeGreaterThan(3000);
    return { near: sums.near[0] / sums.near[1], far: sums.far[0] / sums.far[1] };
  };
  const [filtered, reference] = [await flicker({}), await flicker({ filteredSlopes: false })];
  console.log(
    `mean |frame − next frame| at 30 fps, 8-bit levels: far band (1–5 km) ${filtered.far.toFixed(3)} with the filtered slopes in the light, ${reference.far.toFixed(3)} without; ` +
      `300 m–1 km ${filtered.near.toFixed(3)} and ${reference.near.toFixed(3)}`,
  );
  for (const measured of [filtered, reference]) {
    expect(measured.near).toBeGreaterThan(0.5);
    expect(measured.far).toBeLessThan(0.25);
  }
});

/** The unpolarized Fresnel reflectance of water (n = 1.333) at this cosine, as common/fresnel.glsl. */
function fresnel(cosIncident: number): number {
  const sinT = Math.sqrt(1 - cosIncident * cosIncident) / 1.333;
  const cosT = Math.sqrt(1 - sinT * sinT);
  const rs = (cosIncident - 1.333 * cosT) / (cosIncident + 1.333 * cosT);
  const rp = (1.333 * cosIncident - cosT) / (1.333 * cosIncident + cosT);
  return 0.5 * (rs * rs + rp * rp);
}

/** σ² from the weighted least-squares line of ln(density) against |ζ|² over |ζ|² < window. */
function fitVariance(samples: { slope2: number; density: number }[], window: number): number {
  let [sw, sx, sy, sxx, sxy] = [0, 0, 0, 0, 0];
  for (const { slope2, density } of samples) {
    if (slope2 >= window || !(density > 0)) continue;
    const [x, y, w] = [slope2, Math.log(density), density];
    sw += w;
    sx += w * x;
    sy += w * y;
    sxx += w * x * x;
    sxy += w * x * y;
  }
  const slope = (sw * sxy - sx * sy) / (sw * sxx - sx * sx);
  return -1 / slope;
}
