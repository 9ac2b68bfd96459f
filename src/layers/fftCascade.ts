/**
 * An FFT cascade: one periodic patch of the sea, simulated from its own band of the spectrum
 * (src/spectrum/cascadeBands.ts) by one FFT backend, an FftFieldSource (src/fft/fieldSource.ts): the
 * GPU's fragment passes (src/fft/gpuWaveFields.ts) or JS (src/fft/cpuFieldTextures.ts, optionally
 * in a worker).
 * The queries read a CPU copy of its fields, which cascadeQueryFields.ts keeps.
 *
 * Owns its backend and its queries' copy (with their worker), and frees them in dispose().
 */
import type { WebGLRenderer } from 'three';
import { CpuFieldTextures, webglFloatTextureSupport } from '../fft/cpuFieldTextures';
import type { FftFieldSource } from '../fft/fieldSource';
import { GpuWaveFields, type GpuPrecision } from '../fft/gpuWaveFields';
import type { InitialSpectrum, SpectrumOrigin } from '../spectrum/initialSpectrum';
import { CascadeQueryFields } from './cascadeQueryFields';
import type { LayerFieldsOnCpu, LayerFrame, LayerQueryFields, WaveLayer } from './waveLayer';

/**
 * Which implementation computes a cascade's fields: makes its FftFieldSource (src/fft/fieldSource.ts)
 * for the renderer it draws with: a WebGLRenderer, or null where the fields need nothing of one (src/webgpu/).
 */
export type FftBackend<Renderer = WebGLRenderer> = (renderer: Renderer, spectrum: InitialSpectrum) => FftFieldSource;

/** The GPU's fragment passes (src/fft/gpuWaveFields.ts) in `precision`. */
export function gpuBackend(precision: GpuPrecision): FftBackend {
  return (renderer, spectrum) => new GpuWaveFields(renderer, spectrum, precision);
}

/** The JS FFT (src/fft/cpuFieldTextures.ts), in a worker if `worker`. */
export function jsBackend(worker: boolean): FftBackend {
  return (renderer, spectrum) => new CpuFieldTextures(webglFloatTextureSupport(renderer), spectrum, worker);
}

export class FftCascade<Renderer = WebGLRenderer> implements WaveLayer {
  readonly textures;
  readonly frame: LayerFrame;
  readonly movesSideways = true;
  private readonly backend: FftFieldSource;
  /** The CPU copy the queries read, and the fields computed here on demand. */
  private readonly queries: CascadeQueryFields;

  constructor(
    renderer: Renderer,
    readonly spectrum: InitialSpectrum,
    /** What made `spectrum`: the query worker builds its copy from it. */
    origin: SpectrumOrigin,
    backend: FftBackend<Renderer>,
    /** Whether the queries' fields may be computed in a worker (else here, once per time asked). */
    queryWorkerWanted = true,
    /** The cascade this one replaces, whose queries' provisional copy's arrays it may take over. */
    predecessor: FftCascade<Renderer> | null = null,
  ) {
    this.backend = backend(renderer, spectrum);
    this.queries = new CascadeQueryFields(spectrum, origin, this.backend.cpuFields, queryWorkerWanted, predecessor?.queries ?? null);
    this.textures = { displacement: { value: this.backend.displacement }, derivatives: { value: this.backend.derivatives } };
    this.frame = { size: spectrum.patchSize, origin: [0, 0], periodic: true, resolution: spectrum.resolution };
  }

  /** Why the JS path runs on the main thread although a worker was asked for (CpuFieldTextures.workerFault), or null. */
  get workerFault(): string | null {
    return this.backend.workerFault;
  }

  /** Fragment passes per update on the GPU, 0 in JS. */
  get passCount(): number {
    return this.backend.passCount;
  }

  /** The fields at time t (s), computed from t alone; `step` (s) since the last update is for the workers to ask ahead. */
  update(t: number, step: number): void {
    this.backend.update(t, step);
    this.queries.afterUpdate(t, step);
  }

  /** Whether queries came (queryFields) since the cascade was made, or since forgetQueries. */
  get queriedYet(): boolean {
    return this.queries.queriedYet;
  }

  /** Forgets the queries so far, as if none had come (CascadeQueryFields.forgetQueries): for the Ocean's warm-up. */
  forgetQueries(): void {
    this.queries.forgetQueries();
  }

  /** The fields at time t, computed here on the main thread (for the foam's warm-up and the tests). */
  fieldsOnCpu(t: number): LayerFieldsOnCpu {
    return this.queries.fieldsOnCpu(t);
  }

  queryFields(t: number): LayerQueryFields {
    return this.queries.queryFields(t);
  }

  /** How many times the queries found no fields close enough to the time asked, and computed them here (once per time). */
  get fieldsComputedHere(): number {
    return this.queries.fieldsComputedHere;
  }

  /** The fields the textures show now, on the JS path (no computation); null on the GPU path, which keeps none. */
  shownFieldsOnCpu(): LayerFieldsOnCpu | null {
    return this.backend.shownFieldsOnCpu();
  }

  dispose(): void {
    this.backend.dispose();
    this.queries.dispose();
  }
}
