/**
 * Where a pointer points on the sea: the ray from the camera through a point of the canvas, met
 * with the mean sea level y = 0 (the waves are a few metres at most: a stone dropped there lands
 * within a wave's height of the crest under the pointer). For the app's and the element's "click
 * the sea to drop a stone".
 */
import { Plane, Raycaster, Vector2, Vector3, type Camera } from 'three';

/** The stone a click drops (localWaves.ts drop): a dip 1.2 m wide and 0.8 m deep, whose rings show from a boat's deck or a cliff. */
export const CLICKED_STONE = { radius: 1.2, depth: 0.8 } as const;

const seaLevel = new Plane(new Vector3(0, 1, 0), 0);
const raycaster = new Raycaster();
const pointer = new Vector2();

/** The sea point under (clientX, clientY) of `canvas` seen by `camera`, in `out`; null when the ray misses the sea. */
export function seaPointUnder(camera: Camera, canvas: HTMLElement, clientX: number, clientY: number, out = new Vector3()): Vector3 | null {
  const bounds = canvas.getBoundingClientRect();
  if (bounds.width === 0 || bounds.height === 0) return null;
  pointer.set(((clientX - bounds.left) / bounds.width) * 2 - 1, 1 - ((clientY - bounds.top) / bounds.height) * 2);
  raycaster.setFromCamera(pointer, camera);
  return raycaster.ray.intersectPlane(seaLevel, out);
}
