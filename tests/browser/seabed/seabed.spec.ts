/**
 * Shores on the real GPU path (src/layers/shore.ts, shaders/surface/shoaling.glsl): over a 1:50
 * plane beach the surface the vertex shader draws is the one the queries describe (heightAt at each
 * displaced vertex, within 2 cm, against 2 mm without a seabed as a control of the method), and the drawn
 * waterline lies where the queried surface meets the beach, within one cell of the grid, also while
 * the swash runs it up and down the beach (tests/unit/shoaling.test.ts (e) checks its size against
 * Stockdon et al. 2006 on the queries). The shoaling
 * and breaking laws themselves are proven on the queries (tests/unit/shoaling.test.ts). A seabed
 * from meshes is drawn from above and read back; bad seabeds are refused and the last good one
 * stays. The picture of the beach is written to test-results-<port>/seabed/ for a person to look at.
 */
import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { expect, test } from '@playwright/test';

const PORT = Number(process.env.TEST_PORT ?? 5173);
const OUTPUT = join(PORT === 5173 ? 'test-results' : `test-results-${PORT}`, 'seabed');

test('the drawn surface over a beach is the queried one, and so is its waterline', async ({ page }) => {
  await page.goto('/tests/browser/seabed/seabed.html');
  await expect(page).toHaveTitle('ready');
  // Over the surf zone, looking along the shore.
  const view = { position: [-40, 25, -120], target: [60, 0, 40] };
  const result = await page.evaluate((view) => {
    const h = window.seabed;
    // One cascade, no local waves: its factor alone scales each vertex.
    const single = { patchSizes: [79.3], localWaves: false };
    h.setup(false, 11.3, view.position, view.target, single);
    const plain = h.capture();
    h.setup(true, 11.3, view.position, view.target, single);
    const formula = h.shoreFormula(plain, h.capture());
    h.setup(true, 11.3, view.position, view.target);
    const { offsets } = h.waterline(h.capture());
    return { formula, offsets, picture: h.picture() };
  }, view);
  mkdirSync(OUTPUT, { recursive: true });
  writeFileSync(join(OUTPUT, 'beach.png'), Buffer.from(result.picture.split(',')[1], 'base64'));
  const { formula, offsets } = result;
  const worstShore = Math.max(...offsets);
  console.log(
    `shore formula over ${formula.compared} vertices: worst ${(1000 * formula.worst).toFixed(2)} mm (RMS height ${formula.rms.toFixed(3)} m); ` +
      `${offsets.length} waterline crossings, worst ${worstShore.toFixed(2)} cells from the queried waterline`,
  );
  expect(formula.compared).toBeGreaterThan(1000);
  expect(formula.worst).toBeLessThan(2e-3);
  expect(offsets.length).toBeGreaterThan(20);
  expect(worstShore).toBeLessThanOrEqual(1);
});

// Swash (src/spectrum/swash.ts): the drawn waterline runs up and down the beach with the waves.
// Stockdon et al. 2006 (Coastal Engineering 53, eqs. 11–12) give this sea on a 1:50 beach a
// significant swash S = √(H0·L0·(0.563β² + 0.004)) = 0.75 m, four standard deviations of the
// waterline's elevation. Eight instants a quarter of the peak period (6.2 s) apart span nearly two
// waves: below 0.2·S (7 m along the beach) the waterline would be standing still, above 1.5·S it
// would run further than Stockdon's runup. At every instant the drawn
// waterline is where the queried one is, within one cell.
test('the drawn waterline runs up and down the beach with the waves, where heightAt puts it', async ({ page }) => {
  await page.goto('/tests/browser/seabed/seabed.html');
  await expect(page).toHaveTitle('ready');
  // Near the beach: the waterline at |z| < 30 m lies in the finest rings, at the queries' mip level.
  const view = { position: [-30, 12, -50], target: [10, 0, 0] };
  const result = await page.evaluate((view) => {
    const h = window.seabed;
    const instants = [];
    h.setup(true, 0, view.position, view.target);
    for (const t of [3, 4.6, 6.2, 7.8, 9.4, 11, 12.6, 14.2]) {
      h.advance(t);
      const { offsets, drawn } = h.waterline(h.capture());
      // The runup's edge along the line z = 0 across the beach (heightAt; every drawn crossing is checked
      // against heightAt's above), and for the record the drawn crossing within a metre of the line nearest it.
      const z = 0;
      const queried = h.queriedWaterline(z);
      const nearest = drawn.filter(([, zz]) => Math.abs(zz - z) < 1).reduce((best, [x]) => (Math.abs(x - queried) < Math.abs(best - queried) ? x : best), Infinity);
      const nearby = drawn.map((p, i) => [...p, offsets[i]]).filter(([, zz]) => Math.abs(zz) < 30);
      instants.push({ t, z, queried, nearest, offsets: nearby.map(([, , offset]) => offset), crossings: nearby.length, swash: h.stockdonSwash() });
    }
    return { instants, picture: h.picture() };
  }, view);
  mkdirSync(OUTPUT, { recursive: true });
  writeFileSync(join(OUTPUT, 'swash.png'), Buffer.from(result.picture.split(',')[1], 'base64'));
  // Elevation above still water of the queried runup edge (−depth = x/50).
  const elevations = result.instants.map((i) => -i.queried / 50);
  const range = Math.max(...elevations) - Math.min(...elevations);
  const swash = result.instants[0].swash;
  for (const i of result.instants) {
    console.log(
      `t = ${i.t} s: runup edge at z = ${i.z.toFixed(1)} m ${(-i.queried / 50).toFixed(3)} m above still water (x = ${i.queried.toFixed(2)} m), nearest drawn crossing at x = ${i.nearest.toFixed(2)} m; ` +
        `${i.crossings} drawn crossings at |z| < 30 m, worst ${Math.max(...i.offsets).toFixed(2)} cells from heightAt's`,
    );
    expect(i.crossings).toBeGreaterThan(0);
    expect(Math.max(...i.offsets)).toBeLessThanOrEqual(1);
  }
  console.log(`runup edge's elevation range over ${elevations.length} instants: ${range.toFixed(3)} m (${(range * 50).toFixed(1)} m along the beach); Stockdon's S ${swash.toFixed(3)} m`);
  expect(swash).toBeCloseTo(0.75, 1);
  expect(range).toBeGreaterThan(0.2 * swash);
  expect(range).toBeLessThan(1.5 * swash);
});

// The shoreline foam band (shaders/surface/shoaling.glsl, shoreFoam) is set in depth: from the
// waterline out to h_b = Hs/0.78, where the sea's significant wave breaks (McCowan's index). On a
// plane beach of slope tan β its width across the beach is then x_b = h_b/tan β, the surf zone's
// (Longuet-Higgins 1970, J. Geophys. Res. 75, whose surf zone ends at that depth). With everything
// the shore draws a function of the depth, the foam's cross-shore integral ∫F dx = (1/tan β)·∫F dd
// scales as 1/tan β too: on two beaches of 1:20 and 1:50 side by side, under the same sea, the
// gentle one's is 2.5× the steep one's. Read from the vertex shader's own foam (vShoreFoam, every
// vertex), averaged along 37 m of each beach and over four instants.
// Within 10 %: the one part of the shore that is not a function of depth alone is the swash's
// setup η̄ = 0.35·β·√(H0·L0) (Stockdon et al. 2006, eq. 10), which fades out between the depths S/2
// and 1.5·S (S its significant swash, eqs. 11–12), so there the column depth d + η̄ grows by only
// 1 − η̄/S per metre of depth, and the band is stretched by 1/(1 − η̄/S): on this sea (Hs 1.03 m,
// √(H0·L0) ≈ 5.5 m) 1.31 on the 1:20 beach and 1.12 on the 1:50 one, over the 0.2–0.6 m of the
// band's 1.3 m of depth: about 5 % off 2.5, downwards. The rest is the surf's sampling (the
// waves break at different places on the two beaches).
test('the shoreline foam band is h_b/tan β wide: 2.5× wider on a 1:50 beach than on a 1:20 one', async ({ page }) => {
  await page.goto('/tests/browser/seabed/seabed.html');
  await expect(page).toHaveTitle('ready');
  const result = await page.evaluate(() => {
    const h = window.seabed;
    // 6 m/s: Hs about 0.8 m, h_b about 1 m: bands some 20 and 50 m wide, in cells of a metre or less.
    // From 5 m up (the rings' cells grow with the camera's height): cells of 1.6 m within 25 m, 3.2 m within 51 m, 6.4 m beyond.
    h.setup('twoSlopes', 3, [20, 5, 0], [40, 0, 0], { windSpeed: 6, localWaves: false });
    const across = { xMin: -10, bin: 1, bins: 110 };
    const sums = { steep: new Array<number>(across.bins).fill(0), gentle: new Array<number>(across.bins).fill(0) };
    let breakerDepth = 0;
    let empty = 0;
    const instants = [3, 6, 9, 12];
    for (const t of instants) {
      h.advance(t);
      const vertices = h.capture();
      const steep = h.shoreFoamAcross(vertices, -45, -8, across.xMin, across.bin, across.bins);
      const gentle = h.shoreFoamAcross(vertices, 8, 45, across.xMin, across.bin, across.bins);
      steep.foam.forEach((f, b) => (sums.steep[b] += f / instants.length));
      gentle.foam.forEach((f, b) => (sums.gentle[b] += f / instants.length));
      breakerDepth = gentle.breakerDepth;
      empty = Math.max(empty, steep.empty, gentle.empty);
    }
    // For a person: both beaches from above, the 1:20 one on the left, the sea at the top.
    return { ...sums, breakerDepth, empty, bin: across.bin, picture: h.picture([-40, 70, 0], [40, 0, 0]) };
  });
  mkdirSync(OUTPUT, { recursive: true });
  writeFileSync(join(OUTPUT, 'two-slopes.png'), Buffer.from(result.picture.split(',')[1], 'base64'));
  const integral = (foam: number[]) => foam.reduce((sum, f) => sum + f * result.bin, 0);
  const [steep, gentle] = [integral(result.steep), integral(result.gentle)];
  // Where the band ends: the last bin with foam over a tenth of the profile's largest.
  const end = (foam: number[]) => {
    const peak = Math.max(...foam);
    let last = foam.length - 1;
    while (last > 0 && foam[last] <= 0.1 * peak) last--;
    return (last + 1) * result.bin - 10;
  };
  console.log(
    `h_b ${result.breakerDepth.toFixed(3)} m: x_b = h_b/tan β ${(20 * result.breakerDepth).toFixed(1)} m (1:20) and ${(50 * result.breakerDepth).toFixed(1)} m (1:50); ` +
      `foam's cross-shore integral ${steep.toFixed(3)} and ${gentle.toFixed(3)} m: ratio ${(gentle / steep).toFixed(3)} (1/tan β: 2.5); ` +
      `foam over a tenth of its peak out to x = ${end(result.steep)} and ${end(result.gentle)} m; at most ${result.empty} of ${result.steep.length} bins without a vertex`,
  );
  for (const f of [...result.steep, ...result.gentle]) expect(Number.isFinite(f)).toBe(true);
  expect(result.empty).toBeLessThan((5 / 6) * result.steep.length); // cells no wider than six bins
  expect(steep).toBeGreaterThan(1); // a band, not a calm shore
  expect(Math.abs(gentle / steep / 2.5 - 1)).toBeLessThan(0.1);
});

test('a seabed from meshes is drawn from above; bad seabeds are refused and the last good one stays; its textures are freed', async ({ page }) => {
  await page.goto('/tests/browser/seabed/seabed.html');
  await expect(page).toHaveTitle('ready');
  const result = await page.evaluate(() => {
    const h = window.seabed;
    h.setup(true, 0, [0, 30, 0], [100, 0, 0]);
    const depths = h.meshSeabed([[-200, 0], [0, 300], [500, -500], [2000, 100]]);
    const bad = ['nan', 'noGeometry', 'noArea'].map((kind) => h.badSeabed(kind));
    return { depths, bad, memory: h.memoryCycle() };
  });
  // Every texture the seabeds made (depth maps, shoaling tables) is freed with the Ocean.
  expect(result.memory.after).toEqual(result.memory.before);
  // The plane y = −x/50: depth x/50 (within a millimetre: float32 heights, bilinear over a plane).
  [-200, 0, 500, 2000].forEach((x, i) => expect(Math.abs(result.depths[i] - x / 50)).toBeLessThan(1e-3));
  expect(result.bad.map((b) => b.parameter)).toEqual(['seabed.depthAt', 'seabed.meshes[0]', 'seabed.bounds']);
  for (const b of result.bad) expect(b.depthAfter).toBeCloseTo(20, 3);
});
