/**
 * Light for the objects on the sea (buoys, the boat): a sun from the ocean's sky and a sky/sea
 * hemisphere light. The sea's shader does not use three.js lights; MeshStandardMaterial does.
 */
import { DirectionalLight, Group, HemisphereLight } from 'three';
import type { Ocean } from '../ocean';

const SUN_INTENSITY = 2.5;
const SKY_INTENSITY = 2;

export class SunLight extends Group {
  private readonly sun = new DirectionalLight(0xfff2dd, SUN_INTENSITY);
  private readonly skyLight = new HemisphereLight(0xc4daf0, 0x2a4a62, SKY_INTENSITY);

  constructor(private readonly ocean: Ocean) {
    super();
    this.name = 'sun light';
    this.add(this.sun, this.skyLight);
  }

  /** Puts the sun where the ocean's sky has it, and dims both lights as it sets (call when it moves, or every frame). */
  update(): void {
    const sky = this.ocean.sky;
    this.sun.position.copy(sky.sunDirection).multiplyScalar(100);
    this.sun.intensity = SUN_INTENSITY * sky.skyUniforms.skySunVisibility.value;
    this.skyLight.intensity = SKY_INTENSITY * sky.skyUniforms.skyDaylight.value;
  }
}
