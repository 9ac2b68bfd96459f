/**
 * The GPU simulation path: every field of waveFieldLayout.ts computed in fragment-shader passes
 * over float render targets (WebGL2 through three.js), with no CPU readback.
 *
 * Per update: one pass evolves the spectrum (four packed complex spectra), then log4-many Stockham
 * FFT passes along x and as many along z (a radix-2 pass first on each axis when log2 N is odd;
 * along x the evolution pass does it) ping-pong between two sets of working textures, and
 * a last pass copies the fields into the output target, whose two textures (`displacement`,
 * `derivatives`) wrap with REPEAT and, where the format is filterable, filter linearly with
 * mipmaps generated after the pass.
 *
 * A coarse cascade keeps only its band's modes, a few per cent of the grid: the evolution pass and
 * the passes along x skip the lines (texel rows) that hold only zeros (bandTexelRows).
 *
 * Each FFT pass computes a whole radix-4 butterfly per fragment and writes its four outputs to
 * four layers of (N/2)×(N/2) array textures (shaders/fft/quarterLayout.glsl says where each element
 * lives after each pass). That reads every input once per pass instead of four times, and under
 * SwiftShader makes a pass about three times cheaper than one output per fragment. three.js cannot
 * render to several layers at once, so this file attaches the layers to a framebuffer of its own
 * and hands it to three.js (threeInternals.ts, the one adapter for what three.js does not make
 * public); three.js still allocates, binds and frees the textures.
 *
 * Textures (RGBA unless said):
 *   amplitudes  N×N (h̃0(k), h̃0*(−k))            static, from initialSpectrum.ts
 *   waveVectors N×N (kx, kz, 1/k, m)             static, from initialSpectrum.ts
 *   phases      256×1, (e^{ijφ}, e^{i256jφ})     uploaded each update, from dispersion.ts
 *   twiddles    N×1, (cos 2πj/N, sin 2πj/N)      static
 *   working     2 × (N/2)×(N/2)×4 layers, twice  working storage (two complex fields per texel)
 *   output      N×N (displacement, derivatives)  the result
 * This object owns all of them and frees them in dispose().
 */
import {
  DataTexture,
  FloatType,
  HalfFloatType,
  NearestFilter,
  RGBAFormat,
  RGFormat,
  type ShaderMaterial,
  WebGLRenderTarget,
  type PixelFormat,
  type Texture,
  type TextureDataType,
  WebGLArrayRenderTarget,
  type WebGLRenderer,
} from 'three';
import { shaderSource } from '../shaderSource';
import { UnsupportedError } from '../parameters/options';
import { fillPhaseTable, PHASE_TABLE_SIZE } from '../spectrum/dispersion';
import { largestFrequency, type InitialSpectrum } from '../spectrum/initialSpectrum';
import { FullscreenPass, fullscreenMaterial, periodicFieldTarget, runPasses } from './fullscreenPass';
import { checkThreeInternals, glTextureOf, missingThreeInternals, useExternalFramebuffer } from './threeInternals';
import { FIELD_TEXTURES } from './waveFieldLayout';

export type GpuPrecision = 'float32' | 'float16';

/** How the previous pass left the data: INPUT_LAYOUT of shaders/fft/quarterLayout.glsl. */
type InputLayout = 'QUARTERS' | 'QUARTERS_TRANSPOSED' | 'AFTER_RADIX2' | 'AFTER_RADIX4';

interface FftPass {
  material: ShaderMaterial;
  /** Reads `source`, writes `target`. */
  source: LayeredSpectra;
  target: LayeredSpectra;
  /** log2 of the sub-transform length p before the pass. */
  subtransformLog2: number;
  /** The texel rows it draws (BandRows.drawn), or EVERY_ROW. */
  rows: RowRanges;
}

/** Scissor boxes a pass draws in turn, null standing for the whole target. */
type RowRanges = readonly (TexelRows | null)[];
const EVERY_ROW: RowRanges = [null];

/** The rows of a coarse cascade's band lines, and the rows between them, which hold zeros. */
interface BandRows {
  drawn: RowRanges;
  cleared: TexelRows;
}

/** Rows first … first + count − 1 of texels. */
interface TexelRows {
  first: number;
  count: number;
}

/** Which GPU precision this renderer can render to, best first; null when neither works. */
export function supportedGpuPrecision(renderer: WebGLRenderer): GpuPrecision | null {
  return gpuSupport(renderer).precision;
}

/** MAX_DRAW_BUFFERS per context (gpuSupport). */
const maxDrawBuffers = new WeakMap<WebGL2RenderingContext, number>();

/** Colour attachments each FFT pass writes at once (LayeredSpectra: two array textures of four layers). */
export const FFT_DRAW_BUFFERS = 8;

/**
 * What the GPU path can use on this renderer, and why not the best: the precision (null: none)
 * and, when it is not RGBA32F, the reason in words.
 */
export function gpuSupport(renderer: WebGLRenderer): { precision: GpuPrecision | null; reason: string } {
  const gl = renderer.getContext();
  if (!renderer.capabilities.isWebGL2 || !(gl instanceof WebGL2RenderingContext)) return { precision: null, reason: 'no WebGL 2' };
  // Asked once per context: getParameter waits for the GPU to finish its queue, and the limit stays.
  const drawBuffers = maxDrawBuffers.get(gl) ?? (gl.getParameter(gl.MAX_DRAW_BUFFERS) as number);
  maxDrawBuffers.set(gl, drawBuffers);
  if (drawBuffers < FFT_DRAW_BUFFERS) return { precision: null, reason: `MAX_DRAW_BUFFERS is ${drawBuffers} (the GPU FFT writes ${FFT_DRAW_BUFFERS} at once)` };
  const missingInternals = missingThreeInternals(renderer);
  if (missingInternals !== null) return { precision: null, reason: missingInternals };
  if (renderer.extensions.has('EXT_color_buffer_float')) return { precision: 'float32', reason: '' };
  if (renderer.extensions.has('EXT_color_buffer_half_float')) return { precision: 'float16', reason: 'no EXT_color_buffer_float: half floats' };
  return { precision: null, reason: 'no float render targets (EXT_color_buffer_float, EXT_color_buffer_half_float)' };
}

export class GpuWaveFields {
  /** (Dx, h, Dz, ∂Dx/∂z) */
  readonly displacement: Texture;
  /** (∂h/∂x, ∂h/∂z, ∂Dx/∂x, ∂Dz/∂z) */
  readonly derivatives: Texture;
  /** Fragment passes per update (evolution, FFT, copy to the output). */
  readonly passCount: number;
  readonly output: WebGLRenderTarget;

  private readonly amplitudes: DataTexture;
  private readonly waveVectors: DataTexture;
  private readonly phases: DataTexture;
  private readonly twiddles: DataTexture;
  /** Working storage: two sets to ping-pong between (quarterLayout.glsl). */
  private readonly working: [LayeredSpectra, LayeredSpectra];
  private readonly evolveMaterial: ShaderMaterial;
  /** One program per radix and input layout the passes need. */
  private readonly fftMaterials = new Map<string, ShaderMaterial>();
  /** Along x, then along z. */
  private readonly fftPasses: FftPass[] = [];
  private readonly unpackMaterial: ShaderMaterial;
  private readonly pass = new FullscreenPass();
  private readonly repeatPeriod: number;
  /** The texel rows of the lines the spectrum has modes on (bandTexelRows), null for all. */
  private readonly bandRows: BandRows | null;

  constructor(
    private readonly renderer: WebGLRenderer,
    spectrum: InitialSpectrum,
    readonly precision: GpuPrecision,
  ) {
    checkThreeInternals(renderer);
    this.repeatPeriod = spectrum.repeatPeriod;
    const n = spectrum.resolution;
    const sizeLog2 = Math.log2(n);
    const type: TextureDataType = precision === 'float32' ? FloatType : HalfFloatType;
    this.amplitudes = dataTexture(spectrum.amplitudes, n, n, RGBAFormat);
    this.waveVectors = dataTexture(spectrum.waveVectors, n, n, RGBAFormat);
    this.phases = dataTexture(new Float32Array(4 * PHASE_TABLE_SIZE), PHASE_TABLE_SIZE, 1, RGBAFormat);
    const twiddleTable = new Float32Array(2 * n);
    for (let j = 0; j < n; j++) {
      twiddleTable[2 * j] = Math.cos((2 * Math.PI * j) / n);
      twiddleTable[2 * j + 1] = Math.sin((2 * Math.PI * j) / n);
    }
    this.twiddles = dataTexture(twiddleTable, n, 1, RGFormat);

    this.working = [new LayeredSpectra(n / 2, type), new LayeredSpectra(n / 2, type)];
    this.output = periodicFieldTarget(renderer, n, type, 2);
    [this.displacement, this.derivatives] = this.output.textures;
    this.output.textures.forEach((texture, i) => (texture.name = FIELD_TEXTURES[i]));

    const material = (fragmentShader: string, uniforms: Record<string, { value: unknown }>, defines = {}) =>
      fullscreenMaterial(shaderSource(fragmentShader), { sizeLog2: { value: sizeLog2 }, ...uniforms }, defines);
    const firstRadix2 = sizeLog2 % 2 === 1;
    this.evolveMaterial = material(
      'fft/evolveSpectrum.frag',
      {
        tAmplitudes: { value: this.amplitudes },
        tWaveVectors: { value: this.waveVectors },
        tPhases: { value: this.phases },
      },
      { FIRST_RADIX2: Number(firstRadix2) },
    );
    const fftMaterial = (radix: 2 | 4, alongZ: boolean, layout: InputLayout): ShaderMaterial => {
      const key = `${radix} ${alongZ} ${layout}`;
      let fft = this.fftMaterials.get(key);
      if (!fft) {
        const uniforms = { tSpectra0: { value: null }, tSpectra1: { value: null }, tTwiddles: { value: this.twiddles } };
        const defines = { RADIX: radix, RADIX_LOG2: Math.log2(radix), ALONG_Z: Number(alongZ), INPUT_LAYOUT: layout };
        fft = material('fft/fftPass.frag', { ...uniforms, subtransformLog2: { value: 0 } }, defines);
        this.fftMaterials.set(key, fft);
      }
      return fft;
    };
    // Radix 4 from sub-length p = 1 (or 2 after a radix-2 pass when log2 N is odd) up to N. The
    // first pass of the x axis reads what the evolution pass wrote; the first of the z axis what
    // the last x pass wrote (the same quarters, with x as the line). The passes ping-pong
    // between the two sets of working textures.
    //
    // A coarse cascade has modes only on the lines (z frequencies) of its band: the evolution and
    // x passes draw only those lines' texel rows (bandTexelRows); the other lines stay zero. They
    // are read as zeros by the first z pass from the last x pass's target: when it is working[0]
    // (an even number of x passes), the rows cleared after the evolution pass; else that pass
    // draws every row.
    const bandRows = (this.bandRows = bandTexelRows(n, largestFrequency(spectrum)));
    let [source, target] = this.working;
    for (const alongZ of [false, true]) {
      let layout: InputLayout = alongZ ? 'QUARTERS_TRANSPOSED' : 'QUARTERS';
      const pass = (radix: 2 | 4, p: number): void => {
        const rows = alongZ || bandRows === null ? EVERY_ROW : bandRows.drawn;
        this.fftPasses.push({ material: fftMaterial(radix, alongZ, layout), source, target, subtransformLog2: Math.log2(p), rows });
        [source, target] = [target, source];
      };
      let p = 1;
      if (firstRadix2) {
        if (alongZ) pass(2, p); // along x, the evolution pass did it
        [layout, p] = ['AFTER_RADIX2', 2];
      }
      for (; p < n; p *= 4, layout = 'AFTER_RADIX4') pass(4, p);
      const lastPass = this.fftPasses[this.fftPasses.length - 1];
      if (!alongZ && lastPass.target !== this.working[0]) lastPass.rows = EVERY_ROW;
    }
    const [result0, result1] = source.textures;
    this.unpackMaterial = material('fft/unpackFields.frag', { tSpectra0: { value: result0 }, tSpectra1: { value: result1 } });
    this.passCount = 2 + this.fftPasses.length;
    // Checked now rather than at the first update, so that a device that cannot render to the
    // layered framebuffer makes this throw and the 'auto' path falls back to JS with the reason.
    try {
      for (const spectra of this.working) spectra.prepare(renderer);
    } catch (error) {
      this.dispose();
      throw error;
    }
  }

  /** Computes every field at time t (seconds) into `displacement` and `derivatives`. */
  update(t: number): void {
    fillPhaseTable(this.phases.image.data as Float32Array, t, this.repeatPeriod);
    this.phases.needsUpdate = true;
    const renderer = this.renderer;
    runPasses(renderer, () => {
      this.drawRows(this.working[0], this.bandRows?.drawn ?? EVERY_ROW, this.evolveMaterial);
      if (this.bandRows !== null) this.working[0].clear(renderer, this.bandRows.cleared);
      for (const { material, source, target, subtransformLog2, rows } of this.fftPasses) {
        const uniforms = material.uniforms;
        uniforms.tSpectra0.value = source.textures[0];
        uniforms.tSpectra1.value = source.textures[1];
        uniforms.subtransformLog2.value = subtransformLog2;
        this.drawRows(target, rows, material);
      }
      renderer.setRenderTarget(this.output);
      this.pass.draw(renderer, this.unpackMaterial);
    });
  }

  /** Draws `material` into `target`, once per range of rows. */
  private drawRows(target: LayeredSpectra, rows: RowRanges, material: ShaderMaterial): void {
    for (const range of rows) {
      target.bind(this.renderer, range);
      this.pass.draw(this.renderer, material);
    }
  }

  dispose(): void {
    for (const texture of [this.amplitudes, this.waveVectors, this.phases, this.twiddles]) texture.dispose();
    for (const spectra of this.working) spectra.dispose(this.renderer);
    this.output.dispose();
    for (const material of [this.evolveMaterial, ...this.fftMaterials.values(), this.unpackMaterial]) material.dispose();
    this.pass.dispose();
  }
}

/**
 * One set of FFT working storage: two array textures of four layers (the two working textures of
 * fftPass.frag) and a framebuffer with all eight layers as colour attachments, so one pass writes
 * a butterfly's four outputs to each texture.
 */
class LayeredSpectra {
  readonly textures: [Texture, Texture];
  private readonly arrays: [WebGLArrayRenderTarget, WebGLArrayRenderTarget];
  /** Stands for the framebuffer in three.js's setRenderTarget; three.js allocates nothing for it. */
  private readonly target: WebGLRenderTarget;
  private framebuffer: WebGLFramebuffer | null = null;
  /** The GL textures attached to `framebuffer`. */
  private attached: WebGLTexture[] = [];

  constructor(size: number, type: TextureDataType) {
    const array = () =>
      new WebGLArrayRenderTarget(size, size, 4, {
        type,
        format: RGBAFormat,
        depthBuffer: false,
        minFilter: NearestFilter,
        magFilter: NearestFilter,
        generateMipmaps: false,
      });
    this.arrays = [array(), array()];
    this.textures = [this.arrays[0].texture, this.arrays[1].texture];
    this.target = new WebGLRenderTarget(size, size, { depthBuffer: false, generateMipmaps: false });
  }

  /**
   * Builds the framebuffer of the eight layers (again after a restored context), checking it is
   * complete: throws an UnsupportedError if the device cannot render to it. Done when the GPU path
   * is created, so that 'auto' can fall back then, and before every use.
   */
  prepare(renderer: WebGLRenderer): void {
    if (!this.framebufferIsCurrent(renderer)) this.createFramebuffer(renderer);
  }

  /**
   * Makes the eight layers the render target of the next draw, which then covers only `rows` if
   * given (a scissor box). Allocates nothing once set up.
   */
  bind(renderer: WebGLRenderer, rows: TexelRows | null = null): void {
    this.prepare(renderer);
    // three.js applies a render target's scissor when it is set.
    this.target.scissorTest = rows !== null;
    if (rows !== null) this.target.scissor.set(0, rows.first, this.target.width, rows.count);
    // Every time: after a restored context three.js has a new property map that no longer knows it.
    useExternalFramebuffer(renderer, this.target, this.framebuffer!);
    renderer.setRenderTarget(this.target);
  }

  /** Sets `rows` of all eight layers to zero. */
  clear(renderer: WebGLRenderer, rows: TexelRows): void {
    this.bind(renderer, rows);
    const gl = renderer.getContext() as WebGL2RenderingContext;
    renderer.state.buffers.color.setMask(true); // a material's colorWrite: false would mask the clear
    for (let drawBuffer = 0; drawBuffer < FFT_DRAW_BUFFERS; drawBuffer++) gl.clearBufferfv(gl.COLOR, drawBuffer, ZERO_TEXEL);
  }

  /** Whether `framebuffer` holds the arrays' GL textures, which change when the context is lost and restored. */
  private framebufferIsCurrent(renderer: WebGLRenderer): boolean {
    if (this.framebuffer === null) return false;
    for (let i = 0; i < this.arrays.length; i++) {
      if (glTextureOf(renderer, this.arrays[i]) !== this.attached[i]) return false;
    }
    return true;
  }

  private createFramebuffer(renderer: WebGLRenderer): void {
    const gl = renderer.getContext() as WebGL2RenderingContext;
    const textures = this.arrays.map((array) => glTextureOf(renderer, array));
    this.deleteFramebuffer(renderer);
    const framebuffer = gl.createFramebuffer();
    renderer.state.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
    const attachments: GLenum[] = [];
    textures.forEach((texture, a) => {
      for (let layer = 0; layer < 4; layer++) {
        const attachment = gl.COLOR_ATTACHMENT0 + 4 * a + layer;
        gl.framebufferTextureLayer(gl.FRAMEBUFFER, attachment, texture, 0, layer);
        attachments.push(attachment);
      }
    });
    gl.drawBuffers(attachments); // framebuffer state: set once
    // Checked once per context and layout: the check waits for the GPU to finish its queue (a
    // frame's work under SwiftShader), and the answer cannot change for the same formats and size.
    const layout = `${this.arrays[0].texture.type}/${this.arrays[0].width}`;
    const checked = completeLayouts.get(gl) ?? new Set<string>();
    const status = checked.has(layout) ? gl.FRAMEBUFFER_COMPLETE : gl.checkFramebufferStatus(gl.FRAMEBUFFER);
    renderer.state.bindFramebuffer(gl.FRAMEBUFFER, null);
    if (status !== gl.FRAMEBUFFER_COMPLETE) {
      gl.deleteFramebuffer(framebuffer);
      throw new UnsupportedError('GPU FFT framebuffer', `GPU FFT: the layered framebuffer is incomplete (status 0x${status.toString(16)})`);
    }
    completeLayouts.set(gl, checked.add(layout));
    this.framebuffer = framebuffer;
    this.attached = textures;
  }

  private deleteFramebuffer(renderer: WebGLRenderer): void {
    // After a lost and restored context the old framebuffer is already gone: its textures are no
    // longer the arrays' (asked of three.js, not of GL: gl.isFramebuffer would wait for the GPU).
    if (this.framebufferIsCurrent(renderer)) renderer.getContext().deleteFramebuffer(this.framebuffer);
    this.framebuffer = null;
  }

  dispose(renderer: WebGLRenderer): void {
    this.deleteFramebuffer(renderer);
    for (const array of this.arrays) array.dispose();
  }
}

/**
 * The texel rows of the working textures that hold the lines (z frequencies j) within ±band, as
 * the x passes store them (line l at row l div 2, quarterLayout.glsl): lines 0 … band and
 * N − band … N − 1, and the rows between. Null when they cover every row.
 */
function bandTexelRows(n: number, band: number): BandRows | null {
  const lowCount = Math.floor(band / 2) + 1;
  const highFirst = Math.floor((n - band) / 2);
  if (lowCount >= highFirst) return null;
  const drawn = [{ first: 0, count: lowCount }];
  if (highFirst < n / 2) drawn.push({ first: highFirst, count: n / 2 - highFirst }); // none when the band is 0
  return { drawn, cleared: { first: lowCount, count: highFirst - lowCount } };
}

const ZERO_TEXEL = new Float32Array(4);

/** The layouts (texel type / size) of the layered framebuffer found complete, per GL context. */
const completeLayouts = new WeakMap<WebGLRenderingContext | WebGL2RenderingContext, Set<string>>();

function dataTexture(data: Float32Array, width: number, height: number, format: PixelFormat): DataTexture {
  const texture = new DataTexture(data, width, height, format, FloatType);
  texture.minFilter = NearestFilter;
  texture.magFilter = NearestFilter;
  texture.needsUpdate = true;
  return texture;
}
