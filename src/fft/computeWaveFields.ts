/**
 * An FFT cascade's fields on WebGPURenderer's WebGPU backend, all in compute shaders: the spectrum
 * is evolved into the compute FFT's buffer (computeSpectrum.ts; only the 4 KiB phase table is
 * uploaded per update), transformed (computeFft.ts), and written by one more dispatch into the two
 * field textures of waveFieldLayout.ts, RGBA32F storage textures that three mipmaps before they
 * are sampled. The fields stay on the GPU: the queries compute their own (cpuFields is null;
 * cascadeQueryFields.ts, a worker of their own), as on the WebGL GPU path.
 * Owns the evolution, the FFT, the textures and the copying dispatch; dispose() frees them.
 */
import { FloatType, LinearFilter, LinearMipmapLinearFilter, RedFormat, RepeatWrapping, RGBAFormat } from 'three';
import { StorageTexture, type ComputeNode, type WebGPURenderer } from 'three/webgpu';
import { Fn, instanceIndex, textureStore, uint, uvec2, vec4 } from 'three/tsl';
import { ComputeInverseFft2D } from './computeFft';
import { ComputeSpectrumEvolution } from './computeSpectrum';
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
  /** No fragment passes: four compute dispatches (the evolution, the FFT's two and the copy). */
  readonly passCount = 0;
  /** No worker, and no fields on the CPU: the queries compute their own. */
  readonly workerFault = null;
  readonly cpuFields = null;
  private readonly evolution: ComputeSpectrumEvolution;
  private readonly fft: ComputeInverseFft2D;
  private readonly copy: ComputeNode;

  constructor(
    private readonly renderer: WebGPURenderer,
    spectrum: InitialSpectrum,
  ) {
    const n = spectrum.resolution;
    this.fft = new ComputeInverseFft2D(renderer, n, PACKED_SPECTRA);
    this.evolution = new ComputeSpectrumEvolution(renderer, spectrum, this.fft.fields);
    [this.displacement, this.derivatives] = FIELD_TEXTURES.map((name) => periodicStorageTexture(n, name));
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

  /** Queues the fields at time t (s): the evolution, the FFT and the copy into the textures. */
  update(t: number): void {
    this.evolution.run(t);
    this.fft.run();
    void this.renderer.compute(this.copy);
  }

  dispose(): void {
    this.evolution.dispose();
    this.fft.dispose();
    this.copy.dispose();
    this.displacement.dispose();
    this.derivatives.dispose();
  }
}

/**
 * A float32 storage texture of N×N (RGBA, or red only) that repeats and is sampled with mipmaps, as
 * the JS path's field and foam textures are: the compute path's fields and foam (computeFoam.ts).
 */
export function periodicStorageTexture(n: number, name: string, format: typeof RGBAFormat | typeof RedFormat = RGBAFormat): StorageTexture {
  const texture = new StorageTexture(n, n);
  texture.name = name;
  texture.format = format;
  texture.type = FloatType;
  texture.wrapS = texture.wrapT = RepeatWrapping;
  texture.magFilter = LinearFilter;
  texture.minFilter = LinearMipmapLinearFilter;
  texture.generateMipmaps = true;
  return texture;
}
