/**
 * The GPU FFT engine: unnormalized inverse 2D transforms, X(k) → Σ_k X(k)·e^{+2πi k·x/N} (no 1/N²),
 * in fragment passes, of four complex fields at once (two per texel of two working textures). The
 * cascades (gpuWaveFields.ts) and the local waves (src/layers/gpuLocalWaves.ts) both run their
 * transforms here; the local waves' forward transform is the inverse of the conjugate, conjugated
 * (FFT(z) = conj(IFFT(conj z))), so one engine and one butterfly (shaders/fft/fftPass.frag) serve both.
 *
 * A user draws its input with `load`, in the QUARTERS layout of shaders/fft/quarterLayout.glsl (or
 * AFTER_RADIX2 if its load pass also did the first radix-2 pass along x, as the cascades' evolution
 * pass does), and reads the result of `transform` with fieldAddress (quarterLayout.glsl). Radix-4
 * Stockham passes run along x, then along z (a radix-2 pass first on each axis when log2 N is odd),
 * ping-ponging between two sets of working storage (LayeredSpectra: each pass writes a butterfly's
 * four outputs to four layers of (N/2)×(N/2) array textures). A spectrum whose modes lie on a band
 * of lines near k_z = 0 (a coarse cascade) is loaded and transformed along x on those lines only.
 * Writing a butterfly's four outputs reads every input once per pass instead of four times, and
 * under SwiftShader makes a pass about three times cheaper than one output per fragment. three.js
 * cannot render to several layers at once, so LayeredSpectra attaches the layers to a framebuffer
 * of its own and hands it to three.js (threeInternals.ts, the one adapter for what three.js does
 * not make public); three.js still allocates, binds and frees the textures.
 *
 * Textures: twiddles N×1 (cos 2πj/N, sin 2πj/N), static, computed in double precision because GLSL
 * sin/cos are approximate; two sets of working storage. This object owns them, its materials and
 * its framebuffers, and frees them in dispose().
 */
import {
  DataTexture,
  FloatType,
  NearestFilter,
  RGBAFormat,
  RGFormat,
  type ShaderMaterial,
  type Texture,
  type TextureDataType,
  WebGLArrayRenderTarget,
  WebGLRenderTarget,
  type WebGLRenderer,
} from 'three';
import { UnsupportedError } from '../parameters/options';
import { shaderSource } from '../shaderSource';
import { FullscreenPass, fullscreenMaterial } from './fullscreenPass';
import { glTextureOf, useExternalFramebuffer } from './threeInternals';

/** Colour attachments each FFT pass writes at once (LayeredSpectra: two array textures of four layers). */
export const FFT_DRAW_BUFFERS = 8;

/** How the previous pass left the data: INPUT_LAYOUT of shaders/fft/quarterLayout.glsl. */
type InputLayout = 'QUARTERS' | 'QUARTERS_TRANSPOSED' | 'AFTER_RADIX2' | 'AFTER_RADIX4';

/** One of the two sets of working storage. */
export type WorkingSet = 0 | 1;

interface FftPass {
  material: ShaderMaterial;
  /** log2 of the sub-transform length p before the pass. */
  subtransformLog2: number;
  alongZ: boolean;
  /** The last pass along x. */
  lastAlongX: boolean;
}

/** Scissor boxes a pass draws in turn, null standing for the whole target. */
type RowRanges = readonly (TexelRows | null)[];
const EVERY_ROW: RowRanges = [null];

/** The rows of a band's lines, and the rows between them, which hold zeros. */
interface BandRows {
  drawn: RowRanges;
  cleared: TexelRows;
}

/** Rows first … first + count − 1 of texels. */
interface TexelRows {
  first: number;
  count: number;
}

export interface GpuFftOptions {
  /** N, a power of two from 16. */
  size: number;
  /** FloatType or HalfFloatType working storage. */
  type: TextureDataType;
  /** The load pass also does the first radix-2 pass along x when log2 N is odd (writes AFTER_RADIX2). */
  loadDoesFirstRadix2?: boolean;
  /** The largest |line| (z frequency index) that holds modes; null or omitted: any. */
  band?: number | null;
}

export class GpuFft {
  readonly sizeLog2: number;
  /** (cos 2πj/N, sin 2πj/N), j < N. */
  readonly twiddles: DataTexture;
  /** The two sets of working storage; `textures` of each are the tSpectra0, tSpectra1 of the shaders. */
  readonly sets: readonly [LayeredSpectra, LayeredSpectra];
  /** Along x, then along z. */
  private readonly passes: FftPass[] = [];
  /** One program per radix, axis and input layout the passes need. */
  private readonly materials = new Map<string, ShaderMaterial>();
  /** The texel rows of the band's lines (bandTexelRows), null for all. */
  private readonly bandRows: BandRows | null;
  private readonly pass = new FullscreenPass();

  constructor(
    private readonly renderer: WebGLRenderer,
    { size: n, type, loadDoesFirstRadix2 = false, band = null }: GpuFftOptions,
  ) {
    const sizeLog2 = (this.sizeLog2 = Math.log2(n));
    const table = new Float32Array(2 * n);
    for (let j = 0; j < n; j++) [table[2 * j], table[2 * j + 1]] = [Math.cos((2 * Math.PI * j) / n), Math.sin((2 * Math.PI * j) / n)];
    this.twiddles = new DataTexture(table, n, 1, RGFormat, FloatType);
    this.twiddles.minFilter = this.twiddles.magFilter = NearestFilter;
    this.twiddles.needsUpdate = true;
    this.sets = [new LayeredSpectra(n / 2, type), new LayeredSpectra(n / 2, type)];
    this.bandRows = band === null ? null : bandTexelRows(n, band);

    const material = (radix: 2 | 4, alongZ: boolean, layout: InputLayout): ShaderMaterial => {
      const key = `${radix} ${alongZ} ${layout}`;
      let fft = this.materials.get(key);
      if (!fft) {
        const uniforms = { tSpectra0: { value: null }, tSpectra1: { value: null }, tTwiddles: { value: this.twiddles } };
        const defines = { RADIX: radix, RADIX_LOG2: Math.log2(radix), ALONG_Z: Number(alongZ), INPUT_LAYOUT: layout };
        fft = fullscreenMaterial(shaderSource('fft/fftPass.frag'), { sizeLog2: { value: sizeLog2 }, ...uniforms, subtransformLog2: { value: 0 } }, defines);
        this.materials.set(key, fft);
      }
      return fft;
    };
    // Radix 4 from sub-length p = 1 (or 2 after a radix-2 pass when log2 N is odd) up to N. The
    // first pass of the x axis reads what the load pass wrote; the first of the z axis what the
    // last x pass wrote (the same quarters, with x as the line).
    const firstRadix2 = sizeLog2 % 2 === 1;
    for (const alongZ of [false, true]) {
      let layout: InputLayout = alongZ ? 'QUARTERS_TRANSPOSED' : 'QUARTERS';
      const pass = (radix: 2 | 4, p: number): void => {
        this.passes.push({ material: material(radix, alongZ, layout), subtransformLog2: Math.log2(p), alongZ, lastAlongX: false });
      };
      let p = 1;
      if (firstRadix2) {
        if (alongZ || !loadDoesFirstRadix2) pass(2, p);
        [layout, p] = ['AFTER_RADIX2', 2];
      }
      for (; p < n; p *= 4, layout = 'AFTER_RADIX4') pass(4, p);
      if (!alongZ) this.passes[this.passes.length - 1].lastAlongX = true;
    }
    // Checked now rather than at the first transform, so that a device that cannot render to the
    // layered framebuffer makes this throw and the 'auto' path falls back to JS with the reason.
    try {
      for (const spectra of this.sets) spectra.prepare(renderer);
    } catch (error) {
      this.dispose();
      throw error;
    }
  }

  /** Fragment passes per transform. */
  get passCount(): number {
    return this.passes.length;
  }

  /** The set `transform(from)` leaves its result in. */
  resultOf(from: WorkingSet): WorkingSet {
    return ((from + this.passes.length) % 2) as WorkingSet;
  }

  /**
   * Draws `material` (a fullscreenMaterial writing eight outputs, quarterLayout.glsl) into set
   * `into`: with a band, only its lines' texel rows, the rows between set to zero.
   */
  load(material: ShaderMaterial, into: WorkingSet): void {
    this.drawRows(this.sets[into], this.bandRows?.drawn ?? EVERY_ROW, material);
    if (this.bandRows !== null) this.sets[into].clear(this.renderer, this.bandRows.cleared);
  }

  /**
   * Transforms what `load` put in set `from`, along x and then z; returns the set that holds the
   * result (resultOf(from)). Along x only the band's lines are drawn; the other lines stay zero and
   * are read as zeros by the first z pass from the last x pass's target: when that is `from`, the
   * rows load cleared; else that pass draws every row. Call inside runPasses.
   */
  transform(from: WorkingSet): WorkingSet {
    let [source, target] = from === 0 ? this.sets : [this.sets[1], this.sets[0]];
    for (const { material, subtransformLog2, alongZ, lastAlongX } of this.passes) {
      const uniforms = material.uniforms;
      uniforms.tSpectra0.value = source.textures[0];
      uniforms.tSpectra1.value = source.textures[1];
      uniforms.subtransformLog2.value = subtransformLog2;
      const everyRow = alongZ || this.bandRows === null || (lastAlongX && target !== this.sets[from]);
      this.drawRows(target, everyRow ? EVERY_ROW : this.bandRows!.drawn, material);
      [source, target] = [target, source];
    }
    return this.resultOf(from);
  }

  /** Draws `material` into `target`, once per range of rows. */
  private drawRows(target: LayeredSpectra, rows: RowRanges, material: ShaderMaterial): void {
    for (const range of rows) {
      target.bind(this.renderer, range);
      this.pass.draw(this.renderer, material);
    }
  }

  dispose(): void {
    this.twiddles.dispose();
    for (const spectra of this.sets) spectra.dispose(this.renderer);
    for (const material of this.materials.values()) material.dispose();
    this.pass.dispose();
  }
}

/**
 * One set of FFT working storage: two array textures of four layers (the two working textures of
 * fftPass.frag) and a framebuffer with all eight layers as colour attachments, so one pass writes
 * a butterfly's four outputs to each texture.
 */
export class LayeredSpectra {
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

