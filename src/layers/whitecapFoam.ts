/**
 * The whitecap foam field (model and sources: foamModel.ts): coverage in [0, 1] per texel of the
 * largest periodic layer's patch, kept from frame to frame, on the GPU
 * (shaders/foam/whitecapFoam.frag, ping-pong between two float targets) or in JS (CpuFoamField,
 * uploaded as a DataTexture), the same path as the cascades; or by a FoamProducer given (the WebGPU
 * Ocean's compute shader, src/webgpu/computeFoam.ts, which this module does not import: the WebGL
 * entry point stays free of three/webgpu). It reads the sea's periodic layers
 * (waveLayer.ts), in the contract's order, whatever made them: the FFT cascades, or a user's own.
 *
 * Why in the largest patch: foam must keep its history where the water carries it, so in
 * rest-point coordinates, and over a domain that repeats like the sea so that it covers the whole
 * plane. The layers do not repeat together (the cascades' sizes are not multiples, on purpose), so
 * no square holds the total Jacobian exactly; the largest patch is where the foam of the largest
 * waves (the whitecaps one sees) stays on their crests. The finer layers are sampled at the points
 * of the first patch: elsewhere their share of the folding lands on the same crests, statistically
 * right but not on their own small folds. The surface draws the foam like the largest layer,
 * blended from two copies (patchBlend.ts), with the same texture coordinates.
 *
 * Time: a step of dt in (0, WARM_UP_WINDOW·τ] advances the foam; any other change of time (the
 * first update, time going back, a long jump) rebuilds it from nothing over the warm-up window,
 * which recomputes the layers at the warm-up's times (GPU), or their CPU fields (JS).
 */
import { DataTexture, FloatType, LinearFilter, LinearMipmapLinearFilter, NearestFilter, RedFormat, RepeatWrapping, type Texture, type WebGLRenderer } from 'three';
import { setMipmapLevels, type FloatTextureSupport } from '../fft/cpuFieldTextures';
import type { FieldTarget, GpuDevice, GpuPrecision, PassMaterial } from '../device/gpuDevice';
import { createGpuDevice } from '../device/deviceFor';
import { shaderSource, withLayerCount } from '../shaderSource';
import { CpuFoamField, foamCreationRate, foamSchedule, foamStep, type CascadeOnCpu, type FoamCalibration } from './foamModel';
import type { LayerFrame, WaveLayer } from './waveLayer';

/** What the foam depends on besides the layers. */
export interface FoamSettings {
  /** λ of the choppy map whose Jacobian makes foam. */
  choppiness: number;
  /**
   * J_START, J_FULL and R·τ of the sea (foamModel.ts' calibrateFoam: from the layers' Jacobian
   * statistics, the choppiness and the wind; no foam below Beaufort 3).
   */
  calibration: FoamCalibration;
  /** Multiplies the foam made; 1 is the physical amount, 0 none. */
  amount: number;
  /** τ, s. */
  persistence: number;
}

/** What computes the foam field's steps: GpuFoam, JsFoam, or one made for another device (FoamPath's `producer`). */
export interface FoamProducer {
  /** Coverage in the red channel (the texture may change at each step). */
  readonly texture: { value: Texture | null };
  /** Forgets all foam. */
  clear(): void;
  /**
   * One step of dt seconds ending at `now`; with `time` (a warm-up step) the layers are first brought
   * to that time, else they are current. `rate` is foamCreationRate's.
   */
  step(layers: readonly WaveLayer[], time: number | null, choppiness: number, calibration: FoamCalibration, rate: number, persistence: number, dt: number, now: number): void;
  /** The coverage per texel, row by row. */
  coverageOnCpu(): Float32Array;
  dispose(): void;
}

/**
 * Where the foam is computed: in fragment passes on a WebGLRenderer at the cascades' float type; in
 * JS, uploaded to a float texture of what the renderer's device can do with one (the WebGL Ocean's
 * JS path and the WebGPU Ocean's); or by the producer `producer` makes for the layers and the
 * foam's frame (the WebGPU Ocean's compute shader).
 */
export type FoamPath =
  | { renderer: WebGLRenderer; precision: GpuPrecision }
  | { js: FloatTextureSupport }
  | { producer: (layers: readonly WaveLayer[], frame: LayerFrame) => FoamProducer };

export class WhitecapFoam {
  /** Coverage in the red channel, sampled like the largest cascade's fields. */
  readonly texture: { value: Texture | null };
  readonly frame: LayerFrame;
  private readonly producer: FoamProducer;
  private lastTime = NaN;
  /** True while the field is all zero (cleared, and no foam made since). */
  private empty = true;
  /** The canvas whose restored context the GPU foam listens for, or null (the JS path's survives). */
  private readonly canvas: EventTarget | null;
  /**
   * A restored WebGL context has lost the GPU foam's history (its render targets' contents), which
   * the frames cannot make again by themselves: the next update rebuilds it as after a jump in time
   * (the warm-up), so the same time shows the same foam.
   */
  private readonly onContextRestored = (): void => {
    this.lastTime = NaN;
  };

  /** `layers`: the sea's periodic layers, in the contract's order (orderLayers): the largest last. */
  constructor(
    private readonly layers: readonly WaveLayer[],
    path: FoamPath,
  ) {
    if (layers.length === 0 || layers.some((layer, i) => !layer.frame.periodic || (i > 0 && layer.frame.size < layers[i - 1].frame.size))) {
      throw new RangeError('WhitecapFoam: its layers are periodic ones, from the smallest patch to the largest (orderLayers)');
    }
    const largest = layers[layers.length - 1].frame;
    this.frame = { size: largest.size, origin: [0, 0], periodic: true, resolution: largest.resolution };
    if ('producer' in path) this.producer = path.producer(layers, this.frame);
    else this.producer = 'js' in path ? new JsFoam(path.js, this.frame) : new GpuFoam(createGpuDevice(path.renderer), layers, this.frame, path.precision);
    this.texture = this.producer.texture;
    // Removed in dispose(); guarded for canvas-like objects without listeners, as the sky is.
    this.canvas = 'renderer' in path ? ((path.renderer.domElement as EventTarget | undefined) ?? null) : null;
    this.canvas?.addEventListener?.('webglcontextrestored', this.onContextRestored);
  }

  /**
   * Brings the foam to time t, after the layers were updated to t. On a jump (see the header)
   * the GPU path recomputes the layers at the warm-up's times, ending at t.
   */
  update(t: number, settings: FoamSettings): void {
    const rate = foamCreationRate(settings.calibration, settings.amount, settings.persistence);
    const { clear, steps } = foamSchedule(this.lastTime, t, settings.persistence);
    this.lastTime = t;
    if (clear) {
      this.producer.clear();
      this.empty = true;
    }
    if (this.empty && rate === 0) return; // no foam, and none made: nothing to draw
    this.empty = false;
    for (const { time, dt } of steps) {
      // A warm-up step recomputes the layers at its time; a step to t uses them as they are.
      this.producer.step(this.layers, clear ? time : null, settings.choppiness, settings.calibration, rate, settings.persistence, dt, t);
    }
  }

  /** The coverage per texel, row by row (a read-back on the GPU path: it waits for the GPU). */
  coverageOnCpu(): Float32Array {
    return this.producer.coverageOnCpu();
  }

  dispose(): void {
    this.canvas?.removeEventListener?.('webglcontextrestored', this.onContextRestored);
    this.producer.dispose();
  }
}

/** The foam passes on the GPU: ping-pong between two targets of the layers' float type. Owns its device. */
class GpuFoam implements FoamProducer {
  readonly texture: { value: Texture | null };
  private readonly targets: [FieldTarget, FieldTarget];
  private readonly material: PassMaterial;

  constructor(
    private readonly device: GpuDevice,
    layers: readonly WaveLayer[],
    frame: LayerFrame,
    precision: GpuPrecision,
  ) {
    const m = frame.resolution;
    // Red only: the surface reads the coverage for every pixel (ocean.frag).
    const target = () => device.createFieldTarget({ size: m, precision, channels: 'red', sampling: 'periodic' });
    this.targets = [target(), target()];
    this.targets.forEach((t) => (t.textures[0].name = 'foam'));
    this.texture = { value: this.targets[0].textures[0] };
    this.material = device.passMaterial(withLayerCount(shaderSource('foam/whitecapFoam.frag'), layers.length), {
      tPreviousFoam: { value: null },
      tLayerDisplacement: { value: layers.map((layer) => layer.textures.displacement.value) },
      tLayerDerivatives: { value: layers.map((layer) => layer.textures.derivatives.value) },
      layerTexelScale: { value: layers.map((layer) => (frame.size * layer.frame.resolution) / (m * layer.frame.size)) },
      layerResolution: { value: layers.map((layer) => layer.frame.resolution) },
      choppiness: { value: 1 },
      jacobianStart: { value: 0 },
      jacobianFull: { value: -1 },
      decay: { value: 1 },
      gain: { value: 0 },
    }, { LAYER_COUNT: layers.length });
  }

  clear(): void {
    this.draw(1, { jacobianStart: 0, jacobianFull: -1 }, 0, 0);
  }

  /** One step; at `time` the layers are first recomputed (warm-up), null: they are current. */
  step(layers: readonly WaveLayer[], time: number | null, choppiness: number, calibration: FoamCalibration, rate: number, persistence: number, dt: number): void {
    if (time !== null) for (const layer of layers) layer.update(time, 0);
    const { decay, gain } = foamStep(rate, persistence, dt);
    // A layer may show another texture after an update (a ping-pong): the pass reads those shown now.
    const u = this.material.uniforms;
    layers.forEach((layer, i) => {
      u.tLayerDisplacement.value[i] = layer.textures.displacement.value;
      u.tLayerDerivatives.value[i] = layer.textures.derivatives.value;
    });
    this.draw(choppiness, calibration, decay, gain);
  }

  coverageOnCpu(): Float32Array {
    const target = this.targets.find((t) => t.textures[0] === this.texture.value)!;
    const coverage = new Float32Array(target.size * target.size);
    this.device.readBack(target, coverage);
    return coverage;
  }

  /** The pass, from the target shown to the other one, which is then shown. */
  private draw(choppiness: number, { jacobianStart, jacobianFull }: Pick<FoamCalibration, 'jacobianStart' | 'jacobianFull'>, decay: number, gain: number): void {
    const [read, write] = this.texture.value === this.targets[0].textures[0] ? this.targets : [this.targets[1], this.targets[0]];
    const u = this.material.uniforms;
    u.tPreviousFoam.value = read.textures[0];
    u.choppiness.value = choppiness;
    u.jacobianStart.value = jacobianStart;
    u.jacobianFull.value = jacobianFull;
    u.decay.value = decay;
    u.gain.value = gain;
    this.device.runPasses(() => this.device.draw(this.material, write));
    this.texture.value = write.textures[0];
  }

  dispose(): void {
    for (const target of this.targets) target.dispose();
    this.material.dispose();
    this.device.dispose();
  }
}

/** The foam in JS (CpuFoamField) on the JS path, shown through a DataTexture. */
class JsFoam implements FoamProducer {
  readonly texture: { value: Texture | null };
  private readonly field: CpuFoamField;
  private readonly dataTexture: DataTexture;
  /** Whether the mipmap levels are made here (a float texture that filters but cannot be rendered to), as for the cascades' (cpuFieldTextures.ts). */
  private readonly levelsInJs: boolean;

  constructor({ filterable, renderable }: FloatTextureSupport, frame: LayerFrame) {
    this.field = new CpuFoamField(frame.size, frame.resolution);
    const texture = new DataTexture(this.field.coverage, frame.resolution, frame.resolution, RedFormat, FloatType);
    // The GPU makes the mipmaps by rendering: only into a format that is both filterable and renderable.
    const mipmapped = filterable && renderable;
    this.levelsInJs = filterable && !renderable;
    texture.name = 'foam';
    texture.wrapS = texture.wrapT = RepeatWrapping;
    texture.magFilter = filterable ? LinearFilter : NearestFilter;
    texture.minFilter = filterable ? LinearMipmapLinearFilter : NearestFilter;
    texture.generateMipmaps = mipmapped;
    texture.needsUpdate = true;
    this.dataTexture = texture;
    this.texture = { value: texture };
    this.changed();
  }

  coverageOnCpu(): Float32Array {
    return this.field.coverage.slice();
  }

  clear(): void {
    this.field.clear();
    this.changed();
  }

  /**
   * One step; with `time` from the layers' fields computed at that time, else from those shown (a
   * layer that keeps its fields on the GPU only is read back at `now`).
   */
  step(layers: readonly WaveLayer[], time: number | null, choppiness: number, calibration: FoamCalibration, rate: number, persistence: number, dt: number, now: number): void {
    const onCpu: CascadeOnCpu[] = layers.map((layer) => ({
      fields: time === null ? (layer.shownFieldsOnCpu() ?? layer.fieldsOnCpu(now)) : layer.fieldsOnCpu(time),
      size: layer.frame.size,
      resolution: layer.frame.resolution,
    }));
    this.field.step(onCpu, choppiness, calibration, rate, persistence, dt);
    this.changed();
  }

  /** Uploads the coverage, with its mipmap levels where they are made here. */
  private changed(): void {
    if (this.levelsInJs) setMipmapLevels(this.dataTexture);
    this.dataTexture.needsUpdate = true;
  }

  dispose(): void {
    this.dataTexture.dispose();
  }
}
