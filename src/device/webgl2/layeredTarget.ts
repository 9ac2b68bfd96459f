/**
 * The FFT's working storage on WebGL 2 (a LayeredTarget of ../gpuDevice.ts): two array textures of
 * four layers and a framebuffer with all eight layers as colour attachments, so one pass writes a
 * butterfly's four outputs to each texture. three.js cannot render to several layers at once, so
 * the layers are attached to a framebuffer of its own, handed to three.js (threeInternals.ts,
 * the one adapter for what three.js does not make public); three.js still allocates, binds and
 * frees the textures.
 */
import { NearestFilter, RGBAFormat, type Texture, type TextureDataType, WebGLArrayRenderTarget, WebGLRenderTarget, type WebGLRenderer } from 'three';
import { glTextureOf, useExternalFramebuffer } from './threeInternals';
import { UnsupportedError } from '../../parameters/options';
import type { LayeredTarget, TexelRows } from '../gpuDevice';

export class WebGL2LayeredTarget implements LayeredTarget {
  readonly textures: [Texture, Texture];
  private readonly arrays: [WebGLArrayRenderTarget, WebGLArrayRenderTarget];
  /** Stands for the framebuffer in three.js's setRenderTarget; three.js allocates nothing for it. */
  private readonly target: WebGLRenderTarget;
  private framebuffer: WebGLFramebuffer | null = null;
  /** The GL textures attached to `framebuffer`. */
  private attached: WebGLTexture[] = [];

  constructor(
    private readonly renderer: WebGLRenderer,
    size: number,
    type: TextureDataType,
  ) {
    const array = () =>
      new WebGLArrayRenderTarget(size, size, 4, {
        type,
        format: RGBAFormat,
        depthBuffer: false,
        minFilter: NearestFilter,
        magFilter: NearestFilter,
        generateMipmaps: false,
      });
    this.arrays = [array(), array()];
    this.textures = [this.arrays[0].texture, this.arrays[1].texture];
    this.target = new WebGLRenderTarget(size, size, { depthBuffer: false, generateMipmaps: false });
  }

  /**
   * Builds the framebuffer of the eight layers (again after a restored context), checking it is
   * complete: throws an UnsupportedError if the device cannot render to it. Done when the target
   * is made (WebGL2Device.createLayeredTarget) and before every use.
   */
  prepare(): void {
    if (!this.framebufferIsCurrent()) this.createFramebuffer();
  }

  /**
   * Makes the eight layers the render target of the next draw, which then covers only `rows` if
   * given (a scissor box). Allocates nothing once set up.
   */
  bind(rows: TexelRows | null): void {
    this.prepare();
    // three.js applies a render target's scissor when it is set.
    this.target.scissorTest = rows !== null;
    if (rows !== null) this.target.scissor.set(0, rows.first, this.target.width, rows.count);
    // Every time: after a restored context three.js has a new property map that no longer knows it.
    useExternalFramebuffer(this.renderer, this.target, this.framebuffer!);
    this.renderer.setRenderTarget(this.target);
  }

  /** Whether `framebuffer` holds the arrays' GL textures, which change when the context is lost and restored. */
  private framebufferIsCurrent(): boolean {
    if (this.framebuffer === null) return false;
    for (let i = 0; i < this.arrays.length; i++) {
      if (glTextureOf(this.renderer, this.arrays[i]) !== this.attached[i]) return false;
    }
    return true;
  }

  private createFramebuffer(): void {
    const renderer = this.renderer;
    const gl = renderer.getContext() as WebGL2RenderingContext;
    const textures = this.arrays.map((array) => glTextureOf(renderer, array));
    this.deleteFramebuffer();
    const framebuffer = gl.createFramebuffer();
    renderer.state.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
    const attachments: GLenum[] = [];
    textures.forEach((texture, a) => {
      for (let layer = 0; layer < 4; layer++) {
        const attachment = gl.COLOR_ATTACHMENT0 + 4 * a + layer;
        gl.framebufferTextureLayer(gl.FRAMEBUFFER, attachment, texture, 0, layer);
        attachments.push(attachment);
      }
    });
    gl.drawBuffers(attachments); // framebuffer state: set once
    // Checked once per context and layout: the check waits for the GPU to finish its queue (a
    // frame's work under SwiftShader), and the answer cannot change for the same formats and size.
    const layout = `${this.arrays[0].texture.type}/${this.arrays[0].width}`;
    const checked = completeLayouts.get(gl) ?? new Set<string>();
    const status = checked.has(layout) ? gl.FRAMEBUFFER_COMPLETE : gl.checkFramebufferStatus(gl.FRAMEBUFFER);
    renderer.state.bindFramebuffer(gl.FRAMEBUFFER, null);
    if (status !== gl.FRAMEBUFFER_COMPLETE) {
      gl.deleteFramebuffer(framebuffer);
      throw new UnsupportedError('GPU FFT framebuffer', `GPU FFT: the layered framebuffer is incomplete (status 0x${status.toString(16)})`);
    }
    completeLayouts.set(gl, checked.add(layout));
    this.framebuffer = framebuffer;
    this.attached = textures;
  }

  private deleteFramebuffer(): void {
    // After a lost and restored context the old framebuffer is already gone: its textures are no
    // longer the arrays' (asked of three.js, not of GL: gl.isFramebuffer would wait for the GPU).
    if (this.framebufferIsCurrent()) this.renderer.getContext().deleteFramebuffer(this.framebuffer);
    this.framebuffer = null;
  }

  dispose(): void {
    this.deleteFramebuffer();
    for (const array of this.arrays) array.dispose();
  }
}

/** The layouts (texel type / size) of the layered framebuffer found complete, per GL context. */
const completeLayouts = new WeakMap<WebGLRenderingContext | WebGL2RenderingContext, Set<string>>();
