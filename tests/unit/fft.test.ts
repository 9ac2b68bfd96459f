import { describe, expect, it } from 'vitest';
import { BatchedInverseFft2D } from '../../src/sim/fft';
import { SeededRandom } from '../../src/sim/random';
import { naiveInverseDft2D } from './naiveDft';

describe('BatchedInverseFft2D against a naive DFT', () => {
  for (const n of [8, 16, 32]) {
    it(`matches the inverse DFT at N = ${n} for 3 random complex fields at once`, () => {
      const fields = 3;
      const random = new SeededRandom(100 + n);
      const fft = new BatchedInverseFft2D(n, fields);
      const inputs: [Float64Array, Float64Array][] = [];
      for (let f = 0; f < fields; f++) {
        const real = new Float64Array(n * n);
        const imag = new Float64Array(n * n);
        for (let j = 0; j < n; j++) {
          for (let i = 0; i < n; i++) {
            // Values rounded to float32 first, as the FFT stores them, so only its arithmetic differs.
            real[j * n + i] = Math.fround(random.nextNormal());
            imag[j * n + i] = Math.fround(random.nextNormal());
            fft.inputReal[fft.inputIndex(f, i, j)] = real[j * n + i];
            fft.inputImag[fft.inputIndex(f, i, j)] = imag[j * n + i];
          }
        }
        inputs.push([real, imag]);
      }
      fft.run();
      for (let f = 0; f < fields; f++) {
        const [expectedReal, expectedImag] = naiveInverseDft2D(inputs[f][0], inputs[f][1], n);
        let maxError = 0;
        let sumSquares = 0;
        for (let j = 0; j < n; j++) {
          for (let i = 0; i < n; i++) {
            const at = fft.outputIndex(f, i, j);
            maxError = Math.max(
              maxError,
              Math.abs(fft.outputReal[at] - expectedReal[j * n + i]),
              Math.abs(fft.outputImag[at] - expectedImag[j * n + i]),
            );
            sumSquares += expectedReal[j * n + i] ** 2 + expectedImag[j * n + i] ** 2;
          }
        }
        const rms = Math.sqrt(sumSquares / (2 * n * n));
        // float32 storage between 2·log2(N) stages: the error grows like ε32·√(log N) ≈ 1e-7·RMS;
        // 1e-5·RMS leaves margin yet catches any wrong twiddle, ordering or sign (errors ~RMS).
        expect(maxError / rms).toBeLessThan(1e-5);
      }
    });
  }

  it('rejects a size that is not a power of two', () => {
    expect(() => new BatchedInverseFft2D(12, 1)).toThrow(/power of two/);
  });
});
