/**
 * The whitecap foam field in a WebGPU compute shader, from the wave layers' field textures as the
 * GPU holds them (the compute FFT's, src/fft/computeWaveFields.ts): the FoamProducer of
 * src/layers/whitecapFoam.ts for the WebGPU Ocean's path 'gpu', so that no field is read back and
 * no JS FFT runs for the foam. The TSL twin of shaders/foam/whitecapFoam.frag (the WebGL GPU path's
 * pass), whose model and sources are in src/layers/foamModel.ts:
 *   J = (1 + λ·ΣDx,x)(1 + λ·ΣDz,z) − (λ·ΣDx,z)²   over every layer (Tessendorf 2001 §4.6)
 *   C = clamp((J_START − J) / (J_START − J_FULL), 0, 1)
 *   F ← min(1, F·decay + gain·C),   decay = e^{−Δt/τ}, gain = R·τ·(1 − decay)
 * each layer read at its texel nearest to the foam texel's point, floor(i·texelScale + ½) mod N in
 * float32, as foamModel.ts' nearestTexels picks it.
 *
 * The coverage lives in a storage buffer, one float per texel, which each invocation reads and
 * rewrites at its own texel (so no ping-pong), and is also stored into an R32F storage texture that
 * the surface samples, mipmapped by three before it is sampled, as the fields are. Owns the buffer,
 * the texture and the kernel; dispose() frees them.
 */
import { RedFormat, type Texture } from 'three';
import { StorageBufferAttribute, type StorageTexture, type ComputeNode, type TextureNode, type WebGPURenderer } from 'three/webgpu';
import { clamp, float, floor, Fn, instanceIndex, ivec2, min, storage, textureLoad, textureStore, uint, uniform, uvec2, vec3, vec4 } from 'three/tsl';
import { periodicStorageTexture } from '../fft/computeWaveFields';
import { foamStep, type FoamCalibration } from '../layers/foamModel';
import type { FoamProducer } from '../layers/whitecapFoam';
import type { LayerFrame, WaveLayer } from '../layers/waveLayer';
import { UnsupportedError } from '../parameters/options';

/** Invocations per workgroup: one per foam texel. */
const WORKGROUP = 64;

export class ComputeFoam implements FoamProducer {
  readonly texture: { value: Texture | null };
  /** The coverage per texel, row by row (M² floats). */
  readonly coverage: StorageBufferAttribute;
  private readonly foamTexture: StorageTexture;
  /** The layers' textures as the kernel reads them, set to those the layers show at each step. */
  private readonly layerTextures: { displacement: TextureNode; derivatives: TextureNode }[];
  private readonly settings = { choppiness: uniform(1), jacobianStart: uniform(0), jacobianFull: uniform(-1), decay: uniform(1), gain: uniform(0) };
  private readonly kernel: ComputeNode;

  /** `layers`: the sea's periodic layers (WhitecapFoam's), `frame`: the foam's (the largest layer's patch). */
  constructor(
    private readonly renderer: WebGPURenderer,
    layers: readonly WaveLayer[],
    frame: LayerFrame,
  ) {
    const m = frame.resolution;
    this.coverage = new StorageBufferAttribute(new Float32Array(m * m), 1);
    const texture = (this.foamTexture = periodicStorageTexture(m, 'foam', RedFormat));
    this.texture = { value: texture };
    this.layerTextures = layers.map((layer) => ({
      displacement: textureLoad(layerTexture(layer, 'displacement')),
      derivatives: textureLoad(layerTexture(layer, 'derivatives')),
    }));
    const coverage = storage(this.coverage, 'float', m * m);
    const { choppiness, jacobianStart, jacobianFull, decay, gain } = this.settings;
    const step = Fn(() => {
      const texel = uvec2(instanceIndex.mod(uint(m)), instanceIndex.div(uint(m)));
      const terms = vec3(0).toVar(); // Σ (Dx,x, Dz,z, Dx,z)
      layers.forEach((layer, i) => {
        const n = layer.frame.resolution;
        // The layer's texels per foam texel, in float32 as nearestTexels (foamModel.ts) computes it.
        const scale = Math.fround((frame.size * n) / (m * layer.frame.size));
        const at = ivec2(uvec2(floor(texel.toVec2().mul(float(scale)).add(0.5))).mod(uint(n)));
        const { displacement, derivatives } = this.layerTextures[i];
        terms.addAssign(vec3(derivatives.load(at).zw, displacement.load(at).w)); // level 0
      });
      const jacobian = choppiness.mul(terms.x).add(1).mul(choppiness.mul(terms.y).add(1)).sub(choppiness.mul(terms.z).pow2());
      const folding = clamp(jacobianStart.sub(jacobian).div(jacobianStart.sub(jacobianFull)), 0, 1);
      const foam = coverage.element(instanceIndex);
      const next = min(1, foam.mul(decay).add(gain.mul(folding))).toVar();
      foam.assign(next);
      textureStore(texture, texel, vec4(next, 0, 0, 1));
    });
    this.kernel = step().compute(m * m, [WORKGROUP]);
  }

  clear(): void {
    this.run(1, { jacobianStart: 0, jacobianFull: -1 }, 0, 0);
  }

  step(layers: readonly WaveLayer[], time: number | null, choppiness: number, calibration: FoamCalibration, rate: number, persistence: number, dt: number): void {
    // A warm-up step: the layers at its time, computed on the GPU before the step reads them.
    if (time !== null) for (const layer of layers) layer.update(time, 0);
    layers.forEach((layer, i) => {
      this.layerTextures[i].displacement.value = layerTexture(layer, 'displacement');
      this.layerTextures[i].derivatives.value = layerTexture(layer, 'derivatives');
    });
    const { decay, gain } = foamStep(rate, persistence, dt);
    this.run(choppiness, calibration, decay, gain);
  }

  /** The GPU's coverage is read back asynchronously: readCoverage(). */
  coverageOnCpu(): Float32Array {
    throw new UnsupportedError('coverageOnCpu', 'the compute foam is read back asynchronously, with readCoverage()');
  }

  /** The coverage per texel, row by row, read back after the steps queued so far. */
  async readCoverage(): Promise<Float32Array> {
    return new Float32Array(await this.renderer.getArrayBufferAsync(this.coverage));
  }

  dispose(): void {
    this.kernel.dispose();
    this.coverage.dispose();
    this.foamTexture.dispose();
  }

  private run(choppiness: number, { jacobianStart, jacobianFull }: Pick<FoamCalibration, 'jacobianStart' | 'jacobianFull'>, decay: number, gain: number): void {
    const settings = this.settings;
    settings.choppiness.value = choppiness;
    settings.jacobianStart.value = jacobianStart;
    settings.jacobianFull.value = jacobianFull;
    settings.decay.value = decay;
    settings.gain.value = gain;
    void this.renderer.compute(this.kernel);
  }
}

/** A layer's field texture; a layer without one (none yet) is refused. */
function layerTexture(layer: WaveLayer, name: 'displacement' | 'derivatives'): Texture {
  const texture = layer.textures[name].value;
  if (texture === null) throw new UnsupportedError('layer', `the compute foam reads every layer's ${name} texture, and this layer has none`);
  return texture;
}
