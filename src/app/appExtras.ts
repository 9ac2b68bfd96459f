/** What the app's panel puts on and takes off the scene: the inspector's tiles, the buoys and the boat. */
import type { PerspectiveCamera, Scene } from 'three';
import type { Ocean } from '../ocean';
import { Boat, centreAhead } from '../objects/boat';
import { Buoys } from '../objects/buoys';
import { Inspector } from './inspector';

export class AppExtras {
  inspector: Inspector | null = null;
  buoys: Buoys | null = null;
  boat: Boat | null = null;

  constructor(
    private readonly ocean: Ocean,
    private readonly scene: Scene,
    private readonly camera: PerspectiveCamera,
    private readonly container: HTMLElement,
    /** The inspector's tiles came or went. */
    private readonly inspectorShown: () => void,
  ) {}

  showInspector(show: boolean): void {
    if (show && !this.inspector) this.inspector = new Inspector(this.ocean, this.container);
    if (!show && this.inspector) {
      this.inspector.dispose();
      this.inspector = null;
    }
    this.inspectorShown();
  }

  /** Drops buoys ahead of the camera on the sea at time `t`, or takes them away. */
  showBuoys(show: boolean, t: number): void {
    if (show && !this.buoys) {
      this.buoys = new Buoys(this.ocean);
      this.ocean.update(t, this.camera); // the water they are set down on
      this.buoys.dropAhead(this.camera);
      this.scene.add(this.buoys);
    }
    if (!show && this.buoys) {
      this.buoys.removeFromParent();
      this.buoys.dispose();
      this.buoys = null;
    }
  }

  /** Puts the boat on its course ahead of the camera, or takes it away. */
  showBoat(show: boolean): void {
    if (show && !this.boat) {
      this.boat = new Boat(this.ocean, centreAhead(this.camera));
      this.scene.add(this.boat);
    }
    if (!show && this.boat) {
      this.boat.removeFromParent();
      this.boat.dispose();
      this.boat = null;
    }
  }
}
