/**
 * Layers are equals (src/layers/waveLayer.ts): a layer defined only in this test (SwellLayer, a
 * long-crested swell by linear wave theory) and added through the public API is updated on the
 * sea's clock, drawn by the real vertex shader, felt by the queries, and taken off again; the
 * Ocean refuses what does not meet the contract and leaves the layer to its owner.
 */
import { expect, test, type Page } from '@playwright/test';

async function openOcean(page: Page): Promise<void> {
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(error.message));
  await page.goto('/tests/browser/ocean/ocean.html?width=640&height=360');
  await expect(page).toHaveTitle('ready');
  expect(errors).toEqual([]);
}

/** From the dev server, as the pages load their modules. */
const SWELL_MODULE = '/tests/browser/layers/swellLayer.ts';

test('a layer of its own, added to the simulation, is drawn: every vertex is its rest point plus the sum of all layers there, the swell too', async ({ page }) => {
  await openOcean(page);
  const result = await page.evaluate(async (module) => {
    const { SwellLayer } = (await import(module)) as typeof import('./swellLayer');
    window.ocean.setup({ seed: 7, windSpeed: 8 });
    window.ocean.view([317.3, 3, -161.8], [400, 0, -300]);
    const without = window.ocean.geometryCheck(3.5);
    // 6 waves of 33 m across a 200 m patch (between the 79.3 m and 457 m cascades), 0.8 m high.
    window.ocean.addLayer(new SwellLayer(0.8, 200, 6, 64));
    const withSwell = window.ocean.geometryCheck(3.5);
    const moved = without.heights.filter((h, i) => Math.abs(h - withSwell.heights[i]) > 0.05).length;
    return { byLevel: withSwell.byLevel, count: withSwell.count, moved, rms: withSwell.rms };
  }, SWELL_MODULE);
  console.log(`with the swell: ${result.count} vertices, ${result.moved} moved by over 5 cm, worst error per mip ${JSON.stringify(result.byLevel)} of RMS ${result.rms.toFixed(3)} m`);
  // The swell moves the drawn surface (0.8 m against the cascades' ~0.1 m RMS at 8 m/s)...
  expect(result.moved).toBeGreaterThan(0.5 * result.count);
  // ...and the vertices are where the sum of every layer puts them, as for the cascades alone
  // (ocean.spec.ts): a shader that left the swell out would be off by its height, of order 1 RMS.
  for (const [level, { count, maxError }] of Object.entries(result.byLevel)) {
    expect(count, `vertices at mip ${level}`).toBeGreaterThan(0);
    expect(maxError, `mip ${level}`).toBeLessThan(0.01);
  }
});

test("an Ocean's queries feel a layer added with addLayer, follow it in time, and forget it once removed; the layer stays its owner's", async ({ page }) => {
  await openOcean(page);
  const result = await page.evaluate(async (module) => {
    const { SwellLayer } = (await import(module)) as typeof import('./swellLayer');
    const { Ocean, renderer } = window.ocean;
    // Choppiness 0: every layer is sampled at the point asked, so the swell adds its own height.
    const ocean = new Ocean(renderer, { resolution: 64, windSpeed: 8, seed: 5, choppiness: 0 });
    const swell = new SwellLayer(0.8, 200, 6, 256);
    const points = Array.from({ length: 40 }, (_, p) => [-90 + p * 4.7, 30 - p * 2.3]);
    const heights = (t: number) => {
      ocean.update(t);
      return points.map(([x, z]) => ocean.heightAt(x, z));
    };
    const verticalSpeeds = () => points.map(([x, z]) => ocean.velocityAt(x, z).y);
    const [before, speedsBefore] = [heights(12), verticalSpeeds()];
    ocean.addLayer(swell);
    const [withSwell, speedsWith] = [heights(12), verticalSpeeds()];
    const later = heights(13.5); // the swell's crests move on with its own clock
    let [heightError, speedError, laterError] = [0, 0, 0];
    const cascadesAt135 = (() => {
      ocean.removeLayer(swell);
      return heights(13.5);
    })();
    points.forEach(([x], p) => {
      heightError = Math.max(heightError, Math.abs(withSwell[p] - before[p] - swell.heightAt(x, 12)));
      laterError = Math.max(laterError, Math.abs(later[p] - cascadesAt135[p] - swell.heightAt(x, 13.5)));
      // ∂h/∂t of A·cos(kx − ωt) is A·ω·sin(kx − ωt).
      const expectedSpeed = swell.amplitude * swell.angularFrequency * Math.sin(swell.waveNumber * x - swell.angularFrequency * 12);
      speedError = Math.max(speedError, Math.abs(speedsWith[p] - speedsBefore[p] - expectedSpeed));
    });
    const removedError = Math.max(...heights(12).map((h, p) => Math.abs(h - before[p])));
    const messages: string[] = [];
    for (const bad of [{}, null, { ...swell, frame: { ...swell.frame, size: 0 } }]) {
      try {
        ocean.addLayer(bad as never);
      } catch (error) {
        messages.push(`${(error as Error).name}: ${(error as Error).message}`);
      }
    }
    ocean.addLayer(swell);
    try {
      ocean.addLayer(swell);
    } catch (error) {
      messages.push(`${(error as Error).name}: ${(error as Error).message}`);
    }
    ocean.dispose();
    const speedScale = swell.amplitude * swell.angularFrequency;
    return { heightError, laterError, speedError, speedScale, removedError, messages, disposedWithOcean: swell.disposed };
  }, SWELL_MODULE);
  console.log(`queries with a 0.8 m swell: height off by ${result.heightError.toExponential(2)} m, ${result.laterError.toExponential(2)} m 1.5 s later; ∂h/∂t off by ${result.speedError.toExponential(2)} m/s of ${result.speedScale.toFixed(3)}; after removal ${result.removedError} m`);
  // The queries interpolate each layer bilinearly between texels: for a 33.3 m wave sampled every
  // 0.78 m that is off by at most (k·Δx)²/8 = 0.27 % of A (the linear-interpolation error bound
  // h²·max|f''|/8). 1 % of A leaves room, and is far from a swell left out (off by up to A).
  expect(result.heightError).toBeLessThan(0.01 * 0.8);
  expect(result.laterError).toBeLessThan(0.01 * 0.8);
  expect(result.speedError).toBeLessThan(0.01 * result.speedScale);
  expect(result.removedError).toBe(0);
  expect(result.messages).toHaveLength(4);
  for (const message of result.messages.slice(0, 3)) expect(message).toMatch(/^ParameterError: layer must be a WaveLayer \(waveLayer\.ts\)/);
  expect(result.messages[3]).toMatch(/^ParameterError: layer must be a layer not added yet/);
  expect(result.disposedWithOcean).toBe(false);
});
