/**
 * The simulation as one object: parameters in, field textures out, on the GPU path when the
 * renderer can render to float targets and on the JS path otherwise (or when asked).
 *
 *   parameters ──► spectrum.ts (h̃0, only when parameters change)
 *   time t ──────► GpuWaveFields or CpuFieldTextures (evolve + FFT, every field)
 *              ──► uniforms.tDisplacement, uniforms.tDerivatives (waveFieldLayout.ts)
 *
 * Materials bind `uniforms` once; the `{ value }` objects stay the same when the path or the
 * resolution changes. Bad parameters throw a ParameterError and change nothing, so the scene goes
 * on with the last good values. Owns the path object and frees it in dispose().
 */
import type { Texture, WebGLRenderer } from 'three';
import { CpuFieldTextures } from '../fft/cpuFieldTextures';
import { GpuWaveFields, supportedGpuPrecision, type GpuPrecision } from '../fft/gpuWaveFields';
import { DEFAULT_PARAMETERS, ParameterError, validateParameters, type SimulationParameters } from '../parameters/parameters';
import { createInitialSpectrum, type InitialSpectrum } from '../spectrum/initialSpectrum';

/** Which implementation computes the fields. */
export type SimulationPath = 'gpu-rgba32f' | 'gpu-rgba16f' | 'js' | 'js-worker';
export type PathPreference = 'auto' | 'gpu' | 'js';

export interface SimulationOptions {
  /** 'auto': GPU when float render targets exist (RGBA32F, else RGBA16F), else JS. @defaultValue 'auto' */
  path?: PathPreference;
  /** Run the JS path in a Web Worker so the page stays responsive. @defaultValue true where Worker exists */
  worker?: boolean;
}

interface FieldPath {
  readonly displacement: Texture;
  readonly derivatives: Texture;
  update(t: number): void;
  dispose(): void;
}

export class OceanSimulation {
  /** Stable uniform objects for materials that sample the fields. */
  readonly uniforms = {
    tDisplacement: { value: null as Texture | null },
    tDerivatives: { value: null as Texture | null },
    patchSize: { value: DEFAULT_PARAMETERS.patchSize },
  };
  private currentParameters: SimulationParameters;
  private currentSpectrum!: InitialSpectrum;
  private fieldPath!: FieldPath;
  private currentPath!: SimulationPath;
  private preference: PathPreference;
  private readonly useWorker: boolean;

  constructor(
    private readonly renderer: WebGLRenderer,
    parameters: Partial<SimulationParameters> = {},
    options: SimulationOptions = {},
  ) {
    this.currentParameters = validateParameters(parameters);
    this.preference = checkPreference(options.path ?? 'auto');
    this.useWorker = options.worker ?? typeof Worker !== 'undefined';
    this.rebuild(true);
  }

  get parameters(): Readonly<SimulationParameters> {
    return this.currentParameters;
  }

  get spectrum(): Readonly<InitialSpectrum> {
    return this.currentSpectrum;
  }

  /** The implementation now running. */
  get path(): SimulationPath {
    return this.currentPath;
  }

  /** Switches between the GPU and JS paths ('auto' picks the best available). */
  set pathPreference(preference: PathPreference) {
    this.preference = checkPreference(preference);
    this.rebuild(false);
  }

  get pathPreference(): PathPreference {
    return this.preference;
  }

  /** Fragment passes per GPU update, or 0 on the JS path. */
  get passCount(): number {
    return this.fieldPath instanceof GpuWaveFields ? this.fieldPath.passCount : 0;
  }

  /**
   * Changes some parameters. Throws a ParameterError naming the first bad one and then changes
   * nothing. The spectrum is rebuilt only when something it depends on changed.
   */
  setParameters(changes: Partial<SimulationParameters>): void {
    const next = validateParameters(changes, this.currentParameters);
    const changed = (Object.keys(next) as (keyof SimulationParameters)[]).some((key) => next[key] !== this.currentParameters[key]);
    if (!changed) return;
    this.currentParameters = next;
    this.rebuild(true);
  }

  /** Computes every field at time t in seconds (any finite value; the sea repeats every repeatPeriod). */
  update(t: number): void {
    if (!Number.isFinite(t)) throw new ParameterError('time', t, 'a finite number of seconds');
    this.fieldPath.update(t);
  }

  dispose(): void {
    this.fieldPath.dispose();
    this.uniforms.tDisplacement.value = null;
    this.uniforms.tDerivatives.value = null;
  }

  private rebuild(newSpectrum: boolean): void {
    const params = this.currentParameters;
    if (newSpectrum) this.currentSpectrum = createInitialSpectrum(params);
    const precision = this.preference === 'js' ? null : supportedGpuPrecision(this.renderer);
    if (this.preference === 'gpu' && precision === null) {
      console.warn('three-fft-ocean: this WebGL context cannot render to float textures; using the JS path.');
    }
    // Build the new path before freeing the old one, so three.js can reuse compiled programs.
    const previous = this.fieldPath as FieldPath | undefined;
    this.fieldPath = precision ? this.createGpuPath(precision) : this.createJsPath();
    previous?.dispose();
    this.uniforms.tDisplacement.value = this.fieldPath.displacement;
    this.uniforms.tDerivatives.value = this.fieldPath.derivatives;
    this.uniforms.patchSize.value = params.patchSize;
  }

  private createGpuPath(precision: GpuPrecision): FieldPath {
    const { choppiness, repeatPeriod } = this.currentParameters;
    this.currentPath = precision === 'float32' ? 'gpu-rgba32f' : 'gpu-rgba16f';
    return new GpuWaveFields(this.renderer, this.currentSpectrum, choppiness, repeatPeriod, precision);
  }

  private createJsPath(): FieldPath {
    const { choppiness, repeatPeriod } = this.currentParameters;
    this.currentPath = this.useWorker ? 'js-worker' : 'js';
    return new CpuFieldTextures(this.renderer, this.currentSpectrum, choppiness, repeatPeriod, this.useWorker);
  }
}

function checkPreference(preference: PathPreference): PathPreference {
  if (preference !== 'auto' && preference !== 'gpu' && preference !== 'js') {
    throw new ParameterError('path', preference, "'auto', 'gpu' or 'js'");
  }
  return preference;
}
