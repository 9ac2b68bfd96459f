/**
 * How the app (?renderer=webgpu) and <fft-ocean renderer="webgpu"> start three's WebGPURenderer
 * and the Ocean of three-fft-ocean/webgpu. Both are loaded here with dynamic imports, so a page
 * that draws with WebGLRenderer never downloads them.
 *
 * Where the browser offers no WebGPU adapter (no navigator.gpu, or it returns none), the renderer
 * runs on its own WebGL2 backend (forceWebGL) and `fallback` says why, once on the console too.
 * Options the WebGPU Ocean does not draw yet (its notDrawnYet) are left out rather than refused,
 * so the page shows a sea; `notDrawn` names them for the shell to show.
 */
import type { WebGPURenderer } from 'three/webgpu';
import type { Ocean as WebGPUOcean, WebGPUOceanOptions } from '../webgpu/ocean';

/** A started WebGPURenderer and its Ocean, and what the shell tells its user about them. */
export interface WebGPUStart {
  renderer: WebGPURenderer;
  ocean: WebGPUOcean;
  /** The backend three chose: 'WebGPU', or 'WebGL2' where there is no WebGPU adapter. */
  backend: 'WebGPU' | 'WebGL2';
  /** Why it is not the WebGPU backend, in words; null when it is. */
  fallback: string | null;
  /** The options left out, with what the WebGPU Ocean does not draw yet, in words. */
  notDrawn: { name: string; missing: string }[];
}

/** Fallback reasons already told on this page's console: the note comes once. */
const notedFallbacks = new Set<string>();

/**
 * Makes a WebGPURenderer drawing into `canvas` (initialized: its backend is chosen) and a WebGPU
 * Ocean with `options` less those it does not draw yet. If the Ocean throws, the renderer is
 * disposed before the error is passed on: the caller owns both only once this resolves.
 */
export async function startWebGPUOcean(canvas: HTMLCanvasElement, options: Record<string, unknown>): Promise<WebGPUStart> {
  const [{ WebGPURenderer }, { Ocean, notDrawnYet }] = await Promise.all([import('three/webgpu'), import('../webgpu/ocean')]);
  const fallback = await missingWebGPU();
  const renderer = new WebGPURenderer({ canvas, antialias: false, forceWebGL: fallback !== null, powerPreference: 'high-performance' });
  try {
    await renderer.init();
    const notDrawn = notDrawnYet(options, renderer);
    const accepted = Object.fromEntries(Object.entries(options).filter(([name]) => !notDrawn.some((left) => left.name === name)));
    const ocean = new Ocean(renderer, accepted as WebGPUOceanOptions);
    const backend = (renderer.backend as { isWebGPUBackend?: boolean }).isWebGPUBackend === true ? 'WebGPU' : 'WebGL2';
    if (fallback !== null && !notedFallbacks.has(fallback)) {
      notedFallbacks.add(fallback);
      console.info(`three-fft-ocean/webgpu: ${fallback}: WebGPURenderer draws with its WebGL2 backend.`);
    }
    return { renderer, ocean, backend, fallback, notDrawn };
  } catch (error) {
    renderer.dispose();
    throw error;
  }
}

/** Why this browser has no WebGPU adapter, in words; null when it has one. */
async function missingWebGPU(): Promise<string | null> {
  const gpu = (navigator as Navigator & { gpu?: { requestAdapter(): Promise<unknown> } }).gpu;
  if (gpu === undefined) return 'this browser has no WebGPU (navigator.gpu is undefined)';
  try {
    if ((await gpu.requestAdapter()) !== null) return null;
  } catch {
    // requestAdapter rejects where WebGPU is switched off: no adapter either.
  }
  return 'this browser offers no WebGPU adapter';
}
