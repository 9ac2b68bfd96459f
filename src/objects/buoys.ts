/**
 * A few buoys dropped on the sea ahead of the camera (the panel's "buoys" toggle): each a
 * FloatingBody (src/layers/floatingBody.ts) over ocean.heightAt, drawn as a flat red float with a
 * yellow mast (lit by the app's SunLight). Their motion is integrated frame to frame; after a jump
 * in time (a seek, a reload of t) they are put back at rest on the water. As they move they press
 * on the local waves (FloatingBody.pressOn) and make waves. dispose() frees their geometry and
 * materials and takes them off the water.
 */
import { BoxGeometry, Group, Mesh, MeshStandardMaterial, type Camera, Vector3 } from 'three';
import { FloatingBody } from '../layers/floatingBody';
import type { Ocean } from '../ocean';

/**
 * A float 1.4 × 0.6 × 1.4 m of 300 kg: it rides 0.15 m deep, and stays upright: its metacentre is
 * well above its centre of mass (GM = KB + BM − KG ≈ 0.07 + 1.1 − 0.3 m for the whole waterplane).
 */
const FLOAT_SIZE: [number, number, number] = [1.4, 0.6, 1.4];
const FLOAT_MASS = 300;
/** Where the buoys go, ahead of the camera: (metres ahead, metres to the right). */
const LAYOUT: [number, number][] = [
  [25, -6],
  [35, 8],
  [50, -14],
  [65, 4],
  [85, -2],
];
/** A step longer than this is a jump in time: the buoys are set down at rest instead. */
const MAX_STEP = 1;

export class Buoys extends Group {
  private readonly bodies: FloatingBody[] = [];
  private readonly floats: Mesh[] = [];
  private readonly floatGeometry = new BoxGeometry(...FLOAT_SIZE);
  private readonly mastGeometry = new BoxGeometry(0.08, 1.6, 0.08);
  private readonly floatMaterial = new MeshStandardMaterial({ color: 0xd8281c, roughness: 0.6 });
  private readonly mastMaterial = new MeshStandardMaterial({ color: 0xf2c81a, roughness: 0.5 });
  private lastTime: number | null = null;

  constructor(private readonly ocean: Ocean) {
    super();
    this.name = 'buoys';
    for (let i = 0; i < LAYOUT.length; i++) {
      const buoy = new Mesh(this.floatGeometry, this.floatMaterial);
      const mast = new Mesh(this.mastGeometry, this.mastMaterial);
      mast.position.y = FLOAT_SIZE[1] / 2 + 0.8;
      buoy.add(mast);
      this.add(buoy);
      this.floats.push(buoy);
      this.bodies.push(new FloatingBody({ mass: FLOAT_MASS, size: FLOAT_SIZE, samples: 2 }));
    }
  }

  /** Puts the buoys down ahead of the camera, level, at rest on the water of the current time. */
  dropAhead(camera: Camera): void {
    const forward = camera.getWorldDirection(new Vector3()).setY(0).normalize();
    const right = new Vector3(-forward.z, 0, forward.x);
    this.bodies.forEach((body, i) => {
      const [ahead, across] = LAYOUT[i];
      body.position.copy(camera.position).addScaledVector(forward, ahead).addScaledVector(right, across);
      body.pressOn(this.ocean.localWaves);
      body.settle(this.ocean);
    });
    this.lastTime = null;
    this.sync();
  }

  /** Moves the buoys to time t (s) of the ocean (call after ocean.update(t)). */
  update(t: number): void {
    const dt = this.lastTime === null ? 0 : t - this.lastTime;
    this.lastTime = t;
    if (dt > 0 && dt <= MAX_STEP) for (const body of this.bodies) body.step(dt, this.ocean);
    else if (dt !== 0) for (const body of this.bodies) body.settle(this.ocean);
    this.sync();
  }

  private sync(): void {
    this.floats.forEach((buoy, i) => {
      buoy.position.copy(this.bodies[i].position);
      buoy.quaternion.copy(this.bodies[i].orientation);
    });
  }

  dispose(): void {
    for (const body of this.bodies) body.pressOn(null);
    this.floatGeometry.dispose();
    this.mastGeometry.dispose();
    this.floatMaterial.dispose();
    this.mastMaterial.dispose();
  }
}
