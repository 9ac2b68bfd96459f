/**
 * The simulation as one object: parameters in, wave layers out. It builds one FFT cascade per
 * patch size (params.patchSizes), each from its band of the sea-state spectrum, on the GPU path
 * when the renderer can render to float targets and on the JS path otherwise (or when asked).
 *
 *   parameters ──► src/spectrum (Ψ(k) of the sea state, split into cascade bands, h̃0 per cascade)
 *   time t ──────► layers, one list in the contract's order (waveLayer.ts), on one clock:
 *                    FftCascade × patchSizes.length (evolve + FFT on the GPU or in JS)
 *                    local waves: stones, hulls (localWaves.ts)
 *                    any layer added (addLayer)
 *              ──► whitecap foam from the periodic layers' summed Jacobian, with its history
 *                  (whitecapFoam.ts)
 *              ──► the surface and the queries sum `layers`
 *
 * Bad parameters throw a ParameterError and change nothing, so the scene goes on with the last
 * good values. A change of a shader-only parameter (choppiness) rebuilds nothing. Owns the layers
 * and frees them in dispose().
 */
import type { WebGLRenderer } from 'three';
import type { GpuDevice, GpuPrecision } from '../device/gpuDevice';
import { gpuSupport } from '../device/gpuSupport';
import { createGpuDevice } from '../device/deviceFor';
import {
  ParameterError,
  SHADER_ONLY_PARAMETERS,
  validateParameters,
  type SimulationParameters,
} from '../parameters/parameters';
import { checkOptionNames } from '../parameters/options';
import { createCascadeSpectra, type InitialSpectrum } from '../spectrum/initialSpectrum';
import { FftCascade, gpuBackend, jsBackend, type FftBackend } from './fftCascade';
import { LOCAL_WAVES_OPTION_KEYS, LocalWaves, type LocalWavesOptions } from './localWaves';
import { orderLayers, type WaveLayer } from './waveLayer';
import { calibrateFoam, jacobianCovariance, type FoamCalibration, type JacobianCovariance } from './foamModel';
import { WhitecapFoam } from './whitecapFoam';
import { webglFloatTextureSupport } from '../fft/cpuFieldTextures';

/** Which implementation computes the fields. */
export type SimulationPath = 'gpu-rgba32f' | 'gpu-rgba16f' | 'js' | 'js-worker';
/**
 * The simulation paths a caller may ask for, the one list of them: the Ocean's path option, the
 * local waves' path, the app's URL and panel, <fft-ocean>'s path attribute and the shot CLI all
 * read this.
 */
export const PATH_PREFERENCES = ['auto', 'gpu', 'js'] as const;
export type PathPreference = (typeof PATH_PREFERENCES)[number];
/** PATH_PREFERENCES as messages list them: "'auto', 'gpu' or 'js'". */
export const PATH_PREFERENCES_TEXT = `${PATH_PREFERENCES.slice(0, -1).map((p) => `'${p}'`).join(', ')} or '${PATH_PREFERENCES[PATH_PREFERENCES.length - 1]}'`;

/** Whether `value` is one of PATH_PREFERENCES. */
export function isPathPreference(value: unknown): value is PathPreference {
  return (PATH_PREFERENCES as readonly unknown[]).includes(value);
}

export interface SimulationOptions {
  /** 'auto': GPU when float render targets exist (RGBA32F, else RGBA16F), else JS. @defaultValue 'auto' */
  path?: PathPreference;
  /**
   * Compute on the CPU in Web Workers, so the page stays responsive: the JS path's fields, and on
   * the GPU path the copy of the fields that heightAt and the other queries read. @defaultValue true where Worker exists
   */
  worker?: boolean;
  /**
   * Local waves from stones, hulls and floating bodies (localWaves.ts): false for none, or the grid
   * they are solved on and where. @defaultValue true (128 texels of 1 m, path 'auto')
   */
  localWaves?: boolean | LocalWavesOptions;
}

/**
 * The defaults of SimulationOptions; `worker` is true only where Worker exists (not in Node, say),
 * false elsewhere.
 */
export const DEFAULT_SIMULATION_OPTIONS: Readonly<Required<SimulationOptions>> = Object.freeze({ path: 'auto', worker: true, localWaves: true });

export class OceanSimulation {
  private currentParameters: SimulationParameters;
  /** The parameters the spectra were made from (a later change may have been shader-only). */
  private spectraParameters: SimulationParameters;
  private currentCascades: FftCascade[] = [];
  private currentFoam: WhitecapFoam | null = null;
  private currentLocalWaves: LocalWaves | null = null;
  private readonly localWaveOptions: LocalWavesOptions | null;
  /** Layers added by addLayer, in the order added; their owner is the caller. */
  private readonly addedLayers: WaveLayer[] = [];
  /** Every layer, in the contract's order (orderLayers): a new array whenever the list changes. */
  private currentLayers: readonly WaveLayer[] = [];
  /** Layers not updated yet: their first update is a jump (dt = 0). */
  private readonly notUpdatedYet = new Set<WaveLayer>();
  /** The precision the GPU path runs at (null: the JS path), for a foam rebuilt after addLayer. */
  private gpuPrecision: GpuPrecision | null = null;
  private currentPath!: SimulationPath;
  /** Why the path is not the preferred one's best ('' when it is). */
  private currentReason = '';
  private preference: PathPreference;
  private readonly useWorker: boolean;
  private lastTime = NaN;
  /** The cascades' Jacobian statistics (foamModel.ts), made once per set of spectra. */
  private covariance: { cascades: readonly FftCascade[]; spectra: readonly InitialSpectrum[]; value: JacobianCovariance } | null = null;
  /** The foam's calibration for the choppiness and wind it was made for (calibrateFoam). */
  private calibration: { covariance: JacobianCovariance; choppiness: number; windSpeed: number; value: FoamCalibration } | null = null;
  /**
   * What the last rebuild replaced (cascades, foam), freed after the next update: by then their
   * successors have drawn with the same shaders, which three.js then reuses instead of deleting
   * and compiling them again (a program lives while a material uses it): a parameter change costs
   * no shader compilation.
   */
  private retired: { dispose(): void }[] = [];
  /** What rebuilds made since the last update (cascades, foam, local waves): none of it drew yet. */
  private readonly madeSinceUpdate = new Set<{ dispose(): void }>();
  /** The GPU device, asked what it can do (the path and its reason, the local waves' solver). */
  private readonly device: GpuDevice;

  constructor(
    private readonly renderer: WebGLRenderer,
    parameters: Partial<SimulationParameters> = {},
    options: SimulationOptions = {},
  ) {
    this.currentParameters = this.spectraParameters = validateParameters(parameters);
    checkOptionNames(options, SIMULATION_OPTION_KEYS, 'OceanSimulation options');
    const defaults = DEFAULT_SIMULATION_OPTIONS;
    this.preference = checkPreference(options.path ?? defaults.path);
    this.useWorker = options.worker ?? (defaults.worker && typeof Worker !== 'undefined');
    this.localWaveOptions = checkLocalWaves(options.localWaves ?? defaults.localWaves);
    const localPath = this.localWaveOptions?.path ?? 'auto';
    if (!isPathPreference(localPath)) throw new ParameterError('localWaves.path', localPath, PATH_PREFERENCES_TEXT);
    this.device = createGpuDevice(renderer);
    try {
      this.rebuild(true);
    } catch (error) {
      this.device.dispose();
      throw error;
    }
  }

  get parameters(): Readonly<SimulationParameters> {
    return this.currentParameters;
  }

  /** The FFT cascades, finest first. */
  get cascades(): readonly FftCascade[] {
    return this.currentCascades;
  }

  /**
   * Every layer, what the surface draws and the queries sum: the local waves (if any), the
   * cascades and the layers added, in the contract's order (waveLayer.ts: the largest periodic one
   * last). The same array until the layers change.
   */
  get layers(): readonly WaveLayer[] {
    return this.currentLayers;
  }

  /**
   * Adds a wave layer of the caller's (waveLayer.ts): from the next update on it is updated with
   * the others on the simulation's clock, drawn, queried and, if periodic, read by the foam. The
   * caller keeps it: removeLayer gives it back, and dispose() leaves it to the caller to free.
   */
  addLayer(layer: WaveLayer): void {
    checkWaveLayer(layer);
    if (this.addedLayers.includes(layer)) throw new ParameterError('layer', layer, 'a layer not added yet');
    this.addedLayers.push(layer);
    this.notUpdatedYet.add(layer);
    this.layersChanged(layer.frame.periodic);
  }

  /** Takes a layer addLayer added off the sea (not freed: it is the caller's). */
  removeLayer(layer: WaveLayer): void {
    const at = this.addedLayers.indexOf(layer);
    if (at < 0) throw new ParameterError('layer', layer, 'a layer added with addLayer');
    this.addedLayers.splice(at, 1);
    this.notUpdatedYet.delete(layer);
    this.layersChanged(layer.frame.periodic);
  }

  /** The local waves (stones, hulls), or null when turned off. */
  get localWaves(): LocalWaves | null {
    return this.currentLocalWaves;
  }

  /** The whitecap foam over the largest cascade's patch (whitecapFoam.ts). */
  get foam(): WhitecapFoam {
    return this.currentFoam!;
  }

  /** The initial spectrum of each cascade, finest first. */
  get spectra(): readonly InitialSpectrum[] {
    return this.currentCascades.map((cascade) => cascade.spectrum);
  }

  /** The implementation now running ('js' once a cascade's worker has failed for good). */
  get path(): SimulationPath {
    return this.currentPath === 'js-worker' && this.workerFault() !== null ? 'js' : this.currentPath;
  }

  /** Why the running path is not the best the preference asks for, in words ('' when it is). */
  get pathReason(): string {
    return this.workerFault() ?? this.currentReason;
  }

  /** The first cascade's reason for computing on the main thread instead of its worker, or null. */
  private workerFault(): string | null {
    for (const cascade of this.currentCascades) {
      if (cascade.workerFault !== null) return cascade.workerFault;
    }
    return null;
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
    return this.currentCascades.reduce((sum, cascade) => sum + cascade.passCount, 0);
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

  /**
   * Computes every layer at time t in seconds (any finite value), each stepped by the time since
   * the last update (0 at its first), then the foam.
   */
  update(t: number): void {
    if (!Number.isFinite(t)) throw new ParameterError('time', t, 'a finite number of seconds');
    const dt = Number.isNaN(this.lastTime) ? 0 : t - this.lastTime;
    const { choppiness, foamAmount, foamPersistence } = this.currentParameters;
    this.currentLocalWaves?.setFoam(foamAmount, foamPersistence);
    for (const layer of this.currentLayers) layer.update(t, this.notUpdatedYet.has(layer) ? 0 : dt);
    this.notUpdatedYet.clear();
    this.madeSinceUpdate.clear();
    this.lastTime = t;
    this.currentFoam!.update(t, { choppiness, calibration: this.foamCalibration, amount: foamAmount, persistence: foamPersistence });
    this.disposeRetired();
  }

  /**
   * J_START, J_FULL and R·τ of the whitecap foam for this sea (foamModel.ts' calibrateFoam): from
   * the cascades' modes, the choppiness and the wind; made again only when one of them changed.
   * Layers added with addLayer join the Jacobian but not these statistics.
   */
  get foamCalibration(): FoamCalibration {
    // Per frame this only compares the cascades' array (replaced on every rebuild): no allocation.
    if (this.covariance === null || this.covariance.cascades !== this.currentCascades) {
      const spectra = this.spectra;
      const same = this.covariance !== null && this.covariance.spectra.length === spectra.length && this.covariance.spectra.every((s, i) => s === spectra[i]);
      this.covariance = { cascades: this.currentCascades, spectra, value: same ? this.covariance!.value : jacobianCovariance(spectra) };
    }
    const covariance = this.covariance.value;
    const { choppiness, windSpeed } = this.currentParameters;
    const cached = this.calibration;
    if (cached === null || cached.covariance !== covariance || cached.choppiness !== choppiness || cached.windSpeed !== windSpeed) {
      this.calibration = { covariance, choppiness, windSpeed, value: calibrateFoam(covariance, choppiness, windSpeed) };
    }
    return this.calibration!.value;
  }

  /** Frees the cascades, the local waves and the foam; the layers added stay the caller's. */
  dispose(): void {
    this.disposeRetired();
    for (const cascade of this.currentCascades) cascade.dispose();
    this.currentCascades = [];
    this.currentFoam?.dispose();
    this.currentFoam = null;
    this.currentLocalWaves?.dispose();
    this.currentLocalWaves = null;
    this.addedLayers.length = 0;
    this.currentLayers = [];
    this.device.dispose();
  }

  private rebuild(newSpectra: boolean): void {
    const params = this.currentParameters;
    const spectra = newSpectra ? createCascadeSpectra(params) : this.spectra;
    if (newSpectra) this.spectraParameters = params;
    const support = this.preference === 'js' ? { precision: null, reason: 'asked for' } : gpuSupport(this.device);
    let precision: GpuPrecision | null = support.precision;
    this.currentReason = support.reason;
    // The new layers are built before the old ones are freed (see `retired`); each may take over the
    // arrays of its predecessor's CPU copy for queries.
    const previous = this.currentCascades;
    const cascadesOn = (gpu: GpuPrecision | null) =>
      spectra.map(
        (spectrum, cascade) =>
          new FftCascade(this.renderer, spectrum, { params: this.spectraParameters, cascade }, backendFor(gpu, this.useWorker), this.useWorker, previous[cascade] ?? null),
      );
    try {
      this.currentCascades = cascadesOn(precision);
    } catch (error) {
      if (precision === null) throw error;
      // The GPU path failed to build here (an adapter check, a framebuffer): the JS path instead.
      precision = null;
      this.currentReason = `the GPU path failed: ${error instanceof Error ? error.message : String(error)}`;
      this.currentCascades = cascadesOn(null);
    }
    for (const cascade of this.currentCascades) {
      this.notUpdatedYet.add(cascade);
      this.madeSinceUpdate.add(cascade);
    }
    this.gpuPrecision = precision;
    this.currentPath = precision ? (precision === 'float32' ? 'gpu-rgba32f' : 'gpu-rgba16f') : this.useWorker ? 'js-worker' : 'js';
    if (this.currentReason !== '' && this.preference !== 'js' && !warned.has(this.currentReason)) {
      warned.add(this.currentReason);
      console.warn(`three-fft-ocean: ${this.currentReason}; using the ${PATH_NAMES[this.currentPath]} path.`);
    }
    for (const cascade of previous) this.notUpdatedYet.delete(cascade);
    this.retire(previous);
    const localPath = this.localWaveOptions?.path ?? 'auto';
    this.rebuildLocalWaves(precision === 'float32' && (localPath === 'gpu' || (localPath === 'auto' && !this.device.software)));
    this.layersChanged(true);
  }

  /**
   * Frees what a rebuild replaced: after the next update if it drew (see `retired`), at once if it
   * was made since the last update and never drew (two rebuilds without an update between).
   */
  private retire(replaced: readonly { dispose(): void }[]): void {
    for (const resource of replaced) {
      if (this.madeSinceUpdate.has(resource)) resource.dispose();
      else this.retired.push(resource);
    }
  }

  /**
   * Orders the layers anew (a new array, so the surface rebinds them); when the periodic ones
   * changed, a new foam reads them (its history starts again).
   */
  private layersChanged(periodicChanged: boolean): void {
    const local = this.currentLocalWaves ? [this.currentLocalWaves] : [];
    this.currentLayers = orderLayers([...local, ...this.currentCascades, ...this.addedLayers]);
    if (!periodicChanged) return;
    if (this.currentFoam) this.retire([this.currentFoam]);
    const precision = this.gpuPrecision;
    const periodic = this.currentLayers.filter((layer) => layer.frame.periodic);
    this.currentFoam = new WhitecapFoam(periodic, precision === null ? { js: webglFloatTextureSupport(this.renderer) } : { renderer: this.renderer, precision });
    this.madeSinceUpdate.add(this.currentFoam);
  }

  private disposeRetired(): void {
    if (this.retired.length === 0) return; // every update asks: no new array per frame
    for (const resource of this.retired) resource.dispose();
    this.retired = [];
  }

  /**
   * Keeps the local waves (and the waves on them) through a rebuild unless their solver or the
   * depth changes. Half floats cannot hold their forward FFT: on RGBA16F they are solved in JS.
   */
  private rebuildLocalWaves(useGpu: boolean): void {
    const previous = this.currentLocalWaves;
    const depth = this.currentParameters.depth;
    if (this.localWaveOptions && (previous === null || previous.path !== (useGpu ? 'gpu' : 'js') || previous.grid.depth !== depth)) {
      this.currentLocalWaves = new LocalWaves(this.renderer, depth, useGpu, this.localWaveOptions);
      this.notUpdatedYet.add(this.currentLocalWaves);
      if (previous) this.notUpdatedYet.delete(previous);
      previous?.dispose();
    }
  }
}

/** Each fallback's reason is printed once per page. */
const warned = new Set<string>();

const PATH_NAMES: Record<SimulationPath, string> = { 'gpu-rgba32f': 'GPU RGBA32F', 'gpu-rgba16f': 'GPU RGBA16F', js: 'JS', 'js-worker': 'JS (worker)' };

function backendFor(precision: GpuPrecision | null, worker: boolean): FftBackend {
  return precision ? gpuBackend(precision) : jsBackend(worker);
}

/** The names SimulationOptions has: any other is a misspelling. */
const SIMULATION_OPTION_KEYS: readonly (keyof SimulationOptions)[] = ['path', 'worker', 'localWaves'];

/** The local waves' options (null for none), or a ParameterError naming what is wrong in them; their values are checked by LocalWaves. */
function checkLocalWaves(localWaves: boolean | LocalWavesOptions): LocalWavesOptions | null {
  if (typeof localWaves === 'boolean') return localWaves ? {} : null;
  checkOptionNames(localWaves, LOCAL_WAVES_OPTION_KEYS, 'localWaves', {
    prefix: 'localWaves.',
    allowed: `true, false or an object { ${LOCAL_WAVES_OPTION_KEYS.join(', ')} }`,
  });
  return localWaves;
}

/** A ParameterError unless `layer` has what the contract asks (waveLayer.ts), with a periodic layer's size over 0. */
function checkWaveLayer(layer: WaveLayer): void {
  const candidate = layer as Partial<WaveLayer> | null;
  const frame = candidate?.frame;
  const methods = ['update', 'queryFields', 'fieldsOnCpu', 'shownFieldsOnCpu', 'dispose'] as const;
  const wellFormed =
    typeof candidate === 'object' &&
    candidate !== null &&
    typeof candidate.textures?.displacement === 'object' &&
    typeof candidate.textures?.derivatives === 'object' &&
    typeof candidate.movesSideways === 'boolean' &&
    methods.every((method) => typeof candidate[method] === 'function') &&
    typeof frame === 'object' &&
    Number.isFinite(frame.size) &&
    frame.size > 0 &&
    Number.isInteger(frame.resolution) &&
    frame.resolution > 0 &&
    typeof frame.periodic === 'boolean' &&
    Number.isFinite(frame.origin?.[0]) &&
    Number.isFinite(frame.origin?.[1]);
  if (!wellFormed) {
    throw new ParameterError('layer', layer, `a WaveLayer (waveLayer.ts): { textures: { displacement, derivatives }, frame: { size > 0, origin, periodic, resolution }, movesSideways, ${methods.join(', ')} }`);
  }
}

function checkPreference(preference: PathPreference): PathPreference {
  if (!isPathPreference(preference)) {
    throw new ParameterError('path', preference, PATH_PREFERENCES_TEXT);
  }
  return preference;
}

