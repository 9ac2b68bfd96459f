/**
 * A floating box: heave, pitch and roll of a rigid hull from the buoyancy at sample points of its
 * bottom, for a boat or a buoy on the sea (its horizontal position and heading are the caller's).
 *
 * Archimedes' principle per sample column (strip theory, the simplest form of it): the bottom is
 * split into n×n cells of area A/n²; a cell whose centre point lies d below the water surface
 * above it (heightAt) is pushed up by ρ·g·(A/n²)·min(d, height), at the middle of its submerged
 * column (half way up it along the box's own vertical): so the centre of buoyancy moves to the low
 * side as the box tilts, which is what rights it. The body moves
 * under those forces, its weight m·g and linear damping (a fraction `damping` of critical damping
 * for heave and for rotation: radiation and viscous losses, which strip theory leaves out):
 *     m·dv/dt = Σ F_i − m·g − c·v,        I·dω/dt = Σ (p_i − c) × F_i − c_ω·ω
 * with I the box's inertia tensor in its own axes, stepped by semi-implicit Euler in substeps of at
 * most MAX_SUBSTEP (1/30 s), well inside the heave period 2π·√(draft/g) for drafts above a few
 * centimetres (0.4 s at 4 cm; the scheme is stable while a substep is under a third of it).
 * On flat water the box settles at the draft m / (ρ·A) (tests/unit/floatingBody.test.ts).
 *
 * Given local waves (pressOn), the body also pushes the water: a pressure patch of its footprint
 * that follows it (localWaves.ts), so a body that moves or heaves makes waves. It presses as deep as
 * its bottom is under the sea without the local waves. Measured against the whole surface, a
 * body would press on its own waves: the patch raises the pressure level η + P under it at once,
 * so the next step's draft sees the water higher and presses harder; in the three-scene example
 * the crate's heave grew from 0.2 to over 1 m in three seconds that way.
 */
import { Quaternion, Vector3 } from 'three';
import { checkOptionNames, ParameterError } from '../parameters/options';
import { GRAVITY } from '../spectrum/dispersion';
import type { HullPose, HullShape, PressureSource } from './localWaves';

/** Density of surface sea water, kg/m³ (the EOS-80 equation of state, UNESCO 1981, gives 1024.8 at 35 PSU and 20 °C). */
export const SEA_WATER_DENSITY = 1025;
const MAX_SUBSTEP = 1 / 30;

export interface FloatingBodyOptions {
  /** kg */
  mass: number;
  /** Length along x, height, width along z, m (the box in its own axes). */
  size: [number, number, number];
  /** Sample points per side of the bottom. @defaultValue 4 */
  samples?: number;
  /** Fraction of critical damping, heave and rotation. @defaultValue 0.2 */
  damping?: number;
  /** kg/m³. @defaultValue SEA_WATER_DENSITY */
  density?: number;
}

/** The names FloatingBodyOptions has: any other is a misspelling. */
const FLOATING_BODY_OPTION_KEYS: readonly (keyof FloatingBodyOptions)[] = ['mass', 'size', 'samples', 'damping', 'density'];

/** What the body floats on: any surface with a height at each world point. */
export interface WaterSurface {
  heightAt(x: number, z: number): number;
}

/** What the body can push on (an Ocean's localWaves). */
export interface PressableWater {
  addPressure(shape: HullShape, pose: HullPose): PressureSource;
  /** The height these waves alone add at (x, z), m. */
  heightAt(x: number, z: number): number;
}

export class FloatingBody {
  /** Centre of the box, world m; x and z are the caller's to move. */
  readonly position = new Vector3();
  readonly orientation = new Quaternion();
  readonly velocity = new Vector3();
  /** World frame, rad/s. */
  readonly angularVelocity = new Vector3();
  private readonly mass: number;
  private readonly size: [number, number, number];
  private readonly cellArea: number;
  /** Sample points in the box's own axes (bottom corners of the cells' centres). */
  private readonly points: Vector3[];
  /** Diagonal inertia in the box's own axes, kg·m². */
  private readonly inertia: Vector3;
  private readonly heaveDamping: number;
  private readonly rotationDamping: Vector3;
  private readonly density: number;
  // Scratch, so step() allocates nothing.
  private readonly force = new Vector3();
  private readonly torque = new Vector3();
  private readonly point = new Vector3();
  private readonly arm = new Vector3();
  private readonly spin = new Quaternion();
  private readonly up = new Vector3();
  private readonly inverse = new Quaternion();
  /** Its pressure patch on the local waves (pressOn) and those waves, or null. */
  private pressing: { source: PressureSource; water: PressableWater } | null = null;

  constructor(options: FloatingBodyOptions) {
    checkOptionNames(options, FLOATING_BODY_OPTION_KEYS, 'FloatingBody options', { prefix: 'FloatingBody ' });
    const { mass, size, samples = 4, damping = 0.2, density = SEA_WATER_DENSITY } = options;
    if (!(mass > 0 && mass < Infinity)) throw new ParameterError('FloatingBody mass', mass, 'a finite number of kilograms > 0');
    if (!Array.isArray(size) || size.length !== 3 || !size.every((s) => s > 0 && s < Infinity)) {
      throw new ParameterError('FloatingBody size', size, '[length, height, width], finite metres > 0');
    }
    if (!(Number.isInteger(samples) && samples >= 1 && samples <= 64)) throw new ParameterError('FloatingBody samples', samples, 'a whole number from 1 to 64');
    if (!(damping >= 0 && damping < Infinity)) throw new ParameterError('FloatingBody damping', damping, 'a finite fraction of critical damping ≥ 0');
    if (!(density > 0 && density < Infinity)) throw new ParameterError('FloatingBody density', density, 'a finite density > 0 (kg/m³)');
    const [length, height, width] = size;
    this.mass = mass;
    this.size = [length, height, width];
    this.density = density;
    this.cellArea = (length * width) / samples ** 2;
    this.points = [];
    for (let i = 0; i < samples; i++) {
      for (let j = 0; j < samples; j++) {
        this.points.push(new Vector3(((i + 0.5) / samples - 0.5) * length, -height / 2, ((j + 0.5) / samples - 0.5) * width));
      }
    }
    this.inertia = new Vector3(height ** 2 + width ** 2, length ** 2 + width ** 2, length ** 2 + height ** 2).multiplyScalar(mass / 12);
    // Critical damping 2·√(k·m) for the waterplane's stiffness k in heave (ρ·g·A) and in pitch and
    // roll (ρ·g·A·L²/12, its second moment), each about its own axis.
    const stiffness = density * GRAVITY * length * width;
    this.heaveDamping = 2 * damping * Math.sqrt(stiffness * mass);
    this.rotationDamping = new Vector3(
      2 * damping * Math.sqrt(((stiffness * width ** 2) / 12) * this.inertia.x),
      2 * damping * Math.sqrt(((stiffness * (length ** 2 + width ** 2)) / 12) * this.inertia.y),
      2 * damping * Math.sqrt(((stiffness * length ** 2) / 12) * this.inertia.z),
    );
  }

  /** The draft on flat water, m / (ρ·A), m. */
  get restingDraft(): number {
    return this.mass / (this.density * this.size[0] * this.size[2]);
  }

  /**
   * Advances the body by dt seconds on `water`, asking its height at each sample point per substep
   * (its x and z are yours to set before). Throws, naming it, on a dt or a position that is not a
   * finite number, and leaves the body as it was.
   */
  step(dt: number, water: WaterSurface): void {
    if (!(dt >= 0 && dt < Infinity)) throw new ParameterError('FloatingBody.step(dt)', dt, 'a finite time step ≥ 0 (s)');
    this.checkPosition('FloatingBody.step');
    const substeps = Math.max(1, Math.ceil(dt / MAX_SUBSTEP));
    const h = dt / substeps;
    for (let s = 0; s < substeps; s++) this.substep(h, water);
    this.press(water);
  }

  /**
   * Puts the body at rest, level, at its resting draft on `water` where it is (its x and z): for a
   * body dropped on the sea, or after a jump in time, where stepping from the old state would not do.
   */
  settle(water: WaterSurface): void {
    this.checkPosition('FloatingBody.settle');
    this.position.y = water.heightAt(this.position.x, this.position.z) + this.size[1] / 2 - this.restingDraft;
    this.velocity.set(0, 0, 0);
    this.angularVelocity.set(0, 0, 0);
    this.orientation.identity();
    this.press(water);
  }

  /**
   * Makes the body push on `water` (an Ocean's localWaves) from now on, with a pressure patch of its
   * footprint as deep as it floats, moved at each step and settle; null takes it off the water.
   */
  pressOn(water: PressableWater | null): void {
    this.pressing?.source.remove();
    this.pressing = null;
    if (water === null) return;
    this.checkPosition('FloatingBody.pressOn');
    const [length, , width] = this.size;
    const source = water.addPressure({ length, beam: width, draft: this.restingDraft }, { x: this.position.x, z: this.position.z, heading: 0 });
    this.pressing = { source, water };
  }

  /**
   * Moves the pressure patch (if any) to the body: heading of its +x axis, as deep as its bottom is
   * under `water` without the local waves (see the file's comment).
   */
  private press(water: WaterSurface): void {
    if (this.pressing === null) return;
    const { x, y, z } = this.position;
    const below = water.heightAt(x, z) - this.pressing.water.heightAt(x, z) - (y - this.size[1] / 2);
    const axis = this.point.set(1, 0, 0).applyQuaternion(this.orientation);
    this.pressing.source.setPose(x, z, Math.atan2(axis.z, axis.x), Math.min(Math.max(below, 0), this.size[1]));
  }

  private checkPosition(method: string): void {
    const { x, y, z } = this.position;
    if (![x, y, z].every(Number.isFinite)) throw new ParameterError(`${method}: position`, [x, y, z], 'finite x, y, z (m)');
  }

  private substep(h: number, water: WaterSurface): void {
    const { force, torque, point, arm } = this;
    force.set(0, -this.mass * GRAVITY, 0);
    torque.set(0, 0, 0);
    const height = this.size[1];
    const up = this.up.set(0, 1, 0).applyQuaternion(this.orientation);
    for (const local of this.points) {
      point.copy(local).applyQuaternion(this.orientation).add(this.position);
      const depth = Math.min(water.heightAt(point.x, point.z) - point.y, height);
      if (depth <= 0) continue;
      const lift = this.density * GRAVITY * this.cellArea * depth;
      force.y += lift;
      arm.subVectors(point, this.position).addScaledVector(up, depth / 2);
      // (arm × (0, lift, 0))
      torque.x -= arm.z * lift;
      torque.z += arm.x * lift;
    }
    force.y -= this.heaveDamping * this.velocity.y;
    this.velocity.y += (force.y / this.mass) * h;
    this.position.y += this.velocity.y * h;

    // Rotation in the box's own axes: α = I⁻¹·(τ − c_ω·ω).
    this.inverse.copy(this.orientation).invert();
    torque.applyQuaternion(this.inverse);
    arm.copy(this.angularVelocity).applyQuaternion(this.inverse);
    arm.set(
      arm.x + ((torque.x - this.rotationDamping.x * arm.x) / this.inertia.x) * h,
      arm.y + ((torque.y - this.rotationDamping.y * arm.y) / this.inertia.y) * h,
      arm.z + ((torque.z - this.rotationDamping.z * arm.z) / this.inertia.z) * h,
    );
    this.angularVelocity.copy(arm.applyQuaternion(this.orientation));
    // dq/dt = ½·(0, ω)·q
    const w = this.angularVelocity;
    this.spin.set(w.x * h * 0.5, w.y * h * 0.5, w.z * h * 0.5, 0).multiply(this.orientation);
    this.orientation.set(
      this.orientation.x + this.spin.x,
      this.orientation.y + this.spin.y,
      this.orientation.z + this.spin.z,
      this.orientation.w + this.spin.w,
    );
    this.orientation.normalize();
  }
}
