/**
 * Test page for the simulation core: runs the real GPU path in this page's WebGL2 context and the
 * JS path beside it, and hands the Playwright tests summaries (errors relative to RMS) rather than
 * whole fields.
 */
import { REVISION, WebGLRenderer, type DataTexture, type WebGLRenderTarget } from 'three';
import { CpuWaveFields } from '../../../src/fft/cpuWaveFields';
import { GpuWaveFields, supportedGpuPrecision, type GpuPrecision } from '../../../src/fft/gpuWaveFields';
import { LocalWaves } from '../../../src/layers/localWaves';
import { OceanSimulation } from '../../../src/layers/oceanSimulation';
import { createSeabedMap } from '../../../src/layers/seabed';
import { validateParameters, type SimulationParameters } from '../../../src/parameters/parameters';
import { createCascadeSpectra } from '../../../src/spectrum/initialSpectrum';
import { foamDifference } from '../shared/foamDifference';

const renderer = new WebGLRenderer({ canvas: document.createElement('canvas') });

// Framebuffers alive in this context, counted on the real context's own calls: the GPU FFT makes
// framebuffers of its own (gpuWaveFields.ts), which renderer.info does not see.
const liveFramebuffers = new Set<WebGLFramebuffer>();
{
  const gl = renderer.getContext();
  const create = gl.createFramebuffer.bind(gl);
  const remove = gl.deleteFramebuffer.bind(gl);
  gl.createFramebuffer = () => {
    const framebuffer = create();
    liveFramebuffers.add(framebuffer);
    return framebuffer;
  };
  gl.deleteFramebuffer = (framebuffer) => {
    if (framebuffer) liveFramebuffers.delete(framebuffer);
    remove(framebuffer);
  };
}

/** Per channel of one RGBA field texture: max |gpu − js| / rms(js), and rms(js). */
export interface ChannelComparison {
  relativeMaxError: number;
  rms: number;
}

function readTarget(target: WebGLRenderTarget, textureIndex: number, n: number, precision: GpuPrecision): Float32Array {
  if (precision === 'float32') {
    const pixels = new Float32Array(4 * n * n);
    renderer.readRenderTargetPixels(target, 0, 0, n, n, pixels, undefined, textureIndex);
    return pixels;
  }
  const halves = new Uint16Array(4 * n * n);
  renderer.readRenderTargetPixels(target, 0, 0, n, n, halves, undefined, textureIndex);
  return Float32Array.from(halves, halfToFloat);
}

function halfToFloat(h: number): number {
  const exponent = (h >> 10) & 0x1f;
  const mantissa = h & 0x3ff;
  const sign = h & 0x8000 ? -1 : 1;
  if (exponent === 0) return sign * mantissa * 2 ** -24;
  if (exponent === 31) return mantissa ? NaN : sign * Infinity;
  return sign * (1 + mantissa / 1024) * 2 ** (exponent - 15);
}

function compareChannels(gpu: Float32Array, js: Float32Array): ChannelComparison[] {
  const result: ChannelComparison[] = [];
  for (let c = 0; c < 4; c++) {
    let maxError = 0;
    let sumSquares = 0;
    let count = 0;
    for (let i = c; i < js.length; i += 4, count++) {
      const error = Math.abs(gpu[i] - js[i]);
      // NaN must fail the comparison, not vanish in Math.max.
      maxError = Number.isNaN(error) ? Infinity : Math.max(maxError, error);
      sumSquares += js[i] * js[i];
    }
    const rms = Math.sqrt(sumSquares / count);
    result.push({ relativeMaxError: maxError / rms, rms });
  }
  return result;
}

const harness = {
  /** The three.js release this page runs (tests/browser/simulation/simulation.spec.ts checks it). */
  threeRevision: REVISION,

  supportedPrecision: () => supportedGpuPrecision(renderer),

  /** GPU fields against JS fields for the given parameters at each time. */
  compareGpuWithJs(
    changes: Partial<SimulationParameters>,
    times: number[],
    precision: GpuPrecision = 'float32',
  ): { passCount: number; results: { t: number; cascade: number; displacement: ChannelComparison[]; derivatives: ChannelComparison[] }[] } {
    const params = validateParameters(changes);
    const n = params.resolution;
    // Every cascade: the coarser ones skip what their band leaves zero, in both paths.
    let passCount = 0;
    const results = createCascadeSpectra(params).flatMap((spectrum, cascade) => {
      const gpu = new GpuWaveFields(renderer, spectrum, precision);
      passCount = gpu.passCount;
      const js = new CpuWaveFields(spectrum);
      const atTimes = times.map((t) => {
        gpu.update(t);
        js.update(t);
        return {
          t,
          cascade,
          displacement: compareChannels(readTarget(gpu.output, 0, n, precision), js.displacement),
          derivatives: compareChannels(readTarget(gpu.output, 1, n, precision), js.derivatives),
        };
      });
      gpu.dispose();
      return atTimes;
    });
    return { passCount, results };
  },

  /**
   * The whitecap foam on the GPU path against the JS path (CpuFoamField, the fields computed here)
   * after each time in turn (the first a jump, so a warm-up): the mean JS coverage and the largest
   * difference.
   */
  compareFoamGpuWithJs(changes: Partial<SimulationParameters>, times: number[]): { meanCoverage: number; maxDifference: number }[] {
    const gpu = new OceanSimulation(renderer, changes, { path: 'gpu', worker: false });
    const js = new OceanSimulation(renderer, changes, { path: 'js', worker: false });
    const results = times.map((t) => {
      gpu.update(t);
      js.update(t);
      return foamDifference(js.foam.coverageOnCpu(), gpu.foam.coverageOnCpu());
    });
    gpu.dispose();
    js.dispose();
    return results;
  },

  /** Counts of non-finite values in the GPU fields (both textures) at time t. */
  gpuNonFiniteCount(changes: Partial<SimulationParameters>, t: number): number {
    const params = validateParameters(changes);
    let count = 0;
    for (const spectrum of createCascadeSpectra(params)) {
      const gpu = new GpuWaveFields(renderer, spectrum, 'float32');
      gpu.update(t);
      for (const index of [0, 1]) {
        for (const value of readTarget(gpu.output, index, params.resolution, 'float32')) if (!Number.isFinite(value)) count++;
      }
      gpu.dispose();
    }
    return count;
  },

  /** The initial spectrum's amplitudes, as the bit patterns of their float32 values. */
  spectrumBits(changes: Partial<SimulationParameters>): number[] {
    return createCascadeSpectra(validateParameters(changes)).flatMap((spectrum) => Array.from(new Uint32Array(spectrum.amplitudes.buffer)));
  },

  /**
   * The JS path as the app runs it, in a Web Worker: waits for the worker's fields at time t and
   * compares the uploaded texture data with CpuWaveFields computed here.
   */
  async workerAgainstDirect(changes: Partial<SimulationParameters>, t: number): Promise<{ path: string; maxDifference: number; rms: number }> {
    const simulation = new OceanSimulation(renderer, changes, { path: 'js', worker: true });
    const displacement = () => simulation.cascades[0].textures.displacement.value as DataTexture;
    const deadline = performance.now() + 20_000;
    // The worker answers a frame later; keep asking, as the render loop would.
    while (performance.now() < deadline) {
      simulation.update(t);
      await new Promise((resolve) => setTimeout(resolve, 20));
      if (Array.from(displacement().image.data as Float32Array).some((v) => v !== 0)) break;
    }
    const direct = new CpuWaveFields(simulation.cascades[0].spectrum);
    direct.update(t);
    const fromWorker = displacement().image.data as Float32Array;
    let maxDifference = 0;
    let sumSquares = 0;
    fromWorker.forEach((value, i) => {
      maxDifference = Math.max(maxDifference, Math.abs(value - direct.displacement[i]));
      sumSquares += direct.displacement[i] ** 2;
    });
    const path = simulation.path;
    simulation.dispose();
    return { path, maxDifference, rms: Math.sqrt(sumSquares / fromWorker.length) };
  },

  /** Bad input: errors that name the parameter, and the simulation goes on with its last good values. */
  badInput(): { messages: string[]; unchanged: boolean; nonFinite: number } {
    const simulation = new OceanSimulation(renderer, { resolution: 64, windSpeed: 9 }, { path: 'gpu' });
    const before = { ...simulation.parameters };
    const messages: string[] = [];
    const attempts: (() => void)[] = [
      () => simulation.setParameters({ windSpeed: NaN }),
      () => simulation.setParameters({ resolution: 100 }),
      () => simulation.setParameters({ patchSizes: [-1] }),
      () => simulation.setParameters({ patchSizes: [100, 50] }),
      () => simulation.setParameters({ patchSizes: [50, 60] }),
      () => simulation.setParameters({ spectrum: 'bretschneider' as 'jonswap' }),
      () => simulation.setParameters({ spreading: 'cosine' as 'cos-2s' }),
      () => simulation.setParameters({ fetch: 0 }),
      () => simulation.setParameters({ swellPeriod: -3 }),
      () => simulation.setParameters({ amplitude: -1e-6 }),
      () => simulation.setParameters({ repeatPeriod: 0 }),
      () => simulation.setParameters({ depth: 0 }),
      () => simulation.update(NaN),
    ];
    for (const attempt of attempts) {
      try {
        attempt();
        messages.push('(no error)');
      } catch (error) {
        messages.push((error as Error).message);
      }
    }
    simulation.update(4);
    const unchanged = JSON.stringify(before) === JSON.stringify(simulation.parameters);
    let nonFinite = simulation.foam.coverageOnCpu().filter((v) => !Number.isFinite(v)).length;
    for (const layer of simulation.cascades) {
      const { output } = (layer as unknown as { backend: GpuWaveFields }).backend;
      for (const index of [0, 1]) for (const v of readTarget(output, index, 64, 'float32')) if (!Number.isFinite(v)) nonFinite++;
    }
    simulation.dispose();
    return { messages, unchanged, nonFinite };
  },

  /**
   * renderer.info.memory and the live framebuffers before and after creating, running and
   * disposing simulations on both paths, and the framebuffers while one was alive.
   */
  /**
   * Which layer objects survive a change of each parameter: a shader-only one (choppiness) keeps
   * every cascade and its textures; a spectrum one (wind) builds new ones.
   */
  layersKeptAcross(): { choppiness: boolean; windSpeed: boolean; choppinessApplied: number } {
    const simulation = new OceanSimulation(renderer, { resolution: 32 }, { path: 'gpu', worker: false });
    const same = (before: readonly object[]) => simulation.cascades.every((layer, i) => layer === before[i]);
    let before = [...simulation.cascades];
    simulation.setParameters({ choppiness: 2.5 });
    const choppiness = same(before);
    const choppinessApplied = simulation.parameters.choppiness;
    before = [...simulation.cascades];
    simulation.setParameters({ windSpeed: 17 });
    const windSpeed = same(before);
    simulation.dispose();
    return { choppiness, windSpeed, choppinessApplied };
  },

  /**
   * The local waves on the GPU against the JS solver, through the same history: a stone, a hull
   * under way and turning, and a grid that follows it (so it shifts). After each update: the
   * largest difference of height and slopes, relative to the largest height then. With `beach`, over
   * a seabed with land under the grid's west side (x < −20 m, then 1:10): the depth and the wet mask
   * change as the grid moves.
   */
  compareLocalWavesGpuWithJs(updates: number, beach = false): { maxHeight: number; heightError: number; slopeError: number }[] {
    const options = { resolution: 128, cellSize: 0.5 };
    const paths = [new LocalWaves(renderer, 30, true, options), new LocalWaves(renderer, 30, false, options)];
    const seabed = beach ? createSeabedMap({ depthAt: (x) => (x + 20) / 10, bounds: [-100, -100, 100, 100], resolution: 201 }, renderer) : null;
    for (const waves of paths) waves.setSeabed(seabed);
    const hull = { length: 6, beam: 2, draft: 0.5 };
    const hulls = paths.map((waves) => waves.addPressure(hull, { x: 0, z: 0, heading: 0 }));
    for (const waves of paths) {
      waves.update(0, 0); // the first update starts the clock (a jump: it steps nothing)
      waves.drop(-10, 6, { radius: 1, depth: 0.5 });
    }
    const results = [];
    for (let u = 1; u <= updates; u++) {
      const t = u / 10;
      const pose = { x: 4 * t, z: 0.5 * t * t, heading: Math.atan2(t, 4) };
      paths.forEach((waves, i) => {
        hulls[i].setPose(pose.x, pose.z, pose.heading);
        waves.follow(pose.x, pose.z);
        waves.update(t, 0.1);
      });
      const [gpu, js] = paths.map((waves) => waves.fieldsOnCpu(t));
      let maxHeight = 0;
      let heightError = 0;
      let slopeError = 0;
      for (let texel = 0; texel < js.displacement.length / 4; texel++) {
        maxHeight = Math.max(maxHeight, Math.abs(js.displacement[4 * texel + 1]));
        heightError = Math.max(heightError, Math.abs(gpu.displacement[4 * texel + 1] - js.displacement[4 * texel + 1]) || (Number.isNaN(gpu.displacement[4 * texel + 1]) ? Infinity : 0));
        for (const c of [0, 1]) slopeError = Math.max(slopeError, Math.abs(gpu.derivatives[4 * texel + c] - js.derivatives[4 * texel + c]));
      }
      results.push({ maxHeight, heightError: heightError / maxHeight, slopeError: slopeError / maxHeight });
    }
    for (const waves of paths) waves.dispose();
    seabed?.dispose();
    return results;
  },

  /**
   * A hull on a path, the local waves jumped to time t twice (from elsewhere in between): the
   * fields each time, their largest height, and whether they are the same bits.
   */
  localWavesAfterJumps(t: number): { maxHeight: number; identical: boolean; finite: boolean } {
    // A coarse grid: the run-up is 200 steps, and each costs ~30 ms at N = 128 under SwiftShader.
    const waves = new LocalWaves(renderer, Infinity, true, { resolution: 64, cellSize: 2 });
    const path = (time: number) => ({ x: 5 * time - 100, z: 3, heading: 0 });
    waves.addPressure({ length: 8, beam: 2.6, draft: 0.6 }, path(0), path);
    waves.follow(0, 0);
    const fields = () => Float32Array.from(waves.fieldsOnCpu(t).displacement);
    waves.update(t, 0);
    const first = fields();
    waves.update(t + 0.1, 0.1);
    waves.update(3, 3 - t - 0.1); // a jump back
    waves.update(t, t - 3); // a jump forward again
    const second = fields();
    waves.dispose();
    let maxHeight = 0;
    for (let i = 1; i < first.length; i += 4) maxHeight = Math.max(maxHeight, Math.abs(first[i]));
    return { maxHeight, identical: first.every((v, i) => Object.is(v, second[i])), finite: first.every(Number.isFinite) };
  },

  /** Bad input to the local waves: each call's error message, or '(no error)'. */
  localWavesBadInput(): { messages: string[]; droppedOutside: boolean; finite: boolean } {
    const waves = new LocalWaves(renderer, Infinity, true);
    const messages: string[] = [];
    const attempts: (() => unknown)[] = [
      () => waves.drop(NaN, 0),
      () => waves.drop(0, 0, { radius: 0 }),
      () => waves.drop(0, 0, { depth: -1 }),
      () => waves.addPressure({ length: -1, beam: 1, draft: 1 }, { x: 0, z: 0, heading: 0 }),
      () => waves.addPressure({ length: 5, beam: 1, draft: 1 }, { x: 0, z: Infinity, heading: 0 }),
      () => waves.addPressure({ length: 5, beam: 1, draft: 1 }, { x: 0, z: 0, heading: 0 }).setPose(0, 0, 0, -2),
      () => waves.follow(NaN, 0),
      () => new LocalWaves(renderer, Infinity, false, { resolution: 100 }),
      () => new LocalWaves(renderer, Infinity, false, { cellSize: 0 }),
    ];
    for (const attempt of attempts) {
      try {
        attempt();
        messages.push('(no error)');
      } catch (error) {
        messages.push((error as Error).message);
      }
    }
    const droppedOutside = waves.drop(1e4, 0);
    waves.drop(3, 4);
    waves.update(0, 0);
    waves.update(0.1, 0.1);
    const finite = waves.fieldsOnCpu(0.1).displacement.every(Number.isFinite);
    waves.dispose();
    return { messages, droppedOutside, finite };
  },

  memoryAfterCycles(cycles: number): { before: object; during: number; after: object } {
    const memory = () => ({ ...renderer.info.memory, framebuffers: liveFramebuffers.size });
    const before = memory();
    let during = 0;
    for (let i = 0; i < cycles; i++) {
      const simulation = new OceanSimulation(renderer, { resolution: 32 + 32 * (i % 2), seed: i }, { path: i % 3 === 2 ? 'js' : 'gpu', worker: false });
      simulation.update(i);
      simulation.setParameters({ windSpeed: 5 + i });
      simulation.update(i + 0.5);
      during = Math.max(during, liveFramebuffers.size);
      simulation.dispose();
    }
    return { before, during, after: memory() };
  },
};

declare global {
  interface Window {
    harness: typeof harness;
  }
}
window.harness = harness;
document.title = 'ready';
