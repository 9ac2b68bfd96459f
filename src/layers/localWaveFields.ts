/**
 * Where the local waves (localWaves.ts) are solved, and how their fields reach the surface and the
 * queries: one interface, two solvers behind it. The JS one (localWaveModel.ts) solves into arrays
 * that are the layer's two DataTextures' own; the GPU one (gpuLocalWaves.ts) solves in render
 * targets and is read back for the queries, without waiting for the GPU where it can. Each owns its
 * solver and its textures, and frees them in dispose().
 */
import { ClampToEdgeWrapping, DataTexture, FloatType, LinearFilter, NearestFilter, RGBAFormat, type Texture, type WebGLRenderer } from 'three';
import { GpuLocalWaves } from './gpuLocalWaves';
import { CpuLocalWaves, type LocalWaveGrid, type LocalWaveStep, type LocalWaveWater } from './localWaveModel';
import type { LayerFieldsOnCpu } from './waveLayer';

export interface LocalWaveFields {
  /** 'gpu' or 'js': where the waves are solved. */
  readonly path: 'gpu' | 'js';
  /** The layer's textures, in the layout of a wave layer (waveLayer.ts). */
  readonly textures: { readonly displacement: { value: Texture }; readonly derivatives: { value: Texture } };
  /** The water under the grid from the next step on: the dispersion's depth and the wet mask (localWaveModel.ts). */
  setWater(water: LocalWaveWater): void;
  /** One step of the solver (localWaveModel.ts's scheme). */
  step(step: LocalWaveStep): void;
  /** Every wave gone. */
  clear(): void;
  /** Makes the textures show the solver's state after steps or a clear; `active`: the solver has waves. */
  publish(active: boolean): void;
  /** The fields the surface shows now, on the CPU (read back on the GPU path, once per publish). */
  fieldsOnCpu(active: boolean): LayerFieldsOnCpu;
  /** The fields the textures hold, where they are on the CPU too (the JS path); else null. */
  shownFieldsOnCpu(): LayerFieldsOnCpu | null;
  /** The fields for the queries: on the GPU path those of the last read-back, a newer one started without waiting. */
  queryFields(active: boolean): LayerFieldsOnCpu;
  /** ∂h/∂t of the fields the queries read, in a layer's velocity layout. */
  velocities(active: boolean): Float32Array;
  dispose(): void;
}

export function localWaveFields(renderer: WebGLRenderer, grid: LocalWaveGrid, useGpu: boolean): LocalWaveFields {
  return useGpu ? new GpuLocalWaveFields(renderer, grid) : new JsLocalWaveFields(renderer, grid);
}

/** The JS solver, whose arrays are the textures'. */
class JsLocalWaveFields implements LocalWaveFields {
  readonly path = 'js';
  readonly textures;
  private readonly solver: CpuLocalWaves;
  private readonly dataTextures: [DataTexture, DataTexture];
  private readonly fields: LayerFieldsOnCpu;
  private published = 0;
  private readonly velocityTexels: Float32Array;
  private velocitiesFor = -1;

  constructor(renderer: WebGLRenderer, grid: LocalWaveGrid) {
    const n = grid.resolution;
    const filterable = renderer.extensions.has('OES_texture_float_linear');
    const texture = () => {
      const t = new DataTexture(new Float32Array(4 * n * n), n, n, RGBAFormat, FloatType);
      t.wrapS = t.wrapT = ClampToEdgeWrapping;
      t.minFilter = t.magFilter = filterable ? LinearFilter : NearestFilter;
      t.needsUpdate = true;
      return t;
    };
    this.dataTextures = [texture(), texture()];
    this.fields = { displacement: this.dataTextures[0].image.data as Float32Array, derivatives: this.dataTextures[1].image.data as Float32Array };
    this.solver = new CpuLocalWaves(grid);
    this.textures = { displacement: { value: this.dataTextures[0] }, derivatives: { value: this.dataTextures[1] } };
    this.velocityTexels = new Float32Array(4 * n * n);
  }

  setWater(water: LocalWaveWater): void {
    this.solver.setWater(water);
  }

  step(step: LocalWaveStep): void {
    this.solver.step(step);
  }

  clear(): void {
    this.solver.clear();
  }

  publish(): void {
    this.published++;
    toLayerFields(this.fields, this.solver.height, this.solver.slopeX, this.solver.slopeZ, 1);
    for (const texture of this.dataTextures) texture.needsUpdate = true;
  }

  fieldsOnCpu(): LayerFieldsOnCpu {
    return this.fields;
  }

  shownFieldsOnCpu(): LayerFieldsOnCpu {
    return this.fields;
  }

  queryFields(): LayerFieldsOnCpu {
    return this.fields;
  }

  velocities(): Float32Array {
    if (this.velocitiesFor !== this.published) {
      this.solver.verticalVelocity(this.solver.potential, 1, this.velocityTexels);
      this.velocitiesFor = this.published;
    }
    return this.velocityTexels;
  }

  dispose(): void {
    for (const texture of this.dataTextures) texture.dispose();
  }
}

/** The GPU solver, read back for the queries. */
class GpuLocalWaveFields implements LocalWaveFields {
  readonly path = 'gpu';
  readonly textures;
  private readonly solver: GpuLocalWaves;
  private published = 0;
  /** The fields read back for queries, and the state they are read from (readBackLater swaps in newer ones). */
  private cpuFields: { displacement: Float32Array; derivatives: Float32Array; state: Float32Array } | null = null;
  /** The publish the read-back fields are of. */
  private readBackOf = -1;
  /** The array a read-back without waiting fills, while one is in flight (else null). */
  private pendingRead: Float32Array | null = null;
  /** The spare array for the next read-back without waiting. */
  private spareState: Float32Array | null = null;
  /** The velocities are computed in JS from the read-back potential. */
  private velocitySolver: CpuLocalWaves | null = null;
  private velocityTexels: Float32Array | null = null;
  private velocitiesFor = -1;
  /** The water the solver steps over, which the velocities' ω is for too. */
  private water: LocalWaveWater;
  private disposed = false;

  constructor(
    renderer: WebGLRenderer,
    private readonly grid: LocalWaveGrid,
  ) {
    this.water = { depth: grid.depth, wet: null };
    this.solver = new GpuLocalWaves(renderer, grid);
    this.solver.clear();
    this.textures = { displacement: { value: this.solver.displacement }, derivatives: { value: this.solver.derivatives } };
  }

  setWater(water: LocalWaveWater): void {
    this.water = water;
    this.solver.setWater(water);
  }

  step(step: LocalWaveStep): void {
    this.solver.step(step);
  }

  clear(): void {
    this.solver.clear();
  }

  publish(active: boolean): void {
    this.published++;
    if (active) this.solver.unpack();
  }

  /** Read back at once, once per publish (a quiet solver holds no waves: zero). */
  fieldsOnCpu(active: boolean): LayerFieldsOnCpu {
    const n = this.grid.resolution;
    this.cpuFields ??= { displacement: new Float32Array(4 * n * n), derivatives: new Float32Array(4 * n * n), state: new Float32Array(4 * n * n) };
    if (this.readBackOf !== this.published) {
      this.readBackOf = this.published;
      const state = this.cpuFields.state;
      if (active) this.solver.readState(state);
      else state.fill(0);
      // The state's texels are (η_s, ψ, ∂η_s/∂x, ∂η_s/∂z).
      toLayerFields(this.cpuFields, state, state.subarray(2), state.subarray(3), 4);
    }
    return this.cpuFields;
  }

  shownFieldsOnCpu(): null {
    return null;
  }

  /** Only the first is read back at once; then the last read-back's, a newer one started (readBackLater). */
  queryFields(active: boolean): LayerFieldsOnCpu {
    return this.cpuFields !== null && active ? this.readBackLater() : this.fieldsOnCpu(active);
  }

  /**
   * The fields of the last read-back, after starting a read-back of the current state if it is
   * newer and none is in flight. three.js's readRenderTargetPixelsAsync copies into a pixel buffer
   * behind a fence and polls it, so the main thread never waits for the GPU; the queries read the
   * waves a frame or two old (local waves move by centimetres a second: under a millimetre in a
   * frame).
   */
  private readBackLater(): LayerFieldsOnCpu {
    const fields = this.cpuFields!;
    if (this.readBackOf !== this.published && this.pendingRead === null) {
      const n = this.grid.resolution;
      const publish = this.published;
      const target = (this.pendingRead = this.spareState ?? new Float32Array(4 * n * n));
      this.spareState = null;
      this.solver.readStateLater(target).then(
        () => {
          this.pendingRead = null;
          // Disposed meanwhile, or a read-back that waited has come first: nothing newer here.
          if (this.disposed || publish <= this.readBackOf) {
            this.spareState = target;
            return;
          }
          this.spareState = fields.state;
          fields.state = target;
          this.readBackOf = publish;
          toLayerFields(fields, target, target.subarray(2), target.subarray(3), 4);
        },
        () => (this.pendingRead = null), // a lost context: the next query starts another
      );
    }
    return fields;
  }

  velocities(active: boolean): Float32Array {
    if (this.cpuFields === null) this.fieldsOnCpu(active); // the first read-back
    this.velocityTexels ??= new Float32Array(4 * this.grid.resolution * this.grid.resolution);
    if (this.velocitiesFor !== this.readBackOf) {
      this.velocitySolver ??= new CpuLocalWaves(this.grid);
      this.velocitySolver.setWater(this.water);
      this.velocitySolver.verticalVelocity(this.cpuFields!.state.subarray(1), 4, this.velocityTexels);
      this.velocitiesFor = this.readBackOf;
    }
    return this.velocityTexels;
  }

  dispose(): void {
    this.disposed = true;
    this.solver.dispose();
  }
}

/**
 * Writes the layer layout (0, h, 0, 0), (∂h/∂x, ∂h/∂z, 0, 0) from the height and slopes, texel t's
 * at index t·stride of each array.
 */
function toLayerFields(
  fields: { displacement: Float32Array; derivatives: Float32Array },
  height: ArrayLike<number>,
  slopeX: ArrayLike<number>,
  slopeZ: ArrayLike<number>,
  stride: number,
): void {
  const texels = fields.displacement.length / 4;
  for (let texel = 0; texel < texels; texel++) {
    fields.displacement[4 * texel + 1] = height[texel * stride];
    fields.derivatives[4 * texel] = slopeX[texel * stride];
    fields.derivatives[4 * texel + 1] = slopeZ[texel * stride];
  }
}
