/**
 * Test page for the simulation core: runs the real GPU path in this page's WebGL2 context and the
 * JS path beside it, and hands the Playwright tests summaries (errors relative to RMS) rather than
 * whole fields.
 */
import { WebGLRenderer, type WebGLRenderTarget } from 'three';
import { CpuWaveFields } from '../../../src/sim/cpuWaveFields';
import { GpuWaveFields, supportedGpuPrecision, type GpuPrecision } from '../../../src/sim/gpuWaveFields';
import { validateParameters, type SimulationParameters } from '../../../src/sim/parameters';
import { createInitialSpectrum } from '../../../src/sim/spectrum';

const renderer = new WebGLRenderer({ canvas: document.createElement('canvas') });

/** Per channel of one RGBA field texture: max |gpu − js| / rms(js), and rms(js). */
export interface ChannelComparison {
  relativeMaxError: number;
  rms: number;
}

function readTarget(target: WebGLRenderTarget, textureIndex: number, n: number, precision: GpuPrecision): Float32Array {
  if (precision === 'float32') {
    const pixels = new Float32Array(4 * n * n);
    renderer.readRenderTargetPixels(target, 0, 0, n, n, pixels, undefined, textureIndex);
    return pixels;
  }
  const halves = new Uint16Array(4 * n * n);
  renderer.readRenderTargetPixels(target, 0, 0, n, n, halves, undefined, textureIndex);
  return Float32Array.from(halves, halfToFloat);
}

function halfToFloat(h: number): number {
  const exponent = (h >> 10) & 0x1f;
  const mantissa = h & 0x3ff;
  const sign = h & 0x8000 ? -1 : 1;
  if (exponent === 0) return sign * mantissa * 2 ** -24;
  if (exponent === 31) return mantissa ? NaN : sign * Infinity;
  return sign * (1 + mantissa / 1024) * 2 ** (exponent - 15);
}

function compareChannels(gpu: Float32Array, js: Float32Array): ChannelComparison[] {
  const result: ChannelComparison[] = [];
  for (let c = 0; c < 4; c++) {
    let maxError = 0;
    let sumSquares = 0;
    let count = 0;
    for (let i = c; i < js.length; i += 4, count++) {
      const error = Math.abs(gpu[i] - js[i]);
      // NaN must fail the comparison, not vanish in Math.max.
      maxError = Number.isNaN(error) ? Infinity : Math.max(maxError, error);
      sumSquares += js[i] * js[i];
    }
    const rms = Math.sqrt(sumSquares / count);
    result.push({ relativeMaxError: maxError / rms, rms });
  }
  return result;
}

const harness = {
  supportedPrecision: () => supportedGpuPrecision(renderer),

  /** GPU fields against JS fields for the given parameters at each time. */
  compareGpuWithJs(
    changes: Partial<SimulationParameters>,
    times: number[],
    precision: GpuPrecision = 'float32',
  ): { passCount: number; results: { t: number; displacement: ChannelComparison[]; derivatives: ChannelComparison[] }[] } {
    const params = validateParameters(changes);
    const n = params.resolution;
    const spectrum = createInitialSpectrum(params);
    const gpu = new GpuWaveFields(renderer, spectrum, params.choppiness, params.repeatPeriod, precision);
    const js = new CpuWaveFields(spectrum, params.choppiness, params.repeatPeriod);
    const results = times.map((t) => {
      gpu.update(t);
      js.update(t);
      return {
        t,
        displacement: compareChannels(readTarget(gpu.output, 0, n, precision), js.displacement),
        derivatives: compareChannels(readTarget(gpu.output, 1, n, precision), js.derivatives),
      };
    });
    gpu.dispose();
    return { passCount: gpu.passCount, results };
  },

  /** Counts of non-finite values in the GPU fields (both textures) at time t. */
  gpuNonFiniteCount(changes: Partial<SimulationParameters>, t: number): number {
    const params = validateParameters(changes);
    const gpu = new GpuWaveFields(renderer, createInitialSpectrum(params), params.choppiness, params.repeatPeriod, 'float32');
    gpu.update(t);
    let count = 0;
    for (const index of [0, 1]) {
      for (const value of readTarget(gpu.output, index, params.resolution, 'float32')) if (!Number.isFinite(value)) count++;
    }
    gpu.dispose();
    return count;
  },

  /** The initial spectrum's amplitudes, as the bit patterns of their float32 values. */
  spectrumBits(changes: Partial<SimulationParameters>): number[] {
    const spectrum = createInitialSpectrum(validateParameters(changes));
    return Array.from(new Uint32Array(spectrum.amplitudes.buffer));
  },

  memory: () => ({ ...renderer.info.memory }),
};

declare global {
  interface Window {
    harness: typeof harness;
  }
}
window.harness = harness;
document.title = 'ready';
