/**
 * The GPU solver of the local waves: one step of src/layers/localWaveModel.ts in fragment passes
 * over two RGBA32F targets that ping-pong (shaders/localWaves/):
 *   prepare (shift, sponge, sources) → log2 N forward FFT passes along x, as many along z →
 *   evolve (turn each mode, form the slopes' spectrum) → inverse FFT passes → the state;
 * and, when asked, unpack into the layer's two field textures. Half floats cannot hold the forward
 * transform (its values reach N²× the heights): without float32 targets the JS solver runs instead.
 * Owns its targets, tables and materials and frees them in dispose().
 */
import {
  ClampToEdgeWrapping,
  DataTexture,
  FloatType,
  LinearFilter,
  NearestFilter,
  RGBAFormat,
  RGFormat,
  WebGLRenderTarget,
  type ShaderMaterial,
  type Texture,
  type WebGLRenderer,
} from 'three';
import { FullscreenPass, fullscreenMaterial, runPasses } from '../fft/fullscreenPass';
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
  private readonly targets: [WebGLRenderTarget, WebGLRenderTarget];
  private readonly twiddles: DataTexture;
  private readonly prepare: ShaderMaterial;
  private readonly evolve: ShaderMaterial;
  private readonly fftAlongX: ShaderMaterial;
  private readonly fftAlongZ: ShaderMaterial;
  private readonly unpacker: ShaderMaterial;
  private readonly pass = new FullscreenPass();
  /** Fragment passes per step. */
  readonly passCount: number;

  constructor(
    private readonly renderer: WebGLRenderer,
    readonly grid: LocalWaveGrid,
  ) {
    const n = grid.resolution;
    const stateTarget = () =>
      new WebGLRenderTarget(n, n, { type: FloatType, format: RGBAFormat, depthBuffer: false, minFilter: NearestFilter, magFilter: NearestFilter, generateMipmaps: false });
    this.targets = [stateTarget(), stateTarget()];
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
    const table = new Float32Array(2 * n);
    for (let m = 0; m < n; m++) [table[2 * m], table[2 * m + 1]] = [Math.cos((2 * Math.PI * m) / n), Math.sin((2 * Math.PI * m) / n)];
    this.twiddles = new DataTexture(table, n, 1, RGFormat, FloatType);
    this.twiddles.needsUpdate = true;

    this.prepare = fullscreenMaterial(
      shaderSource('localWaves/prepare.frag'),
      {
        tState: { value: null },
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
    const fft = (alongZ: boolean) =>
      fullscreenMaterial(
        shaderSource('localWaves/fftPass.frag'),
        { tInput: { value: null }, tTwiddles: { value: this.twiddles }, subtransformLog2: { value: 0 }, direction: { value: 1 } },
        { ALONG_Z: Number(alongZ) },
      );
    this.fftAlongX = fft(false);
    this.fftAlongZ = fft(true);
    this.evolve = fullscreenMaterial(shaderSource('localWaves/evolve.frag'), {
      tSpectrum: { value: null },
      dt: { value: 0 },
      gridSize: { value: n * grid.cellSize },
      depth: { value: Math.min(grid.depth, DEEP) },
      gravity: { value: GRAVITY },
    });
    this.unpacker = fullscreenMaterial(shaderSource('localWaves/unpack.frag'), { tState: { value: null } });
    this.passCount = 3 + 4 * Math.log2(n);
  }

  get displacement(): Texture {
    return this.output.textures[0];
  }

  get derivatives(): Texture {
    return this.output.textures[1];
  }

  /** The state after the last step, (η_s, ψ, ∂η_s/∂x, ∂η_s/∂z), for read-back. */
  get state(): WebGLRenderTarget {
    return this.targets[0];
  }

  /** Clears the sea on the grid. */
  clear(): void {
    runPasses(this.renderer, () => {
      for (const target of [...this.targets, this.output]) {
        this.renderer.setRenderTarget(target);
        this.renderer.setClearColor(0x000000, 0);
        this.renderer.clear(true, false, false);
      }
    });
  }

  /** One step; the state ends in targets[0], as it began. */
  step({ shiftX, shiftZ, impulses, dt }: LocalWaveStep): void {
    if (impulses.length > MAX_IMPULSES_PER_STEP) throw new RangeError(`GpuLocalWaves.step: at most ${MAX_IMPULSES_PER_STEP} impulses per step`);
    const u = this.prepare.uniforms;
    u.tState.value = this.targets[0].texture;
    u.shift.value = [shiftX, shiftZ];
    u.dt.value = dt;
    u.impulseCount.value = impulses.length;
    impulses.forEach((impulse, s) => {
      u.impulsePose.value.set([impulse.x, impulse.z, impulse.cos, impulse.sin], 4 * s);
      u.impulseShape.value.set([impulse.halfLength, impulse.halfBeam, impulse.height, 0], 4 * s);
    });
    this.evolve.uniforms.dt.value = dt;
    const [a, b] = this.targets;
    runPasses(this.renderer, () => {
      this.draw(this.prepare, b);
      // Forward: 2·log2 N passes from b end in b; evolve b → a; inverse: a … a.
      this.transform(b, a, -1);
      this.evolve.uniforms.tSpectrum.value = b.texture;
      this.draw(this.evolve, a);
      this.transform(a, b, 1);
    });
  }

  /** Writes the state into the layer's field textures. */
  unpack(): void {
    this.unpacker.uniforms.tState.value = this.targets[0].texture;
    runPasses(this.renderer, () => this.draw(this.unpacker, this.output));
  }

  dispose(): void {
    for (const target of [...this.targets, this.output]) target.dispose();
    this.twiddles.dispose();
    for (const material of [this.prepare, this.evolve, this.fftAlongX, this.fftAlongZ, this.unpacker]) material.dispose();
    this.pass.dispose();
  }

  /** A 2D FFT of `data` in place, using `spare` to ping-pong (an even number of passes). */
  private transform(data: WebGLRenderTarget, spare: WebGLRenderTarget, direction: 1 | -1): void {
    const passes = Math.log2(this.grid.resolution);
    let [source, target] = [data, spare];
    for (const material of [this.fftAlongX, this.fftAlongZ]) {
      material.uniforms.direction.value = direction;
      for (let s = 0; s < passes; s++) {
        material.uniforms.tInput.value = source.texture;
        material.uniforms.subtransformLog2.value = s;
        this.draw(material, target);
        [source, target] = [target, source];
      }
    }
  }

  private draw(material: ShaderMaterial, target: WebGLRenderTarget): void {
    this.renderer.setRenderTarget(target);
    this.pass.draw(this.renderer, material);
  }
}
