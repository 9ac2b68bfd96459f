/**
 * What the app puts in the sea besides the sea (the panel's "scene", the URL's scene=): the open
 * sea alone, or the island of src/objects/island.ts with its reef, pier and moored boat. Choosing
 * the island moves the camera to a boat offshore of its beach (islandPose); a link with the island
 * and no camera of its own starts there too.
 */
import type { Scene } from 'three';
import { Island, ISLAND_VIEW } from '../objects/island';
import type { Ocean } from '../ocean';
import { anglesFromDirection, type CameraPose } from './flyControls';
import { DEFAULT_STATE, type AppState, type SceneChoice } from './urlState';

/** The fly controls' pose that looks at the island's beach (ISLAND_VIEW). */
export function islandPose(): CameraPose {
  const [x, y, z] = ISLAND_VIEW.position;
  const [tx, ty, tz] = ISLAND_VIEW.target;
  const { yaw, pitch } = anglesFromDirection([tx - x, ty - y, tz - z]);
  return { position: [x, y, z], yaw, pitch };
}

/** The camera the app starts from: the island's view when the island is chosen and the URL gave no camera. */
export function startingCam(state: Readonly<AppState>): AppState['cam'] {
  const defaultCam = state.cam.every((value, i) => value === DEFAULT_STATE.cam[i]);
  if (state.scene !== 'island' || !defaultCam) return [...state.cam];
  const { position, yaw, pitch } = islandPose();
  return [...position, yaw, pitch];
}

/** The objects of the chosen scene, in `scene`, on `ocean`'s water. */
export class SceneObjects {
  private current: Island | null = null;

  constructor(
    private readonly scene: Scene,
    private readonly ocean: Ocean,
  ) {}

  get island(): Island | null {
    return this.current;
  }

  /** Puts the chosen scene's objects in (and takes the others out, freeing them); true if that changed anything. */
  show(choice: SceneChoice): boolean {
    if ((choice === 'island') === (this.current !== null)) return false;
    if (choice === 'island') {
      this.current = new Island();
      this.scene.add(this.current);
      // Its sea floor: the waves shoal and break on the beach and the reef (docs/shores.md).
      this.ocean.setSeabed(this.current.seabed);
    } else if (this.current) {
      this.ocean.setSeabed(null); // the open sea's floor, as deep as the depth option
      this.current.removeFromParent();
      this.current.dispose();
      this.current = null;
    }
    return true;
  }

  /** Sets the moored boat on the water of the ocean's time (call after ocean.update). */
  update(): void {
    this.current?.update(this.ocean);
  }
}
