import { describe, expect, it } from 'vitest';
import { BatchedInverseFft2D } from '../../src/fft/fft';
import { ParameterError } from '../../src/parameters/options';
import { SeededRandom } from '../../src/spectrum/random';
import { naiveInverseDft2D } from './naiveDft';

type Complex2D = [Float64Array, Float64Array];

/** `fields` random complex N×N spectra (row-major, index j·N + i), written into the FFT's input. */
function randomInputs(fft: BatchedInverseFft2D, seed: number): Complex2D[] {
  const n = fft.size;
  const random = new SeededRandom(seed);
  const inputs: Complex2D[] = [];
  for (let f = 0; f < fft.fieldCount; f++) {
    const real = new Float64Array(n * n);
    const imag = new Float64Array(n * n);
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        // Values rounded to float32 first, as the FFT's callers store them, so only its arithmetic differs.
        real[j * n + i] = Math.fround(random.nextNormal());
        imag[j * n + i] = Math.fround(random.nextNormal());
        fft.inputReal[fft.inputIndex(f, i, j)] = real[j * n + i];
        fft.inputImag[fft.inputIndex(f, i, j)] = imag[j * n + i];
      }
    }
    inputs.push([real, imag]);
  }
  return inputs;
}

/** max |FFT − expected| / RMS(expected) over field f. */
function relativeError(fft: BatchedInverseFft2D, f: number, [expectedReal, expectedImag]: Complex2D): number {
  const n = fft.size;
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
  return maxError / Math.sqrt(sumSquares / (2 * n * n));
}

/**
 * The inverse 2D DFT as N 1D DFTs along x and then N along z, each evaluated term by term in double
 * precision (O(N³), so larger grids than naiveInverseDft2D's O(N⁴) are affordable).
 */
function rowColumnInverseDft2D([real, imag]: Complex2D, n: number): Complex2D {
  const cos = Float64Array.from({ length: n }, (_, k) => Math.cos((2 * Math.PI * k) / n));
  const sin = Float64Array.from({ length: n }, (_, k) => Math.sin((2 * Math.PI * k) / n));
  const transform = ([re, im]: Complex2D, step: number, along: number): Complex2D => {
    // 1D transforms over index·step within each line, lines `along` apart.
    const outRe = new Float64Array(n * n);
    const outIm = new Float64Array(n * n);
    for (let line = 0; line < n; line++) {
      for (let k = 0; k < n; k++) {
        let sumRe = 0;
        let sumIm = 0;
        for (let m = 0; m < n; m++) {
          const at = line * along + m * step;
          const phase = (k * m) % n;
          sumRe += re[at] * cos[phase] - im[at] * sin[phase];
          sumIm += re[at] * sin[phase] + im[at] * cos[phase];
        }
        outRe[line * along + k * step] = sumRe;
        outIm[line * along + k * step] = sumIm;
      }
    }
    return [outRe, outIm];
  };
  return transform(transform([real, imag], 1, n), n, 1);
}

describe('BatchedInverseFft2D', () => {
  // N = 2, 4 and 8 are a single radix-2, radix-4 and radix-8 step; 16 and 32 add a radix-4 step.
  for (const n of [2, 4, 8, 16, 32]) {
    it(`matches the naive inverse DFT at N = ${n} for 3 random complex fields at once`, () => {
      const fft = new BatchedInverseFft2D(n, 3);
      const inputs = randomInputs(fft, 100 + n);
      fft.run();
      for (let f = 0; f < fft.fieldCount; f++) {
        // Both compute in double from the same float32-rounded input, so they differ by rounding
        // only (observed ≤ 1e-14·RMS, mostly the naive sums'). 1e-12 leaves margin yet catches any
        // wrong twiddle, ordering or sign (errors ~RMS) and any float32 intermediate (~1e-7).
        expect(relativeError(fft, f, naiveInverseDft2D(inputs[f][0], inputs[f][1], n))).toBeLessThan(1e-12);
      }
    });
  }

  // Larger grids take the other loop orders of pass 2 (runs along the row) and more radix-4 steps.
  for (const n of [64, 128]) {
    it(`matches a row–column DFT at N = ${n} for 2 random complex fields at once`, () => {
      const fft = new BatchedInverseFft2D(n, 2);
      const inputs = randomInputs(fft, 200 + n);
      fft.run();
      for (let f = 0; f < fft.fieldCount; f++) {
        expect(relativeError(fft, f, rowColumnInverseDft2D(inputs[f], n))).toBeLessThan(1e-12);
      }
    });
  }

  for (const n of [16, 32, 64]) {
    it(`runToTexels writes what run() computes, as RGBA texels of field pairs (N = ${n})`, () => {
      const fields = new BatchedInverseFft2D(n, 4);
      const texels = new BatchedInverseFft2D(n, 4);
      randomInputs(fields, 300 + n);
      randomInputs(texels, 300 + n);
      fields.run();
      const arrays = [new Float32Array(4 * n * n), new Float32Array(4 * n * n)];
      texels.runToTexels(arrays);
      let maxDifference = 0;
      for (let j = 0; j < n; j++) {
        for (let i = 0; i < n; i++) {
          for (let f = 0; f < 4; f++) {
            const at = fields.outputIndex(f, i, j);
            const texel = 4 * (j * n + i) + 2 * (f % 2);
            const array = arrays[f >> 1];
            // The same butterflies in the same order, then rounded to float32: identical.
            maxDifference = Math.max(
              maxDifference,
              Math.abs(array[texel] - Math.fround(fields.outputReal[at])),
              Math.abs(array[texel + 1] - Math.fround(fields.outputImag[at])),
            );
          }
        }
      }
      expect(maxDifference).toBe(0);
    });
  }

  it('runToTexels rejects a grid below 16 or a wrong number of texel arrays', () => {
    expect(() => new BatchedInverseFft2D(8, 4).runToTexels([new Float32Array(256), new Float32Array(256)])).toThrow(
      /N ≥ 16/,
    );
    expect(() => new BatchedInverseFft2D(16, 4).runToTexels([new Float32Array(1024)])).toThrow(/N ≥ 16/);
  });

  // A band of 3, 7 and 15 of N = 64 lets pass 1 transform every 16th, 8th and 4th column and the
  // one before it; 31 none (BatchedInverseFft2D's inputBand).
  for (const band of [3, 7, 15, 31]) {
    it(`matches a row–column DFT at N = 64 when only frequencies up to ${band} are given (inputBand)`, () => {
      const n = 64;
      const fft = new BatchedInverseFft2D(n, 2, band);
      const inputs = randomInputs(fft, 400 + band);
      const outside = (index: number) => Math.min(index, n - index) > band;
      for (let f = 0; f < fft.fieldCount; f++) {
        for (let j = 0; j < n; j++) {
          for (let i = 0; i < n; i++) {
            if (!outside(i) && !outside(j)) continue;
            inputs[f][0][j * n + i] = inputs[f][1][j * n + i] = 0;
            fft.inputReal[fft.inputIndex(f, i, j)] = fft.inputImag[fft.inputIndex(f, i, j)] = 0;
          }
        }
      }
      fft.run();
      for (let f = 0; f < fft.fieldCount; f++) {
        expect(relativeError(fft, f, rowColumnInverseDft2D(inputs[f], n))).toBeLessThan(1e-12);
      }
    });
  }

  it('skips the columns beyond inputBand: a coefficient there is ignored, as promised zero', () => {
    const n = 64;
    const banded = new BatchedInverseFft2D(n, 1, 7);
    const full = new BatchedInverseFft2D(n, 1);
    // Frequency (9, 0), beyond the band of 7, is a wave along x, the same on every row. Its column
    // is not transformed along z, so in the banded transform it reaches row 0 only.
    for (const fft of [banded, full]) fft.inputReal[fft.inputIndex(0, 9, 0)] = 1;
    banded.run();
    full.run();
    expect(full.outputReal[full.outputIndex(0, 0, 5)]).toBeCloseTo(1, 12);
    expect(banded.outputReal[banded.outputIndex(0, 0, 5)]).toBe(0);
  });

  it('rejects a size that is not a power of two', () => {
    expect(() => new BatchedInverseFft2D(12, 1)).toThrow(/power of two/);
    expect(() => new BatchedInverseFft2D(12, 1)).toThrow(ParameterError);
  });
});
