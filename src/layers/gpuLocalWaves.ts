/**
 * The GPU solver of the local waves: one step of src/layers/localWaveModel.ts in fragment passes,
 * its transforms run by the GPU FFT engine (src/fft/gpuFft.ts) in float32, on a GpuDevice
 * (src/device/gpuDevice.ts; WebGL 2 here):
 *   prepare (shift, sponge, sources) → forward FFT → evolve (turn each mode, form the slopes'
 *   spectrum) → inverse FFT → the state, an RGBA32F target;
 * and, when asked, unpack into the layer's two field textures. Half floats cannot hold the forward
 * transform (its values reach N²× the heights): without float32 targets the JS solver runs instead.
 * Owns its device, targets, engine, materials and the wet mask's texture (made the first time land
 * is under the grid) and frees them in dispose().
 */
import { DataTexture, FloatType, NearestFilter, RedFormat, type Texture, type WebGLRenderer } from 'three';
import type { FieldTarget, PassMaterial } from '../device/gpuDevice';
import type { WebGL2Device } from '../device/webgl2/webgl2Device';
import { createGpuDevice } from '../device/deviceFor';
import { GpuFft } from '../fft/gpuFft';
import { shaderSource } from '../shaderSource';
import { GRAVITY } from '../spectrum/dispersion';
import { MAX_IMPULSES_PER_STEP, SPONGE_WIDTH_FRACTION, spongeEdgeRate, type LocalWaveGrid, type LocalWaveStep, type LocalWaveWater } from './localWaveModel';

/** Deep water in the shader: tanh(min(k·d, 20)) is 1 in float32. */
const DEEP = 1e6;

export class GpuLocalWaves {
  /** The layer's fields after unpack(): (0, η_s, 0, 0) and (∂η_s/∂x, ∂η_s/∂z, 0, 0). */
  private readonly output: FieldTarget;
  /** (η_s, ψ, ∂η_s/∂x, ∂η_s/∂z) after the last step. */
  private readonly state: FieldTarget;
  private readonly device: WebGL2Device;
  private readonly fft: GpuFft;
  private readonly prepare: PassMaterial;
  private readonly evolve: PassMaterial;
  private readonly storeState: PassMaterial;
  private readonly unpacker: PassMaterial;
  /** The wet mask (setWater), null until land is first under the grid. */
  private wetTexture: DataTexture | null = null;
  /** Fragment passes per step. */
  readonly passCount: number;

  constructor(
    renderer: WebGLRenderer,
    readonly grid: LocalWaveGrid,
  ) {
    const n = grid.resolution;
    const device = (this.device = createGpuDevice(renderer));
    // Made first: it throws if the device cannot render to its layered framebuffer.
    try {
      this.fft = new GpuFft(device, { size: n, precision: 'float32' });
    } catch (error) {
      device.dispose();
      throw error;
    }
    this.state = device.createFieldTarget({ size: n, precision: 'float32' });
    // Clamped, so that outside the grid the surface samples the edge texels, which are held at 0.
    this.output = device.createFieldTarget({ size: n, precision: 'float32', count: 2, sampling: 'clamped' });
    const sizeLog2 = { value: this.fft.sizeLog2 };
    this.prepare = device.passMaterial(
      shaderSource('localWaves/prepare.frag'),
      {
        tState: { value: this.state.textures[0] },
        sizeLog2,
        shift: { value: [0, 0] },
        dt: { value: 0 },
        cellSize: { value: grid.cellSize },
        spongeWidth: { value: n * SPONGE_WIDTH_FRACTION },
        spongeEdgeRate: { value: spongeEdgeRate(grid.cellSize) },
        impulsePose: { value: new Float32Array(4 * MAX_IMPULSES_PER_STEP) },
        impulseShape: { value: new Float32Array(4 * MAX_IMPULSES_PER_STEP) },
        impulseCount: { value: 0 },
      },
      { MAX_IMPULSES: MAX_IMPULSES_PER_STEP },
    );
    // Prepared into set 0; the forward transform ends in FORWARD, evolve writes the other set,
    // whose inverse transform ends in INVERSE.
    const forward = this.fft.resultOf(0);
    const inverse = this.fft.resultOf(forward === 0 ? 1 : 0);
    this.evolve = device.passMaterial(shaderSource('localWaves/evolve.frag'), {
      tSpectrum: { value: this.fft.sets[forward].textures[0] },
      sizeLog2,
      dt: { value: 0 },
      gridSize: { value: n * grid.cellSize },
      depth: { value: Math.min(grid.depth, DEEP) },
      gravity: { value: GRAVITY },
    });
    this.storeState = device.passMaterial(shaderSource('localWaves/state.frag'), {
      tSpectra0: { value: this.fft.sets[inverse].textures[0] },
      sizeLog2,
      tWet: { value: null },
      landUnder: { value: false },
    });
    this.unpacker = device.passMaterial(shaderSource('localWaves/unpack.frag'), { tState: { value: this.state.textures[0] } });
    this.passCount = 3 + 2 * this.fft.passCount;
  }

  get displacement(): Texture {
    return this.output.textures[0];
  }

  /** Reads the state, (η_s, ψ, ∂η_s/∂x, ∂η_s/∂z) a texel, into `into` (4·N² floats), waiting for the GPU. */
  readState(into: Float32Array): void {
    this.device.readBack(this.state, into);
  }

  /** As readState, without waiting: resolves once `into` holds it; rejects if the context was lost. */
  readStateLater(into: Float32Array): Promise<void> {
    return this.device.readBackLater(this.state, into);
  }

  get derivatives(): Texture {
    return this.output.textures[1];
  }

  /** Clears the sea on the grid. */
  clear(): void {
    this.device.runPasses(() => {
      for (const target of [this.state, this.output]) this.device.clear(target);
    });
  }

  /** The water under the grid from the next step on (localWaveModel.ts): the dispersion's depth, and land held at zero. */
  setWater({ depth, wet }: LocalWaveWater): void {
    this.evolve.uniforms.depth.value = Math.min(depth, DEEP);
    const u = this.storeState.uniforms;
    u.landUnder.value = wet !== null;
    if (wet === null) return;
    const n = this.grid.resolution;
    if (this.wetTexture === null) {
      this.wetTexture = new DataTexture(new Float32Array(n * n), n, n, RedFormat, FloatType);
      this.wetTexture.minFilter = this.wetTexture.magFilter = NearestFilter;
      u.tWet.value = this.wetTexture;
    }
    (this.wetTexture.image.data as Float32Array).set(wet);
    this.wetTexture.needsUpdate = true;
  }

  /** One step: from `state` to `state`. */
  step({ shiftX, shiftZ, impulses, dt }: LocalWaveStep): void {
    if (impulses.length > MAX_IMPULSES_PER_STEP) throw new RangeError(`GpuLocalWaves.step: at most ${MAX_IMPULSES_PER_STEP} impulses per step`);
    const u = this.prepare.uniforms;
    u.shift.value = [shiftX, shiftZ];
    u.dt.value = dt;
    u.impulseCount.value = impulses.length;
    impulses.forEach((impulse, s) => {
      u.impulsePose.value.set([impulse.x, impulse.z, impulse.cos, impulse.sin], 4 * s);
      u.impulseShape.value.set([impulse.halfLength, impulse.halfBeam, impulse.height, 0], 4 * s);
    });
    this.evolve.uniforms.dt.value = dt;
    this.device.runPasses(() => {
      this.fft.load(this.prepare, 0);
      const forward = this.fft.transform(0);
      const spectra = forward === 0 ? 1 : 0;
      this.fft.load(this.evolve, spectra);
      this.fft.transform(spectra);
      this.device.draw(this.storeState, this.state);
    });
  }

  /** Writes the state into the layer's field textures. */
  unpack(): void {
    this.device.runPasses(() => this.device.draw(this.unpacker, this.output));
  }

  dispose(): void {
    for (const target of [this.state, this.output]) target.dispose();
    this.fft.dispose();
    for (const material of [this.prepare, this.evolve, this.storeState, this.unpacker]) material.dispose();
    this.wetTexture?.dispose();
    this.device.dispose();
  }
}
