/**
 * The JS simulation path: evolves the spectrum and computes every field (waveFieldLayout.ts) on
 * the CPU. It is the fallback when float render targets are missing, runs in a Web Worker in the
 * app, and is the oracle the GPU path is tested against.
 *
 * Time evolution (Tessendorf 2001, eq. 26; course report §2.1):
 *   h̃(k, t) = h̃0(k)·e^{iωt} + h̃0*(−k)·e^{−iωt},  ω = m·2π/T (dispersion.ts).
 */
import { fillPhaseTable, PHASE_TABLE_SIZE } from './dispersion';
import { BatchedInverseFft2D } from './fft';
import type { InitialSpectrum } from './spectrum';

const PACKED_SPECTRA = 4;

export class CpuWaveFields {
  /** RGBA texels (Dx, h, Dz, ∂Dx/∂z). */
  readonly displacement: Float32Array;
  /** RGBA texels (∂h/∂x, ∂h/∂z, ∂Dx/∂x, ∂Dz/∂z). */
  readonly derivatives: Float32Array;
  private readonly fft: BatchedInverseFft2D;
  private readonly phaseTable = new Float32Array(4 * PHASE_TABLE_SIZE);
  /** The spectrum's texels reordered column by column (index i·N + j), so evolve() reads in order. */
  private readonly amplitudesByColumn: Float32Array;
  private readonly waveVectorsByColumn: Float32Array;
  private readonly size: number;

  constructor(
    spectrum: InitialSpectrum,
    private readonly choppiness: number,
    private readonly repeatPeriod: number,
  ) {
    const n = (this.size = spectrum.resolution);
    this.fft = new BatchedInverseFft2D(n, PACKED_SPECTRA);
    this.displacement = new Float32Array(4 * n * n);
    this.derivatives = new Float32Array(4 * n * n);
    this.amplitudesByColumn = new Float32Array(4 * n * n);
    this.waveVectorsByColumn = new Float32Array(4 * n * n);
    for (let i = 0; i < n; i++) {
      for (let j = 0; j < n; j++) {
        const from = 4 * (j * n + i);
        const to = 4 * (i * n + j);
        for (let c = 0; c < 4; c++) {
          this.amplitudesByColumn[to + c] = spectrum.amplitudes[from + c];
          this.waveVectorsByColumn[to + c] = spectrum.waveVectors[from + c];
        }
      }
    }
  }

  /** Computes every field at time t (seconds). Allocates nothing. */
  update(t: number): void {
    fillPhaseTable(this.phaseTable, t, this.repeatPeriod);
    this.evolve();
    this.fft.run();
    this.pack();
  }

  /** h̃(k, t) and the four packed spectra, written into the FFT's input. */
  private evolve(): void {
    const n = this.size;
    const lambda = this.choppiness;
    const { fft, phaseTable: table, amplitudesByColumn: h0, waveVectorsByColumn: waves } = this;
    const re = fft.inputReal;
    const im = fft.inputImag;
    for (let i = 0; i < n; i++) {
      // Four destination runs, one per packed spectrum, each contiguous in j.
      const out0 = fft.inputIndex(0, i, 0);
      const out1 = fft.inputIndex(1, i, 0);
      const out2 = fft.inputIndex(2, i, 0);
      const out3 = fft.inputIndex(3, i, 0);
      for (let j = 0, t = 4 * i * n; j < n; j++, t += 4) {
        const kx = waves[t];
        const kz = waves[t + 1];
        const kInverse = waves[t + 2];
        const m = waves[t + 3];
        // e^{iωt} = e^{i·(m mod 256)·φ} · e^{i·256·(m div 256)·φ}
        const low = 4 * (m & (PHASE_TABLE_SIZE - 1));
        const high = 4 * (m >> 8) + 2;
        const er = table[low] * table[high] - table[low + 1] * table[high + 1];
        const ei = table[low] * table[high + 1] + table[low + 1] * table[high];
        // h̃ = h̃0(k)·e + h̃0*(−k)·conj(e)
        const hr = h0[t] * er - h0[t + 1] * ei + h0[t + 2] * er + h0[t + 3] * ei;
        const hi = h0[t] * ei + h0[t + 1] * er - h0[t + 2] * ei + h0[t + 3] * er;
        // Slope spectra i·kx·h̃ and i·kz·h̃; the displacement ones are λ/k times these.
        const sxr = -kx * hi;
        const sxi = kx * hr;
        const szr = -kz * hi;
        const szi = kz * hr;
        const d = lambda * kInverse;
        // Dx + i·h
        re[out0 + j] = d * sxr - hi;
        im[out0 + j] = d * sxi + hr;
        // Dz + i·∂Dx/∂z, with ∂Dx/∂z = −λ·kx·kz/k·h̃
        const cross = -d * kx * kz;
        re[out1 + j] = d * szr - cross * hi;
        im[out1 + j] = d * szi + cross * hr;
        // ∂h/∂x + i·∂h/∂z
        re[out2 + j] = sxr - szi;
        im[out2 + j] = sxi + szr;
        // ∂Dx/∂x + i·∂Dz/∂z, with −λ·kx²/k·h̃ and −λ·kz²/k·h̃
        const xx = -d * kx * kx;
        const zz = -d * kz * kz;
        re[out3 + j] = xx * hr - zz * hi;
        im[out3 + j] = xx * hi + zz * hr;
      }
    }
  }

  /** FFT output → the two RGBA layouts of waveFieldLayout.ts. */
  private pack(): void {
    const n = this.size;
    const { fft, displacement, derivatives } = this;
    const re = fft.outputReal;
    const im = fft.outputImag;
    for (let j = 0; j < n; j++) {
      const in0 = fft.outputIndex(0, 0, j);
      const in1 = fft.outputIndex(1, 0, j);
      const in2 = fft.outputIndex(2, 0, j);
      const in3 = fft.outputIndex(3, 0, j);
      for (let i = 0, o = 4 * j * n; i < n; i++, o += 4) {
        displacement[o] = re[in0 + i];
        displacement[o + 1] = im[in0 + i];
        displacement[o + 2] = re[in1 + i];
        displacement[o + 3] = im[in1 + i];
        derivatives[o] = re[in2 + i];
        derivatives[o + 1] = im[in2 + i];
        derivatives[o + 2] = re[in3 + i];
        derivatives[o + 3] = im[in3 + i];
      }
    }
  }
}
