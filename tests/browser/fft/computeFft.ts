/**
 * Test page for the compute FFT (src/fft/computeFft.ts) on a real WebGPURenderer's WebGPU backend,
 * driven by tests/browser/fft/computeFft.spec.ts: its output against the JS FFT (src/fft/fft.ts)
 * and against exact answers (the term-by-term DFT, a plane wave), as errors relative to the RMS.
 */
import { WebGPURenderer } from 'three/webgpu';
import { ComputeInverseFft2D } from '../../../src/fft/computeFft';
import { BatchedInverseFft2D } from '../../../src/fft/fft';
import { SeededRandom } from '../../../src/spectrum/random';
import { naiveInverseDft2D } from '../../unit/naiveDft';

/** The four packed spectra of waveFieldLayout.ts: as many complex fields as a cascade transforms. */
const FIELDS = 4;

/** Fields as (re, im) pairs, field f's texel (i, j) at 2·((f·N + j)·N + i): the compute FFT's layout. */
type Fields = Float64Array;

let renderer: WebGPURenderer | null = null;

/** A WebGPURenderer on the WebGPU backend, or why there is none. */
async function open(): Promise<string | null> {
  renderer = new WebGPURenderer();
  await renderer.init();
  if ((renderer.backend as { isWebGPUBackend?: boolean }).isWebGPUBackend !== true) {
    return navigator.gpu ? 'navigator.gpu has no adapter' : 'navigator.gpu is undefined (no --enable-unsafe-webgpu, or not a secure context)';
  }
  return null;
}

/** The compute FFT of `input` (read back after the transform). */
async function computeTransform(fft: ComputeInverseFft2D, input: Fields): Promise<Fields> {
  (fft.data.array as Float32Array).set(input);
  fft.data.needsUpdate = true;
  fft.run();
  return Float64Array.from(new Float32Array(await renderer!.getArrayBufferAsync(fft.data)));
}

/** The JS FFT of `input`, in double precision. */
function jsTransform(n: number, input: Fields): Fields {
  const fft = new BatchedInverseFft2D(n, FIELDS);
  const output = new Float64Array(input.length);
  for (let f = 0; f < FIELDS; f++) {
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const at = 2 * ((f * n + j) * n + i);
        fft.inputReal[fft.inputIndex(f, i, j)] = input[at];
        fft.inputImag[fft.inputIndex(f, i, j)] = input[at + 1];
      }
    }
  }
  fft.run();
  for (let f = 0; f < FIELDS; f++) {
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const at = 2 * ((f * n + j) * n + i);
        output[at] = fft.outputReal[fft.outputIndex(f, i, j)];
        output[at + 1] = fft.outputImag[fft.outputIndex(f, i, j)];
      }
    }
  }
  return output;
}

/** Per field of `count`, the RMS of (actual − expected) over the RMS of expected. */
function relativeRmsErrors(n: number, count: number, actual: Fields, expected: Fields): number[] {
  const errors: number[] = [];
  for (let f = 0; f < count; f++) {
    let difference = 0;
    let magnitude = 0;
    for (let at = 2 * f * n * n; at < 2 * (f + 1) * n * n; at++) {
      difference += (actual[at] - expected[at]) ** 2;
      magnitude += expected[at] ** 2;
    }
    errors.push(Math.sqrt(difference / magnitude));
  }
  return errors;
}

/**
 * Spectra for one transform of all the fields: standard normal numbers (float32 values, so that both
 * transforms see the same input) in every field but the last, which holds one coefficient, 1 at
 * frequency (kx, kz) = (3, 5), whose transform is the plane wave e^{2πi·(3i + 5j)/N}: the exact
 * answer for that field.
 */
function testFields(n: number, seed: number): { input: Fields; planeWave: Fields } {
  const random = new SeededRandom(seed);
  const input = Float64Array.from(new Float32Array(2 * FIELDS * n * n).map(() => random.nextNormal()));
  const last = 2 * (FIELDS - 1) * n * n;
  const [kx, kz] = [3, 5];
  input.fill(0, last);
  input[last + 2 * (kz * n + kx)] = 1;
  const planeWave = new Float64Array(2 * n * n);
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      const angle = (2 * Math.PI * ((i * kx + j * kz) % n)) / n;
      planeWave[2 * (j * n + i)] = Math.cos(angle);
      planeWave[2 * (j * n + i) + 1] = Math.sin(angle);
    }
  }
  return { input, planeWave };
}

/** The term-by-term DFT of every field of `input`. */
function naiveTransform(n: number, input: Fields): Fields {
  const output = new Float64Array(input.length);
  for (let f = 0; f < FIELDS; f++) {
    const field = input.subarray(2 * f * n * n, 2 * (f + 1) * n * n);
    const [re, im] = naiveInverseDft2D(field.filter((_, at) => at % 2 === 0), field.filter((_, at) => at % 2 === 1), n);
    for (let at = 0; at < n * n; at++) {
      output[2 * (f * n * n + at)] = re[at];
      output[2 * (f * n * n + at) + 1] = im[at];
    }
  }
  return output;
}

const harness = {
  open,
  /** The storage buffers the renderer holds, and their bytes (three's renderer.info). */
  storageBuffers(): { count: number; bytes: number } {
    const memory = renderer!.info.memory as unknown as { storageAttributes: number; storageAttributesSize: number };
    return { count: memory.storageAttributes, bytes: memory.storageAttributesSize };
  },
  /**
   * One compute FFT at size n of testFields(): the largest relative RMS error of the fields against
   * the JS FFT, the last field's against its exact plane wave, and, when `naive`, the largest against
   * the term-by-term DFT; and the time (ms) of the transform with its upload and read-back.
   */
  async compare(n: number, naive: boolean): Promise<{ js: number; planeWave: number; naive: number | null; ms: number }> {
    const fft = new ComputeInverseFft2D(renderer!, n, FIELDS);
    try {
      const { input, planeWave } = testFields(n, n);
      const start = performance.now();
      const output = await computeTransform(fft, input);
      const ms = performance.now() - start;
      return {
        js: Math.max(...relativeRmsErrors(n, FIELDS, output, jsTransform(n, input))),
        planeWave: relativeRmsErrors(n, 1, output.subarray(2 * (FIELDS - 1) * n * n), planeWave)[0],
        naive: naive ? Math.max(...relativeRmsErrors(n, FIELDS, output, naiveTransform(n, input))) : null,
        ms,
      };
    } finally {
      fft.dispose();
    }
  },
};

declare global {
  interface Window {
    computeFft: typeof harness;
  }
}
window.computeFft = harness;
document.title = 'ready';
