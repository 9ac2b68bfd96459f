/**
 * The GpuDevice (../gpuDevice.ts) on three.js's WebGLRenderer (WebGL 2): field targets are
 * WebGLRenderTargets, passes are one triangle drawn with a ShaderMaterial (fullscreenPass.ts), the
 * FFT's layered targets attach array-texture layers to a framebuffer of their own
 * (layeredTarget.ts). Each user of the GPU makes its own device and disposes it with itself.
 */
import {
  ClampToEdgeWrapping,
  DataUtils,
  FloatType,
  HalfFloatType,
  LinearFilter,
  LinearMipmapLinearFilter,
  NearestFilter,
  RedFormat,
  RepeatWrapping,
  RGBAFormat,
  type Texture,
  WebGLRenderTarget,
  type WebGLRenderer,
} from 'three';
import { LAYERED_ATTACHMENTS, type FieldTarget, type GpuCapability, type FieldTargetOptions, type GpuDevice, type GpuPrecision, type LayeredTarget, type PassMaterial, type TexelRows } from '../gpuDevice';
import { FullscreenPass, fullscreenMaterial, runPasses } from './fullscreenPass';
import { WebGL2LayeredTarget } from './layeredTarget';
import { missingThreeInternals } from './threeInternals';
import { UnsupportedError } from '../../parameters/options';

/**
 * What is asked of a context once: getParameter may wait for the GPU to finish its queue, and the
 * answers do not change. `software`: whether it renders in software (SwiftShader, llvmpipe, …),
 * where each fragment pass costs ~0.6 ms of fixed overhead, and a step of the local waves at
 * N = 128 took 30 ms in 31 passes where the JS solver takes 4 ms (measured under SwiftShader on
 * 2 cores); on a GPU the passes take well under 1 ms.
 */
interface ContextFacts {
  software: boolean;
  drawBuffers: number;
}

const contextFacts = new WeakMap<WebGL2RenderingContext, ContextFacts>();

function factsOf(gl: WebGL2RenderingContext): ContextFacts {
  let facts = contextFacts.get(gl);
  if (facts === undefined) {
    const info = gl.getExtension('WEBGL_debug_renderer_info');
    const name = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
    facts = { software: /swiftshader|llvmpipe|softpipe|software/i.test(name), drawBuffers: gl.getParameter(gl.MAX_DRAW_BUFFERS) as number };
    contextFacts.set(gl, facts);
  }
  return facts;
}

/** The extension or limit of WebGL 2 behind each capability flag (GpuDevice.capabilityName). */
const CAPABILITY_NAMES: Record<GpuCapability, string> = {
  float32Targets: 'EXT_color_buffer_float',
  float16Targets: 'EXT_color_buffer_half_float',
  float32Filterable: 'OES_texture_float_linear',
  drawBuffers: 'MAX_DRAW_BUFFERS',
};

/** A FieldTarget on WebGL 2: a WebGLRenderTarget, which tests and the bench read back directly. */
export class WebGL2FieldTarget implements FieldTarget {
  readonly renderTarget: WebGLRenderTarget;
  readonly textures: readonly Texture[];

  constructor(
    readonly size: number,
    readonly precision: GpuPrecision,
    readonly channels: 'rgba' | 'red',
    options: ConstructorParameters<typeof WebGLRenderTarget>[2],
  ) {
    this.renderTarget = new WebGLRenderTarget(size, size, options);
    this.textures = this.renderTarget.textures;
  }

  dispose(): void {
    this.renderTarget.dispose();
  }
}

export class WebGL2Device implements GpuDevice {
  private readonly pass = new FullscreenPass();

  constructor(readonly renderer: WebGLRenderer) {}

  get unavailableReason(): string | null {
    if (!this.renderer.capabilities.isWebGL2 || !(this.renderer.getContext() instanceof WebGL2RenderingContext)) return 'no WebGL 2';
    return missingThreeInternals(this.renderer);
  }

  get float32Targets(): boolean {
    return this.renderer.extensions.has(CAPABILITY_NAMES.float32Targets);
  }

  get float16Targets(): boolean {
    return this.renderer.extensions.has(CAPABILITY_NAMES.float16Targets) || this.float32Targets;
  }

  get float32Filterable(): boolean {
    return this.renderer.extensions.has(CAPABILITY_NAMES.float32Filterable);
  }

  get drawBuffers(): number {
    return factsOf(this.gl).drawBuffers;
  }

  get software(): boolean {
    return factsOf(this.gl).software;
  }

  capabilityName(capability: GpuCapability): string {
    return CAPABILITY_NAMES[capability];
  }

  createFieldTarget({ size, precision, count = 1, channels = 'rgba', sampling = 'texels' }: FieldTargetOptions): WebGL2FieldTarget {
    // float32 filters only with OES_texture_float_linear; half floats always do.
    const filterable = sampling !== 'texels' && (precision === 'float16' || this.float32Filterable);
    const wrap = sampling === 'periodic' ? RepeatWrapping : ClampToEdgeWrapping;
    const mipmapped = filterable && sampling === 'periodic';
    return new WebGL2FieldTarget(size, precision, channels, {
      count,
      type: precision === 'float32' ? FloatType : HalfFloatType,
      format: channels === 'red' ? RedFormat : RGBAFormat,
      depthBuffer: false,
      wrapS: wrap,
      wrapT: wrap,
      magFilter: filterable ? LinearFilter : NearestFilter,
      minFilter: mipmapped ? LinearMipmapLinearFilter : filterable ? LinearFilter : NearestFilter,
      generateMipmaps: mipmapped,
    });
  }

  createLayeredTarget(size: number, precision: GpuPrecision): LayeredTarget {
    const unavailable = this.unavailableReason;
    if (unavailable !== null) throw new UnsupportedError('three.js', `three-fft-ocean: ${unavailable}`);
    const target = new WebGL2LayeredTarget(this.renderer, size, precision === 'float32' ? FloatType : HalfFloatType);
    // Checked now rather than at the first pass, so that a device that cannot render to the
    // layered framebuffer makes the caller throw (and the 'auto' path fall back to JS with the reason).
    try {
      target.prepare();
    } catch (error) {
      target.dispose();
      throw error;
    }
    return target;
  }

  passMaterial(fragmentShader: string, uniforms: Record<string, { value: unknown }>, defines: Record<string, unknown> = {}): PassMaterial {
    return fullscreenMaterial(fragmentShader, uniforms, defines);
  }

  runPasses(passes: () => void): void {
    runPasses(this.renderer, passes);
  }

  draw(material: PassMaterial, target: FieldTarget | LayeredTarget, rows: TexelRows | null = null): void {
    this.bind(target, rows);
    this.pass.draw(this.renderer, material);
  }

  clear(target: FieldTarget | LayeredTarget, rows: TexelRows | null = null): void {
    const drawBuffers = this.bind(target, rows);
    const gl = this.gl;
    this.renderer.state.buffers.color.setMask(true); // a material's colorWrite: false would mask the clear
    for (let drawBuffer = 0; drawBuffer < drawBuffers; drawBuffer++) gl.clearBufferfv(gl.COLOR, drawBuffer, ZERO_TEXEL);
  }

  readBack(target: FieldTarget, into: Float32Array): void {
    const { renderTarget, size, precision } = fieldTarget(target);
    if (precision === 'float32') {
      this.renderer.readRenderTargetPixels(renderTarget, 0, 0, size, size, into);
      return;
    }
    const halves = new Uint16Array(into.length);
    this.renderer.readRenderTargetPixels(renderTarget, 0, 0, size, size, halves);
    halves.forEach((half, i) => (into[i] = DataUtils.fromHalfFloat(half)));
  }

  async readBackLater(target: FieldTarget, into: Float32Array): Promise<void> {
    const { renderTarget, size, precision } = fieldTarget(target);
    if (precision !== 'float32') return this.readBack(target, into);
    await this.renderer.readRenderTargetPixelsAsync(renderTarget, 0, 0, size, size, into);
  }

  dispose(): void {
    this.pass.dispose();
  }

  private get gl(): WebGL2RenderingContext {
    return this.renderer.getContext() as WebGL2RenderingContext;
  }

  /** Makes `target` (`rows` of it) the render target; returns its number of colour attachments. */
  private bind(target: FieldTarget | LayeredTarget, rows: TexelRows | null): number {
    if (target instanceof WebGL2LayeredTarget) {
      target.bind(rows);
      return LAYERED_ATTACHMENTS;
    }
    const { renderTarget } = fieldTarget(target);
    // three.js applies a render target's scissor when it is set.
    renderTarget.scissorTest = rows !== null;
    if (rows !== null) renderTarget.scissor.set(0, rows.first, renderTarget.width, rows.count);
    this.renderer.setRenderTarget(renderTarget);
    return renderTarget.textures.length;
  }
}

const ZERO_TEXEL = new Float32Array(4);

function fieldTarget(target: FieldTarget | LayeredTarget): WebGL2FieldTarget {
  if (!(target instanceof WebGL2FieldTarget)) throw new TypeError('WebGL2Device: a target made by another device');
  return target;
}
