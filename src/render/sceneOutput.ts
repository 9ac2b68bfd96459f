/**
 * Draws a scene onto the renderer's canvas with or without multisampling (4× MSAA), switchable
 * from one frame to the next, for the quality levels (runtime/adaptiveQuality.ts).
 *
 * A canvas's own antialiasing is fixed when its WebGL context is made (the `antialias` attribute),
 * so the renderer is made without it, and MSAA, when on, goes through a multisampled render target
 * that three.js draws into exactly as it would into the canvas (tone mapping, sRGB encoding:
 * drawLikeCanvas), resolves into its texture, and that one full-screen triangle copies onto the
 * canvas. The target is 8-bit, like the canvas, so the picture is the one a multisampled canvas
 * shows. With MSAA off the scene is drawn onto the canvas directly and the target is freed.
 *
 * Owns the render target and the copy's geometry and material; dispose() frees them.
 */
import {
  BufferGeometry,
  Float32BufferAttribute,
  Mesh,
  OrthographicCamera,
  ShaderMaterial,
  SRGBColorSpace,
  Vector2,
  WebGLRenderTarget,
  type Camera,
  type Object3D,
  type WebGLRenderer,
} from 'three';
import { drawLikeCanvas } from '../device/webgl2/threeInternals';
import { shaderSource } from '../shaderSource';

/** Samples per pixel with MSAA on: what browsers give a canvas made with antialias: true. */
export const MSAA_SAMPLES = 4;

export class SceneOutput {
  /** Whether the next render() is multisampled. */
  msaa: boolean;
  private target: WebGLRenderTarget | null = null;
  private readonly copy: Mesh<BufferGeometry, ShaderMaterial>;
  /** render() needs a camera; the copy's vertex shader ignores it. */
  private readonly copyCamera = new OrthographicCamera();
  private readonly size = new Vector2();

  constructor(
    private readonly renderer: WebGLRenderer,
    msaa = false,
  ) {
    this.msaa = msaa;
    const geometry = new BufferGeometry();
    // One triangle that covers the canvas (clip space from -1 to 3).
    geometry.setAttribute('position', new Float32BufferAttribute([-1, -1, 0, 3, -1, 0, -1, 3, 0], 3));
    const material = new ShaderMaterial({
      vertexShader: shaderSource('fft/fullscreen.vert'),
      fragmentShader: shaderSource('output/copy.frag'),
      uniforms: { source: { value: null } },
      depthTest: false,
      depthWrite: false,
      toneMapped: false, // done already, in the scene's own shaders
    });
    this.copy = new Mesh(geometry, material);
    this.copy.frustumCulled = false;
  }

  /** The multisampled render target while MSAA is on and something has been drawn (for tests). */
  get multisampleTarget(): WebGLRenderTarget | null {
    return this.target;
  }

  /** Draws `scene` from `camera` onto the canvas, multisampled if `msaa`. */
  render(scene: Object3D, camera: Camera): void {
    const renderer = this.renderer;
    if (!this.msaa) {
      this.freeTarget();
      renderer.render(scene, camera);
      return;
    }
    const target = this.targetOfCanvasSize();
    const previous = renderer.getRenderTarget();
    renderer.setRenderTarget(target);
    renderer.render(scene, camera); // three.js resolves the samples into target.texture at the end
    renderer.setRenderTarget(previous);
    this.copy.material.uniforms.source.value = target.texture;
    // renderer.info then counts the scene's draws and the copy's, as one frame.
    const autoReset = renderer.info.autoReset;
    renderer.info.autoReset = false;
    renderer.render(this.copy, this.copyCamera);
    renderer.info.autoReset = autoReset;
  }

  dispose(): void {
    this.freeTarget();
    this.copy.geometry.dispose();
    this.copy.material.dispose();
  }

  /** The target, made or resized to the drawing buffer's size. */
  private targetOfCanvasSize(): WebGLRenderTarget {
    const { x: width, y: height } = this.renderer.getDrawingBufferSize(this.size);
    if (!this.target) {
      // RGBA8 storage as the canvas has (an sRGB texture would get SRGB8_ALPHA8, which the samples
      // cannot be resolved into from the RGBA8 drawLikeCanvas gives them).
      this.target = new WebGLRenderTarget(width, height, { samples: MSAA_SAMPLES, colorSpace: SRGBColorSpace, internalFormat: 'RGBA8' });
      drawLikeCanvas(this.target);
    } else if (this.target.width !== width || this.target.height !== height) {
      this.target.setSize(width, height);
    }
    return this.target;
  }

  private freeTarget(): void {
    this.target?.dispose();
    this.target = null;
  }
}
