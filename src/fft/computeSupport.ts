/**
 * Whether the compute path (ComputeWaveFields: computeSpectrum.ts, computeFft.ts; and the foam's
 * src/webgpu/computeFoam.ts) can run on a WebGPURenderer, and why not: the WebGPU Ocean's 'auto'
 * runs it where it can and else the JS FFT with this reason (Ocean.path.reason), as the WebGL
 * Ocean's 'auto' reports why its GPU path does not run.
 *
 * What it asks of the device: a WebGPU backend (WebGPURenderer's WebGL2 backend has no compute
 * shaders), a resolution whose lines fit one workgroup (computeFft.ts: 16 to 512), and the limits
 * its kernels use, all within WebGPU's defaults, which three requests its device with.
 */
import type { WebGPURenderer } from 'three/webgpu';

/** The sizes the compute FFT transforms, one workgroup per line, under WebGPU's default limits (computeFft.ts). */
export const MIN_SIZE = 16;
export const MAX_SIZE = 512;

/** The GPUSupportedLimits the compute path reads (a subset of WebGPU's). */
export interface ComputeLimits {
  maxComputeWorkgroupStorageSize: number;
  maxComputeInvocationsPerWorkgroup: number;
  maxComputeWorkgroupSizeX: number;
  maxStorageBuffersPerShaderStage: number;
  maxStorageTexturesPerShaderStage: number;
}

/** Invocations per workgroup of the kernels other than the FFT's (evolution, copy, foam). */
const FLAT_WORKGROUP = 64;

/** Why the compute path cannot run on `renderer` at `resolution`, in words, or null when it can. */
export function computePathUnsupported(renderer: WebGPURenderer, resolution: number): string | null {
  const backend = renderer.backend as { isWebGPUBackend?: boolean; device?: { limits: ComputeLimits } };
  if (backend.isWebGPUBackend !== true || !backend.device) return "WebGPURenderer's WebGL2 backend runs no compute shaders";
  if (resolution < MIN_SIZE || resolution > MAX_SIZE) return `resolution ${resolution}: the compute FFT transforms lines of ${MIN_SIZE} to ${MAX_SIZE} in one workgroup`;
  return computeLimitsShortfall(backend.device.limits, resolution);
}

/** The fields of GPUAdapterInfo (GPUDevice.adapterInfo) that tell a software adapter. */
export interface AdapterFacts {
  architecture?: string;
  description?: string;
  isFallbackAdapter?: boolean;
}

/**
 * Why 'auto' leaves the compute path to `path: 'gpu'` on `renderer`'s adapter, or null: a software
 * adapter (the browser's fallback adapter, SwiftShader, llvmpipe/lavapipe), which runs compute
 * shaders on the CPU lane by lane. Measured there (npm run bench, webgpu-fft, SwiftShader, 2 cores,
 * 2026-11-29): one update of the default three cascades at N = 256 took 406 ms in compute shaders
 * against 8.9 ms for the JS FFT (35 ms for the WebGL Ocean's fragment passes); at N = 512, 3069 ms
 * against 35 ms. The WebGL device's `software` flag tells the same adapters by their names.
 */
export function autoSkipsCompute(renderer: WebGPURenderer): string | null {
  const facts = (renderer.backend as { device?: { adapterInfo?: AdapterFacts } }).device?.adapterInfo;
  return facts && softwareAdapter(facts) ? `a software WebGPU adapter (${facts.architecture || facts.description || 'the fallback adapter'}), where the JS FFT is faster; path 'gpu' runs the compute FFT` : null;
}

/** Whether the adapter these facts describe renders in software. */
export function softwareAdapter(facts: AdapterFacts): boolean {
  return facts.isFallbackAdapter === true || /swiftshader|llvmpipe|lavapipe|softpipe|software/i.test(`${facts.architecture ?? ''} ${facts.description ?? ''}`);
}

/**
 * The first of `limits` below what the compute path needs at `resolution`, in words, or null. Its
 * needs: the FFT keeps two lines of N complex float32 (16·N bytes) in workgroup memory with N/4
 * invocations (computeFft.ts); the evolution binds four storage buffers (computeSpectrum.ts); the
 * copy writes the two field textures (computeWaveFields.ts).
 */
export function computeLimitsShortfall(limits: ComputeLimits, resolution: number): string | null {
  const needs: [keyof ComputeLimits, number, string][] = [
    ['maxComputeWorkgroupStorageSize', 16 * resolution, `bytes (the compute FFT keeps two lines of ${resolution} complex numbers in one workgroup)`],
    ['maxComputeInvocationsPerWorkgroup', Math.max(resolution / 4, FLAT_WORKGROUP), `(the compute FFT runs ${resolution / 4} invocations a line)`],
    ['maxComputeWorkgroupSizeX', Math.max(resolution / 4, FLAT_WORKGROUP), `(the compute FFT runs ${resolution / 4} invocations a line)`],
    ['maxStorageBuffersPerShaderStage', 4, '(the spectrum evolution binds 4)'],
    ['maxStorageTexturesPerShaderStage', 2, '(the fields are written to 2 textures at once)'],
  ];
  for (const [name, needed, why] of needs) {
    if (limits[name] < needed) return `${name} is ${limits[name]}, under ${needed} ${why}`;
  }
  return null;
}
