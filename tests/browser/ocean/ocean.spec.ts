import { expect, test, type Browser, type Page } from '@playwright/test';
import { sharedPages } from '../shared/sharedPages';
import { ALSO_ON_OLDEST_THREE } from '../shared/threeRange';

async function openOcean(page: Page, width = 640, height = 360): Promise<void> {
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(error.message));
  await page.goto(`/tests/browser/ocean/ocean.html?width=${width}&height=${height}`);
  await expect(page).toHaveTitle('ready');
  expect(errors).toEqual([]);
}

// The tests that need no fresh page share one per canvas size, set back as it loaded before each
// (window.ocean.reset: no sea, the first sky and sun, the camera at the origin). Tests keep a page
// of their own where a page's first Ocean matters (the queries' warm-up, the queries from the
// workers), where they listen to the page's console, or where they load other modules (three's
// WebGPU build).
const sharedOceanPage = sharedPages(
  (page, size) => openOcean(page, ...(size.split('x').map(Number) as [number, number])),
  (page) => page.evaluate(() => window.ocean.reset()),
);
const sharedOcean = (browser: Browser, width = 640, height = 360) => sharedOceanPage(browser, `${width}x${height}`);

test.describe('horizon geometry, read back from the real vertex shader', () => {
  // Cameras several patches from the origin (of every cascade: 13.7, 79.3, 457 m), low and high.
  const cameras: [string, [number, number, number], [number, number, number]][] = [
    ['2 m up', [917.3, 2, -561.8], [1000, 0, -700]],
    ['40 m up', [917.3, 40, -561.8], [1000, 0, -700]],
    // 10 000 km away, where float32 holds a world coordinate only to a metre: the surface works in
    // metres from the eye, and must be as exact there.
    ['2 m up, 10 000 km from the origin', [1e7 + 917.3, 2, 1e7 - 561.8], [1e7 + 1000, 0, 1e7 - 700]],
  ];
  for (const [name, position, target] of cameras) {
    test(`each vertex is its rest point plus (Dx, h, Dz) of the simulation there, ${name}`, name === '2 m up' ? ALSO_ON_OLDEST_THREE : {}, async ({ browser }) => {
      const page = await sharedOcean(browser);
      const results = await page.evaluate(
        ([position, target]) => {
          window.ocean.setup({ seed: 7, windSpeed: 14 });
          window.ocean.view(position, target);
          return [window.ocean.geometryCheck(3.5), window.ocean.geometryCheck(9.25)];
        },
        [position, target] as const,
      );
      for (const result of results) {
        expect(result.count).toBeGreaterThan(5000);
        // Rest points are fixed world grid points (multiples of their ring's cell): anchored.
        expect(result.maxOffGrid).toBeLessThan(1e-3);
        for (const [level, { count, maxError }] of Object.entries(result.byLevel)) {
          expect(count, `vertices at mip ${level}`).toBeGreaterThan(0);
          // Float32 positions and bilinear weights: ~1e-5 of the RMS; 1% is the bound, and
          // a wrong texel offset, ring frame or mip gives errors of order 1.
          expect(maxError, `mip ${level}`).toBeLessThan(0.01);
        }
      }
      // 2 m up with 32 cells a ring (360 px), the finest cells are ≥ 2 m / 4: the finest cascade's
      // (13.7 m / 256) mip 4, the middle one's mip 1, the largest one's mip 0.
      if (name.startsWith('2 m up')) expect(Object.keys(results[0].byLevel)).toContain('4');
      // Not frozen: between the two times almost every height changed (those at the coarsest mip,
      // the patch mean, stay put by design).
      const [before, after] = results.map((result) => result.heights);
      expect(after.length).toBe(before.length);
      const moved = before.filter((h, i) => Math.abs(h - after[i]) > 1e-3 * results[0].rms).length;
      const coarsest = results[0].byLevel.coarsest?.count ?? 0;
      expect(moved).toBeGreaterThan(0.98 * (before.length - coarsest));
    });
  }

  test('the same world point gets the same position whichever way the camera moved', async ({ browser }) => {
    const page = await sharedOcean(browser);
    const maxDifference = await page.evaluate(() => {
      window.ocean.setup({ seed: 3 });
      const positions = new Map<string, number>();
      let worst = 0;
      for (const x of [100, 103.7, 131.2]) {
        window.ocean.view([x, 5, 40], [x + 50, 0, -20]);
        const { heights, restPoints } = window.ocean.geometryCheck(2, true);
        restPoints.forEach((key, i) => {
          const seen = positions.get(key);
          if (seen !== undefined) worst = Math.max(worst, Math.abs(seen - heights[i]));
          else positions.set(key, heights[i]);
        });
      }
      return worst;
    });
    expect(maxDifference).toBeLessThan(1e-4);
  });
});

test.describe('shading', () => {
  test('a flat sea under a uniform white sky reflects exactly the Fresnel reflectance', ALSO_ON_OLDEST_THREE, async ({ browser }) => {
    const page = await sharedOcean(browser);
    // Pixels down the middle column, from near the horizon to straight below a tilted camera.
    const pixels: [number, number][] = [0, 10, 20, 30, 45, 60, 90, 130, 180, 240, 300, 359].map((y) => [320, y]);
    const samples = await page.evaluate((pixels) => {
      window.ocean.setUniformEnvironment([1, 1, 1]);
      // Refraction, caustics and glint switched off: the picture is R alone, in linear output.
      window.ocean.setup({ windSpeed: 0 }, { absorption: [1e3, 1e3, 1e3], scatterColour: [0, 0, 0], causticColour: [0, 0, 0] });
      window.ocean.setSun([0, 0.2, 1]);
      window.ocean.view([0, 10, 0], [0, 4, -10]);
      window.ocean.render(0, true);
      return window.ocean.probe(pixels);
    }, pixels);
    // The course report's formula, in its own sin/tan form (the shader uses the amplitude form).
    const reflectance = (cosI: number): number => {
      const thetaI = Math.acos(cosI);
      const thetaT = Math.asin(Math.sin(thetaI) / 1.333);
      return 0.5 * (Math.sin(thetaT - thetaI) ** 2 / Math.sin(thetaT + thetaI) ** 2 + Math.tan(thetaT - thetaI) ** 2 / Math.tan(thetaT + thetaI) ** 2);
    };
    const onSea = samples.filter((sample) => sample.hitsSea);
    expect(onSea.length).toBeGreaterThan(8);
    for (const { value, cosIncident } of onSea) {
      // 8-bit output rounds to 1/255 ≈ 0.004; the issue allows 0.01.
      expect(Math.abs(value - reflectance(cosIncident)), `cos θi = ${cosIncident}`).toBeLessThan(0.01);
    }
    // The probe spans the interesting range: ~0.02 near normal incidence up to far brighter.
    expect(Math.min(...onSea.map((s) => s.value))).toBeLessThan(0.03);
    expect(Math.max(...onSea.map((s) => s.value))).toBeGreaterThan(0.3);
  });
});

test.describe('the sea reaches the horizon', () => {
  // Camera heights from 1 m to 2 km and pitches from level to straight down, away from the origin.
  // (1 m up needs a gentle sea: under 15 m/s of wind the crests are higher than the camera.)
  const views: [string, number, [number, number, number], [number, number, number]][] = [
    ['1 m up, level, 5 m/s wind', 5, [333.3, 1, -71.2], [433.3, 1, -21.2]],
    ['12 m up, looking down 7°', 15, [0, 12, 0], [60, 0, -80]],
    ['60 m up, looking down 60°', 15, [1200, 60, 800], [1230, 8, 815]],
    ['400 m up, level', 15, [-5000, 400, 2500], [-4000, 400, 2000]],
    ['2 km up, looking down 28°', 15, [0, 2000, 0], [2000, 700, 1500]],
    ['2 km up, straight down', 15, [90, 2000, 40], [90.01, 0, 40]],
  ];
  // The panel's extremes, choppiness 4 in a 30 m/s wind (no foam to hide anything): crests fold
  // over everywhere; the folded surface must still close over the sea (its back faces are drawn).
  const extremes: [string, number, [number, number, number], [number, number, number], number][] = [
    ['at the panel\'s extremes (30 m/s, choppiness 4), 12 m up looking down 7°', 30, [0, 12, 0], [60, 0, -80], 4],
    ['at the panel\'s extremes (30 m/s, choppiness 4), 40 m up looking down 35°', 30, [500, 40, 300], [560, 0, 280], 4],
  ];
  for (const [name, windSpeed, position, target, choppiness = 1] of [...views, ...extremes]) {
    test(`no gap below the horizon: ${name}`, async ({ browser }) => {
      const page = await sharedOcean(browser);
      const result = await page.evaluate(
        ([windSpeed, position, target, choppiness]) => {
          window.ocean.setup({ seed: 11, windSpeed, choppiness, foamAmount: 0 });
          window.ocean.view(position, target);
          return window.ocean.holesBelowHorizon(6.5);
        },
        [windSpeed, position, target, choppiness] as const,
      );
      expect(result.checked).toBeGreaterThan(50_000);
      // A gap shows the red background. Below the horizon only single pixels, where a ray grazes
      // between far rings, are tolerated: at most 1 in 20 000 of the pixels checked.
      expect(result.holes, JSON.stringify(result.firstHoles)).toBeLessThanOrEqual(result.checked / 20_000);
    });
  }
});

test('whitecaps show as white water in a strong wind, and not at all in a calm', async ({ browser }) => {
  const page = await sharedOcean(browser);
  const brightened = await page.evaluate(() =>
    [20, 3].map((windSpeed) => {
      window.ocean.view([0, 12, 0], [60, 0, -80]);
      return window.ocean.foamBrightened({ seed: 11, windSpeed }, 30);
    }),
  );
  console.log(`canvas brightened by foam: ${brightened.map((f) => (100 * f).toFixed(2)).join(' % at 20 m/s, ')} % at 3 m/s`);
  // 20 m/s: about 5 % of the sea is covered (tests/unit/whitecapFoam.test.ts), below the horizon.
  expect(brightened[0]).toBeGreaterThan(0.005);
  expect(brightened[0]).toBeLessThan(0.2);
  expect(brightened[1]).toBe(0); // Beaufort 2: no foam at all
});

test('heightAt(x, z) is the height of the rendered surface over (x, z), choppy displacement inverted', async ({ page }) => {
  // Two cascades whose finest texel (40 m / 256) is coarse enough for the rings nearest a camera
  // 2 m up to sample every cascade at mip 0 (128 cells a ring at 1000 px): heightAt is the
  // unfiltered sum of the layers, which the surface draws only there.
  await openOcean(page, 1000, 1000);
  const result = await page.evaluate(() => {
    window.ocean.view([917.3, 2, -561.8], [1000, 0, -700]);
    return window.ocean.heightAtCheck({ seed: 9, windSpeed: 14, choppiness: 1.5, patchSizes: [40, 250] }, 6.75);
  });
  // Vertices where the sea folds over (Jacobian ≤ 0.2; a few % at choppiness 1.5) are ambiguous
  // and left out; Newton's inversion elsewhere lands within ~2e-3 of the RMS (float32 fields). A
  // heightAt that ignored the displacement would be off by ~20% of the RMS here.
  expect(result.compared).toBeGreaterThan(800);
  expect(result.folded).toBeLessThan(result.compared / 10);
  expect(result.maxError / result.rms).toBeLessThan(0.01);
});

for (const [path, jitter] of [['gpu', 0], ['gpu', 0.005], ['js', 0.005]] as const) {
  test(`the queries read fields the workers computed, not the main thread, and agree with the fields of the time asked: ${path} path, steps of 1/60 s ± ${jitter * 1000} ms`, async ({ page }) => {
    await openOcean(page); // a page of its own: it counts the fields the main thread computes while its workers start
    const result = await page.evaluate(([p, j]) => window.ocean.queriesFromWorkers(p, j), [path, jitter] as const);
    console.log(`queries from workers, ${result.path}, jitter ${jitter * 1000} ms: started after ${result.warmUpFrames} frames (${result.computedInWarmUp} computed here, ${result.computedByQueries} of them in the queries); then over 20 frames computed here ${result.computedHere} times, worst error ${(result.worstError * 1000).toFixed(3)} mm (RMS height ${result.rms.toFixed(3)} m); after a new wind ${(result.worstAfterChange * 1000).toFixed(3)} mm (RMS height ${result.rmsAfterChange.toFixed(3)} m)`);
    expect(result.path).toBe(path === 'gpu' ? 'gpu-rgba32f' : 'js-worker');
    // Until the workers have started the queries read a provisional copy computed here, carried like the
    // workers' fields: once per LONGEST_CARRY (40 ms) of simulated time at most, not every frame
    // (steps of 1/60 s ± jitter); from then on, never.
    // The workers start 250 ms after the first query and build their spectra first (~25 frames
    // of ~100 ms here); 60 leaves room for a slower machine.
    expect(result.warmUpFrames).toBeLessThan(60);
    const carriedSpan = Math.ceil((result.warmUpFrames * (1 / 60 + jitter)) / 0.04) + 1;
    expect(result.computedInWarmUp).toBeLessThanOrEqual(result.cascades * carriedSpan);
    // Those are computed with the updates, so that no query waits for them (cascadeQueryFields.ts).
    expect(result.computedByQueries).toBe(0);
    expect(result.computedHere).toBe(0);
    // The workers' fields are asked for the next frame's time (fieldWorker.ts); steps that change
    // by 2·jitter leave that much to carry by the velocities, within 1 % of the RMS height
    // (surfaceQuery.test.ts); without the carry 10 ms off would be ~4 % off.
    expect(result.rms).toBeGreaterThan(0.3);
    expect(result.worstError).toBeLessThan(0.01 * result.rms);
    // After a new wind the new cascades answer from provisional copies (computed in the arrays of
    // the ones they replace) until their workers answer: within the same 1 % (unit test over 400
    // points: surfaceQuery.test.ts), and still none computed inside a query.
    expect(result.rmsAfterChange).toBeGreaterThan(result.rms);
    expect(result.worstAfterChange).toBeLessThan(0.01 * result.rmsAfterChange);
  });
}

for (const path of ['gpu', 'js'] as const) {
  test(`the first update's warm-up queries leave no trace: no query worker, no velocities asked, until the app queries (${path} path)`, async ({ page }) => {
    await openOcean(page); // its first Ocean warms the queries up
    const result = await page.evaluate((p) => window.ocean.warmUpLeavesNoTrace(p), path);
    console.log(`warm-up, ${path} path: ${result.warmUpQueries} queries reached the ${result.cascades} cascades in the first update; workers ${result.workersBefore} before the app's first query, ${result.workersAfter} after; requests for velocities ${result.velocityRequestsBefore} before, ${result.velocityRequestsAfter} after; its height ${(result.heightError * 1000).toFixed(3)} mm from the exact one (RMS ${result.rms.toFixed(3)} m)`);
    // It ran (the page's first Ocean): heightAt, normalAt and velocityAt each asked every cascade.
    expect(result.warmUpQueries).toBeGreaterThanOrEqual(3 * result.cascades);
    // ...and was forgotten: no cascade counts as queried, and on the GPU path no query worker was made
    // (QUERY_WORKER_DELAY_MS after a query); the JS path's workers are its own, one per cascade, and
    // are not asked for velocities (a third more work) until a query wants them.
    expect(result.queriedBefore).toBe(false);
    expect(result.workersBefore).toBe(path === 'gpu' ? 0 : result.cascades);
    expect(result.velocityRequestsBefore).toBe(0);
    // The app's first query then starts the query workers as before (each asked for velocities at the
    // updates after), and is answered within 1 % of the RMS height.
    expect(result.workersAfter).toBe(result.cascades);
    expect(result.velocityRequestsAfter).toBeGreaterThan(0);
    expect(result.heightError).toBeLessThan(0.01 * result.rms);
  });
}

test('the queries read the local waves on the GPU without waiting for it: read back behind a fence, a frame or two late, then the same', async ({ browser }) => {
  const page = await sharedOcean(browser);
  const result = await page.evaluate(() => window.ocean.localWavesQueriedOnGpu());
  console.log(`local waves on the GPU, queried every frame: ${result.waited} read-backs waited after the first, ${result.notWaited} did not; then ${result.worstDifference} m from the fields read back at once (local field up to ${result.largestLocal.toFixed(3)} m)`);
  expect(result.path).toBe('gpu');
  expect(result.waited).toBe(0);
  expect(result.notWaited).toBeGreaterThan(1);
  expect(result.largestLocal).toBeGreaterThan(0.01); // rings around the stone
  expect(result.worstDifference).toBeLessThan(1e-5); // the same fields once the last read-back is in
});

test('heightAt and normalAt include the local waves: after a stone the height differs from the cascades\' by the local field', async ({ browser }) => {
  const page = await sharedOcean(browser);
  const result = await page.evaluate(() => window.ocean.queriesWithLocalWaves());
  expect(result.largestLocal).toBeGreaterThan(0.05); // rings of centimetres around the stone
  expect(result.worstHeight).toBeLessThan(1e-4); // float32 fields, summed in another order
  expect(result.normalsDiffer).toBe(true);
});

test('the batch queries (heightsAt, normalsAt, velocitiesAt) on the GPU path equal the JS path and the single-point queries', async ({ browser }) => {
  const page = await sharedOcean(browser);
  const result = await page.evaluate(() => window.ocean.batchQueries());
  expect(result.largestSpeed).toBeGreaterThan(0.3); // the water moves (m/s)
  // The queries read the JS path's CPU fields on both paths: the same numbers (float32 out).
  expect(result.gpuVersusJs).toBeLessThan(1e-5);
  expect(result.batchVersusSingle).toBeLessThan(1e-5);
  expect(result.messages).toEqual([
    'heightsAt(xz) must be an array of x0, z0, x1, z1, … (an even length); got [1, 2, 3]',
    expect.stringMatching(/^velocitiesAt\(xz, out\) must be an array of at least 3 numbers \(3 per point\); got /),
    'normalsAt(xz)[1] must be a finite coordinate in metres, at most 1e12 in size; got NaN',
    'velocityAt(x, z) must be finite coordinates in metres, at most 1e12 in size; got [Infinity, 0]',
    // Finite, but so far away that the query's texel coordinates would overflow (NaN before).
    'heightAt(x, z) must be finite coordinates in metres, at most 1e12 in size; got [-1.6e+308, 0]',
  ]);
});

test('the sea honours scene.fog (Fog and FogExp2) as three\'s materials do: far water takes the fog colour, near water hardly', ALSO_ON_OLDEST_THREE, async ({ browser }) => {
  const page = await sharedOcean(browser);
  const { near, far } = await page.evaluate(() => window.ocean.fogCheck());
  const [clearNear, clearFar] = [near[0], far[0]];
  // Magenta fog: red and blue rise, green falls. Fog from 40 m to 400 m: none at 20 m, all at 2 km.
  expect(Math.abs(near[1][0] - clearNear[0]) + Math.abs(near[1][1] - clearNear[1])).toBeLessThan(3);
  expect(far[1][0]).toBeGreaterThan(240);
  expect(far[1][1]).toBeLessThan(15);
  // FogExp2 at 0.01/m: 1 − e^{−0.04} = 4 % at 20 m, all at 2 km.
  expect(near[2][0]).toBeGreaterThan(clearNear[0]);
  expect(near[2][1]).toBeLessThan(clearNear[1] + 1);
  expect(far[2][0]).toBeGreaterThan(240);
  expect(far[2][1]).toBeLessThan(15);
  expect(clearFar[1]).toBeGreaterThan(60); // without fog the far sea is not magenta
});

test('with a plain, a logarithmic or a reversed depth buffer the sea hides the submerged half of a floating box', ALSO_ON_OLDEST_THREE, async ({ browser }) => {
  const page = await sharedOcean(browser);
  const modes = await page.evaluate(() => window.ocean.depthBufferCheck());
  for (const { mode, supported, inForce, above, below } of modes) {
    console.log(`depth buffer ${mode}${inForce ? ' (in force)' : ' (not available here: plain depth in force)'}: box above the water ${above.join(',')}, below ${below.join(',')}`);
    // Where this context and three.js can give it, it must be what was drawn with: else the test
    // would pass on a plain depth buffer and check nothing.
    if (supported) expect(inForce, `${mode} depth buffer in force`).toBe(true);
    expect(above, `${mode}: the box above the water is red`).toEqual([255, 0, 0]);
    // Below the water line the sea is drawn, not the box (whose red would show through).
    expect(below[0] - Math.max(below[1], below[2]), `${mode}: the box under the water is hidden`).toBeLessThan(60);
  }
  expect(modes.find((m) => m.mode === 'logarithmic')!.inForce).toBe(true);
});

test('inside an EffectComposer (RenderPass, then OutputPass for tone mapping and colour space) the picture is the plain render\'s', async ({ browser }) => {
  const page = await sharedOcean(browser);
  const result = await page.evaluate(() => window.ocean.composerCheck());
  const show = (rgb: number[]) => rgb.map((c) => c.toFixed(0)).join(',');
  console.log(`EffectComposer against renderer.render: mean difference ${result.meanDifference.toFixed(3)} levels, largest ${result.largestDifference}, ${result.over4} of ${result.channels} channel values over 4; composer's sky ${show(result.sky)}, sea ${show(result.sea)}`);
  // The composer renders into a half-float target and tone-maps in the OutputPass rather than in
  // the materials: only rounding differs (measured: 0.008 levels on average, at most 1). A plain
  // copy in place of the OutputPass (no tone mapping, linear output) is 55 levels off on average.
  expect(result.meanDifference).toBeLessThan(0.5);
  expect(result.largestDifference).toBeLessThanOrEqual(4);
  // Not blank: a bright blue sky over a darker blue sea.
  const [sky, sea] = [result.sky, result.sea];
  expect(sky[2]).toBeGreaterThan(120);
  expect(sky[2]).toBeGreaterThan(sky[0] + 20);
  expect(sea[2]).toBeGreaterThan(sea[0] + 10);
  expect(sea[0] + sea[1] + sea[2]).toBeLessThan(sky[0] + sky[1] + sky[2] - 60);
});

test.describe('under water', () => {
  for (const ior of [1.333, 1.5]) {
    test(`Snell's window: looking up from under a calm sea, the sky shows within asin(1/n) of the zenith (n = ${ior}, within 1°)`, async ({ browser }) => {
      // Snell's law at the water–air interface: light from the whole sky reaches the eye through a
      // cone of half-angle asin(n_air/n_water) (48.6° for water, 41.8° for n = 1.5); outside it the
      // surface reflects totally (Born & Wolf, "Principles of Optics", §1.5.4).
      const page = await sharedOcean(browser, 512, 512);
      const { edgeAngles, centreRed } = await page.evaluate((n) => window.ocean.snellWindow(n), ior);
      const expected = (Math.asin(1 / ior) * 180) / Math.PI;
      console.log(`Snell's window at n = ${ior}: edges at ${edgeAngles.map((a) => a.toFixed(2)).join(', ')}° (asin(1/n) = ${expected.toFixed(2)}°)`);
      expect(centreRed).toBeGreaterThan(50); // the sky, straight up
      expect(edgeAngles).toHaveLength(4);
      for (const angle of edgeAngles) expect(Math.abs(angle - expected)).toBeLessThan(1);
    });
  }
});

test.describe('the Ocean API', () => {
  test('horizonDistanceFor(height) is valid before the first render and reaches the farthest vertex drawn', async ({ browser }) => {
    const page = await sharedOcean(browser);
    for (const [position, target] of [
      [[10, 12, -20], [60, 0, -80]],
      [[-300, 400, 250], [700, 400, -250]],
    ] as [number, number, number][][]) {
      const result = await page.evaluate(
        ([position, target]) => {
          window.ocean.view(position, target);
          return window.ocean.horizonCheck({ resolution: 64, seed: 2 });
        },
        [position, target] as const,
      );
      // Before any render horizonDistance is the distance for a camera at sea level, the least.
      expect(result.beforeAtSeaLevel).toBe(result.seaLevel);
      expect(result.seaLevel).toBeGreaterThan(100);
      expect(result.before).toBeGreaterThan(result.seaLevel);
      // Asked before the render, it is what the render then reports, and the skirt's far corner
      // (what a far plane must reach) lies within it, by less than its last cells.
      expect(result.after).toBe(result.before);
      expect(result.farthest).toBeLessThanOrEqual(result.before);
      expect(result.farthest).toBeGreaterThan(0.85 * result.before);
      expect(result.before).toBeGreaterThan(1000 * position[1]);
    }
  });

  test('colours: a THREE.Color, a hex number, a CSS string or linear [r, g, b]; the British names are aliases', async ({ browser }) => {
    const page = await sharedOcean(browser);
    const result = await page.evaluate(() => {
      const { Ocean, Color, ParameterError, renderer } = window.ocean;
      const ocean = new Ocean(renderer, { resolution: 16, worker: false, scatterColour: '#1a6b80', causticColor: new Color(0x1a6b80) });
      const uniforms = ocean.surface.material.uniforms;
      const teal = new Color(0x1a6b80).toArray();
      const constructed = { scatter: ocean.shading.scatterColor, caustic: ocean.shading.causticColor, uniform: uniforms.scatterColor.value.toArray() };
      ocean.setShading({ causticColour: 0x1a6b80, scatterColor: [0.1, 0.2, 0.3] });
      const set = { scatter: ocean.shading.scatterColor, caustic: ocean.shading.causticColor, uniform: uniforms.causticColor.value.toArray() };
      const errors: string[] = [];
      for (const bad of [{ scatterColor: 'sea green' }, { causticColor: 0x1000000 }, { scatterColour: [1, 2] }, { scatterColr: 'red' }]) {
        try {
          ocean.setShading(bad as never);
        } catch (error) {
          errors.push(`${error instanceof ParameterError}: ${(error as Error).message}`);
        }
      }
      const kept = ocean.shading.scatterColor;
      ocean.dispose();
      return { teal, constructed, set, errors, kept };
    });
    for (const values of [result.constructed.scatter, result.constructed.caustic, result.constructed.uniform, result.set.caustic, result.set.uniform] as number[][]) {
      values.forEach((value, i) => expect(value).toBeCloseTo(result.teal[i], 6));
    }
    expect(result.set.scatter).toEqual([0.1, 0.2, 0.3]);
    expect(result.errors).toEqual([
      expect.stringMatching(/^true: scatterColor must be a colour: .*; got "sea green"$/),
      expect.stringMatching(/^true: causticColor must be a colour: .*; got 16777216$/),
      expect.stringMatching(/^true: scatterColour must be a colour: .*; got \[1, 2\]$/),
      expect.stringMatching(/^true: scatterColr must be one of .* \(did you mean scatterColor\?\); got "red"$/),
    ]);
    expect(result.kept).toEqual([0.1, 0.2, 0.3]);
  });

  test('the sun by direction: a Vector3 or [x, y, z] becomes elevation and azimuth and back; bad ones throw and keep the sun', async ({ browser }) => {
    const page = await sharedOcean(browser);
    const result = await page.evaluate(() => {
      const { Ocean, Vector3, ParameterError, renderer } = window.ocean;
      const sunOf = (ocean: InstanceType<typeof Ocean>) => ({
        elevation: ocean.sky.sunElevation,
        azimuth: ocean.sky.sunAzimuth,
        direction: ocean.sky.sunDirection.toArray(),
        // What the sea's glint and caustics read.
        shaded: (ocean.surface.material.uniforms.sunDirection.value as InstanceType<typeof Vector3>).toArray(),
      });
      const ocean = new Ocean(renderer, { resolution: 16, worker: false, sunDirection: [0, 1, 1] });
      const constructed = sunOf(ocean);
      const direction = new Vector3(-2, 1, -2);
      ocean.setSun({ direction });
      const byVector = sunOf(ocean);
      ocean.setSun({ elevation: 10 });
      const elevationOnly = sunOf(ocean);
      ocean.setSun(25, 60);
      const errors: string[] = [];
      ocean.setSun({ cloudCover: 0.4 });
      for (const bad of [{ direction: [0, 0, 0] }, { direction: [NaN, 1, 0] }, { direction: [1, 1, 1], elevation: 5 }, { elevaton: 5 }, { elevation: 70, cloudCover: 2 }, { cloudCover: NaN }]) {
        try {
          ocean.setSun(bad as never);
        } catch (error) {
          errors.push(`${error instanceof ParameterError}: ${(error as Error).message}`);
        }
      }
      let constructorError = '';
      try {
        new Ocean(renderer, { sunDirection: [0, 0, 0] });
      } catch (error) {
        constructorError = `${error instanceof ParameterError}: ${(error as Error).message}`;
      }
      const kept = sunOf(ocean);
      const clouded = ocean.sky.cloudCover;
      ocean.dispose();
      return { constructed, byVector, elevationOnly, errors, constructorError, kept, clouded };
    });
    expect(result.constructed.elevation).toBeCloseTo(45, 10);
    expect(result.constructed.azimuth).toBeCloseTo(90, 10);
    // (-2, 1, -2): a third of its length up, towards −x and −z.
    expect(result.byVector.elevation).toBeCloseTo((Math.asin(1 / 3) * 180) / Math.PI, 10);
    expect(result.byVector.azimuth).toBeCloseTo(-135, 10);
    [-2 / 3, 1 / 3, -2 / 3].forEach((c, i) => {
      expect(result.byVector.direction[i]).toBeCloseTo(c, 6);
      expect(result.byVector.shaded[i]).toBeCloseTo(c, 6);
    });
    expect(result.elevationOnly.elevation).toBe(10);
    expect(result.elevationOnly.azimuth).toBeCloseTo(-135, 10);
    expect(result.errors).toEqual([
      'true: direction must be a finite, non-zero direction towards the sun: a Vector3 or [x, y, z], y up; got [0, 0, 0]',
      'true: direction must be a finite, non-zero direction towards the sun: a Vector3 or [x, y, z], y up; got [NaN, 1, 0]',
      'true: direction must be given without an elevation or azimuth (it sets both); got [1, 1, 1]',
      expect.stringMatching(/^true: elevaton must be one of elevation, azimuth, direction, cloudCover \(did you mean elevation\?\)/),
      expect.stringMatching(/^true: cloudCover must be a fraction of the sky from 0 \(clear\) to 1 \(overcast\); got 2/),
      expect.stringMatching(/^true: cloudCover must be a fraction of the sky from 0 \(clear\) to 1 \(overcast\); got NaN/),
    ]);
    expect(result.clouded).toBe(0.4); // setSun({ cloudCover }) reaches the sky, and the bad ones above kept it
    expect(result.constructorError).toMatch(/^true: sunDirection must be a finite, non-zero direction/);
    expect([result.kept.elevation, result.kept.azimuth]).toEqual([25, 60]);
  });

  test('setPath and the path option: ocean.path reports the preference, the path that runs and why, and the change is an event', async ({ browser }) => {
    const page = await sharedOcean(browser);
    const result = await page.evaluate(() => {
      const { Ocean, ParameterError, renderer } = window.ocean;
      const ocean = new Ocean(renderer, { resolution: 16, worker: false, localWaves: false, path: 'gpu' });
      const events: string[] = [];
      ocean.addEventListener('pathchange', ({ path }) => events.push(`${path.preference} ${path.running} "${path.reason}"`));
      ocean.update(1);
      const paths = [ocean.path];
      ocean.setPath('js');
      paths.push(ocean.path);
      ocean.update(2);
      ocean.setPath('auto');
      ocean.update(3);
      paths.push(ocean.path);
      let error = '';
      try {
        ocean.setPath('cuda' as never);
      } catch (e) {
        error = `${e instanceof ParameterError}: ${(e as Error).message}`;
      }
      paths.push(ocean.path);
      ocean.dispose();
      // The option at construction, with the JS path's worker.
      const inWorker = new Ocean(renderer, { resolution: 16, localWaves: false, path: 'js' });
      paths.push(inWorker.path);
      inWorker.dispose();
      return { paths, events, error };
    });
    expect(result.paths).toEqual([
      { preference: 'gpu', running: 'gpu-rgba32f', reason: '' },
      { preference: 'js', running: 'js', reason: 'asked for' }, // at once, before the next update
      { preference: 'auto', running: 'gpu-rgba32f', reason: '' },
      { preference: 'auto', running: 'gpu-rgba32f', reason: '' }, // a bad preference changes nothing
      { preference: 'js', running: 'js-worker', reason: 'asked for' },
    ]);
    // The event comes at the update after each change of the running path, not for the first.
    expect(result.events).toEqual(['js js "asked for"', 'auto gpu-rgba32f ""']);
    expect(result.error).toBe('true: path must be \'auto\', \'gpu\' or \'js\'; got "cuda"');
  });

  test('after dispose() every method and getter throws a DisposedError (a ParameterError), and so do its local waves; disposing twice is harmless', async ({ browser }) => {
    const page = await sharedOcean(browser);
    const result = await page.evaluate(() => {
      const { Ocean, ParameterError, DisposedError, renderer } = window.ocean;
      const ocean = new Ocean(renderer, { resolution: 16, worker: false });
      ocean.update(1);
      const waves = ocean.localWaves!; // held by the caller: disposed with the ocean
      ocean.dispose();
      ocean.dispose();
      const calls: [string, () => unknown][] = [
        ['update', () => ocean.update(2)],
        ['setParameters', () => ocean.setParameters({ windSpeed: 5 })],
        ['setShading', () => ocean.setShading({ ior: 1.4 })],
        ['setSun', () => ocean.setSun(10, 20)],
        ['setPath', () => ocean.setPath('js')],
        ['heightAt', () => ocean.heightAt(0, 0)],
        ['normalAt', () => ocean.normalAt(0, 0)],
        ['heightsAt', () => ocean.heightsAt([0, 0], [0])],
        ['horizonDistanceFor', () => ocean.horizonDistanceFor(10)],
        ['horizonDistance', () => ocean.horizonDistance],
        // The getters too: they would read freed layers or report a sea that no longer exists.
        ['time', () => ocean.time],
        ['parameters', () => ocean.parameters],
        ['shading', () => ocean.shading],
        ['heightRms', () => ocean.heightRms],
        ['seaState', () => ocean.seaState],
        ['repeatPeriod', () => ocean.repeatPeriod],
        ['path', () => ocean.path],
        ['localWaves', () => ocean.localWaves],
      ];
      const errors = calls.map(([name, call]) => {
        try {
          call();
          return `${name}: no error`;
        } catch (error) {
          const e = error as InstanceType<typeof DisposedError>;
          return `${name}: ${e instanceof DisposedError && e instanceof ParameterError} ${e.name} ${e.parameter}: ${e.message}`;
        }
      });
      const localWaveErrors = [() => waves.drop(0, 0), () => waves.addPressure({ length: 8, beam: 2.6, draft: 0.6 }, { x: 0, z: 0, heading: 0 }), () => waves.follow(1, 2)].map((call) => {
        try {
          call();
          return 'no error';
        } catch (error) {
          const e = error as InstanceType<typeof DisposedError>;
          return `${e instanceof DisposedError} ${e.parameter}`;
        }
      });
      return { calls: calls.map(([name]) => name), errors, localWaveErrors, children: ocean.children.length };
    });
    const method = (call: string) => (call === 'horizonDistance' ? 'horizonDistanceFor' : call);
    expect(result.calls).toHaveLength(18);
    expect(result.errors).toEqual(
      result.calls.map(
        (call) =>
          `${call}: true DisposedError Ocean.${method(call)}: Ocean.${method(call)}: this Ocean has been disposed (its GPU resources are freed); create a new Ocean`,
      ),
    );
    // The local waves an ocean made are freed with it: a stone dropped on them later would make no waves.
    expect(result.localWaveErrors).toEqual(['true LocalWaves.drop', 'true LocalWaves.addPressure', 'true LocalWaves.follow']);
    expect(result.children).toBe(0); // left in a scene, it draws nothing
  });
});

test('night: as the sun sets the sky and the sea darken together, and with the sun 10° down both are dark', async ({ browser }) => {
  const page = await sharedOcean(browser);
  const views = await page.evaluate(() => window.ocean.nightCheck([30, 0, -3, -6, -10]));
  for (const v of views) {
    console.log(`sun at ${v.elevation}°: sky luminance ${v.sky.toPrecision(3)} (brightest ${v.skyMax}), sea ${v.sea.toPrecision(3)} (brightest ${v.seaMax}), sea/sky ${(v.sea / v.sky).toPrecision(3)}`);
  }
  const [day, , twilight, civilEnd, night] = views;
  expect(day.sky).toBeGreaterThan(0.2); // a bright day, not a black picture
  expect(day.sea).toBeGreaterThan(0.02);
  // From 3° below the horizon the light falls by about 0.35 decades per degree (AMS Glossary of
  // Meteorology, "civil twilight": ~400 lx at sunset, ~3.4 lx at −6°): sky and sea both fall far below
  // the day, and the sea does not stay bright under a dark sky (its share of the sky's light stays
  // within a factor of 3 of the day's).
  for (const dusk of [twilight, civilEnd]) {
    expect(dusk.sky).toBeLessThan(0.3 * day.sky);
    expect(dusk.sea).toBeLessThan(0.3 * day.sea);
    expect(dusk.sea / dusk.sky).toBeLessThan(3 * (day.sea / day.sky));
  }
  // Night: no pixel brighter than 3 levels, sky or sea (before: a black sky over a bright blue sea).
  expect(night.skyMax).toBeLessThanOrEqual(3);
  expect(night.seaMax).toBeLessThanOrEqual(3);
});

test.describe('a JS worker that fails', () => {
  // Each cascade's fields, a few frames after the fault, must be those of the time they show,
  // exactly (the worker and the main thread run the same float64 code into float32 arrays).
  for (const [fault, after, reason] of [
    ['throws', 'js-worker', ''], // replaced by a new worker: still off the main thread
    ['terminated', 'js-worker', ''],
    ['unloadable', 'js', /^the JS worker failed before its first answer/],
    ['blocked', 'js', /^workers are blocked here \(blocked by the test\)/],
  ] as const) {
    test(`${fault}: the sea keeps moving, and ocean.path, the warning and the pathchange event say what runs`, async ({ page }) => {
      test.setTimeout(120_000);
      const warnings: string[] = [];
      page.on('console', (message) => {
        if (message.type() === 'warning' && message.text().includes('worker')) warnings.push(message.text());
      });
      const errors: string[] = [];
      page.on('pageerror', (error) => errors.push(error.message));
      await openOcean(page);
      const result = await page.evaluate((kind) => window.ocean.workerFault(kind), fault);
      console.log(`worker ${fault}: ${result.before} → ${result.after} (${result.reason || 'no reason'}); largest field error ${result.largestError} of heights up to ${result.largestHeight.toFixed(3)} m; events ${JSON.stringify(result.events)}`);
      expect(result.largestHeight).toBeGreaterThan(0.01); // the fields compared are not all zero
      expect(result.largestError).toBe(0);
      expect(result.after).toBe(after);
      if (after === 'js') {
        expect(result.reason).toMatch(reason);
        expect(warnings.some((w) => w.includes('the JS path runs on the main thread'))).toBe(true);
      } else {
        expect(result.reason).toBe('asked for'); // path: 'js' is the preference; nothing fell back
        expect(warnings.some((w) => w.includes('replaced by a new one'))).toBe(true);
      }
      // The event comes when the running path changes after the first update (a blocked worker is
      // known at construction: the path never changes there).
      expect(result.events).toEqual(fault === 'unloadable' ? [expect.stringMatching(/^js: the JS worker failed before its first answer/)] : []);
      expect(errors).toEqual([]); // handled: nothing uncaught
    });
  }
});

test.describe('a renderer the Ocean cannot drive', () => {
  test("three.js's WebGPURenderer (its WebGL2 backend here) gets an UnsupportedError naming it, not a TypeError from inside three.js", async ({ page }) => {
    await openOcean(page, 160, 90);
    const thrown = await page.evaluate(async () => {
      // From the dev server, as a user's bundler would serve them.
      const webgpu = '/node_modules/three/build/three.webgpu.js';
      const oceanModule = '/src/ocean.ts';
      const { WebGPURenderer } = (await import(webgpu)) as typeof import('three/webgpu');
      const { Ocean } = (await import(oceanModule)) as typeof import('../../../src/ocean');
      const renderer = new WebGPURenderer({ forceWebGL: true });
      await renderer.init();
      try {
        new Ocean(renderer as never);
        return null;
      } catch (error) {
        return { name: (error as Error).name, message: (error as Error).message };
      } finally {
        renderer.dispose();
      }
    });
    expect(thrown?.name).toBe('UnsupportedError');
    expect(thrown?.message).toContain("this is three.js's WebGPURenderer: use the Ocean of three-fft-ocean/webgpu for it");
  });
});

test("an Ocean's first frame draws the sea: the grid the drawing buffer asks for is in place before the render (three.js takes a mesh's geometry before its onBeforeRender)", async ({ page }) => {
  // 960×540 asks for 64 cells a ring, not the 32 the grid is made with: the first frame used to
  // draw the grid it replaced, freed, and showed sky over flat dark water.
  await openOcean(page, 960, 540);
  const result = await page.evaluate(() => {
    const { renderer, Ocean, Scene, PerspectiveCamera } = window.ocean;
    const scene = new Scene();
    const camera = new PerspectiveCamera(55, 960 / 540, 0.5, 2e4);
    camera.position.set(0, 12, 0);
    camera.lookAt(60, 0, -80);
    const ocean = new Ocean(renderer);
    scene.add(ocean);
    const gl = renderer.getContext();
    const frame = () => {
      ocean.update(2.5, camera);
      renderer.render(scene, camera);
      const pixels = new Uint8Array(4 * 960 * 540);
      gl.readPixels(0, 0, 960, 540, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
      return pixels;
    };
    const [first, second] = [frame(), frame()];
    ocean.dispose();
    let differing = 0;
    for (let i = 0; i < first.length; i += 4) if (Math.abs(first[i] - second[i]) + Math.abs(first[i + 1] - second[i + 1]) + Math.abs(first[i + 2] - second[i + 2]) > 6) differing++;
    // The sea's rows (the lower third) vary from pixel to pixel: waves, not a flat colour.
    const luminance: number[] = [];
    for (let y = 0; y < 180; y += 3) for (let x = 0; x < 960; x += 3) luminance.push(first[4 * (y * 960 + x)] + first[4 * (y * 960 + x) + 1] + first[4 * (y * 960 + x) + 2]);
    const mean = luminance.reduce((a, b) => a + b, 0) / luminance.length;
    const spread = Math.sqrt(luminance.reduce((a, b) => a + (b - mean) ** 2, 0) / luminance.length);
    return { differing, spread };
  });
  console.log(`first frame at 960×540: ${result.differing} pixels differ from the second frame of the same time; luminance spread in the sea's rows ${result.spread.toFixed(1)}`);
  expect(result.differing).toBe(0);
  expect(result.spread).toBeGreaterThan(5);
});

test("update(t, camera): the local waves' grid follows the camera given, stays without one, and a bad camera is refused naming it", async ({ browser }) => {
  const page = await sharedOcean(browser);
  const result = await page.evaluate(() => {
    const { Ocean, ParameterError, PerspectiveCamera, renderer } = window.ocean;
    const ocean = new Ocean(renderer, { resolution: 16, worker: false });
    const waves = ocean.localWaves!;
    const camera = new PerspectiveCamera();
    const centre = () => waves.frame.origin.map((o) => o + waves.frame.size / 2);
    camera.position.set(300.4, 5, -120.2);
    ocean.update(1, camera);
    ocean.update(1.1, camera); // the grid moves at the update that steps after the target changed
    const followed = centre();
    ocean.update(1.2);
    const withoutCamera = centre();
    let error = '';
    try {
      ocean.update(1.3, { position: [0, 0, 0] } as never);
    } catch (e) {
      error = `${e instanceof ParameterError}: ${(e as Error).message}`;
    }
    ocean.dispose();
    return { followed, withoutCamera, error, cell: waves.grid.cellSize };
  });
  // Centred under the camera to within a texel of the grid (it moves in whole texels).
  expect(Math.abs(result.followed[0] - 300.4)).toBeLessThanOrEqual(result.cell);
  expect(Math.abs(result.followed[1] + 120.2)).toBeLessThanOrEqual(result.cell);
  expect(result.withoutCamera).toEqual(result.followed);
  expect(result.error).toMatch(/^true: update\(t, camera\) must be a three\.js camera \(an Object3D\) the local waves follow, or nothing; got /);
});
