/**
 * The GPU simulation path: every field of waveFieldLayout.ts computed in fragment-shader passes
 * over float render targets (WebGL2 through three.js), with no CPU readback.
 *
 * Per update: one pass evolves the spectrum (four packed complex spectra) into the FFT engine's
 * working storage (gpuFft.ts; when log2 N is odd it also does the first radix-2 pass along x), the
 * engine transforms them (log4-many Stockham passes along x and as many along z), and a last pass
 * copies the fields into the output target, whose two textures (`displacement`, `derivatives`)
 * wrap with REPEAT and, where the format is filterable, filter linearly with mipmaps generated
 * after the pass.
 *
 * A coarse cascade keeps only its band's modes, a few per cent of the grid: the evolution pass and
 * the passes along x skip the lines (texel rows) that hold only zeros (the engine's band).
 *
 * Textures (RGBA unless said):
 *   amplitudes  N×N (h̃0(k), h̃0*(−k))            static, from initialSpectrum.ts
 *   waveVectors N×N (kx, kz, 1/k, m)             static, from initialSpectrum.ts
 *   phases      256×1, (e^{ijφ}, e^{i256jφ})     uploaded each update, from dispersion.ts
 *   output      N×N (displacement, derivatives)  the result
 * and the engine's twiddles and working storage. This object owns all of them (the engine) and
 * frees them in dispose().
 */
import { DataTexture, FloatType, NearestFilter, RGBAFormat, type PixelFormat, type Texture, type WebGLRenderTarget, type WebGLRenderer } from 'three';
import type { GpuPrecision, PassMaterial } from '../device/gpuDevice';
import { gpuSupport } from '../device/gpuSupport';
import type { WebGL2Device, WebGL2FieldTarget } from '../device/webgl2/webgl2Device';
import { createGpuDevice } from '../device/deviceFor';
import { shaderSource } from '../shaderSource';
import { fillPhaseTable, PHASE_TABLE_SIZE } from '../spectrum/dispersion';
import { largestFrequency, type InitialSpectrum } from '../spectrum/initialSpectrum';
import type { FftFieldSource } from './fieldSource';
import { GpuFft, type WorkingSet } from './gpuFft';
import { FIELD_TEXTURES } from './waveFieldLayout';

export type { GpuPrecision };

/** Which GPU precision this renderer can render to, best first; null when neither works (gpuSupport). */
export function supportedGpuPrecision(renderer: WebGLRenderer): GpuPrecision | null {
  const device = createGpuDevice(renderer);
  const { precision } = gpuSupport(device);
  device.dispose();
  return precision;
}

/** The working set the evolution pass writes. */
const EVOLVED: WorkingSet = 0;

export class GpuWaveFields implements FftFieldSource {
  /** (Dx, h, Dz, ∂Dx/∂z) */
  readonly displacement: Texture;
  /** (∂h/∂x, ∂h/∂z, ∂Dx/∂x, ∂Dz/∂z) */
  readonly derivatives: Texture;
  /** Fragment passes per update (evolution, FFT, copy to the output). */
  readonly passCount: number;
  /** No worker, and no fields on the CPU: the queries compute their own. */
  readonly workerFault = null;
  readonly cpuFields = null;

  private readonly amplitudes: DataTexture;
  private readonly waveVectors: DataTexture;
  private readonly phases: DataTexture;
  private readonly device: WebGL2Device;
  private readonly fft: GpuFft;
  private readonly fields: WebGL2FieldTarget;
  private readonly evolveMaterial: PassMaterial;
  private readonly unpackMaterial: PassMaterial;
  private readonly repeatPeriod: number;

  constructor(
    renderer: WebGLRenderer,
    spectrum: InitialSpectrum,
    readonly precision: GpuPrecision,
  ) {
    this.repeatPeriod = spectrum.repeatPeriod;
    const n = spectrum.resolution;
    const sizeLog2 = Math.log2(n);
    const device = (this.device = createGpuDevice(renderer));
    // A coarse cascade has modes only on the lines (z frequencies) of its band: the engine loads
    // and transforms along x only those lines. Made first: it throws if the device cannot render
    // to its layered framebuffer, before anything else is allocated.
    try {
      this.fft = new GpuFft(device, { size: n, precision, loadDoesFirstRadix2: true, band: largestFrequency(spectrum) });
    } catch (error) {
      device.dispose();
      throw error;
    }
    this.amplitudes = dataTexture(spectrum.amplitudes, n, n, RGBAFormat);
    this.waveVectors = dataTexture(spectrum.waveVectors, n, n, RGBAFormat);
    this.phases = dataTexture(new Float32Array(4 * PHASE_TABLE_SIZE), PHASE_TABLE_SIZE, 1, RGBAFormat);

    this.fields = device.createFieldTarget({ size: n, precision, count: 2, sampling: 'periodic' });
    [this.displacement, this.derivatives] = this.fields.textures;
    this.fields.textures.forEach((texture, i) => (texture.name = FIELD_TEXTURES[i]));

    const material = (fragmentShader: string, uniforms: Record<string, { value: unknown }>, defines = {}) =>
      device.passMaterial(shaderSource(fragmentShader), { sizeLog2: { value: sizeLog2 }, ...uniforms }, defines);
    this.evolveMaterial = material(
      'fft/evolveSpectrum.frag',
      {
        tAmplitudes: { value: this.amplitudes },
        tWaveVectors: { value: this.waveVectors },
        tPhases: { value: this.phases },
      },
      { FIRST_RADIX2: sizeLog2 % 2 },
    );
    const [result0, result1] = this.fft.sets[this.fft.resultOf(EVOLVED)].textures;
    this.unpackMaterial = material('fft/unpackFields.frag', { tSpectra0: { value: result0 }, tSpectra1: { value: result1 } });
    this.passCount = 2 + this.fft.passCount;
  }

  /** The render target of `displacement` and `derivatives` (its two textures), to read back. */
  get output(): WebGLRenderTarget {
    return this.fields.renderTarget;
  }

  /** Computes every field at time t (seconds) into `displacement` and `derivatives`. */
  update(t: number): void {
    fillPhaseTable(this.phases.image.data as Float32Array, t, this.repeatPeriod);
    this.phases.needsUpdate = true;
    this.device.runPasses(() => {
      this.fft.load(this.evolveMaterial, EVOLVED);
      this.fft.transform(EVOLVED);
      this.device.draw(this.unpackMaterial, this.fields);
    });
  }

  shownFieldsOnCpu(): null {
    return null;
  }

  dispose(): void {
    for (const texture of [this.amplitudes, this.waveVectors, this.phases]) texture.dispose();
    this.fft.dispose();
    this.fields.dispose();
    for (const material of [this.evolveMaterial, this.unpackMaterial]) material.dispose();
    this.device.dispose();
  }
}

function dataTexture(data: Float32Array, width: number, height: number, format: PixelFormat): DataTexture {
  const texture = new DataTexture(data, width, height, format, FloatType);
  texture.minFilter = NearestFilter;
  texture.magFilter = NearestFilter;
  texture.needsUpdate = true;
  return texture;
}
