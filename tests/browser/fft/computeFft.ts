/**
 * Test page for the compute FFT (src/fft/computeFft.ts) on a real WebGPURenderer's WebGPU backend,
 * driven by tests/browser/fft/computeFft.spec.ts: its output against the JS FFT (src/fft/fft.ts)
 * and against exact answers (the term-by-term DFT, a plane wave), as errors relative to the RMS.
 */
import { PerspectiveCamera, Scene } from 'three';
import { RenderTarget, WebGPURenderer, type StorageTexture } from 'three/webgpu';
import { Ocean } from '../../../src/webgpu/index';
import { ComputeInverseFft2D } from '../../../src/fft/computeFft';
import { BatchedInverseFft2D } from '../../../src/fft/fft';
import { ComputeWaveFields } from '../../../src/fft/computeWaveFields';
import { ComputeSpectrumEvolution } from '../../../src/fft/computeSpectrum';
import { CpuWaveFields } from '../../../src/fft/cpuWaveFields';
import { FIELD_TEXTURES } from '../../../src/fft/waveFieldLayout';
import { validateParameters } from '../../../src/parameters/parameters';
import { createCascadeSpectra } from '../../../src/spectrum/initialSpectrum';
import { CpuFieldTextures } from '../../../src/fft/cpuFieldTextures';
import { FftCascade, type FftBackend } from '../../../src/layers/fftCascade';
import { orderLayers } from '../../../src/layers/waveLayer';
import { WhitecapFoam } from '../../../src/layers/whitecapFoam';
import { calibrateFoam, jacobianCovariance } from '../../../src/layers/foamModel';
import { ComputeFoam } from '../../../src/webgpu/computeFoam';
import { SeededRandom } from '../../../src/spectrum/random';
import { naiveInverseDft2D } from '../../unit/naiveDft';
import { foamDifference } from '../shared/foamDifference';

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
  return fieldsFrom(n, fft.outputReal, fft.outputImag, (f, i, j) => fft.outputIndex(f, i, j));
}

/** Complex fields held as the JS FFT holds them (real and imaginary parts, field f's texel (i, j) at `index`), in the compute FFT's layout. */
function fieldsFrom(n: number, real: Float64Array | Float32Array, imaginary: Float64Array | Float32Array, index: (f: number, i: number, j: number) => number): Fields {
  const fields = new Float64Array(2 * FIELDS * n * n);
  for (let f = 0; f < FIELDS; f++) {
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const at = 2 * ((f * n + j) * n + i);
        fields[at] = real[index(f, i, j)];
        fields[at + 1] = imaginary[index(f, i, j)];
      }
    }
  }
  return fields;
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

/** A sea's cascades on one backend and their whitecap foam, stepped together as the WebGPU Ocean steps them. */
function foamedSea(params: ReturnType<typeof validateParameters>, backend: FftBackend<null>, foamPath: ConstructorParameters<typeof WhitecapFoam>[1]) {
  const spectra = createCascadeSpectra(params);
  const cascades = spectra.map((spectrum, cascade) => new FftCascade(null, spectrum, { params, cascade }, backend, false));
  const foam = new WhitecapFoam(orderLayers(cascades), foamPath);
  const settings = { choppiness: params.choppiness, calibration: calibrateFoam(jacobianCovariance(spectra), params.choppiness, params.windSpeed), amount: params.foamAmount, persistence: params.foamPersistence };
  let last = NaN;
  return {
    foam,
    update(t: number): void {
      for (const cascade of cascades) cascade.update(t, Number.isNaN(last) ? 0 : t - last);
      foam.update(t, settings);
      last = t;
    },
    dispose(): void {
      for (const cascade of cascades) cascade.dispose();
      foam.dispose();
    },
  };
}

/** Calls of the JS FFT (BatchedInverseFft2D's run and runToTexels) on this thread while `during` runs. */
function jsFftCalls(during: () => void): number {
  const prototype = BatchedInverseFft2D.prototype;
  const { run, runToTexels } = prototype;
  let calls = 0;
  prototype.run = function (this: BatchedInverseFft2D) {
    calls++;
    run.call(this);
  };
  prototype.runToTexels = function (this: BatchedInverseFft2D, texels: readonly Float32Array[]) {
    calls++;
    runToTexels.call(this, texels);
  };
  try {
    during();
  } finally {
    Object.assign(prototype, { run, runToTexels });
  }
  return calls;
}

const harness = {
  open,
  /**
   * The whitecap foam of path 'gpu' (ComputeFoam, from the compute FFT's fields) against the JS
   * path's (JsFoam, from the JS FFT's fields) after each time in turn (the first a jump, so a
   * warm-up): the mean JS coverage and the largest difference of any texel. `changes`: the sea.
   */
  async foamPaths(changes: Record<string, number>, times: number[]): Promise<{ meanCoverage: number; maxDifference: number }[]> {
    const params = validateParameters(changes);
    let computeFoam: ComputeFoam | null = null;
    const gpu = foamedSea(params, (_none, spectrum) => new ComputeWaveFields(renderer!, spectrum), { producer: (layers, frame) => (computeFoam = new ComputeFoam(renderer!, layers, frame)) });
    const support = { filterable: true, renderable: false };
    const js = foamedSea(params, (_none, spectrum) => new CpuFieldTextures(support, spectrum, false), { js: support });
    try {
      const results: { meanCoverage: number; maxDifference: number }[] = [];
      for (const t of times) {
        gpu.update(t);
        js.update(t);
        results.push(foamDifference(js.foam.coverageOnCpu(), await computeFoam!.readCoverage()));
      }
      return results;
    } finally {
      gpu.dispose();
      js.dispose();
    }
  },
  /**
   * Calls of the JS FFT on this thread over `frames` frame steps of the WebGPU Ocean (windSpeed 20,
   * whitecaps on, N = 64) after its first update, on `path`, with `worker` as given; no queries.
   */
  jsFftCallsPerFrames(path: 'gpu' | 'js', worker: boolean, frames: number): number {
    const ocean = new Ocean(renderer!, { resolution: 64, windSpeed: 20, seed: 3, worker, path });
    try {
      ocean.update(10);
      return jsFftCalls(() => {
        for (let frame = 1; frame <= frames; frame++) ocean.update(10 + frame / 60);
      });
    } finally {
      ocean.dispose();
    }
  },
  /**
   * The spectra the compute shader evolves (ComputeSpectrumEvolution, read back from the FFT's
   * buffer before any transform) against the JS path's (CpuWaveFields.spectraAt, in double
   * precision), at each time of `times`: per time, the largest relative RMS error of the four
   * packed spectra. Cascade `cascade` (0 the finest, −1 the largest) of a sea of resolution n in
   * water `depth` m deep.
   */
  async evolvedSpectra(n: number, times: number[], depth: number, cascade: number): Promise<number[]> {
    const spectrum = createCascadeSpectra(validateParameters({ resolution: n, windSpeed: 10, seed: 3, depth })).at(cascade)!;
    const fft = new ComputeInverseFft2D(renderer!, n, FIELDS);
    const evolution = new ComputeSpectrumEvolution(renderer!, spectrum, fft.fields);
    const js = new CpuWaveFields(spectrum);
    try {
      const errors: number[] = [];
      for (const t of times) {
        evolution.run(t);
        const evolved = Float64Array.from(new Float32Array(await renderer!.getArrayBufferAsync(fft.data)));
        const input = js.spectraAt(t);
        const expected = fieldsFrom(n, input.inputReal, input.inputImag, (f, i, j) => input.inputIndex(f, i, j));
        errors.push(Math.max(...relativeRmsErrors(n, FIELDS, evolved, expected)));
      }
      return errors;
    } finally {
      evolution.dispose();
      fft.dispose();
    }
  },
  /**
   * A cascade's fields at time t from the compute FFT (ComputeWaveFields, its textures read back)
   * against the JS path's (CpuWaveFields), for each field texture and channel: the largest RMS of
   * the difference over the RMS of the JS field. The first (finest) cascade of a sea of resolution n.
   */
  async cascadeFields(n: number, t: number): Promise<number> {
    const [spectrum] = createCascadeSpectra(validateParameters({ resolution: n, windSpeed: 10, seed: 3 }));
    const gpu = new ComputeWaveFields(renderer!, spectrum);
    try {
      gpu.update(t);
      const js = new CpuWaveFields(spectrum);
      js.update(t);
      let worst = 0;
      for (const name of FIELD_TEXTURES) {
        const backend = renderer!.backend as unknown as { copyTextureToBuffer(texture: StorageTexture, x: number, y: number, w: number, h: number, face: number): Promise<Float32Array> };
        const texels = await backend.copyTextureToBuffer(gpu[name], 0, 0, n, n, 0);
        for (let channel = 0; channel < 4; channel++) {
          let difference = 0;
          let magnitude = 0;
          for (let at = channel; at < 4 * n * n; at += 4) {
            difference += (texels[at] - js[name][at]) ** 2;
            magnitude += js[name][at] ** 2;
          }
          worst = Math.max(worst, Math.sqrt(difference / magnitude));
        }
      }
      return worst;
    } finally {
      gpu.dispose();
    }
  },
  /**
   * The WebGPU Ocean with path 'gpu' against path 'js' (the same small force 7 sea with its
   * whitecaps, N = 64, at time t): the mean difference of their pictures (160×90, 8-bit, in levels,
   * over RGB), the largest in any channel, the largest difference of heightAt at a few points (m),
   * and path 'gpu''s picture (RGBA rows, top first).
   */
  async oceanPaths(t: number): Promise<{ meanLevels: number; maxLevels: number; heights: number; picture: number[] }> {
    const camera = new PerspectiveCamera(60, 16 / 9, 0.5, 30_000);
    camera.position.set(0, 4, 0);
    camera.lookAt(0, 1, -40);
    camera.updateMatrixWorld();
    const target = new RenderTarget(160, 90);
    const pictures: Uint8Array[] = [];
    const heights: number[][] = [];
    for (const path of ['js', 'gpu'] as const) {
      const scene = new Scene();
      const ocean = new Ocean(renderer!, { resolution: 64, windSpeed: 15, seed: 3, worker: false, path });
      scene.add(ocean);
      ocean.update(t);
      renderer!.setRenderTarget(target);
      renderer!.render(scene, camera);
      renderer!.setRenderTarget(null);
      pictures.push(new Uint8Array((await renderer!.readRenderTargetPixelsAsync(target, 0, 0, 160, 90)).buffer));
      heights.push([[0, 0], [3.3, -7.1], [-120, 45.5]].map(([x, z]) => ocean.heightAt(x, z)));
      ocean.dispose();
    }
    target.dispose();
    let sum = 0;
    let max = 0;
    for (let at = 0; at < pictures[0].length; at++) {
      if (at % 4 === 3) continue;
      const difference = Math.abs(pictures[0][at] - pictures[1][at]);
      sum += difference;
      max = Math.max(max, difference);
    }
    return { meanLevels: sum / ((3 / 4) * pictures[0].length), maxLevels: max, heights: Math.max(...heights[0].map((h, i) => Math.abs(h - heights[1][i]))), picture: Array.from(pictures[1]) };
  },
  /** The storage buffers and textures the renderer holds, and their bytes (three's renderer.info). */
  gpuMemory(): { storageBuffers: number; storageBytes: number; textures: number; textureBytes: number } {
    const memory = renderer!.info.memory as unknown as { storageAttributes: number; storageAttributesSize: number; textures: number; texturesSize: number };
    return { storageBuffers: memory.storageAttributes, storageBytes: memory.storageAttributesSize, textures: memory.textures, textureBytes: memory.texturesSize };
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
