/**
 * The view <fft-ocean> shows: a camera drifting over the sea, and the course of the boat that
 * circles ahead of it. Functions of simulated time only, so they stand still when paused.
 */
import type { PerspectiveCamera } from 'three';

/** m/s */
const VIEW_DRIFT_SPEED = 1.5;
/** How far ahead of the drifting view the boat's circle is centred (m). */
const BOAT_AHEAD = 60;

/**
 * The default view: `height` metres up, a few degrees below the horizon, facing 30° to one side
 * of the sun's azimuth (so its glitter path crosses the view), drifting forward at 1.5 m/s and
 * turning slowly. A function of simulated time only, so it stands still when paused.
 */
export function placeCamera(camera: PerspectiveCamera, t: number, height: number, sunAzimuthDeg: number): void {
  const { x, z, heading } = viewDrift(t, sunAzimuthDeg);
  const yaw = heading + 0.12 * Math.sin((2 * Math.PI * t) / 120);
  const forwardX = Math.cos(yaw);
  const forwardZ = Math.sin(yaw);
  camera.position.set(x, height, z);
  const pitch = (-6 * Math.PI) / 180;
  const distance = 100;
  camera.lookAt(
    x + distance * Math.cos(pitch) * forwardX,
    height + distance * Math.sin(pitch),
    z + distance * Math.cos(pitch) * forwardZ,
  );
  camera.updateMatrixWorld();
}

/** The centre of the boat's circle at time t (s): BOAT_AHEAD metres ahead of the drifting view. */
export function boatCentre(t: number, sunAzimuthDeg: number): { x: number; z: number } {
  const view = viewDrift(t, sunAzimuthDeg);
  return { x: view.x + BOAT_AHEAD * Math.cos(view.heading), z: view.z + BOAT_AHEAD * Math.sin(view.heading) };
}

/** Where the default view is on the sea at time t (s), and the heading (rad) it drifts along. */
function viewDrift(t: number, sunAzimuthDeg: number): { x: number; z: number; heading: number } {
  const heading = ((sunAzimuthDeg - 30) * Math.PI) / 180;
  const travelled = VIEW_DRIFT_SPEED * t;
  return { x: travelled * Math.cos(heading), z: travelled * Math.sin(heading), heading };
}
