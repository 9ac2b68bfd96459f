import { describe, expect, it } from 'vitest';
import { computeLimitsShortfall, MAX_SIZE, softwareAdapter, type ComputeLimits } from '../../src/fft/computeSupport';

// WebGPU's default limits (https://www.w3.org/TR/webgpu/#limits), which three requests its device
// with and every adapter offers: the compute path must run within them at every size it takes.
const DEFAULTS: ComputeLimits = {
  maxComputeWorkgroupStorageSize: 16384,
  maxComputeInvocationsPerWorkgroup: 256,
  maxComputeWorkgroupSizeX: 256,
  maxStorageBuffersPerShaderStage: 8,
  maxStorageTexturesPerShaderStage: 4,
};

describe('computeLimitsShortfall: what the WebGPU Ocean\'s compute path needs of a device', () => {
  it('asks for nothing beyond the WebGPU defaults up to N = 512', () => {
    for (let n = 16; n <= MAX_SIZE; n *= 2) expect(computeLimitsShortfall(DEFAULTS, n)).toBeNull();
  });

  it('names the first limit short of what a size needs, its value and the need', () => {
    // Two lines of 512 complex float32 take 8 KiB of workgroup memory; 128 invocations a line.
    expect(computeLimitsShortfall({ ...DEFAULTS, maxComputeWorkgroupStorageSize: 8191 }, 512)).toBe(
      'maxComputeWorkgroupStorageSize is 8191, under 8192 bytes (the compute FFT keeps two lines of 512 complex numbers in one workgroup)',
    );
    expect(computeLimitsShortfall({ ...DEFAULTS, maxComputeWorkgroupStorageSize: 8191 }, 256)).toBeNull();
    expect(computeLimitsShortfall({ ...DEFAULTS, maxComputeInvocationsPerWorkgroup: 64 }, 512)).toMatch(/^maxComputeInvocationsPerWorkgroup is 64, under 128 /);
    expect(computeLimitsShortfall({ ...DEFAULTS, maxComputeWorkgroupSizeX: 100 }, 512)).toMatch(/^maxComputeWorkgroupSizeX is 100, under 128 /);
    expect(computeLimitsShortfall({ ...DEFAULTS, maxStorageBuffersPerShaderStage: 3 }, 64)).toMatch(/^maxStorageBuffersPerShaderStage is 3, under 4 /);
    expect(computeLimitsShortfall({ ...DEFAULTS, maxStorageTexturesPerShaderStage: 1 }, 64)).toMatch(/^maxStorageTexturesPerShaderStage is 1, under 2 /);
  });
});

describe("softwareAdapter: where the WebGPU Ocean's 'auto' leaves the compute path to path 'gpu'", () => {
  it('tells software adapters by GPUAdapterInfo, hardware ones not', () => {
    // SwiftShader's adapter in headless Chromium here (BROWSER.md: vendor google, architecture swiftshader).
    expect(softwareAdapter({ architecture: 'swiftshader', description: '' })).toBe(true);
    expect(softwareAdapter({ architecture: '', description: 'llvmpipe (LLVM 15.0.6, 256 bits)' })).toBe(true);
    expect(softwareAdapter({ architecture: '', description: '', isFallbackAdapter: true })).toBe(true);
    expect(softwareAdapter({ architecture: 'ampere', description: 'NVIDIA GeForce RTX 3060' })).toBe(false);
    expect(softwareAdapter({ architecture: 'rdna-3', description: '' })).toBe(false);
    expect(softwareAdapter({})).toBe(false);
  });
});
