/**
 * What the sea's refraction sees of the scene (the `refractions: 'scene'` shading option): before
 * the sea is drawn, the scene is drawn without it from the same camera into a render target with a
 * depth texture (sceneCapture.ts), and the sea's fragment shader follows each refracted ray into it
 * (shaders/surface/sceneRefraction.glsl). The target has the size of the drawing's viewport times
 * `scale` (the quality level's, runtime/adaptiveQuality.ts; 0 draws nothing and the sea shows the
 * sky through the water alone).
 *
 * Owns its render target (colour and depth texture); dispose() frees them. OceanSurface owns this.
 */
import {
  DepthTexture,
  FloatType,
  HalfFloatType,
  Layers,
  Matrix4,
  NearestFilter,
  Vector2,
  Vector4,
  WebGLRenderTarget,
  type Camera,
  type Scene,
  type Texture,
} from 'three';
import { ParameterError } from '../parameters/options';
import { holdsOnlySeas, isCapturing, renderSceneWithoutSea, type CaptureRenderer } from './sceneCapture';

/** How the depth buffer stores depth (SCENE_DEPTH_* in sceneRefraction.glsl). */
const DEPTH_MODE = { standard: 0, reversed: 1, logarithmic: 2 } as const;

/** The layers of the capture being drawn (one at a time). */
const captureLayers = new Layers();

export class SceneRefraction {
  /** The uniforms of sceneRefraction.glsl, shared with the sea's material (OceanMaterial.shareUniforms). */
  readonly uniforms = {
    sceneColour: { value: null as Texture | null },
    sceneDepth: { value: null as Texture | null },
    sceneCaptured: { value: false },
    sceneProjection: { value: new Matrix4() },
    sceneProjectionInverse: { value: new Matrix4() },
    sceneViewport: { value: new Vector4(0, 0, 1, 1) },
    sceneDepthMode: { value: DEPTH_MODE.standard as number },
    sceneLogDepthRange: { value: 1 },
  };
  /**
   * The layers drawn into the capture (a three.js Layers); null: the camera's own (everything it
   * sees but the sea). @defaultValue null
   */
  layers: { mask: number } | null = null;
  private target: WebGLRenderTarget | null = null;
  private resolutionScale = 1;
  private readonly viewport = new Vector4();

  /**
   * The capture's size as a fraction of the drawing's, (0, 1]; 0 draws no capture. Set by the
   * quality levels (QualityStep.refractionScale).
   * @defaultValue 1
   */
  get scale(): number {
    return this.resolutionScale;
  }

  set scale(scale: number) {
    if (!(typeof scale === 'number' && scale >= 0 && scale <= 1)) throw new ParameterError('refractionScale', scale, 'a number from 0 (no capture) to 1');
    this.resolutionScale = scale;
  }

  /**
   * Draws `scene` without any sea (sceneCapture.ts) from `camera` into the target, sized to the
   * renderer's current viewport, and points the uniforms at it; with scale 0, inside another
   * capture, or where the scene holds nothing but seas (the capture would be transparent, and the
   * shader shows over it exactly what it shows without one), only tells the shader there is none
   * (and frees the target when the scale is 0; otherwise keeps it for the next capture).
   */
  capture(renderer: CaptureRenderer, scene: Scene, camera: Camera): void {
    const u = this.uniforms;
    u.sceneCaptured.value = false;
    if (this.resolutionScale === 0) {
      this.release();
      return;
    }
    if (isCapturing() || holdsOnlySeas(scene)) return;
    currentViewport(renderer, this.viewport);
    const width = Math.max(1, Math.round(this.viewport.z * this.resolutionScale));
    const height = Math.max(1, Math.round(this.viewport.w * this.resolutionScale));
    const target = this.targetOfSize(width, height);
    captureLayers.mask = (this.layers ?? camera.layers).mask;
    renderSceneWithoutSea(renderer, scene, camera, target, captureLayers);
    u.sceneColour.value = target.texture;
    u.sceneDepth.value = target.depthTexture;
    u.sceneCaptured.value = true;
    u.sceneProjection.value.copy(camera.projectionMatrix);
    u.sceneProjectionInverse.value.copy(camera.projectionMatrixInverse);
    u.sceneViewport.value.set(this.viewport.x, this.viewport.y, 1 / this.viewport.z, 1 / this.viewport.w);
    const far = (camera as { far?: number }).far ?? 1;
    if (renderer.capabilities?.logarithmicDepthBuffer ?? renderer.logarithmicDepthBuffer) {
      u.sceneDepthMode.value = DEPTH_MODE.logarithmic;
      u.sceneLogDepthRange.value = Math.log2(far + 1);
    } else {
      u.sceneDepthMode.value = (camera as { reversedDepth?: boolean }).reversedDepth === true ? DEPTH_MODE.reversed : DEPTH_MODE.standard;
    }
  }

  /** The render target of the last capture (null before one, or at scale 0): for tests. */
  get renderTarget(): WebGLRenderTarget | null {
    return this.target;
  }

  dispose(): void {
    this.release();
  }

  private targetOfSize(width: number, height: number): WebGLRenderTarget {
    if (this.target !== null && this.target.width === width && this.target.height === height) return this.target;
    this.release();
    // Half floats: the scene's linear radiance, above 1 where it is bright (tone mapping comes
    // after the sea's shading). A float depth texture keeps a reversed depth buffer's precision.
    const depthTexture = new DepthTexture(width, height, FloatType);
    depthTexture.minFilter = depthTexture.magFilter = NearestFilter;
    this.target = new WebGLRenderTarget(width, height, { type: HalfFloatType, depthTexture, depthBuffer: true });
    this.target.texture.name = 'sceneRefractionColour';
    return this.target;
  }

  /** Frees the target while no capture is wanted (refractions 'sky'); the next capture makes a new one. */
  release(): void {
    this.uniforms.sceneCaptured.value = false;
    if (this.target === null) return;
    this.target.depthTexture?.dispose();
    this.target.dispose();
    this.target = null;
    this.uniforms.sceneColour.value = null;
    this.uniforms.sceneDepth.value = null;
  }
}

/**
 * The viewport the sea is being drawn into, in pixels: WebGLRenderer's current one; for
 * WebGPURenderer (which keeps none while rendering), the whole of its render target or drawing buffer.
 */
function currentViewport(renderer: CaptureRenderer, viewport: Vector4): Vector4 {
  if (renderer.getCurrentViewport) return renderer.getCurrentViewport(viewport);
  const target = renderer.getRenderTarget();
  if (target !== null) return viewport.set(0, 0, target.width, target.height);
  const size = renderer.getDrawingBufferSize(new Vector2());
  return viewport.set(0, 0, size.x, size.y);
}
