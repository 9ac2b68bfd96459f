/**
 * A boat going round a circle (the app's "boat" toggle, <fft-ocean boat>, the shot CLI's --boat),
 * pressing on the local waves (src/layers/localWaves.ts) so that it leaves a Kelvin wake. Its
 * course is a function of the simulation time, so a paused or reloaded scene puts it, and its wake,
 * at the same place. The circle's centre is fixed ahead of the camera (the app) or moves with a
 * drifting view (the element); the local-wave grid follows it. The boat sits on the water at
 * heightAt and tilts with normalAt. dispose() frees its geometry and materials and takes its
 * pressure off the sea.
 */
import { BoxGeometry, Group, Mesh, MeshStandardMaterial, Quaternion, Vector3, type Camera } from 'three';
import type { PressureSource } from '../layers/localWaves';
import type { Ocean } from '../ocean';

/** Hull: length, beam and draft (m); its Froude number U/√(g·L) at SPEED is 0.56. */
const HULL = { length: 8, beam: 2.6, draft: 0.6 };
/** m/s (about 10 knots): its wake's waves are 2πU²/g = 16 m long. */
const SPEED = 5;
/** The circle: its radius, and how far ahead of the camera its centre is (m). */
const RADIUS = 30;
const AHEAD = 45;
/** Half the interval (s) over which the heading is taken from the course. */
const HEADING_STEP = 0.05;

/** Where the centre of the boat's circle is at time t (s), m. */
export type CourseCentre = (t: number) => { x: number; z: number };

/** A centre that stays AHEAD metres in front of where the camera is now, on the sea. */
export function centreAhead(camera: Camera): CourseCentre {
  const forward = camera.getWorldDirection(new Vector3()).setY(0).normalize();
  const centre = { x: camera.position.x + AHEAD * forward.x, z: camera.position.z + AHEAD * forward.z };
  return () => centre;
}

/**
 * The boat's hull and cabin, its bow along +x and its waterline at y = 0, with no motion of its own:
 * the circling Boat and the island's moored boat (island.ts) are this model. setOnWater puts it on
 * the sea. dispose() frees its geometry and materials.
 */
export class BoatModel extends Group {
  private readonly hullGeometry = new BoxGeometry(HULL.length, 1.4, HULL.beam);
  private readonly cabinGeometry = new BoxGeometry(2.6, 1.2, 2);
  private readonly hullMaterial = new MeshStandardMaterial({ color: 0xf2f2ee, roughness: 0.5 });
  private readonly cabinMaterial = new MeshStandardMaterial({ color: 0x33475c, roughness: 0.4 });
  private readonly normal = new Vector3();
  private readonly tilt = new Quaternion();

  constructor() {
    super();
    this.name = 'boat';
    const hull = new Mesh(this.hullGeometry, this.hullMaterial);
    hull.position.y = 0.7 - HULL.draft;
    const cabin = new Mesh(this.cabinGeometry, this.cabinMaterial);
    cabin.position.set(-0.8, 1.3, 0);
    hull.add(cabin);
    this.add(hull);
  }

  /**
   * Sets the boat at (x, z) on the ocean's water of its current time (call after ocean.update),
   * heading along `heading` (radians from +x towards +z), tilted with the water's normal there.
   */
  setOnWater(ocean: Ocean, x: number, z: number, heading: number): void {
    this.position.set(x, ocean.heightAt(x, z), z);
    // Heading about y (from +x towards +z is a turn by −heading), then tilted with the water.
    this.quaternion.setFromAxisAngle(new Vector3(0, 1, 0), -heading);
    this.tilt.setFromUnitVectors(new Vector3(0, 1, 0), ocean.normalAt(x, z, this.normal));
    this.quaternion.premultiply(this.tilt);
  }

  dispose(): void {
    this.hullGeometry.dispose();
    this.cabinGeometry.dispose();
    this.hullMaterial.dispose();
    this.cabinMaterial.dispose();
  }
}

export class Boat extends BoatModel {
  private readonly pressure: PressureSource | null;

  constructor(
    private readonly ocean: Ocean,
    private readonly centreAt: CourseCentre,
  ) {
    super();
    const start = this.poseAt(ocean.time);
    // Its course is a path of time: the local waves move it themselves, and run its wake up to the
    // current time after a jump (a reload, a seek, a still from the shot CLI).
    this.pressure = ocean.localWaves?.addPressure(HULL, start, (t) => this.poseAt(t)) ?? null;
    // The grid follows the circle's centre, by time too: a still's run-up moves it as the centre moved.
    ocean.localWaves?.follow(centreAt);
  }

  /**
   * Where the course puts the boat at time t (s): anticlockwise round the centre seen from above,
   * heading where it goes (along the circle plus the centre's own drift: a central difference).
   */
  poseAt(t: number): { x: number; z: number; heading: number } {
    const [x, z] = this.placeAt(t);
    const [xAfter, zAfter] = this.placeAt(t + HEADING_STEP);
    const [xBefore, zBefore] = this.placeAt(t - HEADING_STEP);
    return { x, z, heading: Math.atan2(zAfter - zBefore, xAfter - xBefore) };
  }

  private placeAt(t: number): [number, number] {
    const angle = (SPEED / RADIUS) * t;
    const centre = this.centreAt(t);
    return [centre.x + RADIUS * Math.cos(angle), centre.z + RADIUS * Math.sin(angle)];
  }

  /** Sets the boat on its course and on the water at the ocean's current time (call after ocean.update). */
  update(): void {
    const { x, z, heading } = this.poseAt(this.ocean.time);
    this.setOnWater(this.ocean, x, z, heading);
  }

  dispose(): void {
    this.pressure?.remove();
    this.ocean.localWaves?.follow(null);
    super.dispose();
  }
}
