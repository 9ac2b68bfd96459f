/**
 * The Ocean for three.js's WebGPURenderer (`three/webgpu`), on its WebGPU backend and on its WebGL2
 * backend (`forceWebGL: true`): `import { Ocean } from 'three-fft-ocean/webgpu'`.
 *
 *   const renderer = new WebGPURenderer();
 *   await renderer.init();
 *   const ocean = new Ocean(renderer, { windSpeed: 12, seed: 7 });
 *   scene.add(ocean);
 *   renderer.setAnimationLoop((ms) => { ocean.update(ms / 1000); renderer.render(scene, camera); });
 *
 * This first slice draws the FFT cascades of the same sea as the WebGL Ocean (the same parameters,
 * spectra and seeded amplitudes, computed by the JS FFT: src/fft/cpuFieldTextures.ts, in a worker
 * by default, uploaded as float textures each frame; with path 'gpu' on the WebGPU backend, by the
 * compute FFT instead: src/fft/computeWaveFields.ts),
 * displaced and lit in TSL (seaNodes.ts, lightNodes.ts) as the WebGL Ocean's ocean.frag lights it:
 * the reflection of its analytic sky (skyNodes.ts, also drawn behind everything), the light from
 * under the surface, the caustics, the sun's glint and the crests' glow; and its whitecap foam,
 * the same field as the WebGL Ocean's JS path makes (src/layers/whitecapFoam.ts, in JS over the
 * largest cascade's patch, on the same clock, uploaded as a float texture), drawn as ocean.frag
 * draws it, with its streaks from force 7 and the spray from force 9 (foamNodes.ts); on its horizon rings round
 * the camera (seaRings.ts), placed before each draw. heightAt and normalAt answer from the same
 * fields and code as the WebGL Ocean's (src/layers/surfaceQuery.ts), so for the same options and
 * time they return the same numbers.
 *
 * From under the water it draws the surface's underside and the deep water behind it, as the WebGL
 * Ocean does (underWaterNodes.ts). When the renderer's device is lost it dispatches devicelost,
 * and update() then throws an UnsupportedError naming the lost device (deviceLoss.ts).
 *
 * What it does not draw yet throws an UnsupportedError when asked for (NOT_YET). Owns its
 * cascades, foam, textures, geometry and materials; dispose() frees them, after which every method
 * throws a DisposedError.
 */
import { DoubleSide, FrontSide, Mesh, Object3D, SphereGeometry, Vector2, Vector3, type BufferGeometry, type Camera, type Object3DEventMap, type Texture } from 'three';
import type { MeshBasicNodeMaterial, WebGPURenderer } from 'three/webgpu';
import { uniform } from 'three/tsl';
import { CpuFieldTextures, type FloatTextureSupport } from '../fft/cpuFieldTextures';
import { ComputeWaveFields } from '../fft/computeWaveFields';
import { FftCascade, type FftBackend } from '../layers/fftCascade';
import { heightAt, normalAt } from '../layers/surfaceQuery';
import { orderLayers, type WaveLayer } from '../layers/waveLayer';
import { checkOption, checkOptionNames, DisposedError, UnsupportedError } from '../parameters/options';
import { ParameterError, SHADER_ONLY_PARAMETERS, SIMULATION_OPTIONS, validateParameters, type SimulationParameters } from '../parameters/parameters';
import { calibrateFoam, jacobianCovariance, type FoamCalibration, type JacobianCovariance } from '../layers/foamModel';
import { WhitecapFoam } from '../layers/whitecapFoam';
import { beaufortAppearance, type BeaufortAppearance } from '../render/beaufortAppearance';
import { FoamShading } from './foamNodes';
import { DEFAULT_SHADING, DEFAULT_SUN, SHADING_OPTIONS, SUN_OPTIONS, type ColorInput } from '../parameters/sceneOptions';
import { sunAngles, type SunDirection } from '../render/skyEnvironment';
import { createCascadeSpectra } from '../spectrum/initialSpectrum';
import { SeaRings } from './seaRings';
import { cellsPerRingForViewport, createHorizonGridGeometry } from '../render/horizonGrid';
import { seaMaterial, skyMaterial, type SeaUniforms } from './seaNodes';
import { skyUniforms } from './skyNodes';
import { seaLightingValues } from '../render/seaLighting';
import { checkCoordinates } from '../oceanQueries';
import { checkRenderer } from '../device/deviceFor';
import { SeaStatistics } from '../oceanStatistics';
import { EYE_SIDE, surfaceBoundFor } from '../render/seaSurfaceMaterial';
import { UnderWaterEye } from './underWaterNodes';
import { deviceLostError, watchDeviceLoss, type DeviceLoss } from './deviceLoss';

export interface WebGPUOceanOptions extends Partial<SimulationParameters> {
  /** Refractive index of water n_w, (1, 3] (ShadingOptions.ior). @defaultValue 1.333 */
  ior?: number;
  /** Colour of the light deep water scatters back, any ColorInput (an array is linear RGB). @defaultValue [0.0, 0.035, 0.06] */
  scatterColor?: ColorInput;
  /** Beer–Lambert absorption σ per colour channel, 1/m (ShadingOptions.absorption). @defaultValue [0.45, 0.07, 0.04] */
  absorption?: [number, number, number];
  /** Exponent of the caustics' brightness (ShadingOptions.causticPower). @defaultValue 32 */
  causticPower?: number;
  /** Colour of the caustics, any ColorInput (ShadingOptions.causticColor). @defaultValue [0.12, 0.12, 0.12] */
  causticColor?: ColorInput;
  /** Sun elevation above the horizon in degrees, [-90, 90] (OceanOptions.sunElevation). @defaultValue 30 */
  sunElevation?: number;
  /** Sun azimuth in degrees from +x towards +z (OceanOptions.sunAzimuth). @defaultValue 40 */
  sunAzimuth?: number;
  /** Direction towards the sun instead of sunElevation and sunAzimuth, y up, any length (OceanOptions.sunDirection). @defaultValue undefined */
  sunDirection?: SunDirection;
  /** How much of the sky is cloud, [0, 1]: 0 clear, 1 overcast (OceanOptions.cloudCover). @defaultValue 0 */
  cloudCover?: number;
  /** Compute the JS FFT in a Web Worker (SimulationOptions.worker). @defaultValue true where Worker exists */
  worker?: boolean;
  /** 'auto' or 'js': the JS FFT; 'gpu': the compute FFT, on the WebGPU backend only (it throws on the WebGL2 backend). @defaultValue 'auto' */
  path?: 'auto' | 'js' | 'gpu';
  /** Only 'sky' (the default here): scene reflections are not drawn yet. @defaultValue 'sky' */
  reflections?: 'sky' | 'scene';
  /** Only 'sky' (the default here): objects under the water are not drawn yet. @defaultValue 'sky' */
  refractions?: 'sky' | 'scene';
  /** Only false (the default here): local waves are not drawn yet. @defaultValue false */
  localWaves?: boolean | object;
  /** Only null (the default): no seabed yet. @defaultValue null */
  seabed?: object | null;
}

/** Options the WebGL Ocean has and this one does not yet: the value it draws, and what is missing. */
const NOT_YET: Record<string, { drawn: unknown; missing: string }> = {
  reflections: { drawn: 'sky', missing: "scene reflections (reflections: 'scene'): the sea reflects its sky" },
  refractions: { drawn: 'sky', missing: "objects seen under the water (refractions: 'scene')" },
  localWaves: { drawn: false, missing: 'local waves (stones, hulls)' },
  seabed: { drawn: null, missing: 'a seabed (shoaling, breaking, the shore)' },
  shadingMode: { drawn: 'full', missing: "the debug shading modes (shadingMode other than 'full')" },
};

/**
 * The options in `options` that ask for what this Ocean does not draw yet on `renderer`, each with
 * what is missing in words: the constructor refuses the first; <fft-ocean renderer="webgpu"> and
 * the app leave them out and say so. The GPU FFT (path 'gpu') runs in compute shaders, on the
 * WebGPU backend only.
 */
export function notDrawnYet(options: object, renderer: WebGPURenderer): { name: string; missing: string }[] {
  const notDrawn = Object.entries(NOT_YET)
    .filter(([name, { drawn }]) => {
      const value = (options as Record<string, unknown>)[name];
      return value !== undefined && value !== drawn;
    })
    .map(([name, { missing }]) => ({ name, missing }));
  if ((options as WebGPUOceanOptions).path === 'gpu' && !isWebGPUBackend(renderer)) {
    notDrawn.push({ name: 'path', missing: "the GPU FFT (path 'gpu') on WebGPURenderer's WebGL2 backend: there the fields come from the JS FFT ('auto' or 'js')" });
  }
  return notDrawn;
}

const SIMULATION_KEYS = Object.keys(SIMULATION_OPTIONS) as (keyof SimulationParameters)[];
const OPTION_KEYS: readonly string[] = [...SIMULATION_KEYS, 'ior', 'scatterColor', 'absorption', 'causticPower', 'causticColor', 'worker', ...Object.keys(SUN_OPTIONS), 'sunDirection', 'path', ...Object.keys(NOT_YET)];

/** What the WebGPU Ocean dispatches (three's addEventListener), beside Object3D's own events. */
export interface WebGPUOceanEventMap extends Object3DEventMap {
  /**
   * The renderer's device was lost (deviceLoss.ts: the WebGPU device, or the WebGL2 backend's
   * context), once; from then on update() throws an UnsupportedError naming it (ocean.deviceLost).
   */
  devicelost: { loss: DeviceLoss };
}

export class Ocean extends Object3D<WebGPUOceanEventMap> {
  /** The FFT cascades, finest first (the JS FFT's fields as float textures). */
  private cascades: FftCascade<null>[] = [];
  private currentLayers: readonly WaveLayer[] = [];
  /** The whitecap foam over the largest cascade's patch, computed in JS (whitecapFoam.ts). */
  private foam!: WhitecapFoam;
  /** The cascades' Jacobian statistics, and the foam's calibration for them at the current choppiness and wind (foamModel.ts). */
  private covariance!: JacobianCovariance;
  private calibration!: FoamCalibration;
  /** The foam pattern's textures and origin, for every surface material. */
  private readonly foamShading = new FoamShading();
  /** The streaks' and spray's values for the current wind (beaufortAppearance.ts). */
  private look!: BeaufortAppearance;
  private parameters: SimulationParameters;
  private readonly uniforms: SeaUniforms;
  private readonly useWorker: boolean;
  /** The renderer whose compute shaders transform the cascades (path 'gpu'), or null for the JS FFT. */
  private readonly computeFft: WebGPURenderer | null;
  private readonly support: FloatTextureSupport;
  private readonly surface: Mesh<BufferGeometry, MeshBasicNodeMaterial>;
  /** The rings' uniforms of the surface's material (made with it by surfaceMaterial), placed under the camera before each draw. */
  private rings!: SeaRings;
  /** Cells on a side of each ring, for the drawing buffer's height (cellsPerRingForViewport). */
  private cellsPerRing: number;
  private readonly drawingBuffer = new Vector2();
  private readonly skyMesh: Mesh<SphereGeometry, MeshBasicNodeMaterial>;
  private currentTime = 0;
  private lastTime = NaN;
  private disposed = false;
  /** The height's RMS for the eye's side of the sea (oceanStatistics.ts, as the WebGL Ocean's). */
  private readonly statistics = new SeaStatistics(() => ({ cascades: this.cascades, parameters: this.parameters }));
  /** The renderer's device, once lost (then update() throws); stops watching for the loss. */
  private lostDevice: DeviceLoss | null = null;
  private readonly unwatchDevice: () => void;

  constructor(renderer: WebGPURenderer, options: WebGPUOceanOptions = {}) {
    super();
    this.name = 'OceanWebGPU';
    this.support = floatTextureSupport(renderer);
    checkOptionNames(options, OPTION_KEYS, 'options', { allowed: 'an object of options, such as { windSpeed: 12 }' });
    const [first] = notDrawnYet(options, renderer);
    if (first) throw new UnsupportedError(first.name, `three-fft-ocean/webgpu does not draw ${first.missing} yet; use the WebGL Ocean (three-fft-ocean) for it`);
    const simulation: Partial<SimulationParameters> = {};
    for (const key of SIMULATION_KEYS) if (options[key] !== undefined) (simulation as Record<string, unknown>)[key] = options[key];
    this.parameters = validateParameters(simulation);
    const ior = options.ior ?? DEFAULT_SHADING.ior;
    const absorption = options.absorption ?? DEFAULT_SHADING.absorption;
    const causticPower = options.causticPower ?? DEFAULT_SHADING.causticPower;
    checkOption(SHADING_OPTIONS, 'ior', ior);
    checkOption(SHADING_OPTIONS, 'absorption', absorption);
    checkOption(SHADING_OPTIONS, 'causticPower', causticPower);
    const sun = sunAngles({ elevation: options.sunElevation, azimuth: options.sunAzimuth, direction: options.sunDirection }, { elevation: DEFAULT_SUN.sunElevation, azimuth: DEFAULT_SUN.sunAzimuth }, 'sunDirection');
    checkOption(SUN_OPTIONS, 'sunElevation', sun.elevation);
    checkOption(SUN_OPTIONS, 'sunAzimuth', sun.azimuth);
    const cloudCover = options.cloudCover ?? DEFAULT_SUN.cloudCover;
    checkOption(SUN_OPTIONS, 'cloudCover', cloudCover);
    this.uniforms = {
      choppiness: uniform(this.parameters.choppiness),
      ior: uniform(ior),
      scatterColor: uniform(new Vector3(...linearColor('scatterColor', options.scatterColor, DEFAULT_SHADING.scatterColor))),
      absorption: uniform(new Vector3(...absorption)),
      causticPower: uniform(causticPower),
      causticColor: uniform(new Vector3(...linearColor('causticColor', options.causticColor, DEFAULT_SHADING.causticColor))),
      sky: skyUniforms(sun.elevation, sun.azimuth, cloudCover),
      eye: new UnderWaterEye(),
    };
    this.useWorker = options.worker ?? typeof Worker !== 'undefined';
    this.computeFft = computeFftRenderer(renderer, options.path);
    this.buildCascades();
    this.cellsPerRing = cellsPerRingForViewport(renderer.getDrawingBufferSize(this.drawingBuffer).y);
    this.surface = new Mesh(createHorizonGridGeometry(this.cellsPerRing), this.surfaceMaterial());
    this.surface.name = 'OceanWebGPU surface';
    this.surface.frustumCulled = false; // the grid follows the camera and moves up and down by the waves
    this.surface.onBeforeRender = (drawing, _scene, camera) => {
      this.fitGrid(drawing as unknown as WebGPURenderer);
      this.rings.place(camera, this.cellsPerRing);
      this.placeEye(camera);
      const eye = camera.matrixWorld.elements;
      this.foamShading.setEye(eye[12], eye[14], this.look);
    };
    this.skyMesh = new Mesh(new SphereGeometry(1, 32, 16), skyMaterial(this.uniforms));
    this.skyMesh.name = 'OceanWebGPU sky';
    this.skyMesh.frustumCulled = false;
    this.skyMesh.renderOrder = -Infinity; // first, under everything
    // Drawn before the surface: it takes the eye's side too, so both show the same frame's.
    this.skyMesh.onBeforeRender = (_drawing, _scene, camera) => this.placeEye(camera);
    this.add(this.skyMesh, this.surface);
    this.unwatchDevice = watchDeviceLoss(renderer, (loss) => {
      this.lostDevice = loss;
      this.dispatchEvent({ type: 'devicelost', loss });
    });
  }

  /** The renderer's lost device (why and the browser's message), or null while it lives. */
  get deviceLost(): DeviceLoss | null {
    this.checkAlive('deviceLost');
    return this.lostDevice;
  }

  /** Every wave layer (the cascades), in the order the surface and the queries sum them. */
  get waveLayers(): readonly WaveLayer[] {
    this.checkAlive('waveLayers');
    return this.currentLayers;
  }

  /**
   * Which FFT computes the cascades: 'gpu', the compute FFT (path 'gpu', on the WebGPU backend), or
   * 'js', the JS FFT ('auto' and 'js'), as the WebGL Ocean's `path.running` names its own.
   */
  get path(): 'gpu' | 'js' {
    this.checkAlive('path');
    return this.computeFft ? 'gpu' : 'js';
  }

  /** The time (s) of the last update. */
  get time(): number {
    this.checkAlive('time');
    return this.currentTime;
  }

  /** Computes the sea at time t (s, any finite value), then its foam, and uploads their fields. */
  update(t: number): void {
    this.checkAlive('update');
    if (!Number.isFinite(t)) throw new ParameterError('time', t, 'a finite number of seconds');
    if (this.lostDevice) throw deviceLostError(this.lostDevice, 'Ocean.update');
    const step = Number.isNaN(this.lastTime) ? 0 : t - this.lastTime;
    for (const cascade of this.cascades) cascade.update(t, step);
    const { choppiness, foamAmount, foamPersistence } = this.parameters;
    this.foam.update(t, { choppiness, calibration: this.calibration, amount: foamAmount, persistence: foamPersistence });
    this.currentTime = this.lastTime = t;
  }

  /**
   * Height (m) of the water surface at the world point (x, z) at the last update's time: the same
   * answer as the WebGL Ocean's heightAt for the same options and time (surfaceQuery.ts).
   */
  heightAt(x: number, z: number): number {
    this.checkAlive('heightAt');
    checkCoordinates('heightAt', x, z);
    return heightAt(this.currentLayers, this.parameters.choppiness, this.currentTime, x, z);
  }

  /** Upward unit normal of the water surface over (x, z), written into `target` (surfaceQuery.ts). */
  normalAt(x: number, z: number, target: Vector3 = new Vector3()): Vector3 {
    this.checkAlive('normalAt');
    checkCoordinates('normalAt', x, z);
    return normalAt(this.currentLayers, this.parameters.choppiness, this.currentTime, x, z, target);
  }

  /** Changes some simulation parameters (a ParameterError names the first bad one and changes nothing). */
  setParameters(changes: Partial<SimulationParameters>): void {
    this.checkAlive('setParameters');
    const next = validateParameters(changes, this.parameters);
    // As the WebGL Ocean's simulation: the spectra stay for the parameters only the shading and the foam read.
    const keepSpectra = (Object.keys(next) as (keyof SimulationParameters)[]).every((key) => SHADER_ONLY_PARAMETERS.includes(key) || String(next[key]) === String(this.parameters[key]));
    this.parameters = next;
    this.uniforms.choppiness.value = next.choppiness;
    if (keepSpectra) {
      this.calibration = calibrateFoam(this.covariance, next.choppiness, next.windSpeed);
      return;
    }
    this.disposeCascades();
    this.buildCascades();
    const old = this.surface.material;
    this.surface.material = this.surfaceMaterial();
    old.dispose();
  }

  /** Frees the cascades (their textures and workers), the grid, the sky and the materials. */
  dispose(): void {
    if (this.disposed) return;
    this.unwatchDevice();
    this.disposeCascades();
    this.cascades = [];
    this.currentLayers = [];
    this.foamShading.dispose();
    this.surface.geometry.dispose();
    this.surface.material.dispose();
    this.skyMesh.geometry.dispose();
    this.skyMesh.material.dispose();
    this.removeFromParent();
    this.disposed = true;
  }

  /** Takes which side of the sea `camera` is on, for the surface and the sky (underWaterNodes.ts). */
  private placeEye(camera: Camera): void {
    const { choppiness } = this.parameters;
    const eye = this.uniforms.eye;
    eye.place(camera, surfaceBoundFor(this.statistics.heightRms), (x, z) => heightAt(this.currentLayers, choppiness, this.currentTime, x, z));
    // From above only the faces turned up are drawn: on the WebGPU backend the backs drawn too put a
    // line along the horizon that the WebGL Ocean has not (514 pixels beyond 8 levels in the default
    // view against 34). From below or at the waterline, both (OceanMaterial's DoubleSide).
    this.surface.material.side = eye.side.value === EYE_SIDE.above ? FrontSide : DoubleSide;
  }

  /** The surface's material over the current layers, with new rings for them. */
  private surfaceMaterial(): MeshBasicNodeMaterial {
    this.rings = new SeaRings(this.currentLayers);
    const foam = { coverage: this.foam.texture.value as Texture, shading: this.foamShading, look: this.look };
    return seaMaterial(this.currentLayers, this.uniforms, seaLightingValues(this.currentLayers, this.parameters.windSpeed), this.rings, foam);
  }

  /**
   * Gives the grid as many cells a ring as the drawing buffer's height asks for. three takes a
   * mesh's geometry before its onBeforeRender, so a grid replaced there is drawn from the next frame.
   */
  private fitGrid(renderer: WebGPURenderer): void {
    const cells = cellsPerRingForViewport(renderer.getDrawingBufferSize(this.drawingBuffer).y);
    if (cells === this.cellsPerRing) return;
    this.surface.geometry.dispose();
    this.surface.geometry = createHorizonGridGeometry(cells);
    this.cellsPerRing = cells;
  }

  /**
   * The cascades of the parameters and their foam: their textures ask nothing more of the renderer
   * than `support`, read once.
   */
  private buildCascades(): void {
    const params = this.parameters;
    const renderer = this.computeFft;
    const backend: FftBackend<null> = renderer ? (_none, spectrum) => new ComputeWaveFields(renderer, spectrum) : (_none, spectrum) => new CpuFieldTextures(this.support, spectrum, this.useWorker);
    const spectra = createCascadeSpectra(params);
    this.cascades = spectra.map((spectrum, cascade) => new FftCascade(null, spectrum, { params, cascade }, backend, this.useWorker));
    this.currentLayers = orderLayers(this.cascades);
    this.covariance = jacobianCovariance(spectra);
    this.calibration = calibrateFoam(this.covariance, params.choppiness, params.windSpeed);
    this.foam = new WhitecapFoam(this.currentLayers, { js: this.support });
    this.look = beaufortAppearance(params.windSpeed, params.windDirection);
    this.lastTime = NaN;
  }

  private disposeCascades(): void {
    for (const cascade of this.cascades) cascade.dispose();
    this.foam.dispose();
  }

  private checkAlive(what: string): void {
    if (this.disposed) throw new DisposedError(`Ocean.${what}`);
  }
}

/**
 * What the renderer's device does with RGBA32F textures. The surface samples them bilinearly, as
 * the queries do: without filtering it would differ from heightAt, so that is refused.
 */
function floatTextureSupport(renderer: WebGPURenderer): FloatTextureSupport {
  checkRenderer(renderer, 'three-fft-ocean/webgpu');
  if (!renderer.initialized) throw new UnsupportedError('renderer', 'the WebGPURenderer is not initialized yet: await renderer.init() before making the Ocean');
  const backend = renderer.backend as { isWebGPUBackend?: boolean };
  const filterable = backend.isWebGPUBackend
    ? renderer.hasFeature('float32-filterable')
    : (renderer.getContext() as WebGL2RenderingContext).getExtension('OES_texture_float_linear') !== null;
  if (!filterable) {
    throw new UnsupportedError('renderer', `this device cannot filter RGBA32F textures (${backend.isWebGPUBackend ? "WebGPU feature 'float32-filterable'" : 'WebGL2 extension OES_texture_float_linear'}), which three-fft-ocean/webgpu needs`);
  }
  // The mipmap levels are made in JS (CpuFieldTextures): three's mipmap generation is not asked to render into float textures.
  return { filterable, renderable: false };
}

/** `renderer` where `path` asks for the compute FFT ('gpu'; notDrawnYet refuses it on the WebGL2 backend), else null. */
function computeFftRenderer(renderer: WebGPURenderer, path: WebGPUOceanOptions['path']): WebGPURenderer | null {
  if (path !== undefined && path !== 'auto' && path !== 'js' && path !== 'gpu') throw new ParameterError('path', path, "'auto', 'js' or 'gpu'");
  return path === 'gpu' ? renderer : null;
}

function isWebGPUBackend(renderer: WebGPURenderer): boolean {
  return (renderer.backend as { isWebGPUBackend?: boolean }).isWebGPUBackend === true;
}

/** A colour option checked by SHADING_OPTIONS' own rule (the WebGL Ocean's), as linear [r, g, b]; `fallback` when not given. */
function linearColor(name: 'scatterColor' | 'causticColor', value: ColorInput | undefined, fallback: readonly [number, number, number]): [number, number, number] {
  if (value === undefined) return [fallback[0], fallback[1], fallback[2]];
  return checkOption(SHADING_OPTIONS, name, value).value as [number, number, number];
}
