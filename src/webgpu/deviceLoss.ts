/**
 * When a WebGPURenderer loses its device: on the WebGPU backend the GPUDevice's `lost` promise, for
 * any reason ('unknown': the browser or the driver dropped it; 'destroyed': device.destroy(),
 * which three's own onDeviceLost ignores, so other code destroying it would go unnoticed); on the
 * WebGL2 backend the canvas's webglcontextlost (three's WebGLBackend then stops drawing for good:
 * it restores nothing). Neither comes back: a new renderer is the only way to draw again, which
 * <fft-ocean renderer="webgpu"> makes by itself (src/embed/elementWebGPU.ts).
 */
import type { WebGPURenderer } from 'three/webgpu';
import { UnsupportedError } from '../parameters/options';

/** A lost device: which API lost it, why (GPUDeviceLostInfo's reason, or 'context lost') and the browser's message. */
export interface DeviceLoss {
  api: 'WebGPU' | 'WebGL2';
  reason: string;
  message: string;
}

/**
 * Calls `onLost` once when `renderer`'s device is lost, unless the returned function (stop
 * watching, as before freeing the renderer on purpose) was called first.
 */
export function watchDeviceLoss(renderer: WebGPURenderer, onLost: (loss: DeviceLoss) => void): () => void {
  let watching = true;
  const lost = (loss: DeviceLoss) => {
    if (!watching) return;
    watching = false;
    onLost(loss);
  };
  const backend = renderer.backend as { isWebGPUBackend?: boolean; device?: GPUDevice };
  if (backend.isWebGPUBackend === true && backend.device) {
    void backend.device.lost.then((info) => lost({ api: 'WebGPU', reason: info.reason ?? 'unknown', message: info.message || 'no message' }));
    return () => {
      watching = false;
    };
  }
  const canvas = renderer.domElement;
  const onContextLost = (event: Event) => lost({ api: 'WebGL2', reason: 'context lost', message: (event as WebGLContextEvent).statusMessage || 'no message' });
  canvas.addEventListener('webglcontextlost', onContextLost);
  return () => {
    watching = false;
    canvas.removeEventListener('webglcontextlost', onContextLost);
  };
}

/** The error for using an Ocean whose renderer lost its device: it names the device, why, and what to do. */
export function deviceLostError(loss: DeviceLoss, what: string): UnsupportedError {
  const device = loss.api === 'WebGPU' ? 'WebGPU device' : 'WebGL2 context';
  return new UnsupportedError(
    'renderer',
    `${what}: the renderer's ${device} was lost (${loss.reason}: ${loss.message}) and three.js's WebGPURenderer does not restore it; dispose this Ocean and make a new WebGPURenderer and Ocean (<fft-ocean renderer="webgpu"> does so by itself)`,
  );
}
