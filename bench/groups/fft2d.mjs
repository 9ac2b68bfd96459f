// A group of `npm run bench` (bench/run.mjs):
//
//   fft2d        BatchedInverseFft2D(N, 1).run() in Node ("js"), and the same inverse 2D complex
//                transform with fft.js row–column ("fft.js"), runs interleaved; fft2d-ratio rows
//                give jsSpeedup = fft.js ms / js ms.
import FFT from 'fft.js';
import { emit, log } from '../lib/output.mjs';
import { SIZES } from '../lib/settings.mjs';
import { ratio, stats, timeInterleaved } from '../lib/stats.mjs';

/** A deterministic pseudo-random complex N×N matrix, index j·N + i (row j = z, column i = x). */
function randomMatrix(n, seed) {
  let state = seed >>> 0;
  const next = () => {
    state = (Math.imul(state, 1664525) + 1013904223) >>> 0;
    return state / 2 ** 32 - 0.5;
  };
  const re = new Float64Array(n * n);
  const im = new Float64Array(n * n);
  for (let k = 0; k < n * n; k++) {
    re[k] = next();
    im[k] = next();
  }
  return { re, im };
}

/** BatchedInverseFft2D with one field, refilled from the matrix before every run. */
function jsFft2d(BatchedInverseFft2D, n, { re, im }) {
  const fft = new BatchedInverseFft2D(n, 1);
  const sourceRe = new Float32Array(fft.inputReal.length);
  const sourceIm = new Float32Array(fft.inputImag.length);
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      sourceRe[fft.inputIndex(0, i, j)] = re[j * n + i];
      sourceIm[fft.inputIndex(0, i, j)] = im[j * n + i];
    }
  }
  return {
    prepare() {
      fft.inputReal.set(sourceRe);
      fft.inputImag.set(sourceIm);
    },
    run: () => fft.run(),
    /** Output (re, im) at column i, row j. */
    value: (i, j) => [fft.outputReal[fft.outputIndex(0, i, j)], fft.outputImag[fft.outputIndex(0, i, j)]],
  };
}

/**
 * fft.js (radix-4, interleaved re/im arrays from createComplexArray), row–column: each row is
 * transformed into a second set of rows, then each column is copied out, transformed and copied
 * back. fft.js's inverseTransform divides by N, so its result is ours / N².
 */
function fftJs2d(n, { re, im }) {
  const fft = new FFT(n);
  const rows = Array.from({ length: n }, () => fft.createComplexArray());
  const transformed = Array.from({ length: n }, () => fft.createComplexArray());
  const column = fft.createComplexArray();
  const columnOut = fft.createComplexArray();
  return {
    prepare() {
      for (let j = 0; j < n; j++) {
        const row = rows[j];
        for (let i = 0; i < n; i++) {
          row[2 * i] = re[j * n + i];
          row[2 * i + 1] = im[j * n + i];
        }
      }
    },
    run() {
      for (let j = 0; j < n; j++) fft.inverseTransform(transformed[j], rows[j]);
      for (let i = 0; i < n; i++) {
        const r = 2 * i;
        for (let j = 0; j < n; j++) {
          column[2 * j] = transformed[j][r];
          column[2 * j + 1] = transformed[j][r + 1];
        }
        fft.inverseTransform(columnOut, column);
        for (let j = 0; j < n; j++) {
          transformed[j][r] = columnOut[2 * j];
          transformed[j][r + 1] = columnOut[2 * j + 1];
        }
      }
    },
    value: (i, j) => [transformed[j][2 * i] * n * n, transformed[j][2 * i + 1] * n * n],
  };
}

/** max |a − b| / rms(a) over the whole matrix: both implementations compute the same transform. */
function relativeDifference(n, a, b) {
  let maxError = 0;
  let sumSquares = 0;
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      const [ar, ai] = a.value(i, j);
      const [br, bi] = b.value(i, j);
      maxError = Math.max(maxError, Math.hypot(ar - br, ai - bi));
      sumSquares += ar * ar + ai * ai;
    }
  }
  return maxError / Math.sqrt(sumSquares / (n * n));
}

/** The fft2d and fft2d-ratio rows, in Node; `server` loads the sources (ssrLoadModule). */
export async function node({ server, results }) {
  const { BatchedInverseFft2D } = await server.ssrLoadModule('/src/fft/fft.ts');
  for (const n of SIZES) {
    log(`fft2d N=${n}: js vs fft.js`);
    const matrix = randomMatrix(n, n);
    const js = jsFft2d(BatchedInverseFft2D, n, matrix);
    const other = fftJs2d(n, matrix);
    js.prepare();
    js.run();
    other.prepare();
    other.run();
    const difference = relativeDifference(n, js, other);
    const [jsSamples, otherSamples] = timeInterleaved([js, other], 2000);
    const jsStats = stats(jsSamples);
    const otherStats = stats(otherSamples);
    const speedup = ratio(otherStats.ms, jsStats.ms);
    results.fftSpeedup[n] = speedup;
    emit({ bench: 'fft2d', N: n, path: 'js', ...jsStats });
    emit({ bench: 'fft2d', N: n, path: 'fft.js', ...otherStats });
    emit({ bench: 'fft2d-ratio', N: n, jsSpeedup: speedup, maxRelDiff: Number(difference.toPrecision(3)) });
  }
}
