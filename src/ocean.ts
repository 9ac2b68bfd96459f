/**
 * Ocean: the whole sea as one three.js Object3D — simulation (src/sim), sky (SkyEnvironment) and
 * surface (OceanSurface) — for any scene.
 *
 *   const ocean = new Ocean(renderer, { windSpeed: 12, seed: 7 });
 *   scene.add(ocean);                    // the sea and, behind everything, its sky
 *   renderer.setAnimationLoop((ms) => { ocean.update(ms / 1000); renderer.render(scene, camera); });
 *
 * The sea is the plane y = 0 of world space; give the camera a far plane of at least
 * ocean.horizonDistance (about 4000 camera heights) so the surface reaches the horizon. Owns everything it creates and frees it
 * in dispose().
 */
import { Object3D, type WebGLRenderer } from 'three';
import { OceanSurface } from './render/oceanSurface';
import type { OceanShadingOptions } from './render/oceanMaterial';
import { SkyBackground } from './render/skyBackground';
import { SkyEnvironment } from './render/skyEnvironment';
import { CpuWaveFields } from './fft/cpuWaveFields';
import { OceanSimulation, type SimulationOptions } from './layers/oceanSimulation';
import { ParameterError, type SimulationParameters } from './parameters/parameters';
import type { InitialSpectrum } from './spectrum/initialSpectrum';

export interface OceanOptions extends Partial<SimulationParameters>, OceanShadingOptions, SimulationOptions {
  /** Sun elevation above the horizon in degrees, [-90, 90]. @defaultValue 30 */
  sunElevation?: number;
  /** Sun azimuth in degrees from +x towards +z. @defaultValue 40 */
  sunAzimuth?: number;
}

const SHADING_KEYS = ['ior', 'absorption', 'scatterColour', 'causticPower', 'causticColour', 'shadingMode'] as const;
const SIMULATION_KEYS = [
  'resolution',
  'patchSize',
  'windSpeed',
  'windDirection',
  'amplitude',
  'smallWaveCutoff',
  'depth',
  'repeatPeriod',
  'choppiness',
  'seed',
] as const;

export class Ocean extends Object3D {
  readonly simulation: OceanSimulation;
  readonly sky: SkyEnvironment;
  readonly surface: OceanSurface;
  /** The sky behind everything (a child; set skyBackground.visible = false to show your own). */
  readonly skyBackground: SkyBackground;
  private currentTime = 0;
  /** CPU copy of the fields for heightAt(), computed lazily for the current time. */
  private probe: { spectrum: InitialSpectrum; fields: CpuWaveFields; time: number } | null = null;
  private rms: { spectrum: InitialSpectrum; value: number } | null = null;

  constructor(renderer: WebGLRenderer, options: OceanOptions = {}) {
    super();
    this.name = 'Ocean';
    const simulationParameters = pick(options, SIMULATION_KEYS);
    const shading = pick(options, SHADING_KEYS);
    this.simulation = new OceanSimulation(renderer, simulationParameters, { path: options.path, worker: options.worker });
    this.sky = new SkyEnvironment(renderer, { sunElevation: options.sunElevation, sunAzimuth: options.sunAzimuth });
    const sim = this.simulation;
    this.surface = new OceanSurface(
      {
        displacement: sim.uniforms.tDisplacement,
        derivatives: sim.uniforms.tDerivatives,
        patchSize: sim.uniforms.patchSize,
        environment: this.sky.environment,
        sunDirection: this.sky.skyUniforms.skySunDirection,
      },
      () => sim.parameters.patchSize / sim.parameters.resolution,
      shading,
    );
    this.skyBackground = new SkyBackground(this.sky);
    this.add(this.surface, this.skyBackground);
  }

  /**
   * Distance in metres from the camera of the last render to the far edge of the surface (it grows
   * with the camera's height): set camera.far at least this large to see the sea to the horizon.
   */
  get horizonDistance(): number {
    return this.surface.farEdgeDistance;
  }

  get time(): number {
    return this.currentTime;
  }

  /**
   * Root mean square of the sea's height in metres over time, from the spectrum: by Parseval the
   * mean of h² over the patch is Σ|h̃(k, t)|², whose average over the repeat period is
   * Σ(|h̃0(k)|² + |h̃0(−k)|²) (the cross terms oscillate). At one instant it differs by up to ~25%.
   */
  get heightRms(): number {
    const spectrum = this.simulation.spectrum as InitialSpectrum;
    if (this.rms?.spectrum !== spectrum) {
      let sum = 0;
      for (const a of spectrum.amplitudes) sum += a * a;
      this.rms = { spectrum, value: Math.sqrt(sum) };
    }
    return this.rms.value;
  }

  /** Computes the sea at `timeSeconds` (any finite number; it repeats every repeatPeriod). */
  update(timeSeconds: number): void {
    this.simulation.update(timeSeconds);
    this.currentTime = timeSeconds;
  }

  get parameters(): Readonly<SimulationParameters> {
    return this.simulation.parameters;
  }

  /** Changes simulation parameters; a bad one throws a ParameterError and nothing changes. */
  setParameters(changes: Partial<SimulationParameters>): void {
    this.simulation.setParameters(changes);
  }

  get shading(): Required<OceanShadingOptions> {
    return this.surface.material.shading;
  }

  /** Changes shading options; a bad one throws a ParameterError and nothing changes. */
  setShading(changes: OceanShadingOptions): void {
    this.surface.material.setShading(changes);
  }

  /** Moves the sun (degrees); the sky, glint and caustics follow. */
  setSun(elevation: number, azimuth: number): void {
    this.sky.setSun(elevation, azimuth);
  }

  /**
   * Height of the water surface at the world point (x, z) at the current time: the height of the
   * surface point x0 that the choppy displacement moves onto (x, z), x0 + D(x0) = (x, z), found by
   * Newton's method with the Jacobian of the fields (waveFieldLayout.ts). Where the surface folds
   * over itself (Jacobian ≤ 0, breaking crests) several points land on (x, z) and the one nearest
   * the start is returned. Computes the fields on the CPU once per time asked (a few ms at N = 256).
   */
  heightAt(x: number, z: number): number {
    if (!Number.isFinite(x) || !Number.isFinite(z)) throw new ParameterError('heightAt(x, z)', `${x}, ${z}`, 'finite coordinates');
    const { fields, spectrum } = this.fieldsNow();
    const n = spectrum.resolution;
    const scale = n / spectrum.patchSize; // texels per metre
    const sample = (data: Float32Array, restX: number, restZ: number, channel: number) =>
      sampleField(data, n, restX * scale, restZ * scale, channel);
    let restX = x;
    let restZ = z;
    for (let iteration = 0; iteration < 20; iteration++) {
      const residualX = restX + sample(fields.displacement, restX, restZ, 0) - x;
      const residualZ = restZ + sample(fields.displacement, restX, restZ, 2) - z;
      if (Math.abs(residualX) + Math.abs(residualZ) < 1e-7) break;
      const jxx = 1 + sample(fields.derivatives, restX, restZ, 2);
      const jzz = 1 + sample(fields.derivatives, restX, restZ, 3);
      const jxz = sample(fields.displacement, restX, restZ, 3);
      const determinant = jxx * jzz - jxz * jxz;
      if (determinant > 0.05) {
        restX -= (jzz * residualX - jxz * residualZ) / determinant;
        restZ -= (jxx * residualZ - jxz * residualX) / determinant;
      } else {
        // Near a fold Newton steps explode: fall back to a damped fixed-point step.
        restX -= 0.5 * residualX;
        restZ -= 0.5 * residualZ;
      }
    }
    return sample(fields.displacement, restX, restZ, 1);
  }

  private fieldsNow(): { fields: CpuWaveFields; spectrum: InitialSpectrum } {
    const spectrum = this.simulation.spectrum as InitialSpectrum;
    const { choppiness, repeatPeriod } = this.simulation.parameters;
    if (!this.probe || this.probe.spectrum !== spectrum) {
      this.probe = { spectrum, fields: new CpuWaveFields(spectrum, choppiness, repeatPeriod), time: NaN };
    }
    if (this.probe.time !== this.currentTime) {
      this.probe.fields.update(this.currentTime);
      this.probe.time = this.currentTime;
    }
    return this.probe;
  }

  dispose(): void {
    this.surface.removeFromParent();
    this.surface.dispose();
    this.skyBackground.dispose();
    this.sky.dispose();
    this.simulation.dispose();
    this.probe = null;
  }
}

/**
 * Bilinear sample with wrap-around of channel c of an RGBA N×N field at continuous texel
 * coordinates (u, v), where texel (i, j) holds the field at (u, v) = (i, j) — the same
 * interpolation the GPU does for the surface (see horizonGrid.ts).
 */
function sampleField(data: Float32Array, n: number, u: number, v: number, c: number): number {
  const i0 = Math.floor(u);
  const j0 = Math.floor(v);
  const fu = u - i0;
  const fv = v - j0;
  const at = (i: number, j: number) => data[4 * ((((j % n) + n) % n) * n + (((i % n) + n) % n)) + c];
  return (1 - fv) * ((1 - fu) * at(i0, j0) + fu * at(i0 + 1, j0)) + fv * ((1 - fu) * at(i0, j0 + 1) + fu * at(i0 + 1, j0 + 1));
}

function pick<T extends object, K extends keyof T>(source: T, keys: readonly K[]): Partial<Pick<T, K>> {
  const result: Partial<Pick<T, K>> = {};
  for (const key of keys) if (source[key] !== undefined) result[key] = source[key];
  return result;
}
