/**
 * Inverse 2D FFT on the CPU, for several complex fields at once:
 *   f(x_n, z_m) = Σ_{n', m'} F(n', m') · e^{+2πi·(n·n' + m·m')/N}   (no 1/N² factor)
 * which is Tessendorf's h(x) = Σ_k h̃(k)·e^{ik·x} on the grid of src/spectrum/initialSpectrum.ts.
 *
 * Layout. One matrix of N rows, each holding the F fields side by side (N numbers each), rows
 * S = F·N + 16 numbers apart, real and imaginary parts in two Float64Arrays. The transform works in
 * place, so the input and output buffers are the same arrays; only the order differs:
 *   input:  row = bit-reversed z index, column = bit-reversed x index:   rev(j)·S + f·N + rev(i)
 *   output: row = z index,              column = x index:                j·S + f·N + i
 * The output rows are the texture rows of waveFieldLayout.ts: no transpose is needed anywhere.
 *
 * Algorithm. Decimation in time (Cooley & Tukey 1965) takes bit-reversed input to natural-order
 * output. The radix-2 stages are grouped in pairs into radix-4 butterflies (with a radix-8 first step
 * when log2 N is odd): of the simple radices, radix 4 needs the fewest floating-point additions per
 * element, and the additions rather than the memory traffic set the pace here (JS has no FMA and
 * no SIMD; larger radices spill registers and measured slower).
 * The first step and the q = 0 butterflies of every step have twiddle 1 and skip the
 * multiplications. Twiddles are computed once, in double precision.
 *   Pass 1, along z (the row index): every butterfly combines four whole rows, so the innermost
 *   loop runs along contiguous columns with its twiddles in registers. The columns are processed
 *   in strips that stay in cache through all the steps.
 *   Pass 2, along x (within each row): rows are processed in small groups that stay in L1. The
 *   innermost loop runs over butterflies that share a twiddle, along the row or across the rows of
 *   the group, whichever run is longer.
 *
 * Why float64: with float32 buffers every load and store in the hot loops converts between float32
 * and float64 (JS arithmetic is double), and that costs more than the extra memory traffic
 * (measured: the transform is 15–20 % faster in float64).
 * Why S = F·N + 16 and not F·N: a power-of-two stride maps the rows of a strip onto the same cache
 * sets. For a similar reason the imaginary buffer starts 2 KiB after the end of the real one: at a
 * multiple of 4 KiB, loads from one and stores to the other at the same index would falsely look
 * dependent to the CPU ("4K aliasing").
 */
import { ParameterError } from '../parameters/options';
/** Columns per pass-1 strip: N rows × 64 columns × 16 bytes (256 KiB at N = 256) stays in L2. */
const STRIP_WIDTH = 64;
/** Pass 2 transforms groups of rows of about this many complex numbers (32 KiB), which stay in L1. */
const ROW_GROUP_SIZE = 2048;
const ROW_PADDING = 16;
/** Doubles (2 KiB) between the end of the real buffer and the start of the imaginary one. */
const IMAG_OFFSET_PADDING = 256;

export class BatchedInverseFft2D {
  /** Spectra in, written by the caller at inputIndex(). The same arrays as the output: run() overwrites them. */
  readonly inputReal: Float64Array;
  readonly inputImag: Float64Array;
  /** Fields out after run(), read at outputIndex(). */
  readonly outputReal: Float64Array;
  readonly outputImag: Float64Array;
  /** Numbers from one row of the buffers to the next (F·N plus padding). */
  readonly rowStride: number;
  private readonly bitReversed: Uint32Array;
  /** The radix of the first step: 4, or 8 when log2 N is odd (2 when N = 2). Every later step is radix 4. */
  private readonly firstRadix: number;
  /**
   * The twiddles of the radix-4 steps after the first, step after step: for the step combining
   * transforms of length h, and each q < h, the powers w, w², w³ of w = e^{2πi·q/4h} as
   * (re, im) pairs, 6 numbers per q.
   */
  private readonly twiddles: Float64Array;
  private readonly rowsPerGroup: number;
  /**
   * The columns pass 1 transforms: every `step`-th from each offset within a strip. With P as in
   * the constructor, c mod P in {0, P − 1} (all of them when P < 4): the others hold zeros, whose
   * transform is zero.
   */
  private readonly liveColumns: { offsets: readonly number[]; step: number };

  /**
   * `inputBand`, when given, promises that every input coefficient with a frequency i (x) or j (z)
   * beyond it is zero (|i| or |j| > inputBand, signed frequencies, |i|, |j| ≤ N/2), and lets the
   * transform skip what holds only zeros. They sit in a regular pattern: with P a power of two and
   * inputBand·P < N, the frequencies up to inputBand have their top log2 P bits all 0 (i < N/P) or
   * all 1 (i > N − N/P), so their bit-reversed columns (and rows) are ≡ 0 or ≡ P − 1 mod P. A coarse
   * FFT cascade keeps modes up to about a fifth of its Nyquist frequency (cascadeBands.ts), so
   * P = 8: pass 1 transforms a quarter of the columns. (Pass 2 cannot skip rows: pass 1 leaves
   * every row of a live column filled.) The caller must write zeros at every other input index
   * before each run (CpuWaveFields.evolve does).
   */
  constructor(
    readonly size: number,
    readonly fieldCount: number,
    inputBand = size / 2,
  ) {
    if (!Number.isInteger(size) || size < 2 || (size & (size - 1)) !== 0) {
      throw new ParameterError('FFT size', size, 'a power of two ≥ 2');
    }
    const n = size;
    this.rowStride = n * fieldCount + ROW_PADDING;
    const length = n * this.rowStride;
    const imagStart = length + IMAG_OFFSET_PADDING;
    const buffer = new Float64Array(imagStart + length);
    this.inputReal = this.outputReal = buffer.subarray(0, length);
    this.inputImag = this.outputImag = buffer.subarray(imagStart, imagStart + length);
    this.bitReversed = bitReversalPermutation(n);
    this.firstRadix = Math.log2(n) % 2 === 0 ? 4 : n === 2 ? 2 : 8;
    const twiddles: number[] = [];
    for (let h = this.firstRadix; h < n; h *= 4) {
      for (let q = 0; q < h; q++) {
        for (let power = 1; power <= 3; power++) {
          const angle = (2 * Math.PI * power * q) / (4 * h); // + sign: inverse transform
          twiddles.push(Math.cos(angle), Math.sin(angle));
        }
      }
    }
    this.twiddles = Float64Array.from(twiddles);
    this.rowsPerGroup = Math.max(1, Math.min(n, Math.floor(ROW_GROUP_SIZE / (n * fieldCount))));
    // The largest P ≤ min(N, STRIP_WIDTH) with inputBand·P < N: P then divides every strip's width.
    let period = 1;
    while (2 * period <= Math.min(n, STRIP_WIDTH) && inputBand * 2 * period < n) period *= 2;
    this.liveColumns = period >= 4 ? { offsets: [0, period - 1], step: period } : { offsets: [0], step: 1 };
  }

  /** Where field f's coefficient for frequency texel (column i, row j) goes in the input buffers. */
  inputIndex(field: number, i: number, j: number): number {
    return this.bitReversed[j] * this.rowStride + field * this.size + this.bitReversed[i];
  }

  /** Where field f's value at sample (column i, row j) is found in the output buffers. */
  outputIndex(field: number, i: number, j: number): number {
    return j * this.rowStride + field * this.size + i;
  }

  /** Transforms the input in place; the output buffers then hold the result. */
  run(): void {
    this.transformAlongZ();
    this.transformAlongX(null);
  }

  /**
   * run(), except that the last butterflies write the result as RGBA texels rather than into the
   * output buffers (which are left unfinished): fields 2t and 2t + 1 of sample (column i, row j) go to
   *   texels[t][4·(j·N + i) + 0..3] = (Re f_2t, Im f_2t, Re f_2t+1, Im f_2t+1),
   * the texture layout of two real fields packed into one transform (waveFieldLayout.ts). Writing
   * them straight from the butterflies saves a pass over the output. Needs N ≥ 16, so that the last
   * step is radix 4, and one array of N² texels per two fields.
   */
  runToTexels(texels: readonly Float32Array[]): void {
    const n = this.size;
    let valid = n >= 16 && 2 * texels.length === this.fieldCount;
    for (let t = 0; t < texels.length; t++) valid &&= texels[t].length === 4 * n * n;
    if (!valid) throw new ParameterError('runToTexels(texels)', texels, '', `runToTexels needs N ≥ 16 and ${this.fieldCount / 2} arrays of ${4 * n * n} numbers`);
    this.transformAlongZ();
    this.transformAlongX(texels);
  }

  /**
   * Pass 1: along the row index, strip by strip of columns; each butterfly combines four rows. Only
   * the live columns (liveColumns).
   */
  private transformAlongZ(): void {
    const { size: n, rowStride: stride, firstRadix, twiddles, outputReal: re, outputImag: im } = this;
    const { offsets, step } = this.liveColumns;
    const width = n * this.fieldCount;
    for (let strip = 0; strip < width; strip += STRIP_WIDTH) {
      const columns = Math.min(STRIP_WIDTH, width - strip) / step;
      for (const offset of offsets) {
        const column = strip + offset;
        // Transforms of length firstRadix over each run of firstRadix consecutive rows.
        firstStep(firstRadix, re, im, column, stride, step, columns, firstRadix * stride, n / firstRadix);
        for (let h = firstRadix, t = 0; h < n; t += 6 * h, h *= 4) {
          // In each block of 4h rows, butterfly q combines rows q, q + h, q + 2h and q + 3h.
          const blockStride = 4 * h * stride;
          const blocks = n / (4 * h);
          radix4Untwiddled(re, im, column, h * stride, step, columns, blockStride, blocks);
          for (let q = 1; q < h; q++) {
            radix4(re, im, twiddles, t + 6 * q, q * stride + column, h * stride, step, columns, blockStride, blocks);
          }
        }
      }
    }
  }

  /** Pass 2: along x within each row, a group of rows at a time; the last step into `texels` if given. */
  private transformAlongX(texels: readonly Float32Array[] | null): void {
    const { size: n, rowStride: stride, firstRadix, twiddles, rowsPerGroup, outputReal: re, outputImag: im } = this;
    const width = n * this.fieldCount;
    for (let row = 0; row < n; row += rowsPerGroup) {
      const start = row * stride;
      const rows = Math.min(rowsPerGroup, n - row);
      // The butterflies that share a twiddle sit every blockLength numbers along each row (for all
      // fields) and every `stride` across the rows of the group: the longer run is the inner loop.
      const firstBlocks = width / firstRadix;
      if (firstBlocks >= rows) firstStep(firstRadix, re, im, start, 1, firstRadix, firstBlocks, stride, rows);
      else firstStep(firstRadix, re, im, start, 1, stride, rows, firstRadix, firstBlocks);
      for (let h = firstRadix, t = 0; h < n; t += 6 * h, h *= 4) {
        if (texels !== null && 4 * h === n) {
          for (let r = 0; r < rows; r++) {
            for (let field = 0; field < this.fieldCount; field++) {
              // Channels 0–1 of texel array field/2 for an even field, 2–3 for an odd one.
              const texelStart = 4 * (row + r) * n + 2 * (field % 2);
              radix4ToTexels(re, im, twiddles, t, start + r * stride + field * n, h, texels[field >> 1], texelStart);
            }
          }
          break;
        }
        const blockLength = 4 * h;
        const blocks = width / blockLength;
        const alongRow = blocks >= rows;
        const innerStride = alongRow ? blockLength : stride;
        const innerCount = alongRow ? blocks : rows;
        const outerStride = alongRow ? stride : blockLength;
        const outerCount = alongRow ? rows : blocks;
        radix4Untwiddled(re, im, start, h, innerStride, innerCount, outerStride, outerCount);
        for (let q = 1; q < h; q++) {
          radix4(re, im, twiddles, t + 6 * q, start + q, h, innerStride, innerCount, outerStride, outerCount);
        }
      }
    }
  }

}

/*
 * The butterfly kernels. Each applies one butterfly at every position
 *   p = first + o·outerStride + i·innerStride,   o < outerCount, i < innerCount,
 * to the elements p + k·distance. They get the arrays as arguments rather than through `this` and
 * always see Float64Arrays, so that the optimizing compiler keeps everything in registers.
 * radix4, radix4ToTexels and radix4Untwiddled repeat the same butterfly arithmetic on purpose: a
 * shared helper would have to hand eight numbers back per butterfly (through an array in memory),
 * in the loops that set the pace of the whole JS path.
 */

/** The first step, radix 2, 4 or 8, on bit-reversed input: twiddles are all trivial. */
function firstStep(
  radix: number,
  re: Float64Array,
  im: Float64Array,
  first: number,
  distance: number,
  innerStride: number,
  innerCount: number,
  outerStride: number,
  outerCount: number,
): void {
  if (radix === 4) radix4Untwiddled(re, im, first, distance, innerStride, innerCount, outerStride, outerCount);
  else if (radix === 8) radix8Untwiddled(re, im, first, distance, innerStride, innerCount, outerStride, outerCount);
  else radix2Untwiddled(re, im, first, distance, innerStride, innerCount, outerStride, outerCount);
}

/**
 * Radix-4 decimation-in-time butterfly, combining four transforms of length h into one of
 * length 4h. Elements p, p + d, p + 2d, p + 3d hold, at the same frequency q < h, the transforms
 * A0, A2, A1, A3 of the subsequences y[4m], y[4m+2], y[4m+1], y[4m+3] (bit-reversed order). With
 * ω = e^{2πi/4h}, w = ω^q and Bb = w^b·Ab, and since ω^h = e^{2πi/4} = i,
 *   X[q + k·h] = A0 + i^k·B1 + (−1)^k·B2 + (−i)^k·B3,   stored at p + k·d:
 *   X0 = (A0 + B2) + (B1 + B3),  X2 = (A0 + B2) − (B1 + B3),
 *   X1 = (A0 − B2) + i·(B1 − B3),  X3 = (A0 − B2) − i·(B1 − B3).
 * The twiddles (w, w², w³) are read from twiddles[t..t+5].
 */
function radix4(
  re: Float64Array,
  im: Float64Array,
  twiddles: Float64Array,
  t: number,
  first: number,
  distance: number,
  innerStride: number,
  innerCount: number,
  outerStride: number,
  outerCount: number,
): void {
  const w1r = twiddles[t];
  const w1i = twiddles[t + 1];
  const w2r = twiddles[t + 2];
  const w2i = twiddles[t + 3];
  const w3r = twiddles[t + 4];
  const w3i = twiddles[t + 5];
  const innerLength = innerStride * innerCount;
  for (let o = 0, base = first; o < outerCount; o++, base += outerStride) {
    for (let p0 = base, end = base + innerLength; p0 < end; p0 += innerStride) {
      const p1 = p0 + distance;
      const p2 = p1 + distance;
      const p3 = p2 + distance;
      const a0r = re[p0];
      const a0i = im[p0];
      const a2r = re[p1];
      const a2i = im[p1];
      const a1r = re[p2];
      const a1i = im[p2];
      const a3r = re[p3];
      const a3i = im[p3];
      const b1r = a1r * w1r - a1i * w1i;
      const b1i = a1r * w1i + a1i * w1r;
      const b2r = a2r * w2r - a2i * w2i;
      const b2i = a2r * w2i + a2i * w2r;
      const b3r = a3r * w3r - a3i * w3i;
      const b3i = a3r * w3i + a3i * w3r;
      const s02r = a0r + b2r;
      const s02i = a0i + b2i;
      const d02r = a0r - b2r;
      const d02i = a0i - b2i;
      const s13r = b1r + b3r;
      const s13i = b1i + b3i;
      const d13r = b1r - b3r;
      const d13i = b1i - b3i;
      re[p0] = s02r + s13r;
      im[p0] = s02i + s13i;
      re[p1] = d02r - d13i;
      im[p1] = d02i + d13r;
      re[p2] = s02r - s13r;
      im[p2] = s02i - s13i;
      re[p3] = d02r + d13i;
      im[p3] = d02i - d13r;
    }
  }
}

/**
 * The last step of pass 2 for one field of one row (q < h = N/4, the radix4 butterfly at
 * first + q), written as two channels of RGBA texels: X_k goes to texels[texelStart + 4·(q + k·h)]
 * (real part) and the channel after it (imaginary part). The twiddles of each q are read from
 * twiddles[t + 6q ..].
 */
function radix4ToTexels(
  re: Float64Array,
  im: Float64Array,
  twiddles: Float64Array,
  t: number,
  first: number,
  h: number,
  texels: Float32Array,
  texelStart: number,
): void {
  for (let q = 0, w = t; q < h; q++, w += 6) {
    const w1r = twiddles[w];
    const w1i = twiddles[w + 1];
    const w2r = twiddles[w + 2];
    const w2i = twiddles[w + 3];
    const w3r = twiddles[w + 4];
    const w3i = twiddles[w + 5];
    const p0 = first + q;
    const p1 = p0 + h;
    const p2 = p1 + h;
    const p3 = p2 + h;
    const a0r = re[p0];
    const a0i = im[p0];
    const a2r = re[p1];
    const a2i = im[p1];
    const a1r = re[p2];
    const a1i = im[p2];
    const a3r = re[p3];
    const a3i = im[p3];
    const b1r = a1r * w1r - a1i * w1i;
    const b1i = a1r * w1i + a1i * w1r;
    const b2r = a2r * w2r - a2i * w2i;
    const b2i = a2r * w2i + a2i * w2r;
    const b3r = a3r * w3r - a3i * w3i;
    const b3i = a3r * w3i + a3i * w3r;
    const s02r = a0r + b2r;
    const s02i = a0i + b2i;
    const d02r = a0r - b2r;
    const d02i = a0i - b2i;
    const s13r = b1r + b3r;
    const s13i = b1i + b3i;
    const d13r = b1r - b3r;
    const d13i = b1i - b3i;
    const o0 = texelStart + 4 * q;
    const o1 = o0 + 4 * h;
    const o2 = o1 + 4 * h;
    const o3 = o2 + 4 * h;
    texels[o0] = s02r + s13r;
    texels[o0 + 1] = s02i + s13i;
    texels[o1] = d02r - d13i;
    texels[o1 + 1] = d02i + d13r;
    texels[o2] = s02r - s13r;
    texels[o2 + 1] = s02i - s13i;
    texels[o3] = d02r + d13i;
    texels[o3 + 1] = d02i - d13r;
  }
}

/** radix4 with w = 1 (q = 0, and the whole first step): additions only. */
function radix4Untwiddled(
  re: Float64Array,
  im: Float64Array,
  first: number,
  distance: number,
  innerStride: number,
  innerCount: number,
  outerStride: number,
  outerCount: number,
): void {
  const innerLength = innerStride * innerCount;
  for (let o = 0, base = first; o < outerCount; o++, base += outerStride) {
    for (let p0 = base, end = base + innerLength; p0 < end; p0 += innerStride) {
      const p1 = p0 + distance;
      const p2 = p1 + distance;
      const p3 = p2 + distance;
      const a0r = re[p0];
      const a0i = im[p0];
      const a2r = re[p1];
      const a2i = im[p1];
      const a1r = re[p2];
      const a1i = im[p2];
      const a3r = re[p3];
      const a3i = im[p3];
      const s02r = a0r + a2r;
      const s02i = a0i + a2i;
      const d02r = a0r - a2r;
      const d02i = a0i - a2i;
      const s13r = a1r + a3r;
      const s13i = a1i + a3i;
      const d13r = a1r - a3r;
      const d13i = a1i - a3i;
      re[p0] = s02r + s13r;
      im[p0] = s02i + s13i;
      re[p1] = d02r - d13i;
      im[p1] = d02i + d13r;
      re[p2] = s02r - s13r;
      im[p2] = s02i - s13i;
      re[p3] = d02r + d13i;
      im[p3] = d02i - d13r;
    }
  }
}

/**
 * The 8-point inverse DFT of the first step when log2 N is odd. Elements p + k·d hold y[rev3(k)]
 * = y0, y4, y2, y6, y1, y5, y3, y7: the first four are the even samples in the bit-reversed order
 * of a 4-point transform, the last four the odd ones. With E and O their 4-point transforms and
 * ε = e^{2πi/8}: X[k] = E[k] + ε^k·O[k], X[k + 4] = E[k] − ε^k·O[k] (one radix-2 step).
 */
function radix8Untwiddled(
  re: Float64Array,
  im: Float64Array,
  first: number,
  distance: number,
  innerStride: number,
  innerCount: number,
  outerStride: number,
  outerCount: number,
): void {
  const innerLength = innerStride * innerCount;
  for (let o = 0, base = first; o < outerCount; o++, base += outerStride) {
    for (let p0 = base, end = base + innerLength; p0 < end; p0 += innerStride) {
      const p1 = p0 + distance;
      const p2 = p1 + distance;
      const p3 = p2 + distance;
      const p4 = p3 + distance;
      const p5 = p4 + distance;
      const p6 = p5 + distance;
      const p7 = p6 + distance;
      // E: the 4-point transform of y0, y2, y4, y6 (stored y0, y4, y2, y6).
      const y0r = re[p0];
      const y0i = im[p0];
      const y4r = re[p1];
      const y4i = im[p1];
      const y2r = re[p2];
      const y2i = im[p2];
      const y6r = re[p3];
      const y6i = im[p3];
      const s04r = y0r + y4r;
      const s04i = y0i + y4i;
      const d04r = y0r - y4r;
      const d04i = y0i - y4i;
      const s26r = y2r + y6r;
      const s26i = y2i + y6i;
      const d26r = y2r - y6r;
      const d26i = y2i - y6i;
      const e0r = s04r + s26r;
      const e0i = s04i + s26i;
      const e1r = d04r - d26i;
      const e1i = d04i + d26r;
      const e2r = s04r - s26r;
      const e2i = s04i - s26i;
      const e3r = d04r + d26i;
      const e3i = d04i - d26r;
      // O: the 4-point transform of y1, y3, y5, y7 (stored y1, y5, y3, y7).
      const y1r = re[p4];
      const y1i = im[p4];
      const y5r = re[p5];
      const y5i = im[p5];
      const y3r = re[p6];
      const y3i = im[p6];
      const y7r = re[p7];
      const y7i = im[p7];
      const s15r = y1r + y5r;
      const s15i = y1i + y5i;
      const d15r = y1r - y5r;
      const d15i = y1i - y5i;
      const s37r = y3r + y7r;
      const s37i = y3i + y7i;
      const d37r = y3r - y7r;
      const d37i = y3i - y7i;
      const o0r = s15r + s37r;
      const o0i = s15i + s37i;
      const o1r = d15r - d37i;
      const o1i = d15i + d37r;
      const o2r = s15r - s37r;
      const o2i = s15i - s37i;
      const o3r = d15r + d37i;
      const o3i = d15i - d37r;
      // ε^k·O[k]: ε = (1 + i)/√2, ε² = i, ε³ = (−1 + i)/√2.
      const t1r = (o1r - o1i) * Math.SQRT1_2;
      const t1i = (o1r + o1i) * Math.SQRT1_2;
      const t3r = -(o3r + o3i) * Math.SQRT1_2;
      const t3i = (o3r - o3i) * Math.SQRT1_2;
      re[p0] = e0r + o0r;
      im[p0] = e0i + o0i;
      re[p4] = e0r - o0r;
      im[p4] = e0i - o0i;
      re[p1] = e1r + t1r;
      im[p1] = e1i + t1i;
      re[p5] = e1r - t1r;
      im[p5] = e1i - t1i;
      re[p2] = e2r - o2i;
      im[p2] = e2i + o2r;
      re[p6] = e2r + o2i;
      im[p6] = e2i - o2r;
      re[p3] = e3r + t3r;
      im[p3] = e3i + t3i;
      re[p7] = e3r - t3r;
      im[p7] = e3i - t3i;
    }
  }
}

/** The only step of a 2-point transform: X0 = y0 + y1, X1 = y0 − y1. */
function radix2Untwiddled(
  re: Float64Array,
  im: Float64Array,
  first: number,
  distance: number,
  innerStride: number,
  innerCount: number,
  outerStride: number,
  outerCount: number,
): void {
  const innerLength = innerStride * innerCount;
  for (let o = 0, base = first; o < outerCount; o++, base += outerStride) {
    for (let p0 = base, end = base + innerLength; p0 < end; p0 += innerStride) {
      const p1 = p0 + distance;
      const ar = re[p0];
      const ai = im[p0];
      const br = re[p1];
      const bi = im[p1];
      re[p0] = ar + br;
      im[p0] = ai + bi;
      re[p1] = ar - br;
      im[p1] = ai - bi;
    }
  }
}

function bitReversalPermutation(n: number): Uint32Array {
  const bitCount = Math.log2(n);
  const table = new Uint32Array(n);
  for (let i = 0; i < n; i++) {
    let reversed = 0;
    for (let bit = 0; bit < bitCount; bit++) reversed |= ((i >> bit) & 1) << (bitCount - 1 - bit);
    table[i] = reversed;
  }
  return table;
}
