/**
 * What the simulation's GPU path can use on a device (any GpuDevice: the choice is made from its
 * capability flags alone), and why not the best, in the device's own words.
 */
import { LAYERED_ATTACHMENTS, type GpuDevice, type GpuPrecision } from './gpuDevice';

export interface GpuSupport {
  /** The precision the GPU path runs at, float32 first; null: the device cannot run it. */
  precision: GpuPrecision | null;
  /** Why it is not float32, in words ('' when it is). */
  reason: string;
}

/**
 * The GPU path's precision on `device`: none where the device is unavailable or one pass cannot
 * write the FFT's LAYERED_ATTACHMENTS layers; else float32 targets, else float16 ones, else none.
 */
export function gpuSupport(device: GpuDevice): GpuSupport {
  const unavailable = device.unavailableReason;
  if (unavailable !== null) return { precision: null, reason: unavailable };
  const drawBuffers = device.drawBuffers;
  if (drawBuffers < LAYERED_ATTACHMENTS) {
    return { precision: null, reason: `${device.capabilityName('drawBuffers')} is ${drawBuffers} (the GPU FFT writes ${LAYERED_ATTACHMENTS} at once)` };
  }
  if (device.float32Targets) return { precision: 'float32', reason: '' };
  const float32 = device.capabilityName('float32Targets');
  if (device.float16Targets) return { precision: 'float16', reason: `no ${float32}: half floats` };
  return { precision: null, reason: `no float render targets (${float32}, ${device.capabilityName('float16Targets')})` };
}
