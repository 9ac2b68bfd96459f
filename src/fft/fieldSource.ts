/**
 * What an FFT cascade (src/layers/fftCascade.ts) asks of the backend that computes its fields: the
 * GPU's fragment passes (gpuWaveFields.ts) and the JS FFT (cpuFieldTextures.ts) both implement
 * FftFieldSource, and a new backend is one more class that does.
 */
import type { Texture } from 'three';
import type { LayerFieldsOnCpu, LayerQueryFields } from '../layers/waveLayer';

/** Fields a backend computes on the CPU anyway, which the queries read instead of computing their own. */
export interface CpuFieldsForQueries {
  /** Whether they come from a worker (not given up). */
  readonly inWorker: boolean;
  /** The fields the textures show, for the queries, or null when there are none (with velocities) yet. */
  forQueries(): LayerQueryFields | null;
  /** Forgets that queries asked: velocities are no longer computed for them. */
  forgetQueries(): void;
}

export interface FftFieldSource {
  /** (Dx, h, Dz, ∂Dx/∂z), the layout of waveFieldLayout.ts. */
  readonly displacement: Texture;
  /** (∂h/∂x, ∂h/∂z, ∂Dx/∂x, ∂Dz/∂z). */
  readonly derivatives: Texture;
  /** Fragment passes per update, 0 for a backend that runs none. */
  readonly passCount: number;
  /** Why the fields are computed on the main thread although a worker was asked for, or null. */
  readonly workerFault: string | null;
  /** Its fields on the CPU for the queries, or null for a backend that keeps none (the GPU). */
  readonly cpuFields: CpuFieldsForQueries | null;
  /** The fields the textures show now, on the CPU (no computation), or null for a backend that keeps none. */
  shownFieldsOnCpu(): LayerFieldsOnCpu | null;
  /** The fields at time t (s); `step` (s) since the last update lets a worker ask ahead. */
  update(t: number, step: number): void;
  dispose(): void;
}
