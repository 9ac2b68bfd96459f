/**
 * The scene reflected in the sea: a render of the scene (without the sea, sceneCapture.ts) from the
 * camera mirrored in the plane y = 0, with an oblique near plane level with the sea's troughs
 * (y = −troughDepth) so that nothing deeper under the water (no object's underside) is in it, and
 * its depth, which shaders/surface/sceneReflection.glsl reads along each wave's reflected ray. Made
 * again before every render of the sea (the surface's onBeforeRender), at `scale` times the drawing
 * buffer's size. Owns its camera and render target.
 *
 * Why the troughs and not the mean level: the reflected rays leave the displaced surface, down to
 * its troughs, and a ray from a trough meets an object below y = 0 (a cliff's foot). Cut at y = 0,
 * the render holds none of that, and just beyond an object's cut base (inside it) it shows nothing:
 * a lookup landing there, from a trough or a step that ends a little behind the object's face near
 * its waterline, finds no coverage and shows the sky, lone bright pixels amid the object's
 * reflection (the island's cliff on a 12 m/s sea: docs/shores.md).
 *
 * The mirror: a point (x, y, z) is seen in calm water where its image (x, −y, z) would be seen
 * (the law of reflection). The mirror camera is the camera reflected in y = 0, turned into a
 * proper rotation (its x axis negated, so that faces keep their winding) with the projection's x
 * flipped to match: the same picture as the main camera would take of the mirrored scene, mirrored
 * left to right, which the shader's matrices account for.
 */
import {
  Camera,
  DepthTexture,
  HalfFloatType,
  Layers,
  Matrix4,
  Plane,
  UnsignedByteType,
  Vector2,
  Vector3,
  Vector4,
  WebGLRenderTarget,
  WebGPUCoordinateSystem,
  type Scene,
  type Texture,
} from 'three';
import { holdsOnlySeas, isCapturing, renderSceneWithoutSea, type CaptureRenderer } from './sceneCapture';

/** Reflection in y = 0: (x, y, z) → (x, −y, z). */
const MIRROR = new Matrix4().makeScale(1, -1, 1);
/** The camera's own x axis negated, which makes the mirrored frame a rotation again. */
const FLIP_X = new Matrix4().makeScale(-1, 1, 1);
const UP = new Vector3(0, 1, 0);

/**
 * A three.js Layers object as the reflection takes it (OceanSurface.reflectionLayers): which of
 * the 32 layers are reflected. The object is a THREE.Layers; change it in place.
 */
export interface ReflectionLayers {
  /** One bit per layer. */
  mask: number;
  /** Only this layer. */
  set(layer: number): void;
  enable(layer: number): void;
  disable(layer: number): void;
  toggle(layer: number): void;
  enableAll(): void;
  disableAll(): void;
  isEnabled(layer: number): boolean;
}

export interface SceneReflectionUniforms {
  sceneReflectionColor: { value: Texture | null };
  sceneReflectionDepth: { value: Texture | null };
  sceneReflectionToClip: { value: Matrix4 };
  sceneReflectionFromClip: { value: Matrix4 };
  sceneReflectionShown: { value: boolean };
}

export class SceneReflection {
  /** The mirror camera: its matrices are set here, never from a position and rotation. */
  private readonly camera = new Camera();
  private target: WebGLRenderTarget | null = null;
  private readonly size = new Vector2();
  private readonly plane = new Plane();
  private readonly eye = new Vector3();
  private readonly toEye = new Matrix4();
  private readonly clipPlane = new Vector4();
  private readonly corner = new Vector4();
  /** The uniforms the surface's material shares (sceneReflection.glsl). */
  readonly uniforms: SceneReflectionUniforms = {
    sceneReflectionColor: { value: null },
    sceneReflectionDepth: { value: null },
    sceneReflectionToClip: { value: new Matrix4() },
    sceneReflectionFromClip: { value: new Matrix4() },
    sceneReflectionShown: { value: false },
  };
  /** Which objects are reflected: those whose layers meet these (and the camera's). All by default. */
  readonly layers = new Layers();
  /** The reflection's size as a fraction of the drawing buffer's; 0 shows the sky instead (no render target is kept). */
  scale = 0.5;
  /**
   * How far below mean sea level the render keeps the scene, m: where the sea's troughs reach
   * (OceanSurface sets it before each render, Ocean to its RMS height). 0: calm water, y = 0.
   */
  troughDepth = 0;

  constructor() {
    this.layers.enableAll();
    this.camera.matrixWorldAutoUpdate = false;
  }

  /**
   * Renders the reflection of `scene` seen from `camera` (before the sea is drawn with it). Where it
   * cannot (scale 0, inside another reflection, a camera that is not a perspective one, or a depth
   * buffer that is logarithmic or reversed, whose depths the shader does not read back) the sea
   * shows its sky; and where there is nothing but seas to reflect (sceneCapture.ts, holdsOnlySeas),
   * nothing is rendered. Every sea's objects are hidden in it (sceneCapture.ts).
   */
  render(renderer: CaptureRenderer, scene: Scene, camera: Camera): void {
    if (isCapturing()) {
      this.uniforms.sceneReflectionShown.value = false;
      return;
    }
    const shown = this.scale > 0 && isPerspective(camera) && plainDepth(renderer) && !holdsOnlySeas(scene);
    this.uniforms.sceneReflectionShown.value = shown;
    if (!shown) {
      if (this.scale <= 0) this.freeTarget();
      return;
    }
    const target = this.targetFor(renderer);
    camera.getWorldPosition(this.eye);
    // At most half the eye's height down: the oblique near plane must stay in front of the mirror
    // camera, which is as far under y = 0 as the eye is above it (Lengyel's method needs it behind
    // the plane).
    const nearPlaneHeight = -Math.min(this.troughDepth, Math.max(this.eye.y, 0) / 2);
    this.placeCamera(camera, nearPlaneHeight);
    const mirror = this.camera;
    mirror.layers.mask = this.layers.mask & camera.layers.mask;
    renderSceneWithoutSea(renderer, scene, mirror, target, mirror.layers, nearPlaneHeight);
    // The shader works from the eye (vFromEye): the matrices take the eye's position in double
    // precision here, not in float32 there.
    const toClip = this.uniforms.sceneReflectionToClip.value;
    toClip.multiplyMatrices(mirror.projectionMatrix, mirror.matrixWorldInverse).multiply(this.toEye.makeTranslation(this.eye));
    this.uniforms.sceneReflectionFromClip.value.copy(toClip).invert();
    this.uniforms.sceneReflectionColor.value = target.texture;
    this.uniforms.sceneReflectionDepth.value = target.depthTexture;
  }

  /** Frees the render target (until the next render), for a sea that shows its sky. */
  freeTarget(): void {
    if (this.target === null) return;
    this.target.depthTexture?.dispose();
    this.target.dispose();
    this.target = null;
    this.uniforms.sceneReflectionColor.value = null;
    this.uniforms.sceneReflectionDepth.value = null;
  }

  /** Frees the render target. */
  dispose(): void {
    this.freeTarget();
  }

  /**
   * The mirror camera of `camera`: its frame M·C·F (M the mirror, F the x flip), its projection
   * F·P·F, then the near plane made oblique on the plane y = `nearPlaneHeight` (Lengyel 2005,
   * "Oblique view frustum depth projection and clipping", J. Game Dev. 1(2): the third row of P
   * replaced so that the near plane is that one), which clips everything below it. In WebGPU's
   * clip space (depth 0 to 1, not −1 to 1) the near plane is z_clip = 0, not z_clip = −w: the row
   * is C·(M4·Q)/(C·Q), not C·2(M4·Q)/(C·Q) − M4 (the same derivation, M4·Q = 1 here).
   */
  private placeCamera(camera: Camera, nearPlaneHeight: number): void {
    const mirror = this.camera;
    mirror.coordinateSystem = camera.coordinateSystem;
    const zeroToOne = camera.coordinateSystem === WebGPUCoordinateSystem;
    mirror.matrixWorld.multiplyMatrices(MIRROR, camera.matrixWorld).multiply(FLIP_X);
    mirror.matrixWorldInverse.copy(mirror.matrixWorld).invert();
    const p = mirror.projectionMatrix.copy(camera.projectionMatrix).premultiply(FLIP_X).multiply(FLIP_X).elements;
    // The plane n·x + c = 0 with n = +y: y = −c.
    const plane = this.plane.set(UP, -nearPlaneHeight).applyMatrix4(mirror.matrixWorldInverse);
    const c = this.clipPlane.set(plane.normal.x, plane.normal.y, plane.normal.z, plane.constant);
    // The frustum's corner opposite the plane, in view space (Lengyel's Q = P⁻¹·(sgn cx, sgn cy, 1, 1)).
    const q = this.corner.set((Math.sign(c.x) + p[8]) / p[0], (Math.sign(c.y) + p[9]) / p[5], -1, (1 + p[10]) / p[14]);
    c.multiplyScalar((zeroToOne ? 1 : 2) / c.dot(q));
    p[2] = c.x;
    p[6] = c.y;
    p[10] = zeroToOne ? c.z : c.z + 1;
    p[14] = c.w;
    mirror.projectionMatrixInverse.copy(mirror.projectionMatrix).invert();
  }

  /** The render target at `scale` times the drawing buffer, with a depth texture; made or resized as needed. */
  private targetFor(renderer: CaptureRenderer): WebGLRenderTarget {
    renderer.getDrawingBufferSize(this.size);
    const width = Math.max(1, Math.round(this.size.x * this.scale));
    const height = Math.max(1, Math.round(this.size.y * this.scale));
    if (this.target === null) {
      // Half floats keep the scene's HDR radiance (a sunlit white is above 1); 8 bits where the
      // GPU cannot render into them (WebGPU, and WebGL2 under WebGPURenderer, always can).
      const extensions = renderer.extensions;
      const halfFloat = extensions === undefined || extensions.has('EXT_color_buffer_half_float') || extensions.has('EXT_color_buffer_float');
      this.target = new WebGLRenderTarget(width, height, {
        type: halfFloat ? HalfFloatType : UnsignedByteType,
        depthTexture: new DepthTexture(width, height),
      });
      this.target.texture.name = 'SceneReflection';
    } else if (this.target.width !== width || this.target.height !== height) {
      this.target.setSize(width, height);
    }
    return this.target;
  }
}

/** A perspective projection (three's isPerspectiveMatrix: its w is −z). */
function isPerspective(camera: Camera): boolean {
  return camera.projectionMatrix.elements[11] === -1;
}

/** Whether `renderer` writes depths as a plain perspective projection does (not logarithmic, not reversed). */
export function plainDepth(renderer: CaptureRenderer): boolean {
  const logarithmic = renderer.capabilities?.logarithmicDepthBuffer ?? renderer.logarithmicDepthBuffer;
  const reversed = renderer.state?.buffers.depth.getReversed?.() ?? renderer.reversedDepthBuffer;
  return logarithmic !== true && reversed !== true;
}
