/**
 * The only place that reaches into three.js beyond its public API: the GPU FFT renders into layers
 * of array textures through a framebuffer of its own (gpuWaveFields.ts, LayeredSpectra), which
 * three.js cannot make. It needs two things three.js keeps to itself:
 *   - the GL texture of a render target (WebGLRenderer.properties → __webglTexture, after
 *     initRenderTarget);
 *   - a way to make its framebuffer the current render target, setRenderTargetFramebuffer (public
 *     in three.js since r139 for WebXR, but not in @types/three).
 * checkThreeInternals() is called before the GPU path is built, so a three.js release without them
 * fails loudly, with a message naming what is missing, instead of drawing a wrong picture.
 */
import { REVISION, type WebGLRenderer, type WebGLRenderTarget } from 'three';
import { UnsupportedError } from '../parameters/options';

interface RendererInternals {
  initRenderTarget?(target: WebGLRenderTarget): void;
  setRenderTargetFramebuffer?(target: WebGLRenderTarget, framebuffer: WebGLFramebuffer | null): void;
  properties: { get(object: object): Record<string, unknown> };
}

/** Throws an Error naming the missing piece when this three.js lacks what the GPU FFT needs. */
export function checkThreeInternals(renderer: WebGLRenderer): void {
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
