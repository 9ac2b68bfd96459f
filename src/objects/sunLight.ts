/**
 * Light for the objects on the sea (buoys, the boat): a sun from the ocean's sky and a sky/sea
 * hemisphere light. The sea's shader does not use three.js lights; MeshStandardMaterial does.
 */
import { DirectionalLight, Group, HemisphereLight } from 'three';
import type { Ocean } from '../ocean';

export class SunLight extends Group {
  private readonly sun = new DirectionalLight(0xfff2dd, 2.5);

  constructor(private readonly ocean: Ocean) {
    super();
    this.name = 'sun light';
    this.add(this.sun, new HemisphereLight(0xc4daf0, 0x2a4a62, 2));
  }

  /** Puts the sun where the ocean's sky has it (call when it moves, or every frame). */
  update(): void {
    this.sun.position.copy(this.ocean.sky.sunDirection).multiplyScalar(100);
  }
}
