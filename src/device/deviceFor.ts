/**
 * The one place that tells which three.js renderer it was handed and makes the GpuDevice for it.
 * Every user of the GPU (the simulation, the cascades, the foam, the local waves) gets its device
 * here, and each entry point checks its renderer here first, so that a renderer of the wrong kind
 * ends in an UnsupportedError that names the entry point to use instead, never in a TypeError
 * from inside three.js.
 *
 * three-fft-ocean's Ocean draws GLSL ShaderMaterials through WebGL 2, which three's WebGPURenderer
 * (even with forceWebGL) does not run; three-fft-ocean/webgpu's Ocean draws TSL node materials,
 * which WebGLRenderer does not run. Renderers are told apart by three's own flags (isWebGLRenderer,
 * isWebGPURenderer), duck-typed as three does, so a renderer of another copy of three counts too.
 */
import type { WebGLRenderer } from 'three';
import { UnsupportedError } from '../parameters/options';
import { WebGL2Device } from './webgl2/webgl2Device';

/** The package's entry points: the WebGL Ocean's and the WebGPU Ocean's. */
export type OceanEntry = 'three-fft-ocean' | 'three-fft-ocean/webgpu';

/** What each entry point draws with, and the import that names it. */
const ENTRIES: Record<OceanEntry, { renderer: 'WebGLRenderer' | 'WebGPURenderer'; import: string }> = {
  'three-fft-ocean': { renderer: 'WebGLRenderer', import: "import { WebGLRenderer } from 'three'" },
  'three-fft-ocean/webgpu': { renderer: 'WebGPURenderer', import: "import { WebGPURenderer } from 'three/webgpu'" },
};

/** Which of three's renderers `renderer` is, by its flags; null for anything else. */
export function rendererKind(renderer: unknown): 'WebGLRenderer' | 'WebGPURenderer' | null {
  const flags = (typeof renderer === 'object' && renderer !== null ? renderer : {}) as { isWebGLRenderer?: unknown; isWebGPURenderer?: unknown; isRenderer?: unknown };
  if (flags.isWebGLRenderer === true) return 'WebGLRenderer';
  // three's Renderer base class (isRenderer) is what WebGPURenderer extends; nothing else sets it.
  if (flags.isWebGPURenderer === true || flags.isRenderer === true) return 'WebGPURenderer';
  return null;
}

/**
 * Throws an UnsupportedError (parameter 'renderer') unless `renderer` is the renderer the Ocean
 * of `entry` draws with; for the other one of three's renderers it names the entry point that
 * draws with it.
 */
export function checkRenderer(renderer: unknown, entry: OceanEntry): void {
  const wanted = ENTRIES[entry];
  const kind = rendererKind(renderer);
  if (kind === wanted.renderer) return;
  const other = (Object.keys(ENTRIES) as OceanEntry[]).find((name) => ENTRIES[name].renderer === kind);
  const given = other === undefined ? 'this is not a three.js renderer' : `this is three.js's ${kind}: use the Ocean of ${other} for it`;
  throw new UnsupportedError('renderer', `renderer: ${entry}'s Ocean draws with three.js's ${wanted.renderer} (${wanted.import}); ${given}`);
}

/**
 * The GpuDevice for `renderer`: a WebGL2Device on three's WebGLRenderer, the only GPU backend of
 * the simulation so far (the WebGPU Ocean computes its fields with the JS FFT, and asks only
 * checkRenderer). Throws as checkRenderer(renderer, 'three-fft-ocean') does for anything else.
 * The caller owns the device and disposes it.
 */
export function createGpuDevice(renderer: unknown): WebGL2Device {
  checkRenderer(renderer, 'three-fft-ocean');
  return new WebGL2Device(renderer as WebGLRenderer);
}
