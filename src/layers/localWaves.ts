/**
 * The local-wave layer: waves that things make on the sea — a stone dropped, a hull under way, a
 * floating body that moves — solved on a square grid that follows the camera (or whatever
 * follow() is given) and added to the FFT sea by the surface and the queries (waveLayer.ts). The
 * model and its proofs are in localWaveModel.ts; where it is solved (the GPU solver of
 * gpuLocalWaves.ts or the JS one of localWaveModel.ts), and how the fields reach the surface and
 * the queries, in localWaveFields.ts. This file keeps the sources, the grid and the time.
 *
 * Sources:
 *   drop(x, z)            a stone: a dip of the surface, once; the rings spread from it.
 *   addPressure(hull)     a hull: a pressure patch you move with setPose() (or that moves along a
 *                         path of time); while it moves it makes waves, a wake when under way.
 * The grid moves in whole texels towards its target each update; the waves stay where they are in
 * the world, and what leaves the grid is gone.
 *
 * Time: update(t, dt) steps by dt (dt = 0: paused). A jump (dt < 0 or over MAX_STEP, or the first
 * update) clears the waves: they are the history of their sources. Hulls that follow a path of
 * time are then run along it up to t (warmUp), so that a still at t shows their wake.
 * When nothing has made a wave for QUIET_AFTER seconds the layer clears and stops stepping (a
 * sea without sources costs nothing).
 */
import type { WebGLRenderer } from 'three';
import { checkOptionNames, DisposedError, ParameterError } from '../parameters/options';
import { localWaveFields, type LocalWaveFields } from './localWaveFields';
import { localWaterUnder, MAX_IMPULSES_PER_STEP, type HeightImpulse, type LocalWaveGrid } from './localWaveModel';
import type { SeabedMap } from './seabed';
import { HullFoam, hullFoamCoverage } from './hullFoam';
import { heightAt } from './surfaceQuery';
import type { PathPreference } from './oceanSimulation';
import type { LayerFieldsOnCpu, LayerFrame, LayerQueryFields, WaveLayer } from './waveLayer';

/** The longest step taken as a step; a longer dt (a hidden tab, a jump) clears the waves. */
const MAX_STEP = 2;
/** Seconds without a source after which the grid is cleared and stepping stops. */
const QUIET_AFTER = 60;
/** Seconds of a travelling hull's path run after a jump, and the step (localWaves.ts warmUp). */
const WARM_UP = 20;
const WARM_UP_STEP = 0.1;
/** Sub-steps per update at most, when sources move more than a quarter of their length per update. */
const MAX_SUBSTEPS = 2;

export interface LocalWavesOptions {
  /** Texels per side, a power of two from 16 to 1024. @defaultValue 128 */
  resolution?: number;
  /** Side of a texel, m, from 0.05 to 10. @defaultValue 1 */
  cellSize?: number;
  /**
   * Where they are solved: 'gpu' (needs float32 render targets), 'js', or 'auto': the GPU unless
   * it renders in software (SwiftShader, llvmpipe), where the JS solver is several times faster.
   * @defaultValue 'auto'
   */
  path?: PathPreference;
}

/** The names of LocalWavesOptions, DropOptions, HullShape and HullPose: any other is a misspelling. */
export const LOCAL_WAVES_OPTION_KEYS: readonly (keyof LocalWavesOptions)[] = ['resolution', 'cellSize', 'path'];
const DROP_OPTION_KEYS: readonly (keyof DropOptions)[] = ['radius', 'depth'];
const HULL_SHAPE_KEYS: readonly (keyof HullShape)[] = ['length', 'beam', 'draft'];
const HULL_POSE_KEYS: readonly (keyof HullPose)[] = ['x', 'z', 'heading'];

/** A stone's dip. */
export interface DropOptions {
  /** Radius of the dip (the e-folding half width of its Gaussian), m, in [0.1, 20]. @defaultValue 1 */
  radius?: number;
  /** Depth of the dip, m, in [0, 5]. @defaultValue 0.5 */
  depth?: number;
}

/** The pressure patch of a hull: a Gaussian footprint of this length and beam, pressing `draft` metres of water down. */
export interface HullShape {
  /** Length over the waterline, m. */
  length: number;
  /** Beam, m. */
  beam: number;
  /** Draft, m. */
  draft: number;
}

/** A hull's place on the sea: (x, z) in metres and heading in radians from +x towards +z. */
export interface HullPose {
  x: number;
  z: number;
  heading: number;
}

/** A pressure patch on the local waves (addPressure); move it every frame with setPose(). */
export interface PressureSource {
  /** Moves the hull; `draft` (m) changes how deep it presses, for a body that heaves. */
  setPose(x: number, z: number, heading: number, draft?: number): void;
  /** Takes it off the sea (the water it pressed down springs back). */
  remove(): void;
}

/** A hull's pose and how deep it presses now (m). */
interface PressedPose extends HullPose {
  draft: number;
}

interface Hull {
  shape: { length: number; beam: number };
  pose: PressedPose;
  /**
   * The pose its pressure is applied at now. A hull put on the sea, or on a cleared sea, is taken
   * as already floating there in equilibrium: it makes waves only when it moves.
   */
  applied: PressedPose;
  removed: boolean;
  /** Where it is at time t, for a hull that follows a path. */
  path?: (t: number) => HullPose;
}

export class LocalWaves implements WaveLayer {
  readonly textures;
  readonly grid: LocalWaveGrid;
  /** The foam the hulls under way make (hullFoam.ts), over the grid's texels; the surface draws it. */
  readonly foam: HullFoam;
  /** The local waves move the surface only up and down. */
  readonly movesSideways = false;
  private readonly solved: LocalWaveFields;
  private readonly currentFrame: { size: number; origin: [number, number]; periodic: false; resolution: number };
  /** The grid's texel (0, 0) in whole texels of the world. */
  private originTexel: [number, number];
  private target: [number, number] = [0, 0];
  private followingCamera = true;
  /** What the grid follows when given a path of time (follow(path)), else null. */
  private followPath: ((t: number) => { x: number; z: number }) | null = null;
  private readonly pendingDrops: HeightImpulse[] = [];
  private readonly hulls: Hull[] = [];
  private quietFor = Infinity;
  /** The whitecaps' amount and persistence τ (s), which the hulls' foam shares (setFoam). */
  private foamAmount = 1;
  private foamPersistence = 3;
  /** The time of the last update, null before the first. */
  private time: number | null = null;
  private disposed = false;
  /** The sea floor under the grid (setSeabed), null: as deep as grid.depth everywhere. */
  private seabed: SeabedMap | null = null;
  /** The grid origin (texels) the solver's water was found for; null: to be found again. */
  private waterFor: [number, number] | null = null;
  /** The wet mask localWaterUnder fills each time the water is found over a seabed (N², made the first time). */
  private wetMask: Float32Array | null = null;
  /** This layer as a list of layers, for the queries. */
  private readonly asLayers: readonly WaveLayer[] = [this];

  constructor(
    renderer: WebGLRenderer,
    depth: number,
    useGpu: boolean,
    options: LocalWavesOptions = {},
  ) {
    checkOptionNames(options, LOCAL_WAVES_OPTION_KEYS, 'localWaves', { prefix: 'localWaves.' });
    const resolution = options.resolution ?? 128;
    const cellSize = options.cellSize ?? 1;
    if (!Number.isInteger(resolution) || resolution < 16 || resolution > 1024 || (resolution & (resolution - 1)) !== 0) {
      throw new ParameterError('localWaves.resolution', resolution, 'a power of two from 16 to 1024');
    }
    if (!(cellSize >= 0.05 && cellSize <= 10)) throw new ParameterError('localWaves.cellSize', cellSize, 'metres per texel from 0.05 to 10');
    this.grid = { resolution, cellSize, depth };
    this.solved = localWaveFields(renderer, this.grid, useGpu);
    this.textures = this.solved.textures;
    this.foam = new HullFoam(resolution, cellSize);
    this.originTexel = this.originFor(this.target);
    this.currentFrame = { size: resolution * cellSize, origin: [0, 0], periodic: false, resolution };
    this.updateFrameOrigin();
  }

  get frame(): LayerFrame {
    return this.currentFrame;
  }

  /**
   * The height of the local waves alone at the world point (x, z), m (0 outside the grid): what
   * they add to the sea there (for a floating body that presses on them, floatingBody.ts).
   */
  heightAt(x: number, z: number): number {
    return heightAt(this.asLayers, 0, this.time ?? 0, x, z);
  }

  /** 'gpu' or 'js': where the waves are solved. */
  get path(): 'gpu' | 'js' {
    return this.solved.path;
  }

  /** True while the layer steps (a source made waves in the last QUIET_AFTER seconds). */
  get active(): boolean {
    return this.quietFor < QUIET_AFTER;
  }

  /**
   * Centres the grid on the world point (x, z) from the next update on (in whole texels), and stops
   * it following the camera; follow(null) makes it follow the camera again (the default). Or give
   * it a path of time, (t) => ({ x, z }): the grid is then where the path is at each update, and
   * during the run-up after a jump in time too (for a still of a hull whose waves move with it).
   */
  follow(x: number | null | ((t: number) => { x: number; z: number }), z?: number): void {
    this.checkAlive('follow');
    this.followPath = null;
    if (x === null) {
      this.followingCamera = true;
      return;
    }
    this.followingCamera = false;
    if (typeof x === 'function') {
      this.followPath = x;
      return;
    }
    if (!Number.isFinite(x) || !Number.isFinite(z)) throw new ParameterError('follow(x, z)', [x, z], 'finite coordinates in metres, null for the camera, or a path (t) => ({ x, z })');
    this.target = [x, z as number];
  }

  /**
   * Throws a DisposedError once this is disposed (with its Ocean, or replaced by a rebuild for
   * another depth or solver): a stone or a hull given then would make no waves, silently.
   */
  private checkAlive(method: string): void {
    if (this.disposed) throw new DisposedError(`LocalWaves.${method}`, 'LocalWaves');
  }

  /** Aims the grid at where its path is at time t (for a grid that follows one). */
  private aimAt(t: number): void {
    if (this.followPath === null) return;
    const { x, z } = this.followPath(t);
    if (!Number.isFinite(x) || !Number.isFinite(z)) throw new ParameterError(`the followed path at t = ${t}`, [x, z], 'finite coordinates in metres');
    this.target = [x, z];
  }

  /**
   * How much foam the hulls make (a factor, 0 none, from 0 to 10) and how long it lasts (the
   * persistence τ, s, from 0.1 to 30): the Ocean gives its foamAmount and foamPersistence, so the
   * hulls' foam fades as the whitecaps' does (hullFoam.ts).
   */
  setFoam(amount: number, persistence: number): void {
    this.checkAlive('setFoam');
    if (!(amount >= 0 && amount <= 10)) throw new ParameterError('hull foam amount', amount, 'a factor from 0 to 10');
    if (!(persistence >= 0.1 && persistence <= 30)) throw new ParameterError('hull foam persistence', persistence, 'seconds from 0.1 to 30');
    this.foamAmount = amount;
    this.foamPersistence = persistence;
  }

  /**
   * The sea floor under the waves (the Ocean gives its seabed before each update; null: none):
   * from the next step on they move at the speed of the mean depth of the water under the grid and
   * stop at the waterline (localWaveModel.ts). Outside the seabed's bounds the water is grid.depth deep.
   */
  setSeabed(seabed: SeabedMap | null): void {
    this.checkAlive('setSeabed');
    if (seabed === this.seabed) return;
    this.seabed = seabed;
    this.waterFor = null;
  }

  /** Where the camera is, for a grid that follows it (Ocean calls this before each update). */
  cameraMoved(x: number, z: number): void {
    if (this.followingCamera) this.target = [x, z];
  }

  /**
   * Drops a stone at the world point (x, z): rings spread from the next update on. A drop outside the
   * grid is ignored (returns false).
   */
  drop(x: number, z: number, options: DropOptions = {}): boolean {
    this.checkAlive('drop');
    if (!Number.isFinite(x) || !Number.isFinite(z)) throw new ParameterError('drop(x, z)', [x, z], 'finite coordinates in metres');
    checkOptionNames(options, DROP_OPTION_KEYS, 'drop options', { prefix: 'drop ' });
    const radius = options.radius ?? 1;
    const depth = options.depth ?? 0.5;
    if (!(radius >= 0.1 && radius <= 20)) throw new ParameterError('drop radius', radius, 'metres from 0.1 to 20');
    if (!(depth >= 0 && depth <= 5)) throw new ParameterError('drop depth', depth, 'metres from 0 to 5');
    const [u, v] = this.toGrid(x, z);
    const size = this.currentFrame.size;
    if (u < 0 || v < 0 || u > size || v > size) return false;
    // Kept in world coordinates: the grid may move before the next step.
    this.pendingDrops.push({ x, z, cos: 1, sin: 0, halfLength: radius, halfBeam: radius, height: -depth });
    this.quietFor = 0;
    return true;
  }

  /**
   * Puts a hull's pressure patch on the sea at `pose`; move it with setPose() as the hull moves. Or
   * give it a `path` of time: it then moves along it by itself, and after a jump in time (a still,
   * a seek) its wake is run up over the 20 s before, so that the sea at a time does not depend on
   * what came before.
   */
  addPressure(shape: HullShape, pose: HullPose, path?: (t: number) => HullPose): PressureSource {
    this.checkAlive('addPressure');
    checkOptionNames(shape, HULL_SHAPE_KEYS, 'hull shape', { prefix: 'hull ' });
    checkOptionNames(pose, HULL_POSE_KEYS, 'hull pose', { prefix: 'hull pose ' });
    for (const key of ['length', 'beam'] as const) {
      if (!(shape[key] >= 0.2 && shape[key] <= 400)) throw new ParameterError(`hull ${key}`, shape[key], 'metres from 0.2 to 400');
    }
    const placed = checkPose({ ...pose, draft: shape.draft });
    const hull: Hull = { shape: { length: shape.length, beam: shape.beam }, pose: placed, applied: placed, removed: false, path };
    this.hulls.push(hull);
    return {
      setPose: (x, z, heading, draft = hull.pose.draft) => {
        hull.pose = checkPose({ x, z, heading, draft });
      },
      remove: () => {
        hull.removed = true;
      },
    };
  }

  update(t: number, dt: number): void {
    const jump = this.time === null || dt < 0 || dt > MAX_STEP;
    this.time = t;
    this.aimAt(t);
    if (jump) {
      this.clear();
      this.warmUp(t);
      return;
    }
    if (dt === 0) return; // paused
    for (const hull of this.hulls) if (hull.path && !hull.removed) hull.pose = checkPose({ ...hull.path(t), draft: hull.pose.draft });
    const moving = this.hulls.some((hull) => hull.removed || !samePose(hull.applied, hull.pose));
    if (moving || this.pendingDrops.length > 0) this.quietFor = 0;
    else this.quietFor += dt;
    if (!this.active) {
      // Nothing to solve: the grid just follows its target (its fields are zero).
      if (this.quietFor - dt < QUIET_AFTER) this.clear();
      this.originTexel = this.originFor(this.target);
      this.updateFrameOrigin();
      return;
    }
    this.advance(dt);
    this.publish();
  }

  /** The textures show the solver's state and the foam. */
  private publish(): void {
    this.solved.publish(this.active);
    this.foam.publish();
  }

  /**
   * After a jump to time t, the waves of the hulls that follow a path: they are run along it over
   * the WARM_UP seconds before t in steps of WARM_UP_STEP, from a calm sea, so that a still at t
   * (and every frame after it) shows the same wake whatever came before.
   */
  private warmUp(t: number): void {
    const travelling = this.hulls.filter((hull) => hull.path);
    if (travelling.length === 0) return;
    for (const hull of travelling) hull.pose = hull.applied = checkPose({ ...hull.path!(t - WARM_UP), draft: hull.pose.draft });
    if (this.followPath) {
      // The sea is calm: the grid can start where its path is.
      this.aimAt(t - WARM_UP);
      this.originTexel = this.originFor(this.target);
    }
    for (let step = 1; step <= Math.round(WARM_UP / WARM_UP_STEP); step++) {
      const time = t - WARM_UP + step * WARM_UP_STEP;
      for (const hull of travelling) hull.pose = checkPose({ ...hull.path!(time), draft: hull.pose.draft });
      this.aimAt(time);
      this.advance(WARM_UP_STEP);
    }
    this.quietFor = 0;
    this.publish();
  }

  /** Steps the waves by dt, with the hulls moving from where they pressed to their new poses. */
  private advance(dt: number): void {
    const substeps = this.substepsFor();
    const starts = this.hulls.map((hull) => hull.applied);
    const targetOrigin = this.originFor(this.target);
    for (let s = 1; s <= substeps; s++) {
      const fraction = s / substeps;
      const origin: [number, number] = s === substeps ? targetOrigin : this.originTexel; // the grid moves once, in the last sub-step
      const shift = [origin[0] - this.originTexel[0], origin[1] - this.originTexel[1]];
      this.originTexel = origin;
      this.updateWater();
      this.foam.shift(shift[0], shift[1]);
      this.foam.fade(dt / substeps, this.foamPersistence);
      const impulses: HeightImpulse[] = s === 1 ? this.pendingDrops.splice(0).map((drop) => this.inGrid(drop)) : [];
      this.hulls.forEach((hull, h) => {
        if (hull.removed) {
          if (s === 1) impulses.push(this.hullImpulse(hull.shape, hull.applied, -1));
          return;
        }
        const pose = interpolatePose(starts[h], hull.pose, fraction);
        if (samePose(pose, hull.applied)) return;
        this.stampFoam(hull, pose, dt / substeps);
        impulses.push(this.hullImpulse(hull.shape, hull.applied, -1), this.hullImpulse(hull.shape, pose, 1));
        hull.applied = pose;
      });
      for (let first = 0; first === 0 || first < impulses.length; first += MAX_IMPULSES_PER_STEP) {
        const step = { shiftX: first === 0 ? shift[0] : 0, shiftZ: first === 0 ? shift[1] : 0, impulses: impulses.slice(first, first + MAX_IMPULSES_PER_STEP), dt: first === 0 ? dt / substeps : 0 };
        this.solved.step(step);
      }
    }
    this.hulls.splice(0, this.hulls.length, ...this.hulls.filter((hull) => !hull.removed));
    this.updateFrameOrigin();
  }

  /**
   * The fields the surface shows now (the last update's; `t` is not used: local waves are a
   * history, not a function of time). On the GPU path they are read back once per update asked.
   */
  fieldsOnCpu(_t: number): LayerFieldsOnCpu {
    return this.solved.fieldsOnCpu(this.active);
  }

  /** The fields the surface shows now, on the JS path; null on the GPU path (fieldsOnCpu reads them back). */
  shownFieldsOnCpu(): LayerFieldsOnCpu | null {
    return this.solved.shownFieldsOnCpu();
  }

  /**
   * The fields for the queries at time t: the local waves carry no time of their own (a history),
   * so they are for the time asked and never carried forward. On the GPU path they are the last
   * read-back's, and a new read-back of the current state starts without waiting; only the first
   * is read back at once.
   */
  queryFields(t: number): LayerQueryFields {
    const { displacement, derivatives } = this.solved.queryFields(this.active);
    return { time: t, resolution: this.grid.resolution, displacement, derivatives, velocities: () => this.solved.velocities(this.active) };
  }

  dispose(): void {
    this.disposed = true;
    this.solved.dispose();
    this.foam.dispose();
  }

  /** Clears every wave (the hulls stay, pressing from their next step on; stones not yet dropped still fall). */
  clear(): void {
    for (const hull of this.hulls) hull.applied = hull.pose;
    this.solved.clear();
    this.foam.clear();
    this.publish();
  }

  /** Hands the solver the water under the grid where it is now, when the grid moved or the seabed changed. */
  private updateWater(): void {
    const [i, j] = this.originTexel;
    if (this.waterFor !== null && this.waterFor[0] === i && this.waterFor[1] === j) return;
    this.waterFor = [i, j];
    const { seabed, grid } = this;
    if (seabed === null) {
      this.solved.setWater({ depth: grid.depth, wet: null });
      return;
    }
    this.wetMask ??= new Float32Array(grid.resolution * grid.resolution);
    this.solved.setWater(localWaterUnder(grid, i * grid.cellSize, j * grid.cellSize, seabed, grid.depth, this.wetMask));
  }

  /** Sub-steps for this update: enough that no hull moves more than a quarter of its length in one. */
  private substepsFor(): number {
    let substeps = 1;
    for (const hull of this.hulls) {
      if (hull.removed) continue;
      const move = Math.hypot(hull.pose.x - hull.applied.x, hull.pose.z - hull.applied.z);
      substeps = Math.max(substeps, Math.ceil(move / (0.25 * Math.min(hull.shape.length, hull.shape.beam * 2))));
    }
    return Math.min(substeps, MAX_SUBSTEPS);
  }

  /** The breaking zone of a hull that moved from where it pressed to `pose` in dt seconds (hullFoam.ts). */
  private stampFoam(hull: Hull, pose: PressedPose, dt: number): void {
    if (dt <= 0) return;
    const speed = Math.hypot(pose.x - hull.applied.x, pose.z - hull.applied.z) / dt;
    const { length, beam } = hull.shape;
    const x = pose.x - this.originTexel[0] * this.grid.cellSize;
    const z = pose.z - this.originTexel[1] * this.grid.cellSize;
    this.foam.stamp(x, z, Math.cos(pose.heading), Math.sin(pose.heading), length, beam, hullFoamCoverage(speed, length, this.foamAmount));
  }

  private hullImpulse(shape: Hull['shape'], pose: PressedPose, sign: 1 | -1): HeightImpulse {
    return this.inGrid({ x: pose.x, z: pose.z, cos: Math.cos(pose.heading), sin: Math.sin(pose.heading), halfLength: shape.length / 2, halfBeam: shape.beam / 2, height: sign * pose.draft });
  }

  /** An impulse placed in the world, placed on the grid as it is now. */
  private inGrid(impulse: HeightImpulse): HeightImpulse {
    const [x, z] = this.toGrid(impulse.x, impulse.z);
    return { ...impulse, x, z };
  }

  /** World (x, z) in metres from the grid's texel (0, 0). */
  private toGrid(x: number, z: number): [number, number] {
    return [x - this.originTexel[0] * this.grid.cellSize, z - this.originTexel[1] * this.grid.cellSize];
  }

  private originFor([x, z]: [number, number]): [number, number] {
    const half = this.grid.resolution / 2;
    return [Math.round(x / this.grid.cellSize) - half, Math.round(z / this.grid.cellSize) - half];
  }

  private updateFrameOrigin(): void {
    this.currentFrame.origin[0] = this.originTexel[0] * this.grid.cellSize;
    this.currentFrame.origin[1] = this.originTexel[1] * this.grid.cellSize;
  }
}

function checkPose(pose: PressedPose): PressedPose {
  if (![pose.x, pose.z, pose.heading].every(Number.isFinite)) {
    throw new ParameterError('hull pose', [pose.x, pose.z, pose.heading], 'finite x, z (m) and heading (radians)');
  }
  if (!(pose.draft >= 0 && pose.draft <= 20)) throw new ParameterError('hull draft', pose.draft, 'metres from 0 to 20');
  return { x: pose.x, z: pose.z, heading: pose.heading, draft: pose.draft };
}

function samePose(a: PressedPose, b: PressedPose): boolean {
  return a.x === b.x && a.z === b.z && a.heading === b.heading && a.draft === b.draft;
}

function interpolatePose(from: PressedPose, to: PressedPose, fraction: number): PressedPose {
  // The shorter way round for the heading.
  const turn = Math.atan2(Math.sin(to.heading - from.heading), Math.cos(to.heading - from.heading));
  const along = (a: number, b: number) => a + (b - a) * fraction;
  return { x: along(from.x, to.x), z: along(from.z, to.z), heading: from.heading + turn * fraction, draft: along(from.draft, to.draft) };
}
