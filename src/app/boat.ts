/**
 * A boat going round a circle ahead of the camera (the panel's "boat" toggle), pressing on the
 * local waves (src/layers/localWaves.ts) so that it leaves a Kelvin wake. Its course is a function
 * of the simulation time, so a paused or reloaded scene puts it at the same place; the local-wave
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
  private heading = 0;

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
    this.pressure = ocean.localWaves?.addPressure(HULL, start) ?? null;
    ocean.localWaves?.follow(this.centre.x, this.centre.z);
  }

  /** Where the course puts the boat at time t (s): anticlockwise seen from above, heading along it. */
  poseAt(t: number): { x: number; z: number; heading: number } {
    const angle = (SPEED / RADIUS) * t;
    return { x: this.centre.x + RADIUS * Math.cos(angle), z: this.centre.z + RADIUS * Math.sin(angle), heading: angle + Math.PI / 2 };
  }

  /** Steers the boat to time t; call before ocean.update(t) so that its wake is stepped with it. */
  update(t: number): void {
    const { x, z, heading } = this.poseAt(t);
    this.pressure?.setPose(x, z, heading);
    this.heading = heading;
    this.position.set(x, 0, z);
  }

  /** Sets the boat on the water of the ocean's current time (call after ocean.update). */
  float(): void {
    const { x, z } = this.position;
    const heading = this.heading;
    this.position.y = this.ocean.heightAt(x, z);
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
