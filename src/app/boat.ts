/**
 * A boat going round a circle ahead of the camera (the panel's "boat" toggle), pressing on the
 * local waves (src/layers/localWaves.ts) so that it leaves a Kelvin wake. Its course is a function
 * of the simulation time, so a paused or reloaded scene puts it, and its wake, at the same place; the local-wave
 * grid follows the circle's centre while it runs. It sits on the water at heightAt and tilts with
 * normalAt. dispose() frees its geometry and materials and takes its pressure off the sea.
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

export class Boat extends Group {
  private readonly centre = new Vector3();
  private readonly pressure: PressureSource | null;
  private readonly hullGeometry = new BoxGeometry(HULL.length, 1.4, HULL.beam);
  private readonly cabinGeometry = new BoxGeometry(2.6, 1.2, 2);
  private readonly hullMaterial = new MeshStandardMaterial({ color: 0xf2f2ee, roughness: 0.5 });
  private readonly cabinMaterial = new MeshStandardMaterial({ color: 0x33475c, roughness: 0.4 });
  private readonly normal = new Vector3();
  private readonly tilt = new Quaternion();

  constructor(
    private readonly ocean: Ocean,
    camera: Camera,
  ) {
    super();
    this.name = 'boat';
    const forward = camera.getWorldDirection(new Vector3()).setY(0).normalize();
    this.centre.copy(camera.position).setY(0).addScaledVector(forward, AHEAD);
    const hull = new Mesh(this.hullGeometry, this.hullMaterial);
    hull.position.y = 0.7 - HULL.draft;
    const cabin = new Mesh(this.cabinGeometry, this.cabinMaterial);
    cabin.position.set(-0.8, 1.3, 0);
    hull.add(cabin);
    this.add(hull);
    const start = this.poseAt(ocean.time);
    // Its course is a path of time: the local waves move it themselves, and run its wake up to the
    // current time after a jump (a reload, a seek, a still from the shot CLI).
    this.pressure = ocean.localWaves?.addPressure(HULL, start, (t) => this.poseAt(t)) ?? null;
    ocean.localWaves?.follow(this.centre.x, this.centre.z);
  }

  /** Where the course puts the boat at time t (s): anticlockwise seen from above, heading along it. */
  poseAt(t: number): { x: number; z: number; heading: number } {
    const angle = (SPEED / RADIUS) * t;
    return { x: this.centre.x + RADIUS * Math.cos(angle), z: this.centre.z + RADIUS * Math.sin(angle), heading: angle + Math.PI / 2 };
  }

  /** Sets the boat on its course and on the water at the ocean's current time (call after ocean.update). */
  update(): void {
    const { x, z, heading } = this.poseAt(this.ocean.time);
    this.position.set(x, this.ocean.heightAt(x, z), z);
    // Heading about y (from +x towards +z is a turn by −heading), then tilted with the water.
    this.quaternion.setFromAxisAngle(new Vector3(0, 1, 0), -heading);
    this.tilt.setFromUnitVectors(new Vector3(0, 1, 0), this.ocean.normalAt(x, z, this.normal));
    this.quaternion.premultiply(this.tilt);
  }

  dispose(): void {
    this.pressure?.remove();
    this.ocean.localWaves?.follow(null);
    this.hullGeometry.dispose();
    this.cabinGeometry.dispose();
    this.hullMaterial.dispose();
    this.cabinMaterial.dispose();
  }
}
