/**
 * Benchmark page for `npm run bench` (bench/run.mjs drives it through Playwright): times one full
 * GpuWaveFields.update() (every field) and one CpuWaveFields.update() in this page, and hands back
 * raw samples in milliseconds; run.mjs takes the medians.
 *
 * GPU work is timed two ways, interleaved round by round:
 *   - timer query: EXT_disjoint_timer_query_webgl2 TIME_ELAPSED_EXT around update(), the result
 *     read asynchronously, samples taken while the GPU was disjoint thrown away;
 *   - readPixels sync: wall clock from an idle GPU through update() and a 1-pixel
 *     readRenderTargetPixels of the output, which cannot return before the passes are done
 *     (gl.finish() does not block in Chromium). This includes one GPU round trip, measured
 *     alone as `syncOnly`.
 */
import { WebGLRenderer } from 'three';
import { CpuWaveFields } from '../../src/fft/cpuWaveFields';
import { GpuWaveFields, supportedGpuPrecision, type GpuPrecision } from '../../src/fft/gpuWaveFields';
import { validateParameters } from '../../src/parameters/parameters';
import { createInitialSpectrum } from '../../src/spectrum/initialSpectrum';

/** EXT_disjoint_timer_query_webgl2; lib.dom has no type for it. */
interface TimerQueryExtension {
  readonly TIME_ELAPSED_EXT: GLenum;
  readonly GPU_DISJOINT_EXT: GLenum;
}

const renderer = new WebGLRenderer({ canvas: document.createElement('canvas') });
const gl = renderer.getContext() as WebGL2RenderingContext;
const timerQuery = gl.getExtension('EXT_disjoint_timer_query_webgl2') as TimerQueryExtension | null;
const RESULT_TIMEOUT_MS = 10_000;

export interface FieldsOptions {
  resolution: number;
  /** Which implementations to time; each round runs every one of them once, in this order. */
  gpu: GpuPrecision | null;
  js: boolean;
  warmupRounds: number;
  rounds: number;
}

export interface FieldsSamples {
  resolution: number;
  passCount: number | null;
  /** Milliseconds per update; null when not run (or no timer query extension). */
  gpuTimerQuery: number[] | null;
  gpuReadPixels: number[] | null;
  /** A 1-pixel readPixels on an idle GPU alone: the overhead inside each gpuReadPixels sample. */
  syncOnly: number[] | null;
  js: number[] | null;
  /** Timer query samples thrown away because GPU_DISJOINT_EXT was set. */
  disjointDiscarded: number;
}

const nextTask = (): Promise<void> => new Promise((resolve) => setTimeout(resolve, 0));

/** GPU time of work() in ms from a TIME_ELAPSED_EXT query, or null if the GPU was disjoint. */
async function timeWithQuery(ext: TimerQueryExtension, query: WebGLQuery, work: () => void): Promise<number | null> {
  gl.getParameter(ext.GPU_DISJOINT_EXT); // reading it clears it
  gl.beginQuery(ext.TIME_ELAPSED_EXT, query);
  work();
  gl.endQuery(ext.TIME_ELAPSED_EXT);
  gl.flush();
  const start = performance.now();
  // Results are never available in the task that ended the query.
  do {
    await nextTask();
    if (performance.now() - start > RESULT_TIMEOUT_MS) throw new Error('timer query result never became available');
  } while (!gl.getQueryParameter(query, gl.QUERY_RESULT_AVAILABLE));
  const disjoint = gl.getParameter(ext.GPU_DISJOINT_EXT) as boolean;
  const nanoseconds = gl.getQueryParameter(query, gl.QUERY_RESULT) as number;
  return disjoint ? null : nanoseconds / 1e6;
}

async function fields(options: FieldsOptions): Promise<FieldsSamples> {
  const params = validateParameters({ resolution: options.resolution });
  const spectrum = createInitialSpectrum(params);
  const gpu = options.gpu
    ? new GpuWaveFields(renderer, spectrum, params.choppiness, params.repeatPeriod, options.gpu)
    : null;
  const js = options.js ? new CpuWaveFields(spectrum, params.choppiness, params.repeatPeriod) : null;
  const pixel = options.gpu === 'float16' ? new Uint16Array(4) : new Float32Array(4);
  const sync = (): void => renderer.readRenderTargetPixels(gpu!.output, 0, 0, 1, 1, pixel);
  const query = gpu && timerQuery ? gl.createQuery() : null;

  const samples: FieldsSamples = {
    resolution: options.resolution,
    passCount: gpu?.passCount ?? null,
    gpuTimerQuery: query ? [] : null,
    gpuReadPixels: gpu ? [] : null,
    syncOnly: gpu ? [] : null,
    js: js ? [] : null,
    disjointDiscarded: 0,
  };
  let t = 1.25;
  const nextTime = (): number => (t += 0.0371); // a different time for every update
  try {
    for (let round = 0; round < options.warmupRounds + options.rounds; round++) {
      const keep = round >= options.warmupRounds;
      if (gpu && query && timerQuery) {
        sync();
        let ms: number | null = null;
        for (let attempt = 0; ms === null && attempt < 5; attempt++) {
          ms = await timeWithQuery(timerQuery, query, () => gpu.update(nextTime()));
          if (ms === null && keep) samples.disjointDiscarded++;
        }
        if (keep && ms !== null) samples.gpuTimerQuery!.push(ms);
      }
      if (gpu) {
        sync();
        let start = performance.now();
        gpu.update(nextTime());
        sync();
        const ms = performance.now() - start;
        start = performance.now();
        sync();
        const syncMs = performance.now() - start;
        if (keep) {
          samples.gpuReadPixels!.push(ms);
          samples.syncOnly!.push(syncMs);
        }
      }
      if (js) {
        const start = performance.now();
        js.update(nextTime());
        const ms = performance.now() - start;
        if (keep) samples.js!.push(ms);
      }
      await nextTask(); // let the page breathe between rounds
    }
  } finally {
    if (query) gl.deleteQuery(query);
    gpu?.dispose();
  }
  return samples;
}

const bench = {
  info: () => {
    const debug = gl.getExtension('WEBGL_debug_renderer_info');
    return {
      renderer: debug ? String(gl.getParameter(debug.UNMASKED_RENDERER_WEBGL)) : String(gl.getParameter(gl.RENDERER)),
      supportedPrecision: supportedGpuPrecision(renderer),
      halfFloat: renderer.extensions.has('EXT_color_buffer_half_float'),
      timerQuery: timerQuery !== null,
      crossOriginIsolated: self.crossOriginIsolated,
      userAgent: navigator.userAgent,
    };
  },
  fields,
};

declare global {
  interface Window {
    bench: typeof bench;
  }
}
window.bench = bench;
document.title = 'ready';
