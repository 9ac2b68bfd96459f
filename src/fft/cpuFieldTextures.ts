/**
 * The JS path's output as textures in the layout of waveFieldLayout.ts, so the surface material
 * samples the same thing whichever path runs. The fields are computed either right here
 * (`worker: false`: the result is in the textures as soon as update() returns) or in a Web Worker
 * (fieldWorker.ts: the page stays responsive; the textures show the latest finished fields,
 * asked for the time of the frame they arrive for). Owns its two DataTextures and the worker. The
 * fields shown are also what the queries read (forQueries): with the worker, once the queries ask,
 * it computes the velocities too.
 *
 * When the worker is given up (fieldWorker.ts says when), the computation moves onto the main
 * thread for good, and `workerFault` says why (OceanSimulation reports it as its path).
 */
import {
  DataTexture,
  FloatType,
  LinearFilter,
  LinearMipmapLinearFilter,
  NearestFilter,
  RepeatWrapping,
  RGBAFormat,
  type WebGLRenderer,
} from 'three';
import { CpuWaveFields } from './cpuWaveFields';
import type { CpuFieldsForQueries, FftFieldSource } from './fieldSource';
import type { InitialSpectrum } from '../spectrum/initialSpectrum';
import type { LayerQueryFields } from '../layers/waveLayer';
import { FIELD_TEXTURES } from './waveFieldLayout';
import type { FieldArrays } from './fieldArrays';
import { FieldWorker } from './fieldWorker';
import type { WorkerReply } from './waveFieldWorker';

/**
 * What the device can do with RGBA32F textures: filter them (linear), and render to them (which
 * generateMipmap needs). The one thing the JS path's textures ask of a renderer.
 */
export interface FloatTextureSupport {
  readonly filterable: boolean;
  readonly renderable: boolean;
}

/** What a WebGLRenderer's context can do with RGBA32F textures. */
export function webglFloatTextureSupport(renderer: WebGLRenderer): FloatTextureSupport {
  return { filterable: renderer.extensions.has('OES_texture_float_linear'), renderable: renderer.extensions.has('EXT_color_buffer_float') };
}

export class CpuFieldTextures implements FftFieldSource, CpuFieldsForQueries {
  readonly displacement: DataTexture;
  readonly derivatives: DataTexture;
  /** The main thread's computation (no worker, or the worker given up), or null. */
  private fields: CpuWaveFields | null = null;
  private worker: FieldWorker | null = null;
  private fault: string | null = null;
  /** Whether the mipmap levels are computed in JS (float textures that filter but cannot be rendered to). */
  private readonly levelsInJs: boolean;
  /** The fields shown, for the queries (null before the first), and whether their velocities are at hand. */
  private shown: { forQueries: LayerQueryFields; hasVelocities: boolean } | null = null;
  /** Set by the first query: from then on the worker computes the velocities as well. */
  private velocitiesWanted = false;

  constructor(
    support: FloatTextureSupport,
    private readonly spectrum: InitialSpectrum,
    useWorker: boolean,
  ) {
    const n = spectrum.resolution;
    const { filterable } = support;
    // generateMipmap renders into the texture: RGBA32F must also be renderable (EXT_color_buffer_float),
    // or it fails (GL_INVALID_OPERATION) and the levels hold garbage. There the levels are made
    // here, by the same 2×2 box filter, and uploaded with the texture.
    const mipmapped = filterable && support.renderable;
    this.levelsInJs = filterable && !mipmapped;
    // Without a worker the textures show CpuWaveFields' own arrays: nothing is copied.
    this.fields = useWorker ? null : new CpuWaveFields(spectrum);
    const [displacement, derivatives] = FIELD_TEXTURES.map((name) =>
      fieldTexture(this.fields?.[name] ?? new Float32Array(4 * n * n), n, filterable, mipmapped, name),
    );
    this.displacement = displacement;
    this.derivatives = derivatives;
    if (useWorker) {
      this.worker = new FieldWorker(spectrum, 'JS worker', (reply) => this.receive(reply), (fault) => this.runOnMainThread(fault));
    }
  }

  /** It runs no fragment passes. */
  readonly passCount = 0;

  /** Its fields are the queries' too (CascadeQueryFields reads them where it can). */
  get cpuFields(): CpuFieldsForQueries {
    return this;
  }

  shownFieldsOnCpu(): { displacement: Float32Array; derivatives: Float32Array } {
    return this.shownFields;
  }

  /** Whether the fields come from a worker (not given up). */
  get inWorker(): boolean {
    return this.worker !== null;
  }

  /**
   * Why the fields are computed on the main thread although a worker was asked for (the worker
   * failed, or workers are blocked), or null.
   */
  get workerFault(): string | null {
    return this.fault;
  }

  /** The fields at time t (s), `step` s after the last update (the worker's fields are asked ahead by it, fieldWorker.ts). */
  update(t: number, step: number): void {
    if (this.fields) {
      this.fields.update(t);
      this.shown = { forQueries: this.fields.forQueries(t), hasVelocities: true };
      this.markUpdated();
      return;
    }
    // Frames are dropped while the worker is busy.
    this.worker!.request(t, step, this.velocitiesWanted);
  }

  /**
   * The fields the textures show, for the queries, or null when there are none yet (or, from the
   * worker, none with velocities yet: the next ones will have them). On the main thread their
   * velocities are computed when first asked.
   */
  forQueries(): LayerQueryFields | null {
    this.velocitiesWanted = true;
    return this.shown?.hasVelocities ? this.shown.forQueries : null;
  }

  /** Forgets that queries asked (FftCascade.forgetQueries): the worker is not asked for velocities. */
  forgetQueries(): void {
    this.velocitiesWanted = false;
  }

  /** From now on the fields are computed here, in the arrays the textures show. */
  private runOnMainThread(fault: string): void {
    this.fault = fault;
    console.warn(`three-fft-ocean: ${fault}; the JS path runs on the main thread.`);
    this.worker = null;
    this.fields = new CpuWaveFields(this.spectrum);
    this.displacement.image.data = this.fields.displacement;
    this.derivatives.image.data = this.fields.derivatives;
    this.shown = null;
  }

  /** Shows the worker's finished fields; returns the arrays they replace, for its next request. */
  private receive({ t, ...arrays }: WorkerReply): FieldArrays {
    const previous = { ...this.shownFields, velocities: this.shown?.hasVelocities ? this.shown.forQueries.velocities() : null };
    this.displacement.image.data = arrays.displacement;
    this.derivatives.image.data = arrays.derivatives;
    const { displacement, derivatives, velocities } = arrays;
    this.shown = { forQueries: { time: t, resolution: this.spectrum.resolution, displacement, derivatives, velocities: () => velocities! }, hasVelocities: velocities !== null };
    this.markUpdated();
    return previous;
  }

  /** The arrays the textures show (the latest finished time). */
  get shownFields(): { displacement: Float32Array; derivatives: Float32Array } {
    return { displacement: this.displacement.image.data as Float32Array, derivatives: this.derivatives.image.data as Float32Array };
  }

  private markUpdated(): void {
    for (const texture of [this.displacement, this.derivatives]) {
      if (this.levelsInJs) setMipmapLevels(texture);
      texture.needsUpdate = true;
    }
  }

  dispose(): void {
    this.worker?.dispose();
    this.displacement.dispose();
    this.derivatives.dispose();
  }
}

/**
 * The texture's mipmap chain down to 1×1, from its image of square float texels of any number of
 * channels: each level the mean of 2×2 texels of the one above, wrapping (the fields repeat), as
 * generateMipmap's box filter does. Reuses the levels' arrays from one update to the next.
 */
export function setMipmapLevels(texture: DataTexture): void {
  const data = texture.image.data as Float32Array;
  let size = texture.image.width;
  const channels = data.length / (size * size);
  const levels = texture.mipmaps as { data: Float32Array; width: number; height: number }[];
  levels[0] = { data, width: size, height: size };
  for (let level = 1; size > 1; level++) {
    const above = levels[level - 1].data;
    const half = size / 2;
    if (levels[level]?.width !== half) levels[level] = { data: new Float32Array(channels * half * half), width: half, height: half };
    const below = levels[level].data;
    for (let j = 0; j < half; j++) {
      for (let i = 0; i < half; i++) {
        const a = channels * (2 * j * size + 2 * i);
        const b = a + channels * size;
        for (let c = 0; c < channels; c++) below[channels * (j * half + i) + c] = 0.25 * (above[a + c] + above[a + channels + c] + above[b + c] + above[b + channels + c]);
      }
    }
    size = half;
  }
}

function fieldTexture(data: Float32Array, n: number, filterable: boolean, mipmapped: boolean, name: string): DataTexture {
  const texture = new DataTexture(data, n, n, RGBAFormat, FloatType);
  texture.name = name;
  texture.wrapS = texture.wrapT = RepeatWrapping;
  texture.magFilter = filterable ? LinearFilter : NearestFilter;
  // Filterable: mipmapped, by the GPU where it can render to the texture, else by setMipmapLevels.
  texture.minFilter = filterable ? LinearMipmapLinearFilter : NearestFilter;
  texture.generateMipmaps = mipmapped;
  if (filterable && !mipmapped) setMipmapLevels(texture);
  return texture;
}
