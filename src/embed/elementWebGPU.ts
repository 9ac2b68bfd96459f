/**
 * What an <fft-ocean renderer="webgpu"> holds while it is near the screen: its canvas, a
 * WebGPURenderer (on its WebGL2 backend where the browser has no WebGPU adapter), scene, camera
 * and the Ocean of three-fft-ocean/webgpu, started by src/runtime/webgpuStart.ts (which loads
 * three/webgpu only now). The quality levels apply as with WebGL (applyQuality.ts), but MSAA;
 * what the WebGPU Ocean does not draw yet (the options webgpuStart leaves out, and the element's
 * boat and stones) is named in `notDrawn`.
 */
import { ACESFilmicToneMapping, PerspectiveCamera, Scene } from 'three';
import type { WebGPURenderer } from 'three/webgpu';
import type { Ocean as WebGPUOcean } from '../webgpu/ocean';
import type { DeviceLoss } from '../webgpu/deviceLoss';
import { startWebGPUOcean, type WebGPUStart } from '../runtime/webgpuStart';
import type { OceanOptions } from '../ocean';
import { elementCanvas } from './elementScene';
import { fitFarPlane } from '../runtime/farPlane';

export interface WebGPULive {
  kind: 'webgpu';
  canvas: HTMLCanvasElement;
  renderer: WebGPURenderer;
  scene: Scene;
  camera: PerspectiveCamera;
  ocean: WebGPUOcean;
  /** The backend drawing, why it is not WebGPU (null when it is), and the options left out. */
  status: Pick<WebGPUStart, 'backend' | 'fallback' | 'notDrawn'>;
  /** The pixel ratio at render scale 1. */
  pixelRatio: number;
  resizeObserver: ResizeObserver;
  /** Removes every listener createWebGPULive added. */
  removeListeners: () => void;
  /**
   * Whether the renderer's device is lost (the Ocean's devicelost: deviceLoss.ts), which it never
   * gets back: the element then draws no more with it and makes a new renderer and Ocean.
   */
  contextLost: boolean;
}

/** The element's own settings the WebGPU Ocean does not draw yet, with what is missing. */
const ELEMENT_NOT_DRAWN = { boat: 'the boat and its wake (local waves)' } as const;

/**
 * Makes the canvas (not yet in the page), the renderer, the ocean with `options`, the scene and
 * the camera. `boat`: whether the element asks for its boat, which is named in notDrawn.
 * Rejects as startWebGPUOcean does (holding nothing).
 */
export async function createWebGPULive(options: OceanOptions, boat: boolean, events: { activityChanged(): void; resized(): void; deviceLost(loss: DeviceLoss): void }): Promise<WebGPULive> {
  const canvas = elementCanvas();
  // The JS FFT on this thread: the fields of a frame's time are in place when update() returns, so
  // a paused element and renderFrame() show the sea of that time (a worker's fields would arrive a
  // frame or more later, and a paused element draws no more frames to show them).
  const { renderer, ocean, backend, fallback, notDrawn } = await startWebGPUOcean(canvas, { ...options, worker: false });
  if (boat) notDrawn.push({ name: 'boat', missing: ELEMENT_NOT_DRAWN.boat });
  renderer.toneMapping = ACESFilmicToneMapping;
  const scene = new Scene();
  scene.add(ocean);
  const onVisibilityChange = () => events.activityChanged();
  document.addEventListener('visibilitychange', onVisibilityChange);
  // As a lost WebGL context (elementScene.ts): no frames while it is lost; then the element starts afresh.
  const onDeviceLost = ({ loss }: { loss: DeviceLoss }) => {
    live.contextLost = true;
    events.activityChanged();
    events.deviceLost(loss);
  };
  ocean.addEventListener('devicelost', onDeviceLost);
  const live: WebGPULive = {
    kind: 'webgpu',
    canvas,
    renderer,
    scene,
    camera: new PerspectiveCamera(50, 16 / 9, 0.5, 1e4),
    ocean,
    status: { backend, fallback, notDrawn },
    pixelRatio: Math.min(window.devicePixelRatio || 1, 2),
    resizeObserver: new ResizeObserver(() => events.resized()),
    contextLost: false,
    removeListeners: () => {
      document.removeEventListener('visibilitychange', onVisibilityChange);
      ocean.removeEventListener('devicelost', onDeviceLost);
    },
  };
  return live;
}

/** Frees everything createWebGPULive made: the ocean, the renderer (and its device) and the canvas. */
export function disposeWebGPULive(live: WebGPULive): void {
  live.resizeObserver.disconnect();
  live.removeListeners();
  live.scene.remove(live.ocean);
  live.ocean.dispose();
  live.renderer.dispose();
  live.canvas.remove();
}

/**
 * Draws time `t` for the camera `placeCamera` puts: the WebGPU Ocean updated to it, the far plane
 * out to its horizon (farPlane.ts), the render. (The WebGL element's frame loop also wraps very
 * long times by the repeat period; not done here yet.)
 */
export function drawWebGPU(live: WebGPULive, t: number, placeCamera: (t: number) => void): void {
  placeCamera(t);
  live.ocean.update(t);
  fitFarPlane(live.camera, live.ocean);
  live.renderer.render(live.scene, live.camera);
}
