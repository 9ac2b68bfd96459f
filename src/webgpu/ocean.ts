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
 * spectra and seeded amplitudes: on the WebGPU backend, where the device can (path 'auto' or 'gpu',
 * src/fft/computeSupport.ts), evolved and transformed in compute shaders, src/fft/computeWaveFields.ts;
 * else by the JS FFT, src/fft/cpuFieldTextures.ts, in a worker by default, uploaded as float
 * textures each frame),
 * displaced and lit in TSL (seaNodes.ts, lightNodes.ts) as the WebGL Ocean's ocean.frag lights it:
 * the reflection of its analytic sky (skyNodes.ts, also drawn behind everything), the light from
 * under the surface, the caustics, the sun's glint and the crests' glow; and its whitecap foam,
 * the same field as the WebGL Ocean's JS path makes (src/layers/whitecapFoam.ts, over the largest
 * cascade's patch, on the same clock: in JS, uploaded as a float texture, or on the compute path in a
 * compute shader from the compute FFT's fields, computeFoam.ts), drawn as ocean.frag
 * draws it, with its streaks from force 7 and the spray from force 9 (foamNodes.ts); the scene's
 * objects reflected in it and seen through it (reflections and refractions 'scene', sceneLightNodes.ts); on its horizon rings round
 * the camera (seaRings.ts), placed before each draw. heightAt and normalAt answer from the same
 * fields and code as the WebGL Ocean's (src/layers/surfaceQuery.ts), so for the same options and
 * time they return the same numbers. Over a seabed (the `seabed` option, setSeabed) the waves
 * shoal and break, run up the beach and foam there, by the WebGL Ocean's shore (src/layers/shore.ts)
 * drawn by TSL twins of its GLSL (shoreNodes.ts), and the queries follow the same surface.
 *
 * From under the water it draws the surface's underside and the deep water behind it, as the WebGL
 * Ocean does (underWaterNodes.ts). When the renderer's device is lost it dispatches devicelost,
 * and update() then throws an UnsupportedError naming the lost device (deviceLoss.ts).
 *
 * What it does not draw yet throws an UnsupportedError when asked for (NOT_YET). Owns its
 * cascades, foam, shore, textures, geometry and materials; dispose() frees them, after which every
 * method throws a DisposedError.
 */
import { DoubleSide, FrontSide, Mesh, Object3D, SphereGeometry, Vector2, Vector3, type BufferGeometry, type Camera, type Texture } from 'three';
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
import { ComputeFoam } from './computeFoam';
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
import { Shore } from '../layers/shore';
import type { Seabed } from '../layers/seabed';
import { seabedMapFor, ShoreNodes } from './shoreNodes';
import { autoSkipsCompute, computePathUnsupported } from '../fft/computeSupport';

import { SceneLight } from './sceneLightNodes';
import { addSea, removeSea } from '../render/sceneCapture';
import type { ReflectionLayers } from '../render/sceneReflection';
import type { OceanEventMap, OceanPath, SeaStateSummary, SunPosition, WritableNumbers } from '../ocean';
import type { PathPreference } from '../layers/oceanSimulation';
import { velocityAt } from '../layers/surfaceQuery';
import { surfaceHeightsAt, surfaceVectorsAt, surfaceVelocityAt, type QueriedSea } from '../oceanQueries';
import { SeaStatistics, type StatisticsSource } from '../oceanStatistics';
import { isOptionsObject } from '../parameters/options';
import type { ShadingChanges, ShadingOptions } from '../parameters/sceneOptions';
import { readSunPosition } from '../render/sunPosition';
import { farEdgeDistance, FEWEST_CELLS_PER_RING } from '../render/horizonGrid';
import { setSkySun } from './skyNodes';
import { shadingOf, shadingWith, writeShading } from './seaShading';
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
  /**
   * 'auto': the compute FFT where the device can run it (a WebGPU backend, resolution 16 to 512,
   * src/fft/computeSupport.ts), else the JS FFT, saying why in `path.reason`; 'gpu': the compute FFT
   * (an UnsupportedError where it cannot run); 'js': the JS FFT. @defaultValue 'auto'
   */
  path?: PathPreference;
  /** 'scene': the scene's objects (reflectionLayers) reflected in the sea in front of its sky; 'sky': the sky alone (ShadingOptions.reflections). @defaultValue 'scene' */
  reflections?: 'sky' | 'scene';
  /** 'scene': what lies under the surface seen through it; 'sky': the sky through the water alone (ShadingOptions.refractions). @defaultValue 'scene' */
  refractions?: 'sky' | 'scene';
  /** Only false (the default here): local waves are not drawn yet. @defaultValue false */
  localWaves?: boolean | object;
  /**
   * The sea floor under part of the sea (OceanOptions.seabed, Ocean.setSeabed): waves shoal and
   * break over it. As a function or a heightfield; meshes are refused here (UnsupportedError).
   * @defaultValue null
   */
  seabed?: Seabed | null;
}

/** Options the WebGL Ocean has and this one does not yet: the value it draws, and what is missing. */
const NOT_YET: Record<string, { drawn: unknown; missing: string }> = {
  localWaves: { drawn: false, missing: 'local waves (stones, hulls)' },
  shadingMode: { drawn: 'full', missing: "the debug shading modes (shadingMode other than 'full')" },
};

/**
 * The options in `options` that ask for what this Ocean does not draw yet on `renderer`, each with
 * what is missing in words: the constructor refuses the first; <fft-ocean renderer="webgpu"> and
 * the app leave them out and say so. The GPU FFT (path 'gpu') runs in compute shaders, on the
 * WebGPU backend only.
 */
export function notDrawnYet(options: object, renderer: WebGPURenderer): { name: string; missing: string }[] {
  const notDrawn = optionsNotDrawnYet(options);
  if ((options as WebGPUOceanOptions).path === 'gpu' && !isWebGPUBackend(renderer)) {
    notDrawn.push({ name: 'path', missing: "the GPU FFT (path 'gpu') on WebGPURenderer's WebGL2 backend: there the fields come from the JS FFT ('auto' or 'js')" });
  }
  return notDrawn;
}

/** The options in `options` that ask for what NOT_YET names (notDrawnYet without the renderer's part). */
function optionsNotDrawnYet(options: object): { name: string; missing: string }[] {
  return Object.entries(NOT_YET)
    .filter(([name, { drawn }]) => {
      const value = (options as Record<string, unknown>)[name];
      return value !== undefined && value !== drawn;
    })
    .map(([name, { missing }]) => ({ name, missing }));
}

/** Refuses the first of `notDrawn` (notDrawnYet's) with an UnsupportedError naming it. */
function refuseNotDrawn(notDrawn: { name: string; missing: string }[]): void {
  const [first] = notDrawn;
  if (first) throw new UnsupportedError(first.name, `three-fft-ocean/webgpu does not draw ${first.missing} yet; use the WebGL Ocean (three-fft-ocean) for it`);
}

const SIMULATION_KEYS = Object.keys(SIMULATION_OPTIONS) as (keyof SimulationParameters)[];
const OPTION_KEYS: readonly string[] = [...SIMULATION_KEYS, 'ior', 'scatterColor', 'absorption', 'causticPower', 'causticColor', 'worker', ...Object.keys(SUN_OPTIONS), 'sunDirection', 'path', 'seabed', 'reflections', 'refractions', ...Object.keys(NOT_YET)];

/** What the WebGPU Ocean dispatches (three's addEventListener): the WebGL Ocean's events, and devicelost. */
export interface WebGPUOceanEventMap extends OceanEventMap {
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
  /** The whitecap foam over the largest cascade's patch (whitecapFoam.ts), in JS, or on path 'gpu' in a compute shader (computeFoam.ts). */
  private foam!: WhitecapFoam;
  /** The cascades' Jacobian statistics, and the foam's calibration for them at the current choppiness and wind (foamModel.ts). */
  private covariance!: JacobianCovariance;
  private calibration!: FoamCalibration;
  /** The foam pattern's textures and origin, for every surface material. */
  private readonly foamShading = new FoamShading();
  /** The streaks' and spray's values for the current wind (beaufortAppearance.ts). */
  private look!: BeaufortAppearance;
  private simulationParameters: SimulationParameters;
  private readonly uniforms: SeaUniforms;
  private readonly useWorker: boolean;
  private readonly renderer: WebGPURenderer;
  private readonly pathPreference: PathPreference;
  /** The renderer whose compute shaders make the cascades and the foam, or null for the JS FFT; chosen with the cascades (fftChoice). */
  private computeFft: WebGPURenderer | null = null;
  /** Why 'auto' runs the JS FFT, or ''. */
  private pathReason = '';
  private readonly support: FloatTextureSupport;
  private readonly surface: Mesh<BufferGeometry, MeshBasicNodeMaterial>;
  /** The rings' uniforms of the surface's material (made with it by surfaceMaterial), placed under the camera before each draw. */
  private rings!: SeaRings;
  /** Cells on a side of each ring, for the drawing buffer's height (cellsPerRingForViewport). */
  private cellsPerRing: number;
  private readonly drawingBuffer = new Vector2();
  private readonly skyMesh: Mesh<SphereGeometry, MeshBasicNodeMaterial>;
  /** The seabed and its shoaling factors (src/layers/shore.ts, the WebGL Ocean's), owned here. */
  private readonly shore = new Shore();
  /** The surface material's shore nodes over the shore's textures of now (shoreNodes.ts); null without a seabed. */
  private shoreNodes: ShoreNodes | null = null;
  /** The scene reflected in the sea and seen through it, and their captures (sceneLightNodes.ts). */
  private readonly sceneLight: SceneLight;
  private currentTime = 0;
  private lastTime = NaN;
  private disposed = false;
  /** The renderer's device, once lost (then update() throws); stops watching for the loss. */
  private lostDevice: DeviceLoss | null = null;
  private readonly unwatchDevice: () => void;

  constructor(renderer: WebGPURenderer, options: WebGPUOceanOptions = {}) {
    super();
    this.name = 'OceanWebGPU';
    this.support = floatTextureSupport(renderer);
    checkOptionNames(options, OPTION_KEYS, 'options', { allowed: 'an object of options, such as { windSpeed: 12 }' });
    refuseNotDrawn(notDrawnYet(options, renderer));
    const simulation: Partial<SimulationParameters> = {};
    for (const key of SIMULATION_KEYS) if (options[key] !== undefined) (simulation as Record<string, unknown>)[key] = options[key];
    this.simulationParameters = validateParameters(simulation);
    // Checked before anything is allocated: a bad seabed throws with nothing to free.
    this.shore.setMap(options.seabed === undefined || options.seabed === null ? null : seabedMapFor(options.seabed));
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
    this.renderer = renderer;
    this.pathPreference = checkPath(options.path);
    const reflections = checkOption(SHADING_OPTIONS, 'reflections', options.reflections ?? DEFAULT_SHADING.reflections).value;
    const refractions = checkOption(SHADING_OPTIONS, 'refractions', options.refractions ?? DEFAULT_SHADING.refractions).value;
    this.sceneLight = new SceneLight(renderer, { reflections: reflections === 'scene', refractions: refractions === 'scene' });
    this.buildCascades(this.fftChoice(this.parameters));
    this.cellsPerRing = cellsPerRingForViewport(renderer.getDrawingBufferSize(this.drawingBuffer).y, this.fewestCellsPerRing);
    this.surface = new Mesh(createHorizonGridGeometry(this.cellsPerRing), this.surfaceMaterial());
    this.surface.name = 'OceanWebGPU surface';
    this.surface.frustumCulled = false; // the grid follows the camera and moves up and down by the waves
    this.surface.onBeforeRender = (drawing, _scene, camera) => {
      this.fitGrid(drawing as unknown as WebGPURenderer);
      this.rings.place(camera, this.cellsPerRing);
      this.placeEye(camera);
      const eye = camera.matrixWorld.elements;
      this.foamShading.setEye(eye[12], eye[14], this.look);
      if (this.shoreNodes) this.placeShore(eye[12], eye[14]);
    };
    this.skyMesh = new Mesh(new SphereGeometry(1, 32, 16), skyMaterial(this.uniforms));
    this.skyMesh.name = 'OceanWebGPU sky';
    this.skyMesh.frustumCulled = false;
    this.skyMesh.renderOrder = -Infinity; // first, under everything
    // Before the sky, first in the render: the eye's side of the sea (the surface takes it too, so
    // both show the same frame's), then the captures of the scene the sea shows (sceneLightNodes.ts),
    // before any object of it is drawn.
    this.skyMesh.onBeforeRender = (drawing, scene, camera) => {
      this.placeEye(camera);
      this.sceneLight.capture(drawing as unknown as WebGPURenderer, scene, camera);
    };
    this.add(this.skyMesh, this.surface);
    // Every capture (this sea's and any other's) leaves this sea and its sky out (sceneCapture.ts).
    addSea(this, [this]);
    this.unwatchDevice = watchDeviceLoss(renderer, (loss) => {
      this.lostDevice = loss;
      this.dispatchEvent({ type: 'devicelost', loss });
    });
  }

  /**
   * Which objects the sea reflects with reflections 'scene' (the WebGL Ocean's reflectionLayers): a
   * three.js Layers, all layers at first; an object is reflected where its layers meet these and the
   * camera's. Change it in place (reflectionLayers.disable(1)).
   */
  get reflectionLayers(): ReflectionLayers {
    this.checkAlive('reflectionLayers');
    return this.sceneLight.reflection.layers;
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
   * The FFT path, as the WebGL Ocean's: the preference (the `path` option), the one running and,
   * when it is not the best the preference asks for, why ('' when it is). Running: 'gpu-rgba32f',
   * the compute FFT into RGBA32F fields (src/fft/computeSupport.ts says where it runs); 'js-worker',
   * the JS FFT in Web Workers; 'js', the JS FFT on the main thread (worker: false, or a worker
   * failed for good: the reason says why).
   */
  get path(): OceanPath {
    this.checkAlive('path');
    const workerFault = this.cascades.map((cascade) => cascade.workerFault).find((fault) => fault !== null) ?? null;
    const running = this.computeFft ? 'gpu-rgba32f' : this.useWorker && workerFault === null ? 'js-worker' : 'js';
    return { preference: this.pathPreference, running, reason: workerFault ?? this.pathReason };
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
    this.fitGrid(this.renderer); // as the WebGL Ocean fits its grid at update: a new size or quality level is drawn from this frame
    this.notePathChange();
  }

  /**
   * Height (m) of the water surface at the world point (x, z) at the last update's time: the same
   * answer as the WebGL Ocean's heightAt for the same options and time (surfaceQuery.ts).
   */
  heightAt(x: number, z: number): number {
    this.checkAlive('heightAt');
    checkCoordinates('heightAt', x, z);
    return heightAt(this.currentLayers, this.parameters.choppiness, this.currentTime, x, z, this.preparedShore());
  }

  /** Upward unit normal of the water surface over (x, z), written into `target` (surfaceQuery.ts). */
  normalAt(x: number, z: number, target: Vector3 = new Vector3()): Vector3 {
    this.checkAlive('normalAt');
    checkCoordinates('normalAt', x, z);
    return normalAt(this.currentLayers, this.parameters.choppiness, this.currentTime, x, z, target, this.preparedShore());
  }

  /**
   * Puts a sea floor under part of the sea, or takes it away (null), as the WebGL Ocean's setSeabed:
   * a function `{ depthAt(x, z), bounds: [xMin, zMin, xMax, zMax], resolution? }` or a heightfield
   * `{ depths, width, height, bounds }`; meshes (`{ meshes }`) throw an UnsupportedError here. Over
   * it each cascade shoals and breaks, with surf foam and swash on the beach, drawn and queried
   * alike (docs/shores.md). A bad seabed throws a ParameterError naming what is wrong and the last
   * good one stays.
   */
  setSeabed(seabed: Seabed | null): void {
    this.checkAlive('setSeabed');
    this.shore.setMap(seabed === null ? null : seabedMapFor(seabed));
    this.replaceSurfaceMaterial();
  }

  /** Depth of the sea floor (m below mean sea level; negative over land) under (x, z): the seabed's, else the `depth` option. */
  depthAt(x: number, z: number): number {
    this.checkAlive('depthAt');
    checkCoordinates('depthAt(x, z)', x, z);
    return this.shore.active ? this.shore.depthAt(x, z) : this.parameters.depth;
  }

  // ---- The WebGL Ocean's API (src/ocean.ts), each method documented there; the same shared code answers. ----

  /** The fewest cells a side of each ring of the grid (the WebGL Ocean's surface.fewestCellsPerRing): the quality levels lower it. */
  fewestCellsPerRing = FEWEST_CELLS_PER_RING;
  /** The running path at the last update, to tell when it changes (the pathchange event). */
  private runningPath: OceanPath['running'] | null = null;
  /** What the shared queries and statistics read: the cascades, their layers and the parameters now. */
  private readonly sea: QueriedSea & StatisticsSource = ((ocean: Ocean) => ({
    get layers() {
      return ocean.currentLayers;
    },
    get cascades() {
      return ocean.cascades;
    },
    get parameters() {
      return ocean.simulationParameters;
    },
  }))(this);
  /** The sea's statistics (the WebGL Ocean's): Hs and the peak period for the swash, heightRms and seaState. */
  private readonly statistics = new SeaStatistics(() => this.sea);

  /** The simulation parameters in force (Ocean.parameters). */
  get parameters(): Readonly<SimulationParameters> {
    this.checkAlive('parameters');
    return this.simulationParameters;
  }

  /** RMS of the sea's height over time, m, from the spectra (Ocean.heightRms, oceanStatistics.ts). */
  get heightRms(): number {
    this.checkAlive('heightRms');
    return this.statistics.heightRms;
  }

  /** Significant wave height and peak period of the parameters' sea (Ocean.seaState). */
  get seaState(): SeaStateSummary {
    this.checkAlive('seaState');
    return this.statistics.seaState;
  }

  /** Seconds after which the sea repeats exactly (Ocean.repeatPeriod). */
  get repeatPeriod(): number {
    this.checkAlive('repeatPeriod');
    return this.statistics.repeatPeriod;
  }

  /**
   * Distance (m) from a camera `cameraHeight` m up to the far edge of the surface drawn into the
   * renderer's drawing buffer at its current size (Ocean.horizonDistanceFor): the camera's far plane must reach it.
   */
  horizonDistanceFor(cameraHeight: number): number {
    this.checkAlive('horizonDistanceFor');
    if (typeof cameraHeight !== 'number' || !Number.isFinite(cameraHeight)) throw new ParameterError('cameraHeight', cameraHeight, 'a finite height in metres above the sea');
    const cells = cellsPerRingForViewport(this.renderer.getDrawingBufferSize(this.drawingBuffer).y, this.fewestCellsPerRing);
    return farEdgeDistance(cameraHeight, this.currentLayers, cells);
  }

  /** horizonDistanceFor the camera of the last render (sea level before the first, and after a rebuild until the next render). */
  get horizonDistance(): number {
    return this.horizonDistanceFor(this.rings.eyeHeight);
  }

  /** Velocity (m/s) of the water surface over (x, z) at the last update's time, in `target` (Ocean.velocityAt). */
  velocityAt(x: number, z: number, target = new Vector3()): Vector3 {
    this.checkAlive('velocityAt');
    return surfaceVelocityAt('velocityAt', this.sea, null, this.currentTime, x, z, target);
  }

  /** heightAt for the points x0, z0, x1, z1, … of `xz`, one per point into `out` (Ocean.heightsAt). Allocates nothing. */
  heightsAt<T extends WritableNumbers>(xz: ArrayLike<number>, out: T): T {
    this.checkAlive('heightsAt');
    return surfaceHeightsAt('heightsAt', this.sea, null, this.currentTime, xz, out);
  }

  /** normalAt for many points: three numbers per point of `xz` in `out` (Ocean.normalsAt). */
  normalsAt<T extends WritableNumbers>(xz: ArrayLike<number>, out: T): T {
    this.checkAlive('normalsAt');
    return surfaceVectorsAt('normalsAt', normalAt, this.sea, null, this.currentTime, xz, out);
  }

  /** velocityAt for many points: three numbers (m/s) per point of `xz` in `out` (Ocean.velocitiesAt). */
  velocitiesAt<T extends WritableNumbers>(xz: ArrayLike<number>, out: T): T {
    this.checkAlive('velocitiesAt');
    return surfaceVectorsAt('velocitiesAt', velocityAt, this.sea, null, this.currentTime, xz, out);
  }

  /** The shading options in use, colours as linear [r, g, b] (Ocean.shading). */
  get shading(): ShadingOptions {
    this.checkAlive('shading');
    return shadingOf(this.uniforms, this.sceneLight.options);
  }

  /**
   * Changes shading options as Ocean.setShading does: a bad one throws a ParameterError, a mode not
   * drawn here yet an UnsupportedError (as the constructor), and nothing changes.
   */
  setShading(changes: ShadingChanges): void {
    this.checkAlive('setShading');
    if (!isOptionsObject(changes)) throw new ParameterError('setShading', changes, 'an object of shading options, such as { ior: 1.34 }');
    const drawn = this.sceneLight.options;
    const next = shadingWith(this.uniforms, drawn, changes);
    refuseNotDrawn(optionsNotDrawnYet(next));
    // The captures are made with the Ocean (sceneLightNodes.ts): here they are chosen by the constructor only.
    for (const name of ['reflections', 'refractions'] as const) {
      if ((next[name] === 'scene') !== drawn[name]) throw new UnsupportedError(name, `three-fft-ocean/webgpu sets ${name} when the Ocean is made, not by setShading: make a new Ocean with { ${name}: '${next[name]}' }`);
    }
    writeShading(this.uniforms, next);
  }

  /** Moves the sun, or clouds the sky over, as Ocean.setSun: the sky, glint, caustics and foam's light follow. */
  setSun(elevation: number, azimuth: number): void;
  setSun(sun: SunPosition): void;
  setSun(sunOrElevation: SunPosition | number, azimuth?: number): void {
    this.checkAlive('setSun');
    const sky = this.uniforms.sky;
    const sun = readSunPosition(sunOrElevation, azimuth, sky.angles);
    setSkySun(sky, sun.elevation, sun.azimuth, sun.cloudCover ?? sky.cloudCover.value);
  }

  /** Dispatches pathchange when the running path changed since the last update (not at the first). */
  private notePathChange(): void {
    const { running } = this.path;
    if (running === this.runningPath) return;
    const first = this.runningPath === null;
    this.runningPath = running;
    if (!first) this.dispatchEvent({ type: 'pathchange', path: this.path });
  }

  // ---- (end of the WebGL Ocean's API) ----

  /** Changes some simulation parameters (a ParameterError names the first bad one and changes nothing). */
  setParameters(changes: Partial<SimulationParameters>): void {
    this.checkAlive('setParameters');
    const next = validateParameters(changes, this.parameters);
    const choice = this.fftChoice(next); // path 'gpu' at a resolution it cannot run throws here, changing nothing
    // As the WebGL Ocean's simulation: the spectra stay for the parameters only the shading and the foam read.
    const keepSpectra = (Object.keys(next) as (keyof SimulationParameters)[]).every((key) => SHADER_ONLY_PARAMETERS.includes(key) || String(next[key]) === String(this.parameters[key]));
    this.simulationParameters = next;
    this.uniforms.choppiness.value = next.choppiness;
    if (keepSpectra) {
      this.calibration = calibrateFoam(this.covariance, next.choppiness, next.windSpeed);
      return;
    }
    this.disposeCascades();
    this.buildCascades(choice);
    this.replaceSurfaceMaterial();
  }

  /** Frees the cascades (their textures and workers), the grid, the sky and the materials. */
  dispose(): void {
    if (this.disposed) return;
    this.unwatchDevice();
    this.disposeCascades();
    this.cascades = [];
    this.currentLayers = [];
    this.foamShading.dispose();
    this.sceneLight.dispose();
    removeSea(this);
    this.surface.geometry.dispose();
    this.surface.material.dispose();
    this.skyMesh.geometry.dispose();
    this.skyMesh.material.dispose();
    this.shore.dispose();
    this.shoreNodes = null;
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
    // scene.fog falls on the sea seen from above only: ocean.frag returns before its fog where it shades
    // the underside. Here the whole material follows the eye (made again when the eye crosses).
    const fogged = eye.side.value !== EYE_SIDE.below;
    if (this.surface.material.fog !== fogged) {
      this.surface.material.fog = fogged;
      this.surface.material.needsUpdate = true;
    }
  }

  /** The surface's material over the current layers and seabed, with new rings for them. */
  private surfaceMaterial(): MeshBasicNodeMaterial {
    this.rings = new SeaRings(this.currentLayers);
    const foam = { coverage: this.foam.texture.value as Texture, shading: this.foamShading, look: this.look };
    const shore = this.preparedShore();
    this.shoreNodes = shore ? new ShoreNodes(shore) : null;
    const lighting = seaLightingValues(this.currentLayers, this.parameters.windSpeed);
    // The mirror render keeps the scene down to the troughs (sceneReflection.ts), as the WebGL Ocean's: its RMS height.
    this.sceneLight.reflection.troughDepth = lighting.heightRms;
    return seaMaterial(this.currentLayers, this.uniforms, lighting, this.rings, foam, this.shoreNodes, this.sceneLight);
  }

  /** Makes the surface's material again (new layers, a new seabed) and frees the one before. */
  private replaceSurfaceMaterial(): void {
    const old = this.surface.material;
    this.surface.material = this.surfaceMaterial();
    old.dispose();
  }

  /** The shore for the queries and the surface, its factors made for the layers of now; null without a seabed. */
  private preparedShore(): Shore | null {
    if (!this.shore.active) return null;
    this.shore.prepare(this.currentLayers, this.cascades, this.parameters.depth, 4 * this.statistics.heightRms, this.statistics.seaState.peakPeriod);
    return this.shore;
  }

  /** Before each draw: the shore's values for the eye at (x, z) m, into the material's nodes. */
  private placeShore(x: number, z: number): void {
    this.preparedShore();
    this.shore.setEye(x, z);
    this.shoreNodes!.sync();
  }

  /**
   * Gives the grid as many cells a ring as the drawing buffer's height asks for. three takes a
   * mesh's geometry before its onBeforeRender, so a grid replaced there is drawn from the next frame.
   */
  private fitGrid(renderer: WebGPURenderer): void {
    const cells = cellsPerRingForViewport(renderer.getDrawingBufferSize(this.drawingBuffer).y, this.fewestCellsPerRing);
    if (cells === this.cellsPerRing) return;
    this.surface.geometry.dispose();
    this.surface.geometry = createHorizonGridGeometry(cells);
    this.cellsPerRing = cells;
  }

  /**
   * The cascades of the parameters and their foam: their textures ask nothing more of the renderer
   * than `support`, read once.
   */
  private buildCascades({ compute, reason }: { compute: boolean; reason: string }): void {
    const params = this.parameters;
    const renderer = (this.computeFft = compute ? this.renderer : null);
    this.pathReason = reason;
    const backend: FftBackend<null> = renderer ? (_none, spectrum) => new ComputeWaveFields(renderer, spectrum) : (_none, spectrum) => new CpuFieldTextures(this.support, spectrum, this.useWorker);
    const spectra = createCascadeSpectra(params);
    this.cascades = spectra.map((spectrum, cascade) => new FftCascade(null, spectrum, { params, cascade }, backend, this.useWorker));
    this.currentLayers = orderLayers(this.cascades);
    this.covariance = jacobianCovariance(spectra);
    this.calibration = calibrateFoam(this.covariance, params.choppiness, params.windSpeed);
    this.foam = new WhitecapFoam(this.currentLayers, renderer ? { producer: (layers, frame) => new ComputeFoam(renderer, layers, frame) } : { js: this.support });
    this.look = beaufortAppearance(params.windSpeed, params.windDirection);
    this.lastTime = NaN;
  }

  /**
   * Whether the cascades of `params` run on the compute path and, when 'auto' cannot, why: 'js'
   * never; 'auto' where computePathUnsupported finds nothing missing; 'gpu' there too, else it throws.
   */
  private fftChoice(params: SimulationParameters): { compute: boolean; reason: string } {
    if (this.pathPreference === 'js') return { compute: false, reason: '' };
    const unsupported = computePathUnsupported(this.renderer, params.resolution);
    if (unsupported === null) {
      const slower = this.pathPreference === 'auto' ? autoSkipsCompute(this.renderer) : null;
      return slower === null ? { compute: true, reason: '' } : { compute: false, reason: slower };
    }
    if (this.pathPreference === 'gpu') throw new UnsupportedError('path', `the compute FFT (path 'gpu') cannot run here: ${unsupported}; 'auto' or 'js' runs the JS FFT`);
    return { compute: false, reason: unsupported };
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

/** The `path` option, checked ('auto' when left out). */
function checkPath(path: unknown): PathPreference {
  if (path === undefined) return 'auto';
  if (path !== 'auto' && path !== 'js' && path !== 'gpu') throw new ParameterError('path', path, "'auto', 'js' or 'gpu'");
  return path;
}

function isWebGPUBackend(renderer: WebGPURenderer): boolean {
  return (renderer.backend as { isWebGPUBackend?: boolean }).isWebGPUBackend === true;
}

/** A colour option checked by SHADING_OPTIONS' own rule (the WebGL Ocean's), as linear [r, g, b]; `fallback` when not given. */
function linearColor(name: 'scatterColor' | 'causticColor', value: ColorInput | undefined, fallback: readonly [number, number, number]): [number, number, number] {
  if (value === undefined) return [fallback[0], fallback[1], fallback[2]];
  return checkOption(SHADING_OPTIONS, name, value).value as [number, number, number];
}
