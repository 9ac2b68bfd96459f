/**
 * An FFT cascade: one periodic patch of the sea, simulated from its own band of the spectrum
 * (src/spectrum/cascadeBands.ts) by one FFT backend, the GPU's fragment passes
 * (src/fft/gpuWaveFields.ts) or JS (src/fft/cpuFieldTextures.ts, optionally in a worker).
 * Owns its backend and its CPU copy for queries, and frees both in dispose().
 */
import type { WebGLRenderer } from 'three';
import { CpuFieldTextures } from '../fft/cpuFieldTextures';
import { UnsupportedError } from '../parameters/options';
import { CpuWaveFields } from '../fft/cpuWaveFields';
import { GpuWaveFields, type GpuPrecision } from '../fft/gpuWaveFields';
import type { InitialSpectrum } from '../spectrum/initialSpectrum';
import type { LayerFieldsOnCpu, LayerFrame, WaveLayer } from './waveLayer';

/** Which implementation computes a cascade's fields. */
export type FftBackend = { kind: 'gpu'; precision: GpuPrecision } | { kind: 'js'; worker: boolean };

export class FftCascade implements WaveLayer {
  readonly textures;
  readonly frame: LayerFrame;
  readonly movesSideways = true;
  private readonly backend: GpuWaveFields | CpuFieldTextures;
  /** The JS fields for queries, computed on demand for the time last asked, and their velocities (for the time they were last asked). */
  private query: { fields: CpuWaveFields; time: number; velocities: Float32Array | null; velocityTime: number } | null = null;

  constructor(
    renderer: WebGLRenderer,
    readonly spectrum: InitialSpectrum,
    backend: FftBackend,
  ) {
    this.backend =
      backend.kind === 'gpu' ? new GpuWaveFields(renderer, spectrum, backend.precision) : new CpuFieldTextures(renderer, spectrum, backend.worker);
    this.textures = { displacement: { value: this.backend.displacement }, derivatives: { value: this.backend.derivatives } };
    this.frame = { size: spectrum.patchSize, origin: [0, 0], periodic: true, resolution: spectrum.resolution };
  }

  /** Why the JS path runs on the main thread although a worker was asked for (CpuFieldTextures.workerFault), or null. */
  get workerFault(): string | null {
    return this.backend instanceof CpuFieldTextures ? this.backend.workerFault : null;
  }

  /** Fragment passes per update on the GPU, 0 in JS. */
  get passCount(): number {
    return this.backend instanceof GpuWaveFields ? this.backend.passCount : 0;
  }

  /** The fields at time t (s), computed from t alone (no state carried between updates). */
  update(t: number): void {
    this.backend.update(t);
  }

  fieldsOnCpu(t: number): LayerFieldsOnCpu {
    return this.fieldsOnCpuQuery(t).fields;
  }

  /** The JS fields for queries at time t (computed once per t asked). */
  private fieldsOnCpuQuery(t: number): NonNullable<FftCascade['query']> {
    this.query ??= { fields: new CpuWaveFields(this.spectrum), time: NaN, velocities: null, velocityTime: NaN };
    if (this.query.time !== t) {
      this.query.fields.update(t);
      this.query.time = t;
    }
    return this.query;
  }

  velocitiesOnCpu(t: number): Float32Array {
    const query = this.fieldsOnCpuQuery(t);
    if (query.velocityTime !== t) {
      query.velocities = query.fields.updateVelocities(t);
      query.velocityTime = t;
    }
    return query.velocities!;
  }

  /** The fields the textures show now, on the JS path (no computation); the GPU path keeps none. */
  shownFieldsOnCpu(): LayerFieldsOnCpu {
    if (this.backend instanceof GpuWaveFields) throw new UnsupportedError('shownFieldsOnCpu', 'FftCascade.shownFieldsOnCpu: the GPU path keeps its fields on the GPU');
    return this.backend.shownFields;
  }

  dispose(): void {
    this.backend.dispose();
    this.query = null;
  }
}
