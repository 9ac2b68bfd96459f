/**
 * The GPU path's choice (src/device/gpuSupport.ts) is made from a device's capability flags alone,
 * and its reasons name what the device lacks in the device's words. The devices here are plain
 * objects with only the capability part of GpuDevice: gpuSupport asks nothing else. (The WebGL 2
 * device's own flags are exercised in the browser: tests/browser/app, "falls back …", hides
 * MAX_DRAW_BUFFERS, the extensions and three.js's internals from a real context.)
 */
import { describe, expect, it } from 'vitest';
import { LAYERED_ATTACHMENTS, type GpuCapability, type GpuDevice } from '../../src/device/gpuDevice';
import { gpuSupport } from '../../src/device/gpuSupport';

type Capabilities = Pick<GpuDevice, 'unavailableReason' | 'float32Targets' | 'float16Targets' | 'float32Filterable' | 'drawBuffers' | 'software' | 'capabilityName'>;

function device(changes: Partial<Capabilities> = {}): GpuDevice {
  const capabilities: Capabilities = {
    unavailableReason: null,
    float32Targets: true,
    float16Targets: true,
    float32Filterable: true,
    drawBuffers: LAYERED_ATTACHMENTS,
    software: false,
    capabilityName: (capability: GpuCapability) => `<${capability}>`,
    ...changes,
  };
  return capabilities as GpuDevice;
}

describe('gpuSupport', () => {
  it('takes float32 where the device renders to it, with no reason', () => {
    expect(gpuSupport(device())).toEqual({ precision: 'float32', reason: '' });
  });

  it('takes float16 without float32 targets, naming what is missing', () => {
    expect(gpuSupport(device({ float32Targets: false }))).toEqual({ precision: 'float16', reason: 'no <float32Targets>: half floats' });
  });

  it('takes neither without float targets, naming both', () => {
    expect(gpuSupport(device({ float32Targets: false, float16Targets: false }))).toEqual({
      precision: null,
      reason: 'no float render targets (<float32Targets>, <float16Targets>)',
    });
  });

  it(`needs ${LAYERED_ATTACHMENTS} textures written by one pass (the FFT's layered target)`, () => {
    expect(gpuSupport(device({ drawBuffers: LAYERED_ATTACHMENTS - 1 }))).toEqual({
      precision: null,
      reason: `<drawBuffers> is ${LAYERED_ATTACHMENTS - 1} (the GPU FFT writes ${LAYERED_ATTACHMENTS} at once)`,
    });
  });

  it("gives an unavailable device's reason before any flag", () => {
    expect(gpuSupport(device({ unavailableReason: 'three.js r999 has no X', drawBuffers: 1, float32Targets: false }))).toEqual({
      precision: null,
      reason: 'three.js r999 has no X',
    });
  });
});
