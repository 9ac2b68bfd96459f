/**
 * The Oceans' queries of the surface (src/layers/surfaceQuery.ts sums the layers): one point, or
 * many points at once into arrays without allocating, with the checks of what is asked; and the
 * once-per-page warm-up of their code. Ocean's methods (src/ocean.ts, and src/webgpu/ocean.ts's) call these.
 */
import { Vector3 } from 'three';
import type { Ocean, WritableNumbers } from './ocean';
import type { OceanSimulation } from './layers/oceanSimulation';
import type { Shore } from './layers/shore';
import { heightAt, normalAt, velocityAt } from './layers/surfaceQuery';
import { ParameterError } from './parameters/parameters';

/**
 * The farthest from the origin, in metres along x or z, that the queries are asked about. Up to
 * it a double holds a coordinate to a tenth of a millimetre, finer than the finest texel of any
 * sea (a 1 m patch at N = 1024); far beyond it the texel coordinates and the blend's phases
 * overflow to ±Infinity, and the answer would be NaN.
 */
const MAX_COORDINATE = 1e12;
/** MAX_COORDINATE as the errors say it. */
const WITHIN_RANGE = 'in metres, at most 1e12 in size';

/** What the queries read of a sea: its layers and parameters (an OceanSimulation, or the WebGPU Ocean's own). */
export type QueriedSea = Pick<OceanSimulation, 'layers' | 'parameters'>;

/** The batch queries' one vector, reused (nothing is allocated per point). */
const scratch = { x: 0, y: 0, z: 0 };

/** Whether an Ocean of this page has run the queries once (warmUpQueries). */
let queryCodeWarm = false;

/**
 * Height of the surface at (x, z) at time t (s), shoaled over `shore`'s seabed (null: none); a
 * ParameterError naming `method` for bad coordinates.
 */
export function surfaceHeightAt(method: string, { layers, parameters }: QueriedSea, shore: Shore | null, t: number, x: number, z: number): number {
  checkCoordinates(`${method}(x, z)`, x, z);
  return heightAt(layers, parameters.choppiness, t, x, z, shore);
}

/** Upward unit normal of the surface over (x, z) at time t, in `target`. */
export function surfaceNormalAt(method: string, { layers, parameters }: QueriedSea, shore: Shore | null, t: number, x: number, z: number, target: Vector3): Vector3 {
  checkCoordinates(`${method}(x, z)`, x, z);
  return normalAt(layers, parameters.choppiness, t, x, z, target, shore);
}

/** Velocity (m/s) of the surface over (x, z) at time t, in `target`. */
export function surfaceVelocityAt(method: string, { layers, parameters }: QueriedSea, shore: Shore | null, t: number, x: number, z: number, target: Vector3): Vector3 {
  checkCoordinates(`${method}(x, z)`, x, z);
  return velocityAt(layers, parameters.choppiness, t, x, z, target, shore);
}

/** Heights at the points x0, z0, x1, z1, … of `xz`, one per point into `out` (returned). */
export function surfaceHeightsAt<T extends WritableNumbers>(method: string, { layers, parameters }: QueriedSea, shore: Shore | null, t: number, xz: ArrayLike<number>, out: T): T {
  const count = checkBatch(method, xz, out, 1);
  for (let p = 0; p < count; p++) out[p] = heightAt(layers, parameters.choppiness, t, xz[2 * p], xz[2 * p + 1], shore);
  return out;
}

/** `query` (normalAt or velocityAt) at the points of `xz`, three numbers per point into `out` (returned). */
export function surfaceVectorsAt<T extends WritableNumbers>(
  method: string,
  query: typeof normalAt,
  { layers, parameters }: QueriedSea,
  shore: Shore | null,
  t: number,
  xz: ArrayLike<number>,
  out: T,
): T {
  const count = checkBatch(method, xz, out, 3);
  for (let p = 0; p < count; p++) {
    query(layers, parameters.choppiness, t, xz[2 * p], xz[2 * p + 1], scratch, shore);
    out[3 * p] = scratch.x;
    out[3 * p + 1] = scratch.y;
    out[3 * p + 2] = scratch.z;
  }
  return out;
}

/**
 * Once per page, at the first update of its first Ocean, unless the app queried first: asks each
 * query once of this sea, then has the cascades forget it (FftCascade.forgetQueries). V8 then
 * compiles the query code and learns its types here, not in the app's first query, which would
 * otherwise pay for that compilation (issue 10 asks for no query over 1 ms; docs/performance.md
 * has the first heightAt as last measured). The queries read the fields
 * the update has just made for them (fftCascade.ts): nothing is computed for them, except on the
 * JS path without a worker, the velocities (one FFT).
 */
export function warmUpQueries(ocean: Ocean): void {
  if (queryCodeWarm) return;
  queryCodeWarm = true;
  const cascades = ocean.simulation.cascades;
  if (cascades.some((cascade) => cascade.queriedYet)) return; // the app's own queries compiled it
  const out = new Vector3();
  ocean.heightAt(0, 0);
  ocean.normalAt(0, 0, out);
  ocean.velocityAt(0, 0, out);
  for (const cascade of cascades) cascade.forgetQueries();
}

function isCoordinate(value: unknown): boolean {
  return typeof value === 'number' && Math.abs(value) <= MAX_COORDINATE;
}

/** Throws a ParameterError naming `method` unless x and z are coordinates the queries answer for. */
export function checkCoordinates(method: string, x: number, z: number): void {
  if (!isCoordinate(x) || !isCoordinate(z)) throw new ParameterError(method, [x, z], `finite coordinates ${WITHIN_RANGE}`);
}

/** Checks a batch query's arrays (`perPoint` numbers out per point); returns the point count. */
function checkBatch(method: string, xz: ArrayLike<number>, out: WritableNumbers, perPoint: number): number {
  if (xz === null || typeof xz !== 'object' || typeof xz.length !== 'number' || xz.length % 2 !== 0) {
    throw new ParameterError(`${method}(xz)`, xz, 'an array of x0, z0, x1, z1, … (an even length)');
  }
  const count = xz.length / 2;
  if (out === null || typeof out !== 'object' || !(out.length >= perPoint * count)) {
    throw new ParameterError(`${method}(xz, out)`, out, `an array of at least ${perPoint * count} numbers (${perPoint} per point)`);
  }
  for (let i = 0; i < xz.length; i++) {
    if (!isCoordinate(xz[i])) throw new ParameterError(`${method}(xz)[${i}]`, xz[i], `a finite coordinate ${WITHIN_RANGE}`);
  }
  return count;
}
