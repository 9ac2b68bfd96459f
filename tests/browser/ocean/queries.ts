/**
 * The Ocean's queries (heightAt, normalAt, the batch queries, horizonDistanceFor) against the
 * surface the page renders and the fields of the layers, with the local waves on the GPU.
 */
import { Vector3 } from 'three';
import { Ocean } from '../../../src/ocean';
import { heightAt, normalAt } from '../../../src/layers/surfaceQuery';
import type { SimulationParameters } from '../../../src/parameters/parameters';
import { geometryCheck } from './geometryCapture';
import { camera, renderer, withOcean } from './oceanPage';

/**
 * heightAt against the rendered surface: an Ocean's own surface is read back from the vertex
 * shader (geometryCheck); a vertex displaced to (px, py, pz) is the surface point that lands on
 * (px, pz), so heightAt(px, pz) must be py.
 */
export function heightAtCheck(
  changes: Partial<SimulationParameters>,
  t: number,
): { compared: number; folded: number; maxError: number; rms: number } {
  return withOcean(changes, (ocean) => {
    ocean.update(t);
    const { displacedAtMip0, rms } = geometryCheck(t);
    // Where the surface folds (J ≤ 0.2 at the rest point) more than one point lands on (x, z).
    const unfolded = displacedAtMip0.filter(([, , , jacobian]) => jacobian > 0.2);
    let maxError = 0;
    for (const [x, y, z] of unfolded) maxError = Math.max(maxError, Math.abs(ocean.heightAt(x, z) - y));
    return { compared: unfolded.length, folded: displacedAtMip0.length - unfolded.length, maxError, rms };
  });
}

/**
 * The queries over the local waves: after a stone, heightAt and normalAt of the Ocean against the
 * same queries over the cascades alone (surfaceQuery.ts), at points around the stone. Without
 * choppiness the rest point under (x, z) is (x, z) itself, so the difference in height must be the
 * local field there (bilinear), and the normals must differ where its slopes are. (With it, every
 * layer is sampled at the rest point the choppy map moves onto (x, z), as the surface does.)
 */
export function queriesWithLocalWaves(): { largestLocal: number; worstHeight: number; normalsDiffer: boolean } {
  return withOcean({ resolution: 64, windSpeed: 6, seed: 4, choppiness: 0 }, (ocean) => {
    const waves = ocean.localWaves!;
    waves.follow(0, 0);
    ocean.update(10);
    waves.drop(3, -2, { radius: 1.2, depth: 0.8 });
    for (let t = 10.1; t < 13; t += 0.1) ocean.update(t);
    const { size, origin, resolution } = waves.frame;
    const local = waves.fieldsOnCpu(ocean.time).displacement;
    const localAt = (x: number, z: number) => {
      const [u, v] = [((x - origin[0]) / size) * resolution, ((z - origin[1]) / size) * resolution];
      const [i, j] = [Math.floor(u), Math.floor(v)];
      const [fu, fv] = [u - i, v - j];
      const h = (a: number, b: number) => local[4 * (b * resolution + a) + 1];
      return (1 - fv) * ((1 - fu) * h(i, j) + fu * h(i + 1, j)) + fv * ((1 - fu) * h(i, j + 1) + fu * h(i + 1, j + 1));
    };
    const cascades = ocean.simulation.cascades;
    const { choppiness } = ocean.parameters;
    let [largestLocal, worstHeight, normalsDiffer] = [0, 0, false];
    for (let x = -5; x <= 11; x += 0.7) {
      for (let z = -10; z <= 6; z += 0.7) {
        const expected = heightAt(cascades, choppiness, ocean.time, x, z);
        largestLocal = Math.max(largestLocal, Math.abs(localAt(x, z)));
        worstHeight = Math.max(worstHeight, Math.abs(ocean.heightAt(x, z) - expected - localAt(x, z)));
        const withLocal = ocean.normalAt(x, z);
        const without = normalAt(cascades, choppiness, ocean.time, x, z, new Vector3());
        normalsDiffer ||= withLocal.angleTo(without) > 0.02;
      }
    }
    return { largestLocal, worstHeight, normalsDiffer };
  });
}

/**
 * The batch queries on the GPU path against the JS path and against the single-point ones, and
 * their errors: the largest differences, and each bad call's message.
 */
export function batchQueries(): { gpuVersusJs: number; batchVersusSingle: number; largestSpeed: number; messages: string[] } {
  const options = { resolution: 64, windSpeed: 11, seed: 8, worker: false } as const;
  const oceans = [new Ocean(renderer, { ...options, path: 'gpu' }), new Ocean(renderer, { ...options, path: 'js' })];
  const xz = new Float64Array(2 * 200);
  for (let p = 0; p < 200; p++) [xz[2 * p], xz[2 * p + 1]] = [-80 + (p % 20) * 8.3, -50 + Math.floor(p / 20) * 9.7];
  const results = oceans.map((ocean) => {
    ocean.update(0);
    ocean.localWaves!.drop(3, 4);
    for (let t = 0.1; t < 2; t += 0.1) ocean.update(21 + t);
    return { heights: ocean.heightsAt(xz, new Float32Array(200)), normals: ocean.normalsAt(xz, new Float32Array(600)), velocities: ocean.velocitiesAt(xz, new Float64Array(600)) };
  });
  let [gpuVersusJs, batchVersusSingle, largestSpeed] = [0, 0, 0];
  const [gpu, js] = results;
  for (const key of ['heights', 'normals', 'velocities'] as const) {
    for (let i = 0; i < js[key].length; i++) gpuVersusJs = Math.max(gpuVersusJs, Math.abs(gpu[key][i] - js[key][i]));
  }
  const vector = new Vector3();
  for (let p = 0; p < 200; p++) {
    const [x, z] = [xz[2 * p], xz[2 * p + 1]];
    const ocean = oceans[1];
    batchVersusSingle = Math.max(batchVersusSingle, Math.abs(ocean.heightAt(x, z) - js.heights[p]));
    ocean.velocityAt(x, z, vector);
    largestSpeed = Math.max(largestSpeed, vector.length());
    for (const [c, value] of [vector.x, vector.y, vector.z].entries()) batchVersusSingle = Math.max(batchVersusSingle, Math.abs(value - js.velocities[3 * p + c]));
    ocean.normalAt(x, z, vector);
    for (const [c, value] of [vector.x, vector.y, vector.z].entries()) batchVersusSingle = Math.max(batchVersusSingle, Math.abs(value - js.normals[3 * p + c]));
  }
  const messages: string[] = [];
  for (const attempt of [
    () => oceans[1].heightsAt([1, 2, 3], new Float32Array(2)),
    () => oceans[1].velocitiesAt([1, 2], new Float32Array(2)),
    () => oceans[1].normalsAt([1, NaN], new Float32Array(3)),
    () => oceans[1].velocityAt(Infinity, 0),
    () => oceans[1].heightAt(-1.6e308, 0),
  ]) {
    try {
      attempt();
      messages.push('(no error)');
    } catch (error) {
      messages.push((error as Error).message);
    }
  }
  for (const ocean of oceans) ocean.dispose();
  return { gpuVersusJs, batchVersusSingle, largestSpeed, messages };
}

/**
 * The local waves on the GPU and the queries: after a stone, frames of an update and heightAt at
 * points around it. Returns the read-backs that waited for the GPU (readRenderTargetPixels) after
 * the first query, those that did not (readRenderTargetPixelsAsync), and, after frames with no
 * update (the last read-back in), the largest difference between heightAt and the same query over
 * the fields read back at once (fieldsOnCpu), and how far the local field reaches there.
 */
export async function localWavesQueriedOnGpu(): Promise<{ path: string; waited: number; notWaited: number; worstDifference: number; largestLocal: number }> {
  const ocean = new Ocean(renderer, { resolution: 64, choppiness: 0, seed: 4, localWaves: { path: 'gpu' } });
  const waves = ocean.localWaves!;
  const counts = { waited: 0, notWaited: 0, inFlight: 0 };
  const { readRenderTargetPixels, readRenderTargetPixelsAsync } = renderer;
  renderer.readRenderTargetPixels = (...args: Parameters<typeof readRenderTargetPixels>) => {
    counts.waited++;
    return readRenderTargetPixels.apply(renderer, args);
  };
  renderer.readRenderTargetPixelsAsync = (...args: Parameters<typeof readRenderTargetPixelsAsync>) => {
    counts.notWaited++;
    counts.inFlight++;
    return readRenderTargetPixelsAsync.apply(renderer, args).finally(() => counts.inFlight--);
  };
  const points = Array.from({ length: 36 }, (_, p) => [(p % 6) * 1.3 - 2, Math.floor(p / 6) * 1.3 - 5]);
  try {
    waves.follow(0, 0);
    ocean.update(10);
    waves.drop(1, -2, { radius: 1.2, depth: 0.8 });
    ocean.heightAt(0, 0); // the first query reads back at once
    const waitedAtFirst = counts.waited;
    for (let t = 10.05; t < 12; t += 0.05) {
      ocean.update(t);
      for (const [x, z] of points) ocean.heightAt(x, z);
      await new Promise((resolve) => setTimeout(resolve, 20));
    }
    // No more updates: queries until the read-backs in flight are in and none newer is started.
    for (let i = 0; i < 200; i++) {
      const started = counts.notWaited;
      ocean.heightAt(0, 0);
      if (counts.inFlight === 0 && counts.notWaited === started) break;
      await new Promise((resolve) => setTimeout(resolve, 50));
    }
    const waited = counts.waited - waitedAtFirst;
    const queried = points.map(([x, z]) => ocean.heightAt(x, z));
    const local = waves.fieldsOnCpu(ocean.time).displacement; // read back at once
    const cascadesOnly = points.map(([x, z]) => heightAt(ocean.simulation.cascades, 0, ocean.time, x, z));
    const { size, origin, resolution } = waves.frame;
    let [worstDifference, largestLocal] = [0, 0];
    points.forEach(([x, z], p) => {
      // choppiness 0: the local field at (x, z) itself, bilinear
      const [u, v] = [((x - origin[0]) / size) * resolution, ((z - origin[1]) / size) * resolution];
      const [i, j] = [Math.floor(u), Math.floor(v)];
      const [fu, fv] = [u - i, v - j];
      const h = (a: number, b: number) => local[4 * (b * resolution + a) + 1];
      const localHeight = (1 - fv) * ((1 - fu) * h(i, j) + fu * h(i + 1, j)) + fv * ((1 - fu) * h(i, j + 1) + fu * h(i + 1, j + 1));
      largestLocal = Math.max(largestLocal, Math.abs(localHeight));
      worstDifference = Math.max(worstDifference, Math.abs(queried[p] - cascadesOnly[p] - localHeight));
    });
    return { path: waves.path, waited, notWaited: counts.notWaited, worstDifference, largestLocal };
  } finally {
    renderer.readRenderTargetPixels = readRenderTargetPixels;
    renderer.readRenderTargetPixelsAsync = readRenderTargetPixelsAsync;
    ocean.dispose();
  }
}

/**
 * An Ocean's horizonDistanceFor(camera height) asked before its first render, its
 * horizonDistance then and after the render from the current view, and the farthest vertex from
 * the camera that the vertex shader placed (the skirt's corner).
 */
export function horizonCheck(changes: Partial<SimulationParameters>): { before: number; beforeAtSeaLevel: number; seaLevel: number; after: number; farthest: number } {
  return withOcean(changes, (ocean) => {
    const before = ocean.horizonDistanceFor(camera.position.y);
    const beforeAtSeaLevel = ocean.horizonDistance;
    const seaLevel = ocean.horizonDistanceFor(0);
    const { farthest } = geometryCheck(0); // places the rings for the camera, as a render does
    return { before, beforeAtSeaLevel, seaLevel, after: ocean.horizonDistance, farthest };
  });
}
