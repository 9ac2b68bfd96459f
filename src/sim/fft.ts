/**
 * Inverse 2D FFT on the CPU, for several complex fields at once:
 *   f(x_n, z_m) = Σ_{n', m'} F(n', m') · e^{+2πi·(n·n' + m·m')/N}   (no 1/N² factor)
 * which is Tessendorf's h(x) = Σ_k h̃(k)·e^{ik·x} on the grid of spectrum.ts.
 *
 * Layout and why. A 2D transform is N 1D transforms along x, then N along z. Rather than transform
 * one strided column at a time (the usual row–column method, slow in JS), every butterfly here
 * combines two whole rows of the matrix, so the innermost loop runs over contiguous memory,
 * F·N numbers long when F fields sit side by side in each row:
 *   input  buffer, row r = bit-reversed x index, then [field][z]:   index rev(i)·S + f·N + j
 *   output buffer, row r = z index, then [field][x]:                 index j·S + f·N + i
 * Rows are S = F·N + 16 numbers apart: a power-of-two stride would map every row of a cache strip
 * to the same cache sets and evict them from each other.
 * Pass 1 transforms along the row index (x) with radix-2 decimation in time (Cooley & Tukey 1965),
 * stages fused in pairs, in place; a transpose, which also bit-reverses the new row order, brings z into the row index;
 * pass 2 transforms along z the same way. Twiddles are precomputed in double precision.
 */
/** Columns per cache strip: N rows × 64 columns × 8 bytes stays within L2 up to N = 1024. */
const STRIP_WIDTH = 64;
const TRANSPOSE_TILE = 16;
const ROW_PADDING = 16;

export class BatchedInverseFft2D {
  /** Spectra in, written by the caller at inputIndex(). Overwritten by run(). */
  readonly inputReal: Float32Array;
  readonly inputImag: Float32Array;
  /** Fields out after run(), read at outputIndex(). */
  readonly outputReal: Float32Array;
  readonly outputImag: Float32Array;
  private readonly rowStride: number;
  private readonly bitReversed: Uint32Array;
  private readonly twiddleCos: Float64Array;
  private readonly twiddleSin: Float64Array;

  constructor(
    readonly size: number,
    readonly fieldCount: number,
  ) {
    if (!Number.isInteger(size) || size < 2 || (size & (size - 1)) !== 0) {
      throw new RangeError(`FFT size must be a power of two ≥ 2; got ${size}`);
    }
    this.rowStride = size * fieldCount + ROW_PADDING;
    const length = size * this.rowStride;
    this.inputReal = new Float32Array(length);
    this.inputImag = new Float32Array(length);
    this.outputReal = new Float32Array(length);
    this.outputImag = new Float32Array(length);
    this.bitReversed = bitReversalPermutation(size);
    this.twiddleCos = new Float64Array(size / 2);
    this.twiddleSin = new Float64Array(size / 2);
    for (let q = 0; q < size / 2; q++) {
      const angle = (2 * Math.PI * q) / size; // + sign: inverse transform
      this.twiddleCos[q] = Math.cos(angle);
      this.twiddleSin[q] = Math.sin(angle);
    }
  }

  /** Where field f's coefficient for frequency texel (column i, row j) goes in the input buffers. */
  inputIndex(field: number, i: number, j: number): number {
    return this.bitReversed[i] * this.rowStride + field * this.size + j;
  }

  /** Where field f's value at sample (column i, row j) is found in the output buffers. */
  outputIndex(field: number, i: number, j: number): number {
    return j * this.rowStride + field * this.size + i;
  }

  run(): void {
    this.transformAlongRows(this.inputReal, this.inputImag);
    this.transposeWithBitReversal();
    this.transformAlongRows(this.outputReal, this.outputImag);
  }

  /**
   * Transform along the row index, in place; rows are in bit-reversed order on entry. Radix-2
   * decimation in time, with each pair of consecutive stages fused into one radix-4 step (a
   * "radix-2²" butterfly) so the data is swept half as often. The columns are processed in strips
   * that fit in cache, each strip going through every stage before the next strip starts.
   */
  private transformAlongRows(real: Float32Array, imag: Float32Array): void {
    const n = this.size;
    const width = n * this.fieldCount;
    for (let column = 0; column < width; column += STRIP_WIDTH) {
      const end = Math.min(width, column + STRIP_WIDTH);
      let span = 1; // length of the sub-transforms already done
      if (Math.log2(n) % 2 === 1) {
        this.radix2Stage(real, imag, column, end);
        span = 2;
      }
      for (; span < n; span *= 4) this.radix4Step(real, imag, column, end, span);
    }
  }

  /** First stage when log2 N is odd: sub-transforms of length 1 → 2 (twiddle 1). */
  private radix2Stage(real: Float32Array, imag: Float32Array, from: number, to: number): void {
    const offset = this.rowStride;
    for (let row = 0; row < this.size; row += 2) {
      for (let a = row * offset + from, end = row * offset + to; a < end; a++) {
        const b = a + offset;
        const ar = real[a];
        const ai = imag[a];
        const br = real[b];
        const bi = imag[b];
        real[a] = ar + br;
        imag[a] = ai + bi;
        real[b] = ar - br;
        imag[b] = ai - bi;
      }
    }
  }

  /**
   * Two radix-2 stages at once, sub-transforms of length h → 4h. For rows x0..x3 at q, q+h, q+2h,
   * q+3h of a block, with w1 = e^{2πi·q/2h} and w2 = e^{2πi·q/4h}:
   *   stage 1: x0' = x0 + w1·x1, x1' = x0 − w1·x1, x2' = x2 + w1·x3, x3' = x2 − w1·x3
   *   stage 2: y0 = x0' + w2·x2', y2 = x0' − w2·x2', y1 = x1' + i·w2·x3', y3 = x1' − i·w2·x3'
   * (the twiddle of position q + h at length 4h is w2·e^{2πi/4} = i·w2).
   */
  private radix4Step(
    real: Float32Array,
    imag: Float32Array,
    from: number,
    to: number,
    h: number,
  ): void {
    const n = this.size;
    const stride1 = n / (2 * h); // twiddle table index step for length 2h
    const stride2 = n / (4 * h);
    const rowOffset = h * this.rowStride;
    for (let start = 0; start < n; start += 4 * h) {
      for (let q = 0; q < h; q++) {
        const w1r = this.twiddleCos[q * stride1];
        const w1i = this.twiddleSin[q * stride1];
        const w2r = this.twiddleCos[q * stride2];
        const w2i = this.twiddleSin[q * stride2];
        const base = (start + q) * this.rowStride;
        for (let i0 = base + from, end = base + to; i0 < end; i0++) {
          const i1 = i0 + rowOffset;
          const i2 = i1 + rowOffset;
          const i3 = i2 + rowOffset;
          const r0 = real[i0];
          const m0 = imag[i0];
          const r1 = real[i1];
          const m1 = imag[i1];
          const r2 = real[i2];
          const m2 = imag[i2];
          const r3 = real[i3];
          const m3 = imag[i3];
          // stage 1
          const x1r = r1 * w1r - m1 * w1i;
          const x1i = r1 * w1i + m1 * w1r;
          const x3r = r3 * w1r - m3 * w1i;
          const x3i = r3 * w1i + m3 * w1r;
          const a0r = r0 + x1r;
          const a0i = m0 + x1i;
          const a1r = r0 - x1r;
          const a1i = m0 - x1i;
          const a2r = r2 + x3r;
          const a2i = m2 + x3i;
          const a3r = r2 - x3r;
          const a3i = m2 - x3i;
          // stage 2: t2 = w2·a2', t3 = i·w2·a3'
          const t2r = a2r * w2r - a2i * w2i;
          const t2i = a2r * w2i + a2i * w2r;
          const t3r = -(a3r * w2i + a3i * w2r);
          const t3i = a3r * w2r - a3i * w2i;
          real[i0] = a0r + t2r;
          imag[i0] = a0i + t2i;
          real[i2] = a0r - t2r;
          imag[i2] = a0i - t2i;
          real[i1] = a1r + t3r;
          imag[i1] = a1i + t3i;
          real[i3] = a1r - t3r;
          imag[i3] = a1i - t3i;
        }
      }
    }
  }

  /** output[rev(j)][f][i] = input[i][f][j]: z becomes the (bit-reversed) row index. */
  private transposeWithBitReversal(): void {
    const n = this.size;
    const fields = this.fieldCount;
    const { inputReal, inputImag, outputReal, outputImag, bitReversed, rowStride: stride } = this;
    const tile = Math.min(n, TRANSPOSE_TILE); // tiles keep both sides of the copy in cache
    for (let i0 = 0; i0 < n; i0 += tile) {
      for (let j0 = 0; j0 < n; j0 += tile) {
        for (let f = 0; f < fields; f++) {
          for (let j = j0; j < j0 + tile; j++) {
            const to = bitReversed[j] * stride + f * n;
            for (let i = i0; i < i0 + tile; i++) {
              const from = i * stride + f * n + j;
              outputReal[to + i] = inputReal[from];
              outputImag[to + i] = inputImag[from];
            }
          }
        }
      }
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
