/**
 * Ocean: the whole sea as one three.js Object3D — simulation (src/layers/oceanSimulation.ts), sky (SkyEnvironment) and
 * surface (OceanSurface) — for any scene.
 *
 *   const ocean = new Ocean(renderer, { windSpeed: 12, seed: 7 });
 *   scene.add(ocean);                    // the sea and, behind everything, its sky
 *   renderer.setAnimationLoop((ms) => { ocean.update(ms / 1000, camera); renderer.render(scene, camera); });
 *
 * The sea is the plane y = 0 of world space; give the camera a far plane of at least
 * ocean.horizonDistanceFor(camera's height) (several thousand heights) so the surface reaches the
 * horizon. Owns everything it creates and frees it in dispose(); after that every method and getter
 * throws a DisposedError.
 */
import { Object3D, Vector3, type Object3DEventMap, type WebGLRenderer } from 'three';
import { OceanSurface } from './render/oceanSurface';
import type { ReflectionLayers } from './render/sceneReflection';
import { OceanMaterial, type OceanShadingOptions } from './render/oceanMaterial';
import { SkyBackground } from './render/skyBackground';
import { surfaceBoundFor } from './render/seaSurfaceMaterial';
import { SkyEnvironment, sunAngles, type SunDirection } from './render/skyEnvironment';
import { OceanSimulation, type PathPreference, type SimulationOptions, type SimulationPath } from './layers/oceanSimulation';
import type { LocalWaves } from './layers/localWaves';
import type { WaveLayer } from './layers/waveLayer';
import { checkThreeRelease } from './threeRelease';
import { readSunPosition } from './render/sunPosition';
import { checkRenderer } from './device/deviceFor';
import { heightAt, normalAt, velocityAt } from './layers/surfaceQuery';
import { checkCoordinates, surfaceHeightAt, surfaceHeightsAt, surfaceNormalAt, surfaceVectorsAt, surfaceVelocityAt, warmUpQueries } from './oceanQueries';
import { SeaStatistics } from './oceanStatistics';
import { checkOptionNames, DisposedError, isOptionsObject, optionAliases } from './parameters/options';
import { ParameterError, SIMULATION_OPTIONS, type SimulationParameters } from './parameters/parameters';
import { DEFAULT_SUN, SHADING_OPTIONS, SUN_OPTIONS, type ShadingChanges, type ShadingOptions } from './parameters/sceneOptions';
import { createSeabedMap, type Seabed } from './layers/seabed';
import { Shore } from './layers/shore';

export interface OceanOptions extends Partial<SimulationParameters>, OceanShadingOptions, SimulationOptions {
  /** Sun elevation above the horizon in degrees, [-90, 90]. @defaultValue 30 */
  sunElevation?: number;
  /** Sun azimuth in degrees from +x towards +z. @defaultValue 40 */
  sunAzimuth?: number;
  /** How much of the sky is cloud, [0, 1]: 0 clear, 1 overcast (SunOptions.cloudCover); see Ocean.setSun. @defaultValue 0 */
  cloudCover?: number;
  /**
   * Direction towards the sun instead of sunElevation and sunAzimuth: a Vector3 or [x, y, z] in
   * world space (y up), any length; see Ocean.setSun.
   * @defaultValue undefined (the sun is at sunElevation and sunAzimuth)
   */
  sunDirection?: SunDirection;
  /**
   * The sea floor under part of the sea (see Ocean.setSeabed): waves shoal and break over it.
   * @defaultValue null (the sea is as deep as `depth` everywhere)
   */
  seabed?: Seabed | null;
}

/** Where the sun is, for Ocean.setSun: degrees (a missing one stays as it is), or a direction instead. */
export interface SunPosition {
  /** Degrees above the horizon, [-90, 90]. @defaultValue the elevation in force */
  elevation?: number;
  /** Degrees from +x towards +z. @defaultValue the azimuth in force */
  azimuth?: number;
  /**
   * Towards the sun in world space (y up), any length but 0: a Vector3 or [x, y, z]. Not with
   * elevation or azimuth. @defaultValue undefined (the sun is at elevation and azimuth)
   */
  direction?: SunDirection;
  /** How much of the sky is cloud, [0, 1]: 0 clear, 1 overcast (SunOptions.cloudCover). @defaultValue the cover in force */
  cloudCover?: number;
}

export { DisposedError };

const SHADING_ALIASES = optionAliases(SHADING_OPTIONS);
/** The shading options' names, British aliases included. */
const SHADING_NAMES = [...Object.keys(SHADING_OPTIONS), ...Object.keys(SHADING_ALIASES)] as (keyof ShadingChanges)[];
const SIMULATION_KEYS = Object.keys(SIMULATION_OPTIONS) as (keyof SimulationParameters)[];
/** Every option the constructor takes (and the aliases above): a misspelt one is an error, not silently ignored. */
const OCEAN_OPTION_KEYS: readonly string[] = [
  ...SIMULATION_KEYS,
  ...Object.keys(SHADING_OPTIONS),
  ...Object.keys(SUN_OPTIONS),
  'sunDirection',
  'path',
  'worker',
  'localWaves',
  'seabed',
];

/** What the batch queries write into. */
export type WritableNumbers = { length: number; [index: number]: number };

/** Where update's camera is in the world, reused. */
const viewerPosition = new Vector3();

/** Significant wave height (m) and peak period (s) of a sea state. */
export interface SeaStateSummary {
  significantWaveHeight: number;
  peakPeriod: number;
}

/** The FFT path: the preference, the one running and why it is not the best asked for (Ocean.path). */
export interface OceanPath {
  preference: PathPreference;
  running: SimulationPath;
  reason: string;
}

/** What an Ocean dispatches (three's addEventListener), beside Object3D's own events. */
export interface OceanEventMap extends Object3DEventMap {
  /**
   * The running FFT path changed, seen at an update(): after setPath or a parameter change, or by
   * itself when a JS worker failed for good and the main thread took over. `path` is ocean.path.
   */
  pathchange: { path: OceanPath };
}

export class Ocean extends Object3D<OceanEventMap> {
  readonly simulation: OceanSimulation;
  readonly sky: SkyEnvironment;
  readonly surface: OceanSurface;
  /** The sky behind everything (a child; set skyBackground.visible = false to show your own). */
  readonly skyBackground: SkyBackground;
  private currentTime = 0;
  /** The running path at the last update, to tell when it changes (the pathchange event). */
  private runningPath: SimulationPath | null = null;
  private disposed = false;
  /** heightRms, seaState and repeatPeriod, each computed once per set of spectra or parameters. */
  private readonly statistics = new SeaStatistics(() => this.simulation);
  /** The seabed and its shoaling factors (shore.ts), owned here. */
  private readonly shore = new Shore();

  constructor(
    private readonly renderer: WebGLRenderer,
    options: OceanOptions = {},
  ) {
    super();
    checkThreeRelease();
    checkRenderer(renderer, 'three-fft-ocean');
    this.name = 'Ocean';
    checkOptionNames(options, OCEAN_OPTION_KEYS, 'options', { aliases: SHADING_ALIASES, allowed: 'an object of options, such as { windSpeed: 12 }' });
    const simulationParameters = pick(options, SIMULATION_KEYS);
    const shading = pick(options, SHADING_NAMES);
    const sun = sunAngles(
      { elevation: options.sunElevation, azimuth: options.sunAzimuth, direction: options.sunDirection },
      { elevation: DEFAULT_SUN.sunElevation, azimuth: DEFAULT_SUN.sunAzimuth },
      'sunDirection',
    );
    // Checked before anything is allocated: a bad seabed throws with nothing to free.
    this.shore.setMap(options.seabed === undefined || options.seabed === null ? null : createSeabedMap(options.seabed, renderer));
    this.simulation = new OceanSimulation(renderer, simulationParameters, { path: options.path, worker: options.worker, localWaves: options.localWaves });
    this.sky = new SkyEnvironment(renderer, { sunElevation: sun.elevation, sunAzimuth: sun.azimuth, cloudCover: options.cloudCover });
    const sim = this.simulation;
    this.surface = new OceanSurface(
      new OceanMaterial({ environment: this.sky.environment, sunDirection: this.sky.skyUniforms.skySunDirection, daylight: this.sky.skyUniforms }, shading),
      () => ({
        layers: sim.layers,
        choppiness: sim.parameters.choppiness,
        foam: sim.foam.texture,
        windSpeed: sim.parameters.windSpeed,
        windDirection: sim.parameters.windDirection,
        surfaceBound: surfaceBoundFor(this.heightRms),
        // 1 RMS: a Gaussian surface lies below it at 16 % of points. Deeper, the reflection would
        // hold more of what is under the water, the undersides of objects at the waterline too
        // (docs/shores.md: a box's lone speckles on a 20 m/s sea, 40 here, 82 at 2 and 3 RMS).
        troughDepth: this.heightRms,
        waterHeightAt: (x: number, z: number) => heightAt(sim.layers, sim.parameters.choppiness, this.currentTime, x, z, this.preparedShore()),
        shore: this.preparedShore(),
        hullFoam: sim.localWaves,
      }),
    );
    this.skyBackground = new SkyBackground(this.sky, { backgroundWater: this.surface.backgroundWater, deepWater: this.surface.material.deepWater });
    this.surface.hideInCaptures(this.skyBackground);
    this.add(this.surface, this.skyBackground);
  }

  /**
   * Puts a sea floor under part of the sea, or takes it away (null). Given as a function
   * `{ depthAt(x, z), bounds: [xMin, zMin, xMax, zMax], resolution? }` (metres below mean sea
   * level, negative over land), a heightfield `{ depths, width, height, bounds }` (width × height
   * depths, x fastest), or three.js meshes `{ meshes, bounds?, resolution? }` drawn from above into a
   * depth map. Outside its bounds the sea is as deep as the `depth` option. Over it each cascade's
   * waves shoal by linear wave theory and break where they would be higher than 0.78 × the depth
   * (McCowan), with surf foam; the queries and floating bodies follow the same surface
   * (docs/shores.md). A bad seabed throws a ParameterError naming what is wrong and the last good
   * one stays.
   */
  setSeabed(seabed: Seabed | null): void {
    this.checkAlive('setSeabed');
    this.shore.setMap(seabed === null ? null : createSeabedMap(seabed, this.renderer));
  }

  /** Depth of the sea floor (m below mean sea level; negative over land) under (x, z): the seabed's, else the `depth` option. */
  depthAt(x: number, z: number): number {
    this.checkAlive('depthAt');
    checkCoordinates('depthAt(x, z)', x, z);
    return this.shore.active ? this.shore.depthAt(x, z) : this.simulation.parameters.depth;
  }

  /**
   * Distance in metres from a camera `cameraHeight` metres above the sea to the far edge of the
   * surface, as it is drawn into the renderer's drawing buffer at its current size (several
   * thousand heights): set camera.far at least this large to see the sea to the horizon. Valid
   * from construction; ask again after the size or the patch sizes change.
   */
  horizonDistanceFor(cameraHeight: number): number {
    this.checkAlive('horizonDistanceFor');
    if (typeof cameraHeight !== 'number' || !Number.isFinite(cameraHeight)) {
      throw new ParameterError('cameraHeight', cameraHeight, 'a finite height in metres above the sea');
    }
    return this.surface.farEdgeDistanceFor(cameraHeight, this.renderer);
  }

  /**
   * horizonDistanceFor the height of the camera of the last render; before the first render, for a
   * camera at sea level (the least it can be).
   */
  get horizonDistance(): number {
    return this.horizonDistanceFor(this.surface.cameraHeight);
  }

  get time(): number {
    this.checkAlive('time');
    return this.currentTime;
  }

  /**
   * Root mean square of the sea's height in metres over time, from the spectra: by Parseval the
   * mean of h² over a patch is Σ|h̃(k, t)|², whose average over the repeat period is
   * Σ(|h̃0(k)|² + |h̃0(−k)|²) (the cross terms oscillate); the cascades hold disjoint bands, so their
   * variances add. At one instant it differs by up to ~25%.
   */
  get heightRms(): number {
    this.checkAlive('heightRms');
    return this.statistics.heightRms;
  }

  /**
   * The sea state the parameters describe, from the spectrum's moments (seaState.ts): significant
   * wave height Hs = 4√m0 (m) and peak period Tp (s; 0 without waves). The simulated sea holds the
   * part of the spectrum its cascades cover: 4·heightRms is its Hs.
   */
  get seaState(): SeaStateSummary {
    this.checkAlive('seaState');
    return this.statistics.seaState;
  }

  /**
   * Computes the sea at `timeSeconds` (any finite number; it repeats every repeatPeriod). `camera`
   * is where the viewer is this frame: the local waves' grid follows it (unless told to follow
   * something else, localWaves.follow). Without one the grid stays where it was.
   */
  update(timeSeconds: number, camera?: Object3D): void {
    this.checkAlive('update');
    if (camera !== undefined) {
      // Duck-typed, as three.js does: a camera from another copy of three counts too.
      if ((camera as { isObject3D?: unknown } | null)?.isObject3D !== true) {
        throw new ParameterError('update(t, camera)', camera, 'a three.js camera (an Object3D) the local waves follow, or nothing');
      }
      camera.getWorldPosition(viewerPosition);
      this.simulation.localWaves?.cameraMoved(viewerPosition.x, viewerPosition.z);
    }
    this.simulation.localWaves?.setSeabed(this.shore.seabed);
    this.simulation.update(timeSeconds);
    this.surface.fitDrawingBuffer(this.renderer);
    this.currentTime = timeSeconds;
    this.warmUpQueries();
    const running = this.simulation.path;
    if (running !== this.runningPath) {
      const first = this.runningPath === null;
      this.runningPath = running;
      if (!first) this.dispatchEvent({ type: 'pathchange', path: this.path });
    }
  }

  get parameters(): Readonly<SimulationParameters> {
    this.checkAlive('parameters');
    return this.simulation.parameters;
  }

  /**
   * Seconds after which the sea repeats exactly (every cascade's waves where they were): a render
   * loop may wrap its time by it (wrapLongTime) without any change to the picture.
   */
  get repeatPeriod(): number {
    this.checkAlive('repeatPeriod');
    return this.statistics.repeatPeriod;
  }

  /**
   * The FFT path: the preference (the `path` option or setPath), the one running
   * ('gpu-rgba32f', 'gpu-rgba16f', 'js' or 'js-worker') and, when it is not the best the preference
   * asks for, why ('' when it is): e.g. "MAX_DRAW_BUFFERS is 4 (the GPU FFT writes 8 at once)".
   */
  get path(): OceanPath {
    this.checkAlive('path');
    const { pathPreference: preference, path: running, pathReason: reason } = this.simulation;
    return { preference, running, reason };
  }

  /** Changes the FFT path: 'auto' (the GPU where it can, else JS), 'gpu' or 'js'; the sea is rebuilt on it. */
  setPath(preference: PathPreference): void {
    this.checkAlive('setPath');
    this.simulation.pathPreference = preference;
  }

  /**
   * The local waves (src/layers/localWaves.ts): drop(x, z) drops a stone, addPressure(hull, pose)
   * puts a hull on the sea that makes a wake as it moves; null with `localWaves: false`. Their grid
   * follows the camera unless told to follow something else.
   */
  get localWaves(): LocalWaves | null {
    this.checkAlive('localWaves');
    return this.simulation.localWaves;
  }

  /**
   * Adds a wave layer of your own (the WaveLayer contract, src/layers/waveLayer.ts: its fields'
   * textures, where they lie, and how to update and query them): from the next update on it moves
   * with the sea's clock, the surface draws it, the queries and floating bodies feel it, and a
   * periodic one makes whitecaps with the rest. It stays yours: removeLayer gives it back, and
   * dispose() does not free it. A ParameterError names what is missing from a layer that does not
   * meet the contract.
   */
  addLayer(layer: WaveLayer): void {
    this.checkAlive('addLayer');
    this.simulation.addLayer(layer);
  }

  /** Takes a layer that addLayer added off the sea (it is not freed). */
  removeLayer(layer: WaveLayer): void {
    this.checkAlive('removeLayer');
    this.simulation.removeLayer(layer);
  }

  /** Changes simulation parameters; a bad one throws a ParameterError and nothing changes. */
  setParameters(changes: Partial<SimulationParameters>): void {
    this.checkAlive('setParameters');
    if (!isOptionsObject(changes)) throw new ParameterError('setParameters', changes, 'an object of parameters, such as { windSpeed: 12 }');
    this.simulation.setParameters(changes);
  }

  /** The shading options in use (colours as linear [r, g, b]). */
  get shading(): ShadingOptions {
    this.checkAlive('shading');
    return this.surface.material.shading;
  }

  /**
   * Changes shading options (colours as a THREE.Color, a hex number, a CSS string or linear
   * [r, g, b]); a bad one throws a ParameterError and nothing changes.
   */
  setShading(changes: OceanShadingOptions): void {
    this.checkAlive('setShading');
    if (!isOptionsObject(changes)) throw new ParameterError('setShading', changes, 'an object of shading options, such as { ior: 1.34 }');
    this.surface.material.setShading(changes);
  }

  /**
   * Which objects the sea reflects with reflections 'scene' (OceanSurface.reflectionLayers): those
   * whose layers meet this mask and the camera's; every layer by default. Change it in place.
   */
  get reflectionLayers(): ReflectionLayers {
    this.checkAlive('reflectionLayers');
    return this.surface.reflectionLayers;
  }

  /**
   * Moves the sun; the sky, glint and caustics follow. Either in degrees, setSun(elevation,
   * azimuth) or setSun({ elevation, azimuth }) (a missing one stays), or by the direction towards
   * it, setSun({ direction }): a Vector3 or [x, y, z] (y up, any length but 0), which becomes
   * elevation atan2(y, √(x² + z²)) and azimuth atan2(z, x), from +x towards +z. Bad values throw a
   * ParameterError and the sun stays. setSun({ cloudCover }) clouds the sky over (0 clear … 1
   * overcast, SunOptions.cloudCover): the sky greys and the sun, its glint and caustics dim.
   */
  setSun(elevation: number, azimuth: number): void;
  setSun(sun: SunPosition): void;
  setSun(sunOrElevation: SunPosition | number, azimuth?: number): void {
    this.checkAlive('setSun');
    const sun = readSunPosition(sunOrElevation, azimuth, { elevation: this.sky.sunElevation, azimuth: this.sky.sunAzimuth });
    this.sky.setSun(sun.elevation, sun.azimuth);
    if (sun.cloudCover !== undefined) this.sky.setCloudCover(sun.cloudCover);
  }

  /**
   * Height of the water surface at the world point (x, z) at the current time, over every layer
   * (surfaceQuery.ts: the rest point that the choppy displacement moves onto (x, z), found by
   * Newton's method), from CPU copies of the fields that workers computed for about this time
   * (fftCascade.ts); until they have some (just after the ocean is built or rebuilt, a jump in
   * time), from a provisional copy that update() computes here at most once per 40 ms (about 7 ms
   * for three 256² cascades once warm), within about 0.5 cm of the workers' answers.
   */
  heightAt(x: number, z: number): number {
    this.checkAlive('heightAt');
    return surfaceHeightAt('heightAt', this.simulation, this.preparedShore(), this.currentTime, x, z);
  }

  /**
   * Upward unit normal of the water surface over the world point (x, z) at the current time, in
   * `target` (surfaceQuery.ts: the normal of the choppy surface at the point heightAt finds). For
   * a buoy's tilt, a boat's pitch and roll.
   */
  normalAt(x: number, z: number, target = new Vector3()): Vector3 {
    this.checkAlive('normalAt');
    return surfaceNormalAt('normalAt', this.simulation, this.preparedShore(), this.currentTime, x, z, target);
  }

  /**
   * Velocity (m/s) of the water surface over the world point (x, z) at the current time, in
   * `target`: the orbital velocity of the surface particle there, over every layer (surfaceQuery.ts).
   * For a floating body's drag, spray, or what the water carries.
   */
  velocityAt(x: number, z: number, target = new Vector3()): Vector3 {
    this.checkAlive('velocityAt');
    return surfaceVelocityAt('velocityAt', this.simulation, this.preparedShore(), this.currentTime, x, z, target);
  }

  /**
   * heightAt for many points at once: `xz` holds x0, z0, x1, z1, … and `out` gets one height per
   * point (and is returned). Allocates nothing.
   */
  heightsAt<T extends WritableNumbers>(xz: ArrayLike<number>, out: T): T {
    this.checkAlive('heightsAt');
    return surfaceHeightsAt('heightsAt', this.simulation, this.preparedShore(), this.currentTime, xz, out);
  }

  /** normalAt for many points: three numbers (x, y, z) per point of `xz` in `out`. Allocates nothing. */
  normalsAt<T extends WritableNumbers>(xz: ArrayLike<number>, out: T): T {
    this.checkAlive('normalsAt');
    return surfaceVectorsAt('normalsAt', normalAt, this.simulation, this.preparedShore(), this.currentTime, xz, out);
  }

  /** velocityAt for many points: three numbers (m/s) per point of `xz` in `out`. Allocates nothing. */
  velocitiesAt<T extends WritableNumbers>(xz: ArrayLike<number>, out: T): T {
    this.checkAlive('velocitiesAt');
    return surfaceVectorsAt('velocitiesAt', velocityAt, this.simulation, this.preparedShore(), this.currentTime, xz, out);
  }

  /**
   * Frees every GPU resource the Ocean made and takes its sea and sky out of it (left in a scene it
   * draws nothing). Every method and getter throws a DisposedError from then on; disposing again does nothing.
   */
  dispose(): void {
    if (this.disposed) return;
    this.disposed = true;
    this.surface.removeFromParent();
    this.surface.dispose();
    this.skyBackground.removeFromParent();
    this.skyBackground.dispose();
    this.sky.dispose();
    this.simulation.dispose();
    this.shore.dispose();
  }

  /** The shore for the queries and the surface, its factors made for the layers of now; null without a seabed. */
  private preparedShore(): Shore | null {
    if (!this.shore.active) return null;
    const sim = this.simulation;
    this.shore.prepare(sim.layers, sim.cascades, sim.parameters.depth, 4 * this.heightRms, this.statistics.seaState.peakPeriod);
    return this.shore;
  }

  /** Once per page, at the first update of its first Ocean: compiles the query code (oceanQueries.ts). */
  private warmUpQueries(): void {
    warmUpQueries(this);
  }

  private checkAlive(method: string): void {
    if (this.disposed) throw new DisposedError(`Ocean.${method}`);
  }
}

function pick<T extends object, K extends keyof T>(source: T, keys: readonly K[]): Partial<Pick<T, K>> {
  const result: Partial<Pick<T, K>> = {};
  for (const key of keys) if (source[key] !== undefined) result[key] = source[key];
  return result;
}
