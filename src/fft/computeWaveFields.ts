/**
 * An FFT cascade's fields on WebGPURenderer's WebGPU backend, from the compute FFT
 * (computeFft.ts): the spectrum is evolved in JS (CpuWaveFields.spectraAt, the JS path's own
 * code), uploaded, transformed in compute shaders, and written by one more dispatch into the two
 * field textures of waveFieldLayout.ts, RGBA32F storage textures that three mipmaps before they
 * are sampled. The fields stay on the GPU: the queries compute their own (cpuFields is null).
 * Owns the FFT, the textures and the copying dispatch; dispose() frees them.
 */
import { FloatType, LinearFilter, LinearMipmapLinearFilter, RepeatWrapping } from 'three';
import { StorageTexture, type ComputeNode, type WebGPURenderer } from 'three/webgpu';
import { Fn, instanceIndex, textureStore, uint, uvec2, vec4 } from 'three/tsl';
import { ComputeInverseFft2D } from './computeFft';
import { CpuWaveFields } from './cpuWaveFields';
import type { FftFieldSource } from './fieldSource';
import type { InitialSpectrum } from '../spectrum/initialSpectrum';
import type { LayerFieldsOnCpu } from '../layers/waveLayer';
import { FIELD_TEXTURES } from './waveFieldLayout';

/** The packed spectra, two per field texture (waveFieldLayout.ts). */
const PACKED_SPECTRA = 2 * FIELD_TEXTURES.length;
/** Invocations per workgroup of the copy into the textures. */
const COPY_WORKGROUP = 64;

export class ComputeWaveFields implements FftFieldSource {
  readonly displacement: StorageTexture;
  readonly derivatives: StorageTexture;
  /** No fragment passes: three compute dispatches (the FFT's two and the copy). */
  readonly passCount = 0;
  /** No worker (the spectrum is evolved on the main thread), and no fields on the CPU: the queries compute their own. */
  readonly workerFault = null;
  readonly cpuFields = null;
  private readonly spectra: CpuWaveFields;
  private readonly fft: ComputeInverseFft2D;
  /** For each element of the FFT's buffer (field f, row j, column i, in that order), where it is in the spectra's input. */
  private readonly places: Uint32Array;
  private readonly copy: ComputeNode;

  constructor(
    private readonly renderer: WebGPURenderer,
    spectrum: InitialSpectrum,
  ) {
    const n = spectrum.resolution;
    this.spectra = new CpuWaveFields(spectrum);
    this.fft = new ComputeInverseFft2D(renderer, n, PACKED_SPECTRA);
    const input = this.spectra.spectraAt(0);
    this.places = new Uint32Array(PACKED_SPECTRA * n * n);
    for (let f = 0, p = 0; f < PACKED_SPECTRA; f++) {
      for (let j = 0; j < n; j++) {
        for (let i = 0; i < n; i++, p++) this.places[p] = input.inputIndex(f, i, j);
      }
    }
    [this.displacement, this.derivatives] = FIELD_TEXTURES.map((name) => fieldTexture(n, name));
    const fields = this.fft.fields;
    const copy = Fn(() => {
      const texel = uvec2(instanceIndex.bitAnd(uint(n - 1)), instanceIndex.div(uint(n)));
      [this.displacement, this.derivatives].forEach((texture, t) => {
        // Packed spectra 2t and 2t + 1 (each f + i·g, two real fields) make texture t's four channels.
        const first = fields.element(instanceIndex.add(uint(2 * t * n * n)));
        const second = fields.element(instanceIndex.add(uint((2 * t + 1) * n * n)));
        textureStore(texture, texel, vec4(first, second));
      });
    });
    this.copy = copy().compute(n * n, [COPY_WORKGROUP]);
  }

  shownFieldsOnCpu(): LayerFieldsOnCpu | null {
    return null;
  }

  update(t: number): void {
    const input = this.spectra.spectraAt(t);
    const { inputReal: re, inputImag: im } = input;
    const data = this.fft.data.array as Float32Array;
    const places = this.places;
    for (let p = 0; p < places.length; p++) {
      data[2 * p] = re[places[p]];
      data[2 * p + 1] = im[places[p]];
    }
    this.fft.data.needsUpdate = true;
    this.fft.run();
    void this.renderer.compute(this.copy);
  }

  dispose(): void {
    this.fft.dispose();
    this.copy.dispose();
    this.displacement.dispose();
    this.derivatives.dispose();
  }
}

/** An RGBA32F storage texture of N×N that repeats and is sampled with mipmaps, as the JS path's field textures are. */
function fieldTexture(n: number, name: string): StorageTexture {
  const texture = new StorageTexture(n, n);
  texture.name = name;
  texture.type = FloatType;
  texture.wrapS = texture.wrapT = RepeatWrapping;
  texture.magFilter = LinearFilter;
  texture.minFilter = LinearMipmapLinearFilter;
  texture.generateMipmaps = true;
  return texture;
}
