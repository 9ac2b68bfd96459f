/**
 * The JS simulation path: evolves the spectrum and computes every field (waveFieldLayout.ts) on
 * the CPU. It is the fallback when float render targets are missing, runs in a Web Worker in the
 * app, and is the oracle the GPU path is tested against.
 *
 * Time evolution (Tessendorf 2001, eq. 26; course report §2.1):
 *   h̃(k, t) = h̃0(k)·e^{iωt} + h̃0*(−k)·e^{−iωt},  ω = m·2π/T (dispersion.ts).
 * ω depends on |k| only (and src/spectrum/initialSpectrum.ts stores h̃0*(−k) next to each h̃0(k)), so
 * h̃(−k, t) = conj(h̃(k, t)): evolve() computes h̃ once for each pair of wave vectors ±k and writes
 * the packed spectra of both.
 *
 * Velocities (for the queries' velocityAt): the time derivative of the displacement texture,
 *   ∂h̃/∂t = iω·(h̃0(k)·e^{iωt} − h̃0*(−k)·e^{−iωt}),
 * with the same ω, packed like the displacement (Dx and Dz are multiples of h̃): (∂Dx/∂t, ∂h/∂t,
 * ∂Dz/∂t, ∂²Dx/∂z∂t) per texel, computed only when asked (updateVelocities).
 */
import { fillPhaseTable, PHASE_TABLE_SIZE } from '../spectrum/dispersion';
import { BatchedInverseFft2D } from './fft';
import { largestFrequency, type InitialSpectrum } from '../spectrum/initialSpectrum';
import type { LayerQueryFields } from '../layers/waveLayer';

/** What of an initial spectrum the fields are computed from (all a worker is sent). */
export type SpectrumForFields = Pick<InitialSpectrum, 'resolution' | 'repeatPeriod' | 'amplitudes' | 'waveVectors'>;

const PACKED_SPECTRA = 4;
/**
 * Numbers per mode in `modes`: with h̃0(k) = a and h̃0*(−k) = b,
 * (Re a + Re b, Im b − Im a, Im a + Im b, Re a − Re b), then kx, kz, 1/|k|, m as in src/spectrum/initialSpectrum.ts.
 */
const MODE_LENGTH = 8;

export class CpuWaveFields {
  private readonly fft: BatchedInverseFft2D;
  /**
   * The two fields, displacement then derivatives, made on first use (spectraAt asks for the
   * spectra only: 8 MB it would not read at N = 512): the FFT writes its two pairs of
   * packed fields straight into them.
   */
  private texels: readonly [Float32Array, Float32Array] | null;
  private readonly phaseTable = new Float32Array(4 * PHASE_TABLE_SIZE);
  /**
   * The modes with a nonzero amplitude, each pair ±k once (both are written together), in the
   * FFT's input order so that evolve() writes nearly in order: MODE_LENGTH numbers each. Float64:
   * the sums of amplitudes are exact. A coarse cascade keeps only a few per cent of its grid.
   */
  private readonly modes: Float64Array;
  /**
   * For each of `modes`, where field 0 of k and of −k goes in the FFT input, as row·N + column
   * (the row stride differs between the fields' FFT and the velocities').
   */
  private readonly modePlaces: Uint32Array;
  /** Whether the FFT input holds other (zero) modes too, to be cleared before each evolve(). */
  private readonly hasZeroModes: boolean;
  private readonly size: number;
  /** The largest |x| or |z| frequency of a mode the spectrum keeps: the FFTs skip what lies beyond. */
  private readonly inputBand: number;

  private readonly repeatPeriod: number;
  /** The velocity texels and the two-field FFT that makes them, once velocities are first asked for. */
  private velocityFields: { texels: Float32Array; fft: BatchedInverseFft2D } | null = null;

  /**
   * `reuse`: fields no longer wanted, whose arrays these take over if they have the same grid and
   * band (their fields are then overwritten): on this machine fresh memory costs ~4 ms per MB, and a
   * 256² spectrum's fields ~10 MB.
   */
  constructor(spectrum: SpectrumForFields, reuse: CpuWaveFields | null = null) {
    this.repeatPeriod = spectrum.repeatPeriod;
    const n = (this.size = spectrum.resolution);
    this.inputBand = largestFrequency(spectrum);
    const same = reuse !== null && reuse.size === n && reuse.inputBand === this.inputBand ? reuse : null;
    const fft = (this.fft = same?.fft ?? new BatchedInverseFft2D(n, PACKED_SPECTRA, this.inputBand));
    this.texels = same?.texels ?? null;
    this.velocityFields = same?.velocityFields ?? null;
    // Each pair of wave vectors ±k once, as the one of the two with the lower input index, in the
    // order of the input indexes (so that evolve() writes through the buffers nearly in order).
    const pairCount = (n * n) / 2 + 2; // k ≡ −k at (0, 0), (N/2, 0), (0, N/2) and (N/2, N/2)
    // The input row of frequency j, and column of frequency i: the bit reversal, its own inverse,
    // so it also gives the frequency of an input row or column.
    const placeOf = Uint32Array.from({ length: n }, (_, i) => fft.inputIndex(0, i, 0));
    const negated = (index: number) => (n - index) % n;
    const { amplitudes, waveVectors } = spectrum;
    /** Calls `keep` for each pair kept, in input order, and returns how many. */
    const forEachPair = (keep: (kept: number, at: number, partnerAt: number, from: number) => void) => {
      let kept = 0;
      for (let row = 0; row < n; row++) {
        for (let column = 0; column < n; column++) {
          const i = placeOf[column];
          const j = placeOf[row];
          const at = row * n + column;
          const partnerAt = placeOf[negated(j)] * n + placeOf[negated(i)];
          const from = 4 * (j * n + i);
          if (partnerAt < at || (amplitudes[from] === 0 && amplitudes[from + 1] === 0 && amplitudes[from + 2] === 0 && amplitudes[from + 3] === 0)) continue;
          keep(kept++, at, partnerAt, from);
        }
      }
      return kept;
    };
    // Counted first, so that the arrays are made to size: a coarse cascade keeps a few per cent of
    // the pairs, and fresh memory is slow here (above).
    const kept = forEachPair(() => {});
    const modes = (this.modes = new Float64Array(MODE_LENGTH * kept));
    const indexes = (this.modePlaces = new Uint32Array(2 * kept));
    forEachPair((k, at, partnerAt, from) => {
      const to = MODE_LENGTH * k;
      const [aRe, aIm, bRe, bIm] = [amplitudes[from], amplitudes[from + 1], amplitudes[from + 2], amplitudes[from + 3]];
      [modes[to], modes[to + 1], modes[to + 2], modes[to + 3]] = [aRe + bRe, bIm - aIm, aIm + bIm, aRe - bRe];
      for (let c = 0; c < 4; c++) modes[to + 4 + c] = waveVectors[from + c];
      [indexes[2 * k], indexes[2 * k + 1]] = [at, partnerAt];
    });
    this.hasZeroModes = kept < pairCount;
  }

  /** RGBA texels (Dx, h, Dz, ∂Dx/∂z). */
  get displacement(): Float32Array {
    return this.fieldTexels()[0];
  }

  /** RGBA texels (∂h/∂x, ∂h/∂z, ∂Dx/∂x, ∂Dz/∂z). */
  get derivatives(): Float32Array {
    return this.fieldTexels()[1];
  }

  /** Computes every field at time t (seconds). Allocates nothing after the first. */
  update(t: number): void {
    this.spectraAt(t);
    this.fft.runToTexels(this.fieldTexels());
  }

  /**
   * The four packed spectra of waveFieldLayout.ts at time t (s), untransformed, in the JS FFT's
   * input (at inputIndex): what the compute shader's evolution (computeSpectrum.ts) is tested
   * against. The fields are left as they were. Valid until the next call or update.
   */
  spectraAt(t: number): Pick<BatchedInverseFft2D, 'inputReal' | 'inputImag' | 'inputIndex'> {
    fillPhaseTable(this.phaseTable, t, this.repeatPeriod);
    this.evolve(this.fft, false);
    return this.fft;
  }

  /**
   * The fields last computed, which are for time t (s), as the queries read them; their velocities
   * are computed on the first call, then kept. Valid until the next update.
   */
  forQueries(t: number): LayerQueryFields {
    let velocities: Float32Array | null = null;
    return { time: t, resolution: this.size, displacement: this.displacement, derivatives: this.derivatives, velocities: () => (velocities ??= this.updateVelocities(t)) };
  }

  /**
   * The time derivative of the displacement at time t (s), RGBA texels (∂Dx/∂t, ∂h/∂t, ∂Dz/∂t,
   * ∂²Dx/∂z∂t) in m/s, in the layout of `displacement`. Returns the same array every time.
   */
  updateVelocities(t: number): Float32Array {
    const n = this.size;
    this.velocityFields ??= { texels: new Float32Array(4 * n * n), fft: new BatchedInverseFft2D(n, 2, this.inputBand) };
    const { texels, fft } = this.velocityFields;
    fillPhaseTable(this.phaseTable, t, this.repeatPeriod);
    this.evolve(fft, true);
    fft.runToTexels([texels]);
    return texels;
  }

  private fieldTexels(): readonly [Float32Array, Float32Array] {
    const n = this.size;
    return (this.texels ??= [new Float32Array(4 * n * n), new Float32Array(4 * n * n)]);
  }

  /**
   * h̃(±k, t), or with `velocities` ∂h̃(±k, t)/∂t, and the packed spectra at ±k (four, or the
   * displacement's two), written into the input of `fft` (whose layout is this.fft's).
   */
  private evolve(fft: BatchedInverseFft2D, velocities: boolean): void {
    const { phaseTable: table, modes, modePlaces } = this;
    // ω = m·ω0 (dispersion.ts), for the velocities.
    const omega0 = (2 * Math.PI) / this.repeatPeriod;
    const re = fft.inputReal;
    const im = fft.inputImag;
    const n = this.size;
    if (this.hasZeroModes) {
      // The FFT ran in place: its buffers hold the last fields. The zero modes are written here.
      re.fill(0);
      im.fill(0);
    }
    // A local copy: an imported binding read in the loop can cost a getter call per read (Vite SSR).
    const lowMask = PHASE_TABLE_SIZE - 1;
    const stride = fft.rowStride;
    const sizeLog2 = Math.log2(n);
    const columnMask = n - 1;
    for (let mode = 0, t = 0; mode < modePlaces.length / 2; mode++, t += MODE_LENGTH) {
      // Packed spectrum f at k lives at `at` + f·N. A mode that is its own partner (k ≡ −k on the
      // grid: k = 0 and the Nyquist corners and edges' midpoints) is written twice, the same value
      // up to rounding.
      const place = modePlaces[2 * mode];
      const partnerPlace = modePlaces[2 * mode + 1];
      const at = (place >> sizeLog2) * stride + (place & columnMask);
      const partnerAt = (partnerPlace >> sizeLog2) * stride + (partnerPlace & columnMask);
      const kx = modes[t + 4];
      const kz = modes[t + 5];
      const kInverse = modes[t + 6];
      const m = modes[t + 7];
      // e^{iωt} = e^{i·(m mod 256)·φ} · e^{i·256·(m div 256)·φ}
      const low = 4 * (m & lowMask);
      const high = 4 * (m >> 8) + 2;
      const er = table[low] * table[high] - table[low + 1] * table[high + 1];
      const ei = table[low] * table[high + 1] + table[low + 1] * table[high];
      // h̃(k) = a·e + b·conj(e) = hr + i·hi, with a = h̃0(k), b = h̃0*(−k) (see MODE_LENGTH);
      // h̃(−k) = conj(h̃(k)). Its time derivative: iω·(a·e − b·conj(e)), also conjugate at −k.
      let hr = modes[t] * er + modes[t + 1] * ei;
      let hi = modes[t + 2] * er + modes[t + 3] * ei;
      if (velocities) {
        const omega = m * omega0;
        const gr = modes[t + 3] * er - modes[t + 2] * ei;
        const gi = modes[t] * ei - modes[t + 1] * er;
        hr = -omega * gi;
        hi = omega * gr;
      }
      // The packed spectra of waveFieldLayout.ts as multiples of h̃, at k and at −k, where kx, kz
      // and so ax = kx/k, az = kz/k change sign (1/k does not) and h̃ becomes conj(h̃). λ = 1 here:
      // the surface and the queries scale D and its derivatives by the choppiness.
      const ax = kInverse * kx;
      const az = kInverse * kz;
      // Dx + i·h = i·(1 + ax)·h̃;   at −k: i·(1 − ax)·conj(h̃)
      const dxh = 1 + ax;
      const dxhPartner = 1 - ax;
      re[at] = -dxh * hi;
      im[at] = dxh * hr;
      re[partnerAt] = dxhPartner * hi;
      im[partnerAt] = dxhPartner * hr;
      // Dz + i·∂Dx/∂z = i·(az − ax·kz)·h̃;   at −k: i·(−az − ax·kz)·conj(h̃)
      const dzCross = az - ax * kz;
      const dzCrossPartner = -az - ax * kz;
      re[at + n] = -dzCross * hi;
      im[at + n] = dzCross * hr;
      re[partnerAt + n] = dzCrossPartner * hi;
      im[partnerAt + n] = dzCrossPartner * hr;
      if (velocities) continue; // the displacement's two packed spectra are all it needs
      // ∂h/∂x + i·∂h/∂z = (−kz + i·kx)·h̃;   at −k: (kz − i·kx)·conj(h̃)
      re[at + 2 * n] = -kz * hr - kx * hi;
      im[at + 2 * n] = kx * hr - kz * hi;
      re[partnerAt + 2 * n] = kz * hr - kx * hi;
      im[partnerAt + 2 * n] = -kx * hr - kz * hi;
      // ∂Dx/∂x + i·∂Dz/∂z = (xx + i·zz)·h̃ with xx = −λ·kx²/k, zz = −λ·kz²/k;   at −k: (xx + i·zz)·conj(h̃)
      const xx = -ax * kx;
      const zz = -az * kz;
      re[at + 3 * n] = xx * hr - zz * hi;
      im[at + 3 * n] = xx * hi + zz * hr;
      re[partnerAt + 3 * n] = xx * hr + zz * hi;
      im[partnerAt + 3 * n] = zz * hr - xx * hi;
    }
  }
}

