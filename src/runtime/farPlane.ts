/**
 * The camera's far plane, out to the horizon the sea reaches: the one rule the app, <fft-ocean>,
 * the shot CLI and the examples use (the first three through the frame loop, frameLoop.ts), and
 * the WebGPU app and element.
 */
import type { PerspectiveCamera } from 'three';
import type { Ocean } from '../ocean';

/** Never nearer than this (m): a far plane of 10 km keeps the depth buffer's precision and the sky behind the sea. */
const MIN_FAR = 1e4;
/** How far beyond the surface's far edge the far plane goes, so that the edge is never clipped. */
const FAR_MARGIN = 1.5;

/**
 * The far plane for a camera `cameraHeight` metres above the sea: 1.5 × ocean.horizonDistanceFor
 * that height, at least 10 km (`ocean`: the WebGL Ocean or the WebGPU one, src/webgpu/ocean.ts).
 */
export function farPlaneFor(ocean: Pick<Ocean, 'horizonDistanceFor'>, cameraHeight: number): number {
  return Math.max(MIN_FAR, FAR_MARGIN * ocean.horizonDistanceFor(cameraHeight));
}

/**
 * Moves `camera`'s far plane out to the horizon the sea reaches from its height (farPlaneFor), and
 * updates its projection. Call it after the camera moved, before the render.
 */
export function fitFarPlane(camera: PerspectiveCamera, ocean: Pick<Ocean, 'horizonDistanceFor'>): void {
  camera.far = farPlaneFor(ocean, camera.position.y);
  camera.updateProjectionMatrix();
}
