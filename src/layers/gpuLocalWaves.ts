/**
 * The GPU solver of the local waves: one step of src/layers/localWaveModel.ts in fragment passes,
 * its transforms run by the GPU FFT engine (src/fft/gpuFft.ts) in float32:
 *   prepare (shift, sponge, sources) → forward FFT → evolve (turn each mode, form the slopes'
 *   spectrum) → inverse FFT → the state, an RGBA32F target;
 * and, when asked, unpack into the layer's two field textures. Half floats cannot hold the forward
 * transform (its values reach N²× the heights): without float32 targets the JS solver runs instead.
 * Owns its targets, engine and materials and frees them in dispose().
 */
import {
  ClampToEdgeWrapping,
  FloatType,
  LinearFilter,
  NearestFilter,
  RGBAFormat,
  WebGLRenderTarget,
  type ShaderMaterial,
  type Texture,
  type WebGLRenderer,
} from 'three';
import { FullscreenPass, fullscreenMaterial, runPasses } from '../fft/fullscreenPass';
import { GpuFft } from '../fft/gpuFft';
import { shaderSource } from '../shaderSource';
import { GRAVITY } from '../spectrum/dispersion';
import { MAX_IMPULSES_PER_STEP, SPONGE_WIDTH_FRACTION, spongeEdgeRate, type LocalWaveGrid, type LocalWaveStep } from './localWaveModel';

/**
 * Whether the context renders in software (SwiftShader, llvmpipe, …). There each fragment pass
 * costs ~0.6 ms of fixed overhead, and a step's 31 passes at N = 128 take 30 ms where the JS solver
 * takes 4 ms (measured under SwiftShader on 2 cores); on a GPU the passes take well under 1 ms.
 */
export function isSoftwareRenderer(renderer: WebGLRenderer): boolean {
  const gl = renderer.getContext();
  // Asked once per context: getParameter may wait for the GPU to finish its queue.
  let software = softwareContexts.get(gl);
  if (software === undefined) {
    const info = gl.getExtension('WEBGL_debug_renderer_info');
    software = /swiftshader|llvmpipe|softpipe|software/i.test(String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER)));
    softwareContexts.set(gl, software);
  }
  return software;
}

const softwareContexts = new WeakMap<WebGLRenderingContext | WebGL2RenderingContext, boolean>();

/** Deep water in the shader: tanh(min(k·d, 20)) is 1 in float32. */
const DEEP = 1e6;

export class GpuLocalWaves {
  /** The layer's fields after unpack(): (0, η_s, 0, 0) and (∂η_s/∂x, ∂η_s/∂z, 0, 0). */
  readonly output: WebGLRenderTarget;
  /** (η_s, ψ, ∂η_s/∂x, ∂η_s/∂z) after the last step. */
  readonly state: WebGLRenderTarget;
  private readonly fft: GpuFft;
  private readonly prepare: ShaderMaterial;
  private readonly evolve: ShaderMaterial;
  private readonly storeState: ShaderMaterial;
  private readonly unpacker: ShaderMaterial;
  private readonly pass = new FullscreenPass();
  /** Fragment passes per step. */
  readonly passCount: number;

  constructor(
    private readonly renderer: WebGLRenderer,
    readonly grid: LocalWaveGrid,
  ) {
    const n = grid.resolution;
    // Made first: it throws if the device cannot render to its layered framebuffer.
    this.fft = new GpuFft(renderer, { size: n, type: FloatType });
    this.state = new WebGLRenderTarget(n, n, { type: FloatType, format: RGBAFormat, depthBuffer: false, minFilter: NearestFilter, magFilter: NearestFilter, generateMipmaps: false });
    const filterable = renderer.extensions.has('OES_texture_float_linear');
    // Clamped, so that outside the grid the surface samples the edge texels, which are held at 0.
    this.output = new WebGLRenderTarget(n, n, {
      count: 2,
      type: FloatType,
      format: RGBAFormat,
      depthBuffer: false,
      wrapS: ClampToEdgeWrapping,
      wrapT: ClampToEdgeWrapping,
      minFilter: filterable ? LinearFilter : NearestFilter,
      magFilter: filterable ? LinearFilter : NearestFilter,
      generateMipmaps: false,
    });
    const sizeLog2 = { value: this.fft.sizeLog2 };
    this.prepare = fullscreenMaterial(
      shaderSource('localWaves/prepare.frag'),
      {
        tState: { value: this.state.texture },
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
    this.evolve = fullscreenMaterial(shaderSource('localWaves/evolve.frag'), {
      tSpectrum: { value: this.fft.sets[forward].textures[0] },
      sizeLog2,
      dt: { value: 0 },
      gridSize: { value: n * grid.cellSize },
      depth: { value: Math.min(grid.depth, DEEP) },
      gravity: { value: GRAVITY },
    });
    this.storeState = fullscreenMaterial(shaderSource('localWaves/state.frag'), { tSpectra0: { value: this.fft.sets[inverse].textures[0] }, sizeLog2 });
    this.unpacker = fullscreenMaterial(shaderSource('localWaves/unpack.frag'), { tState: { value: this.state.texture } });
    this.passCount = 3 + 2 * this.fft.passCount;
  }

  get displacement(): Texture {
    return this.output.textures[0];
  }

  get derivatives(): Texture {
    return this.output.textures[1];
  }

  /** Clears the sea on the grid. */
  clear(): void {
    runPasses(this.renderer, () => {
      for (const target of [this.state, this.output]) {
        this.renderer.setRenderTarget(target);
        this.renderer.setClearColor(0x000000, 0);
        this.renderer.clear(true, false, false);
      }
    });
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
    runPasses(this.renderer, () => {
      this.fft.load(this.prepare, 0);
      const forward = this.fft.transform(0);
      const spectra = forward === 0 ? 1 : 0;
      this.fft.load(this.evolve, spectra);
      this.fft.transform(spectra);
      this.draw(this.storeState, this.state);
    });
  }

  /** Writes the state into the layer's field textures. */
  unpack(): void {
    runPasses(this.renderer, () => this.draw(this.unpacker, this.output));
  }

  dispose(): void {
    for (const target of [this.state, this.output]) target.dispose();
    this.fft.dispose();
    for (const material of [this.prepare, this.evolve, this.storeState, this.unpacker]) material.dispose();
    this.pass.dispose();
  }

  private draw(material: ShaderMaterial, target: WebGLRenderTarget): void {
    this.renderer.setRenderTarget(target);
    this.pass.draw(this.renderer, material);
  }
}
