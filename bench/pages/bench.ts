/**
 * Benchmark page for `npm run bench` (bench/run.mjs drives it through Playwright): times one full
 * GpuWaveFields.update() (every field) and one CpuWaveFields.update() in this page, for one cascade
 * (`fields`) or for every cascade of a set of patch sizes (`cascades`, one update of each cascade
 * per sample), and hands back raw samples in milliseconds; bench/lib/stats.mjs takes the medians.
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
import { createCascadeSpectra, type InitialSpectrum } from '../../src/spectrum/initialSpectrum';

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
  /** Fragment passes per GPU update over every cascade timed; null when the GPU path was not run. */
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

export interface CascadesOptions extends FieldsOptions {
  /** One set of patch sizes per subject; a sample updates every cascade of its set. */
  patchSizeSets: number[][];
}

export interface CascadesSamples extends FieldsSamples {
  patchSizes: number[];
  cascades: number;
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

/**
 * What one sample updates: every cascade of a list of spectra, on the GPU (all passes of all
 * cascades inside one timer query, or between two syncs) and/or in JS (one after the other).
 */
class Subject {
  readonly gpu: GpuWaveFields[] | null;
  readonly js: CpuWaveFields[] | null;
  readonly samples: FieldsSamples;
  private readonly pixel: Float32Array | Uint16Array;
  private readonly query: WebGLQuery | null;

  constructor(spectra: readonly InitialSpectrum[], options: FieldsOptions) {
    this.gpu = options.gpu ? spectra.map((spectrum) => new GpuWaveFields(renderer, spectrum, options.gpu!)) : null;
    this.js = options.js ? spectra.map((spectrum) => new CpuWaveFields(spectrum)) : null;
    this.pixel = options.gpu === 'float16' ? new Uint16Array(4) : new Float32Array(4);
    this.query = this.gpu && timerQuery ? gl.createQuery() : null;
    this.samples = {
      resolution: options.resolution,
      passCount: this.gpu ? this.gpu.reduce((sum, fields) => sum + fields.passCount, 0) : null,
      gpuTimerQuery: this.query ? [] : null,
      gpuReadPixels: this.gpu ? [] : null,
      syncOnly: this.gpu ? [] : null,
      js: this.js ? [] : null,
      disjointDiscarded: 0,
    };
  }

  /**
   * 1-pixel readPixels of the last cascade's output. GL commands run in order, so it cannot
   * return before the passes of every cascade updated before it are done.
   */
  private sync(): void {
    const gpu = this.gpu!;
    renderer.readRenderTargetPixels(gpu[gpu.length - 1].output, 0, 0, 1, 1, this.pixel);
  }

  /** One round: each implementation once, each update at a new time from nextTime(). */
  async round(keep: boolean, nextTime: () => number): Promise<void> {
    const { gpu, js, query, samples } = this;
    if (gpu && query && timerQuery) {
      this.sync();
      let ms: number | null = null;
      for (let attempt = 0; ms === null && attempt < 5; attempt++) {
        const t = nextTime();
        ms = await timeWithQuery(timerQuery, query, () => gpu.forEach((fields) => fields.update(t)));
        if (ms === null && keep) samples.disjointDiscarded++;
      }
      if (keep && ms !== null) samples.gpuTimerQuery!.push(ms);
    }
    if (gpu) {
      this.sync();
      const t = nextTime();
      let start = performance.now();
      for (const fields of gpu) fields.update(t);
      this.sync();
      const ms = performance.now() - start;
      start = performance.now();
      this.sync();
      const syncMs = performance.now() - start;
      if (keep) {
        samples.gpuReadPixels!.push(ms);
        samples.syncOnly!.push(syncMs);
      }
    }
    if (js) {
      const t = nextTime();
      const start = performance.now();
      for (const fields of js) fields.update(t);
      const ms = performance.now() - start;
      if (keep) samples.js!.push(ms);
    }
  }

  dispose(): void {
    if (this.query) gl.deleteQuery(this.query);
    this.gpu?.forEach((fields) => fields.dispose());
  }
}

/** Warm-up and timed rounds of the subjects, interleaved round by round. */
async function timeSubjects(subjects: readonly Subject[], options: FieldsOptions): Promise<void> {
  let t = 1.25;
  const nextTime = (): number => (t += 0.0371); // a different time for every update
  for (let round = 0; round < options.warmupRounds + options.rounds; round++) {
    for (const subject of subjects) await subject.round(round >= options.warmupRounds, nextTime);
    await nextTask(); // let the page breathe between rounds
  }
}

/** The `fields` rows: the first (finest) cascade of the default patch sizes. */
async function fields(options: FieldsOptions): Promise<FieldsSamples> {
  const params = validateParameters({ resolution: options.resolution });
  const subject = new Subject(createCascadeSpectra(params).slice(0, 1), options);
  try {
    await timeSubjects([subject], options);
  } finally {
    subject.dispose();
  }
  return subject.samples;
}

/** The `cascades` rows: every cascade of each set of patch sizes, the sets interleaved. */
async function cascades(options: CascadesOptions): Promise<CascadesSamples[]> {
  const subjects: Subject[] = [];
  try {
    for (const patchSizes of options.patchSizeSets) {
      const params = validateParameters({ resolution: options.resolution, patchSizes });
      subjects.push(new Subject(createCascadeSpectra(params), options));
    }
    await timeSubjects(subjects, options);
  } finally {
    subjects.forEach((subject) => subject.dispose());
  }
  return subjects.map((subject, i) => ({
    ...subject.samples,
    patchSizes: options.patchSizeSets[i],
    cascades: options.patchSizeSets[i].length,
  }));
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
  cascades,
};

declare global {
  interface Window {
    bench: typeof bench;
  }
}
window.bench = bench;
document.title = 'ready';
