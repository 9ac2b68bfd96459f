/**
 * The Ocean's queries in a frame loop, read from the fields its workers computed
 * (cascadeQueryFields.ts), and the JS path's workers when they fail: each compared with the
 * fields computed here for the time asked.
 */
import { Vector3 } from 'three';
import { Ocean } from '../../../src/ocean';
import { heightAt } from '../../../src/layers/surfaceQuery';
import type { WaveLayer } from '../../../src/layers/waveLayer';
import { FftCascade } from '../../../src/layers/fftCascade';
import { QUERY_WORKER_DELAY_MS } from '../../../src/layers/cascadeQueryFields';
import { renderer } from './oceanPage';

/**
 * The page's first Ocean, whose first update runs the queries once and has its cascades forget
 * them (Ocean.warmUpQueries): frames without queries for QUERY_WORKER_DELAY_MS + 0.35 s, then a
 * query and as long again. Returns how many queries reached the cascades in the first update
 * (FftCascade.queryFields counted), whether any cascade counted as queried before the app's
 * query, the Workers made and the requests for fields with velocities sent to workers before and
 * after it (Worker counted), and the first answer against the height from fields computed for the
 * time asked.
 */
export async function warmUpLeavesNoTrace(path: 'gpu' | 'js'): Promise<{
  warmUpQueries: number;
  cascades: number;
  queriedBefore: boolean;
  workersBefore: number;
  workersAfter: number;
  velocityRequestsBefore: number;
  velocityRequestsAfter: number;
  heightError: number;
  rms: number;
}> {
  const RealWorker = window.Worker;
  let [workersMade, velocityRequests] = [0, 0];
  window.Worker = class extends RealWorker {
    constructor(url: string | URL, options?: WorkerOptions) {
      super(url, options);
      workersMade++;
    }
    override postMessage(message: unknown, transfer?: Transferable[] | StructuredSerializeOptions): void {
      if ((message as { type?: string; velocities?: boolean }).velocities === true) velocityRequests++;
      super.postMessage(message, transfer as Transferable[]);
    }
  };
  const queryFields = FftCascade.prototype.queryFields;
  let queries = 0;
  FftCascade.prototype.queryFields = function (this: FftCascade, t: number) {
    queries++;
    return queryFields.call(this, t);
  };
  const ocean = new Ocean(renderer, { path, worker: true, localWaves: false, seed: 3 });
  try {
    const cascades = ocean.simulation.cascades;
    let t = 10;
    // Frames 30 ms apart for QUERY_WORKER_DELAY_MS and more (a query worker due has been made by
    // then), and on until `done`: a worker busy with its last request is asked for nothing new,
    // for as long as its answer takes on this machine.
    const frames = async (done = () => true) => {
      for (const until = performance.now() + QUERY_WORKER_DELAY_MS + 350; performance.now() < until || !done(); ) {
        ocean.update((t += 1 / 60));
        await new Promise((resolve) => setTimeout(resolve, 30));
      }
    };
    ocean.update(t);
    const warmUpQueries = queries;
    await frames();
    const queriedBefore = cascades.some((cascade) => cascade.queriedYet);
    const [workersBefore, velocityRequestsBefore] = [workersMade, velocityRequests];
    const height = ocean.heightAt(3, -4);
    const heightError = Math.abs(height - heightAt(exactLayers(cascades), ocean.parameters.choppiness, t, 3, -4));
    await frames(() => velocityRequests > 0);
    return { warmUpQueries, cascades: cascades.length, queriedBefore, workersBefore, workersAfter: workersMade, velocityRequestsBefore, velocityRequestsAfter: velocityRequests, heightError, rms: ocean.heightRms };
  } finally {
    ocean.dispose();
    window.Worker = RealWorker;
    FftCascade.prototype.queryFields = queryFields;
  }
}

/**
 * The queries in a frame loop as an app makes them: update, heightAt and normalAt at 25 points,
 * then a pause for the workers (a frame of a slow renderer). On the GPU path the queries read the
 * query workers' fields, on the JS path the JS workers' (cascadeQueryFields.ts). The steps are 1/60 s,
 * or alternately 1/60 s ± `jitter`. Frames run until no cascade has computed fields here for
 * three frames in a row (the workers started: `warmUpFrames`, at most 40), then 20 more, over which
 * it returns how many times the cascades computed fields here, and the worst difference between
 * heightAt and the height from fields computed for the time asked. Then a new wind (14 m/s: new
 * cascades, which read provisional copies until their workers answer) and 3 frames, with the same
 * worst difference (`worstAfterChange`, RMS height `rmsAfterChange`). `computedByQueries` counts
 * the fields computed here inside the queries (not in the updates) over all frames.
 */
export async function queriesFromWorkers(
  path: 'gpu' | 'js',
  jitter: number,
): Promise<{
  warmUpFrames: number;
  computedInWarmUp: number;
  computedByQueries: number;
  cascades: number;
  computedHere: number;
  worstError: number;
  rms: number;
  worstAfterChange: number;
  rmsAfterChange: number;
  path: string;
}> {
  const ocean = new Ocean(renderer, { path, worker: true, localWaves: false, seed: 3 });
  const { choppiness } = ocean.parameters;
  let cascades = ocean.simulation.cascades;
  let exact = exactLayers(cascades);
  const points = Array.from({ length: 25 }, (_, p) => [(p % 5) * 23.1 - 40, Math.floor(p / 5) * 19.7 - 35]);
  const normal = new Vector3();
  const computedHere = () => cascades.reduce((sum, cascade) => sum + cascade.fieldsComputedHere, 0);
  let t = 20;
  let frame = 0;
  let computedByQueries = 0;
  /** One frame; with `compare`, heightAt's worst difference from the exact height, and the squared heights. */
  const step = async (compare: boolean) => {
    t += 1 / 60 + (frame++ % 2 === 0 ? jitter : -jitter);
    ocean.update(t);
    const beforeQueries = computedHere();
    let [worst, squares] = [0, 0];
    for (const [x, z] of points) {
      const height = ocean.heightAt(x, z);
      ocean.normalAt(x, z, normal);
      if (!compare) continue;
      const expected = heightAt(exact, choppiness, t, x, z);
      worst = Math.max(worst, Math.abs(height - expected));
      squares += expected ** 2;
    }
    computedByQueries += computedHere() - beforeQueries;
    await new Promise((resolve) => setTimeout(resolve, 80));
    return { worst, squares };
  };
  try {
    for (let quiet = 0; quiet < 3 && frame < 60; ) {
      const before = computedHere();
      await step(false);
      quiet = computedHere() === before ? quiet + 1 : 0;
    }
    const warmUpFrames = frame;
    const computedInWarmUp = computedHere();
    const before = computedHere();
    /** `frames` frames compared: the worst difference and the RMS height. */
    const compared = async (frames: number) => {
      let [worstError, squares] = [0, 0];
      for (let i = 0; i < frames; i++) {
        const { worst, squares: s } = await step(true);
        worstError = Math.max(worstError, worst);
        squares += s;
      }
      return [worstError, Math.sqrt(squares / (frames * points.length))];
    };
    const [worstError, rms] = await compared(20);
    const computedAfterWarmUp = computedHere() - before;
    ocean.setParameters({ windSpeed: 14 });
    cascades = ocean.simulation.cascades;
    exact = exactLayers(cascades);
    const [worstAfterChange, rmsAfterChange] = await compared(3);
    return {
      warmUpFrames,
      computedInWarmUp,
      computedByQueries,
      cascades: cascades.length,
      computedHere: computedAfterWarmUp,
      worstError,
      rms,
      worstAfterChange,
      rmsAfterChange,
      path: ocean.path.running,
    };
  } finally {
    ocean.dispose();
  }
}

/**
 * The JS path in workers, and what happens when a worker fails: `fault` is 'throws' (an
 * exception in the worker), 'terminated' (killed from outside: it never answers again),
 * 'unloadable' (its script cannot load: it fails before any answer) or 'blocked' (new Worker
 * throws, as under a CSP without worker-src). For each: the path before and after, the reason,
 * the pathchange events, and how far the shown fields of every cascade are, a few frames after
 * the fault, from the JS fields computed here at the time they show (0 when they are right).
 */
export async function workerFault(fault: 'throws' | 'terminated' | 'unloadable' | 'blocked'): Promise<{
  before: string;
  after: string;
  reason: string;
  events: string[];
  largestError: number;
  largestHeight: number;
}> {
  const RealWorker = window.Worker;
  if (fault === 'blocked') {
    window.Worker = class {
      constructor() {
        throw new DOMException('blocked by the test', 'SecurityError');
      }
    } as unknown as typeof Worker;
  } else if (fault === 'unloadable') {
    window.Worker = class extends RealWorker {
      constructor(_url: string | URL, options?: WorkerOptions) {
        super('/no-such-worker-script.js', options);
      }
    };
  }
  const ocean = new Ocean(renderer, { resolution: 32, path: 'js', worker: true, localWaves: false });
  window.Worker = RealWorker;
  const events: string[] = [];
  ocean.addEventListener('pathchange', ({ path }) => events.push(`${path.running}: ${path.reason}`));
  const pause = () => new Promise((resolve) => setTimeout(resolve, 30));
  const layers = ocean.simulation.cascades;
  /** Updates at t until every cascade shows the fields of t (at most `seconds` of frames). */
  const runUntilShown = async (t: number, seconds: number) => {
    const until = performance.now() + seconds * 1000;
    let error = Infinity;
    while (performance.now() < until) {
      ocean.update(t);
      await pause();
      error = Math.max(...layers.map((layer) => largestDifference(layer.shownFieldsOnCpu()!.displacement, layer.fieldsOnCpu(t).displacement)));
      if (error === 0) break;
    }
    return error;
  };
  await runUntilShown(1, 20);
  const before = ocean.path.running;
  const { worker } = (layers[0] as unknown as { backend: { worker: { worker: Worker } } }).backend;
  if (fault === 'throws') {
    // Arrays too short for the fields: filling them throws (a RangeError) in the worker.
    const spare = { displacement: new Float32Array(1), derivatives: new Float32Array(1), velocities: null };
    worker.worker.postMessage({ type: 'update', t: 2, velocities: false, spare });
  }
  if (fault === 'terminated') worker.worker.terminate();
  // Long enough for a silent worker to be given up (4 s) and its replacement to answer.
  const largestError = await runUntilShown(3, 20);
  const largestHeight = Math.max(...layers.map((layer) => Math.max(...layer.fieldsOnCpu(3).displacement.map(Math.abs))));
  const result = { before, after: ocean.path.running, reason: ocean.path.reason, events, largestError, largestHeight };
  ocean.dispose();
  return result;
}

/** The largest |a[i] − b[i]|. */
function largestDifference(a: ArrayLike<number>, b: ArrayLike<number>): number {
  let largest = 0;
  for (let i = 0; i < a.length; i++) largest = Math.max(largest, Math.abs(a[i] - b[i]));
  return largest;
}

/** The same cascades, each answering the queries with its fields computed here for the time asked. */
function exactLayers(cascades: readonly FftCascade[]): WaveLayer[] {
  return cascades.map((cascade) => ({
    textures: cascade.textures,
    frame: cascade.frame,
    movesSideways: true,
    update: () => {},
    dispose: () => {},
    queryFields: (t: number) => ({ time: t, resolution: cascade.frame.resolution, ...cascade.fieldsOnCpu(t), velocities: () => new Float32Array(0) }),
    fieldsOnCpu: (t: number) => cascade.fieldsOnCpu(t),
    shownFieldsOnCpu: () => null,
  }));
}
