/**
 * A wave layer defined only in the tests, against the contract (src/layers/waveLayer.ts), to prove
 * that a new kind of layer is one class plus its test: a single long-crested swell
 *   h(x, z, t) = A·cos(k·x − ω·t),   ω = √(g·k)  (deep-water dispersion of linear (Airy) waves,
 *   Lamb, Hydrodynamics, 6th ed., §229),
 * over a periodic square patch holding a whole number of wavelengths, so it tiles the sea. It only
 * moves the surface up and down (no horizontal displacement), as a swell seen with choppiness 0.
 */
import { DataTexture, FloatType, LinearFilter, LinearMipmapLinearFilter, RepeatWrapping, RGBAFormat } from 'three';
import type { LayerFieldsOnCpu, LayerFrame, LayerQueryFields, WaveLayer } from '../../../src/layers/waveLayer';

const GRAVITY = 9.81;

export class SwellLayer implements WaveLayer {
  readonly frame: LayerFrame;
  readonly movesSideways = false;
  readonly textures;
  /** ω, rad/s. */
  readonly angularFrequency: number;
  /** k, rad/m. */
  readonly waveNumber: number;
  disposed = false;
  private readonly displacement: DataTexture;
  private readonly derivatives: DataTexture;

  /** `wavelengths` whole waves across a patch of `size` metres, `resolution` texels a side, amplitude A in metres. */
  constructor(
    readonly amplitude: number,
    size: number,
    wavelengths: number,
    resolution: number,
  ) {
    this.frame = { size, origin: [0, 0], periodic: true, resolution };
    this.waveNumber = (2 * Math.PI * wavelengths) / size;
    this.angularFrequency = Math.sqrt(GRAVITY * this.waveNumber);
    const texture = () => {
      const data = new DataTexture(new Float32Array(4 * resolution * resolution), resolution, resolution, RGBAFormat, FloatType);
      data.wrapS = data.wrapT = RepeatWrapping;
      data.magFilter = LinearFilter;
      data.minFilter = LinearMipmapLinearFilter;
      data.generateMipmaps = true;
      return data;
    };
    this.displacement = texture();
    this.derivatives = texture();
    this.textures = { displacement: { value: this.displacement }, derivatives: { value: this.derivatives } };
  }

  /** The swell's height at (x, z) at time t, from the formula (not the texels). */
  heightAt(x: number, t: number): number {
    return this.amplitude * Math.cos(this.waveNumber * x - this.angularFrequency * t);
  }

  update(t: number): void {
    const fields = this.fieldsOnCpu(t);
    this.displacement.image.data!.set(fields.displacement);
    this.derivatives.image.data!.set(fields.derivatives);
    this.displacement.needsUpdate = this.derivatives.needsUpdate = true;
  }

  fieldsOnCpu(t: number): LayerFieldsOnCpu & { velocities: Float32Array } {
    const n = this.frame.resolution;
    const [displacement, derivatives, velocities] = [0, 1, 2].map(() => new Float32Array(4 * n * n));
    const { amplitude: a, waveNumber: k, angularFrequency: omega } = this;
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const phase = k * ((i * this.frame.size) / n) - omega * t;
        const texel = 4 * (j * n + i);
        displacement[texel + 1] = a * Math.cos(phase); // h
        derivatives[texel] = -a * k * Math.sin(phase); // ∂h/∂x
        velocities[texel + 1] = a * omega * Math.sin(phase); // ∂h/∂t
      }
    }
    return { displacement, derivatives, velocities };
  }

  shownFieldsOnCpu(): null {
    return null;
  }

  queryFields(t: number): LayerQueryFields {
    const { displacement, derivatives, velocities } = this.fieldsOnCpu(t);
    return { time: t, resolution: this.frame.resolution, displacement, derivatives, velocities: () => velocities };
  }

  dispose(): void {
    this.displacement.dispose();
    this.derivatives.dispose();
    this.disposed = true;
  }
}
