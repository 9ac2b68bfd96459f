/**
 * The only place that reaches into three.js beyond its public API: what the WebGL 2 device
 * (webgl2Device.ts) and the scene's output (src/render/sceneOutput.ts) need that three.js keeps to
 * itself. The supported releases are src/threeRelease.ts.
 *
 * The GPU FFT renders into layers of array textures through a framebuffer of its own
 * (layeredTarget.ts), which three.js cannot make. It needs two things three.js keeps to itself:
 *   - the GL texture of a render target (WebGLRenderer.properties → __webglTexture, after
 *     initRenderTarget);
 *   - a way to make its framebuffer the current render target, setRenderTargetFramebuffer (public
 *     in three.js since r139 for WebXR, but not in @types/three).
 * The device asks missingThreeInternals() for its unavailableReason and before it makes a layered
 * target, so a three.js release without them falls back to JS with a message naming what is
 * missing ('auto'), or fails loudly with it, instead of drawing a wrong picture.
 */
import { REVISION, type WebGLRenderer, type WebGLRenderTarget } from 'three';
import { UnsupportedError } from '../../parameters/options';

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
