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
 * ping-ponging between two sets of working storage (LayeredTarget of src/device/gpuDevice.ts: each
 * pass writes a butterfly's four outputs to four layers of (N/2)×(N/2) array textures). A spectrum whose modes lie on a band
 * of lines near k_z = 0 (a coarse cascade) is loaded and transformed along x on those lines only.
 * Writing a butterfly's four outputs reads every input once per pass instead of four times, and
 * under SwiftShader makes a pass about three times cheaper than one output per fragment. It runs
 * on a GpuDevice (src/device/gpuDevice.ts), which its user gives it.
 *
 * Textures: twiddles N×1 (cos 2πj/N, sin 2πj/N), static, computed in double precision because GLSL
 * sin/cos are approximate; two sets of working storage. This object owns them and its materials
 * (not the device), and frees them in dispose().
 */
import { DataTexture, FloatType, NearestFilter, RGFormat } from 'three';
import type { GpuDevice, GpuPrecision, LayeredTarget, PassMaterial, TexelRows } from '../device/gpuDevice';
import { shaderSource } from '../shaderSource';

/** How the previous pass left the data: INPUT_LAYOUT of shaders/fft/quarterLayout.glsl. */
type InputLayout = 'QUARTERS' | 'QUARTERS_TRANSPOSED' | 'AFTER_RADIX2' | 'AFTER_RADIX4';

/** One of the two sets of working storage. */
export type WorkingSet = 0 | 1;

interface FftPass {
  material: PassMaterial;
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

export interface GpuFftOptions {
  /** N, a power of two from 16. */
  size: number;
  /** The working storage's floats. */
  precision: GpuPrecision;
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
  readonly sets: readonly [LayeredTarget, LayeredTarget];
  /** Along x, then along z. */
  private readonly passes: FftPass[] = [];
  /** One program per radix, axis and input layout the passes need. */
  private readonly materials = new Map<string, PassMaterial>();
  /** The texel rows of the band's lines (bandTexelRows), null for all. */
  private readonly bandRows: BandRows | null;

  /** Throws an UnsupportedError, holding nothing, if the device cannot render to the working storage. */
  constructor(
    private readonly device: GpuDevice,
    { size: n, precision, loadDoesFirstRadix2 = false, band = null }: GpuFftOptions,
  ) {
    const sizeLog2 = (this.sizeLog2 = Math.log2(n));
    const table = new Float32Array(2 * n);
    for (let j = 0; j < n; j++) [table[2 * j], table[2 * j + 1]] = [Math.cos((2 * Math.PI * j) / n), Math.sin((2 * Math.PI * j) / n)];
    const first = device.createLayeredTarget(n / 2, precision);
    try {
      this.sets = [first, device.createLayeredTarget(n / 2, precision)];
    } catch (error) {
      first.dispose();
      throw error;
    }
    this.twiddles = new DataTexture(table, n, 1, RGFormat, FloatType);
    this.twiddles.minFilter = this.twiddles.magFilter = NearestFilter;
    this.twiddles.needsUpdate = true;
    this.bandRows = band === null ? null : bandTexelRows(n, band);

    const material = (radix: 2 | 4, alongZ: boolean, layout: InputLayout): PassMaterial => {
      const key = `${radix} ${alongZ} ${layout}`;
      let fft = this.materials.get(key);
      if (!fft) {
        const uniforms = { tSpectra0: { value: null }, tSpectra1: { value: null }, tTwiddles: { value: this.twiddles } };
        const defines = { RADIX: radix, RADIX_LOG2: Math.log2(radix), ALONG_Z: Number(alongZ), INPUT_LAYOUT: layout };
        fft = device.passMaterial(shaderSource('fft/fftPass.frag'), { sizeLog2: { value: sizeLog2 }, ...uniforms, subtransformLog2: { value: 0 } }, defines);
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
  load(material: PassMaterial, into: WorkingSet): void {
    this.drawRows(this.sets[into], this.bandRows?.drawn ?? EVERY_ROW, material);
    if (this.bandRows !== null) this.device.clear(this.sets[into], this.bandRows.cleared);
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
  private drawRows(target: LayeredTarget, rows: RowRanges, material: PassMaterial): void {
    for (const range of rows) this.device.draw(material, target, range);
  }

  dispose(): void {
    this.twiddles.dispose();
    for (const spectra of this.sets) spectra.dispose();
    for (const material of this.materials.values()) material.dispose();
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


