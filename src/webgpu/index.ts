/**
 * The entry for three.js's WebGPURenderer, `import { Ocean } from 'three-fft-ocean/webgpu'`: an
 * Ocean that draws with WebGPURenderer (its WebGPU backend, or its WebGL2 backend with
 * `forceWebGL: true`). A first slice: see docs/embedding.md "WebGPURenderer" for what it draws
 * and what not yet. This file only re-exports.
 * @module three-fft-ocean/webgpu
 */
export { Ocean, type WebGPUOceanEventMap, type WebGPUOceanOptions } from './ocean';
export type { DeviceLoss } from './deviceLoss';
export type { OceanPath } from '../ocean';
export type { PathPreference } from '../layers/oceanSimulation';
export { DisposedError, UnsupportedError } from '../parameters/options';
export { ParameterError } from '../parameters/parameters';
