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
 * Releases before r180 are refused (checkThreeRelease, from the Ocean and the GPU FFT), as they
 * draw no sea or a wrong one: r160 to r164 lack what the GPU FFT uses; up to r176 a
 * WebGLArrayRenderTarget ignores its texture options, so the FFT's working layers are 8-bit and the
 * sea a smear; up to r179 three.js's logarithmic depth chunks answer to another define
 * (USE_LOGDEPTHBUF), so with logarithmicDepthBuffer the sea's shaders do not compile. Releases
 * after the newest tested one are refused too, rather than trusted with these internals.
 */
import { REVISION, type WebGLRenderer, type WebGLRenderTarget } from 'three';
import { UnsupportedError } from '../parameters/options';

/**
 * The oldest and the newest three.js release supported, both tested: the browser tests run against
 * the newest (the devDependency) and, through scripts/test-three-range.mjs, the oldest.
 */
export const SUPPORTED_THREE_RELEASES = { oldest: 180, newest: 187 } as const;

/** The same releases as an npm range: package.json's peerDependencies.three (a unit test compares them). */
export const THREE_PEER_RANGE = `>=0.${SUPPORTED_THREE_RELEASES.oldest}.0 <0.${SUPPORTED_THREE_RELEASES.newest + 1}.0`;

/**
 * Throws an UnsupportedError naming the release and the supported ones when `revision` (three.js's
 * REVISION: '187', or '188dev' for a build between releases) is outside them.
 */
export function checkThreeRelease(revision: string = REVISION): void {
  const release = Number.parseInt(revision, 10);
  const { oldest, newest } = SUPPORTED_THREE_RELEASES;
  if (!(release >= oldest && release <= newest)) {
    throw new UnsupportedError('three.js', `three-fft-ocean supports three.js r${oldest} to r${newest} (${THREE_PEER_RANGE}), not r${revision}`);
  }
}

interface RendererInternals {
  initRenderTarget?(target: WebGLRenderTarget): void;
  setRenderTargetFramebuffer?(target: WebGLRenderTarget, framebuffer: WebGLFramebuffer | null): void;
  properties: { get(object: object): Record<string, unknown> };
}

/** Throws an UnsupportedError naming the release or the missing piece when this three.js lacks what the GPU FFT needs. */
export function checkThreeInternals(renderer: WebGLRenderer): void {
  checkThreeRelease();
  const internals = renderer as unknown as RendererInternals;
  for (const method of ['initRenderTarget', 'setRenderTargetFramebuffer'] as const) {
    if (typeof internals[method] !== 'function') {
      throw new UnsupportedError('three.js', `three-fft-ocean: the GPU FFT needs WebGLRenderer.${method}, which three.js r${REVISION} does not have`);
    }
  }
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
