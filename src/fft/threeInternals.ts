/**
 * The only place that reaches into three.js beyond its public API, and the three.js releases this
 * package supports.
 *
 * The GPU FFT renders into layers of array textures through a framebuffer of its own
 * (gpuWaveFields.ts, LayeredSpectra), which three.js cannot make. It needs two things three.js
 * keeps to itself:
 *   - the GL texture of a render target (WebGLRenderer.properties → __webglTexture, after
 *     initRenderTarget);
 *   - a way to make its framebuffer the current render target, setRenderTargetFramebuffer (public
 *     in three.js since r139 for WebXR, but not in @types/three).
 * checkThreeInternals() is called before the GPU path is built, so a three.js release without them
 * fails loudly, with a message naming what is missing, instead of drawing a wrong picture.
 *
 * Releases before r180 are refused (checkThreeRelease, from the Ocean), as they draw no sea or a
 * wrong one: r160 to r164 lack what the GPU FFT uses; up to r176 a WebGLArrayRenderTarget ignores
 * its texture options, so the FFT's working layers are 8-bit and the sea a smear; up to r179
 * three.js's logarithmic depth chunks answer to another define (USE_LOGDEPTHBUF), so with
 * logarithmicDepthBuffer the sea's shaders do not compile. Releases after the newest tested one
 * run: three.js ships every few weeks, and a package that refused the next release would break
 * every new install. What could break there is only what this file reaches into, so
 * missingThreeInternals() decides whether the GPU FFT may run; without it the path 'auto' (and
 * 'gpu') falls back to JS and says why (ocean.simulation.pathReason, the app's status line).
 */
import { REVISION, type WebGLRenderer, type WebGLRenderTarget } from 'three';
import { UnsupportedError } from '../parameters/options';

/**
 * The oldest three.js release supported and the newest tested: the browser tests run against the
 * devDependency (the newest tested) and, through scripts/test-three-range.mjs, the oldest and the
 * newest on the registry when it is newer.
 */
export const SUPPORTED_THREE_RELEASES = { oldest: 180, newestTested: 187 } as const;

/** The releases as an npm range, open above: package.json's peerDependencies.three (a unit test compares them). */
export const THREE_PEER_RANGE = `>=0.${SUPPORTED_THREE_RELEASES.oldest}.0`;

/** The releases already told about in this page: the note comes once. */
const notedReleases = new Set<string>();

/**
 * Throws an UnsupportedError naming the release and the range when `revision` (three.js's
 * REVISION: '187', or '188dev' for a build between releases) is older than the oldest supported;
 * for a release newer than the newest tested, logs one console note and returns.
 */
export function checkThreeRelease(revision: string = REVISION): void {
  const release = Number.parseInt(revision, 10);
  const { oldest, newestTested } = SUPPORTED_THREE_RELEASES;
  if (!(release >= oldest)) {
    throw new UnsupportedError('three.js', `three-fft-ocean supports three.js r${oldest} and newer (${THREE_PEER_RANGE}), not r${revision}`);
  }
  if (release > newestTested && !notedReleases.has(revision)) {
    notedReleases.add(revision);
    console.info(`three-fft-ocean: three.js r${revision} is newer than the newest release tested (r${newestTested}); running, with the GPU FFT where three.js's internals still fit it.`);
  }
}

/**
 * Throws an UnsupportedError when `renderer` is not three.js's WebGLRenderer: the sea's materials
 * are GLSL ShaderMaterials and its FFT draws through WebGL 2, which three's WebGPURenderer (from
 * 'three/webgpu', even with forceWebGL) does not run. Without this check such a renderer fails
 * deep inside three.js with a TypeError that names nothing a user passed.
 */
export function checkWebGLRenderer(renderer: unknown): void {
  const flags = (renderer ?? {}) as { isWebGLRenderer?: boolean; isWebGPURenderer?: boolean; isRenderer?: boolean };
  if (flags.isWebGLRenderer === true) return;
  const given = flags.isWebGPURenderer === true || flags.isRenderer === true ? "three.js's WebGPURenderer" : 'not a three.js renderer';
  throw new UnsupportedError(
    'renderer',
    `renderer: three-fft-ocean's Ocean draws with three.js's WebGLRenderer (import { WebGLRenderer } from 'three'); this is ${given}, which it does not drive yet`,
  );
}

interface RendererInternals {
  initRenderTarget?(target: WebGLRenderTarget): void;
  setRenderTargetFramebuffer?(target: WebGLRenderTarget, framebuffer: WebGLFramebuffer | null): void;
  properties: { get(object: object): Record<string, unknown> };
}

/**
 * What this three.js lacks of the internals the GPU FFT uses, as a sentence for the path's reason,
 * or null when it has them all.
 */
export function missingThreeInternals(renderer: WebGLRenderer): string | null {
  const internals = renderer as unknown as Partial<RendererInternals>;
  for (const method of ['initRenderTarget', 'setRenderTargetFramebuffer'] as const) {
    if (typeof internals[method] !== 'function') return `three.js r${REVISION} has no WebGLRenderer.${method}, which the GPU FFT needs`;
  }
  if (typeof internals.properties?.get !== 'function') return `three.js r${REVISION} has no WebGLRenderer.properties, which the GPU FFT needs`;
  return null;
}

/** Throws an UnsupportedError naming the missing piece when this three.js lacks what the GPU FFT needs. */
export function checkThreeInternals(renderer: WebGLRenderer): void {
  const missing = missingThreeInternals(renderer);
  if (missing !== null) throw new UnsupportedError('three.js', `three-fft-ocean: ${missing}`);
}

/** The GL texture of a render target, allocated if it is not yet. */
export function glTextureOf(renderer: WebGLRenderer, target: WebGLRenderTarget): WebGLTexture {
  const internals = renderer as unknown as RendererInternals;
  internals.initRenderTarget!(target);
  const texture = internals.properties.get(target.texture).__webglTexture;
  if (!(texture instanceof WebGLTexture)) {
    throw new UnsupportedError('three.js', `three-fft-ocean: three.js r${REVISION} keeps no __webglTexture for a render target's texture`);
  }
  return texture;
}

/** Makes `framebuffer` what three.js binds for `target` (three.js allocates nothing for the target). */
export function useExternalFramebuffer(renderer: WebGLRenderer, target: WebGLRenderTarget, framebuffer: WebGLFramebuffer): void {
  (renderer as unknown as RendererInternals).setRenderTargetFramebuffer!(target, framebuffer);
}

/**
 * Makes three.js draw into `target` as it draws onto the canvas: tone mapped, and encoded into the
 * colour space of the target's texture (sRGB). three.js does this only for the canvas and for the
 * render targets of WebXR, which it tells by `isXRRenderTarget` (read in r180 to r187 by
 * WebGLRenderer's setProgram, WebGLPrograms, WebGLTextures and UniformsUtils); any other target
 * gets linear colour without tone mapping. A multisampled target made so and copied onto a
 * canvas without antialiasing gives the pixels a multisampled canvas would (render/sceneOutput.ts).
 */
export function drawLikeCanvas(target: WebGLRenderTarget): void {
  (target as unknown as { isXRRenderTarget: boolean }).isXRRenderTarget = true;
}
