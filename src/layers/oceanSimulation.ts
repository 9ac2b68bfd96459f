/**
 * The simulation as one object: parameters in, wave layers out. It builds one FFT cascade per
 * patch size (params.patchSizes), each from its band of the sea-state spectrum, on the GPU path
 * when the renderer can render to float targets and on the JS path otherwise (or when asked).
 *
 *   parameters ──► src/spectrum (Ψ(k) of the sea state, split into cascade bands, h̃0 per cascade)
 *   time t ──────► layers: FftCascade × patchSizes.length (evolve + FFT on the GPU or in JS)
 *              ──► whitecap foam from their summed Jacobian, with its history (whitecapFoam.ts)
 *              ──► the surface, the queries and the inspector sum `layers` (waveLayer.ts)
 *
 * Bad parameters throw a ParameterError and change nothing, so the scene goes on with the last
 * good values. A change of a shader-only parameter (choppiness) rebuilds nothing. Owns the layers
 * and frees them in dispose().
 */
import { FloatType, HalfFloatType, type WebGLRenderer } from 'three';
import { supportedGpuPrecision } from '../fft/gpuWaveFields';
import {
  ParameterError,
  SHADER_ONLY_PARAMETERS,
  validateParameters,
  type SimulationParameters,
} from '../parameters/parameters';
import { createCascadeSpectra, type InitialSpectrum } from '../spectrum/initialSpectrum';
import { FftCascade, type FftBackend } from './fftCascade';
import type { WaveLayer } from './waveLayer';
import { WhitecapFoam } from './whitecapFoam';

/** Which implementation computes the fields. */
export type SimulationPath = 'gpu-rgba32f' | 'gpu-rgba16f' | 'js' | 'js-worker';
export type PathPreference = 'auto' | 'gpu' | 'js';

export interface SimulationOptions {
  /** 'auto': GPU when float render targets exist (RGBA32F, else RGBA16F), else JS. @defaultValue 'auto' */
  path?: PathPreference;
  /** Run the JS path in a Web Worker so the page stays responsive. @defaultValue true where Worker exists */
  worker?: boolean;
}

export class OceanSimulation {
  private currentParameters: SimulationParameters;
  private currentLayers: FftCascade[] = [];
  private currentFoam: WhitecapFoam | null = null;
  private currentPath!: SimulationPath;
  private preference: PathPreference;
  private readonly useWorker: boolean;
  private lastTime = NaN;

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

  /** The FFT cascades, finest first: what the surface and the queries sum. */
  get layers(): readonly FftCascade[] {
    return this.currentLayers;
  }

  /** The whitecap foam over the largest cascade's patch (whitecapFoam.ts). */
  get foam(): WhitecapFoam {
    return this.currentFoam!;
  }

  /** The initial spectrum of each cascade, finest first. */
  get spectra(): readonly InitialSpectrum[] {
    return this.currentLayers.map((layer) => layer.spectrum);
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

  /** Fragment passes per GPU update over all cascades, or 0 on the JS path. */
  get passCount(): number {
    return this.currentLayers.reduce((sum, layer) => sum + layer.passCount, 0);
  }

  /**
   * Changes some parameters. Throws a ParameterError naming the first bad one and then changes
   * nothing. The spectra are rebuilt only when something they depend on changed.
   */
  setParameters(changes: Partial<SimulationParameters>): void {
    const next = validateParameters(changes, this.currentParameters);
    const changed = (Object.keys(next) as (keyof SimulationParameters)[]).filter(
      (key) => String(next[key]) !== String(this.currentParameters[key]),
    );
    this.currentParameters = next;
    if (changed.some((key) => !SHADER_ONLY_PARAMETERS.includes(key))) this.rebuild(true);
  }

  /** Computes every layer at time t in seconds (any finite value). */
  update(t: number): void {
    if (!Number.isFinite(t)) throw new ParameterError('time', t, 'a finite number of seconds');
    const dt = Number.isNaN(this.lastTime) ? 0 : t - this.lastTime;
    for (const layer of this.currentLayers as readonly WaveLayer[]) layer.update(t, dt);
    this.lastTime = t;
    const { choppiness, windSpeed, foamAmount, foamPersistence } = this.currentParameters;
    this.currentFoam!.update(t, { choppiness, windSpeed, amount: foamAmount, persistence: foamPersistence });
  }

  dispose(): void {
    for (const layer of this.currentLayers) layer.dispose();
    this.currentLayers = [];
    this.currentFoam?.dispose();
    this.currentFoam = null;
  }

  private rebuild(newSpectra: boolean): void {
    const params = this.currentParameters;
    const spectra = newSpectra ? createCascadeSpectra(params) : this.spectra;
    const precision = this.preference === 'js' ? null : supportedGpuPrecision(this.renderer);
    if (this.preference === 'gpu' && precision === null) {
      console.warn('three-fft-ocean: this WebGL context cannot render to float textures; using the JS path.');
    }
    const backend: FftBackend = precision ? { kind: 'gpu', precision } : { kind: 'js', worker: this.useWorker };
    this.currentPath = precision ? (precision === 'float32' ? 'gpu-rgba32f' : 'gpu-rgba16f') : this.useWorker ? 'js-worker' : 'js';
    // Build the new layers before freeing the old ones, so three.js can reuse compiled programs.
    const previous = this.currentLayers;
    this.currentLayers = spectra.map((spectrum) => new FftCascade(this.renderer, spectrum, backend));
    for (const layer of previous) layer.dispose();
    this.currentFoam?.dispose();
    this.currentFoam = new WhitecapFoam(this.renderer, this.currentLayers, precision === null ? null : precision === 'float32' ? FloatType : HalfFloatType);
    this.lastTime = NaN;
  }
}

function checkPreference(preference: PathPreference): PathPreference {
  if (preference !== 'auto' && preference !== 'gpu' && preference !== 'js') {
    throw new ParameterError('path', preference, "'auto', 'gpu' or 'js'");
  }
  return preference;
}

