/**
 * The scene in the WebGPU Ocean's sea: its objects reflected in the waves (reflections 'scene') and
 * what lies under the surface seen through it (refractions 'scene'), as the WebGL Ocean draws them.
 * The captures are the WebGL Ocean's own classes, which draw through either of three's renderers
 * (src/render/sceneReflection.ts: the scene from the eye mirrored in y = 0, its near plane cut
 * obliquely at the sea's troughs; src/render/sceneRefraction.ts: the scene from the eye; both
 * without any sea and without background, src/render/sceneCapture.ts); the nodes here are the TSL
 * twins of the GLSL that reads them (shaders/surface/sceneReflection.glsl and
 * shaders/surface/sceneRefraction.glsl: each function names the one it mirrors, which cites the
 * method's sources).
 *
 * Why not three's `reflector()` (ReflectorNode): it mirrors and clips at one plane, its own (y = 0
 * here), with no clip bias in r187, so rays leaving the troughs find nothing of what lies below
 * y = 0 just behind an object's face, the sky's bright speckles that sceneReflection.ts cuts at the
 * troughs against; it draws the scene's background and every sea but its own material, and the
 * Ocean's sky mesh, opaque, where the coverage blend needs alpha 0 where there is no object; and it
 * has no layer mask. Why not three's viewport textures (viewportSharedTexture,
 * viewportDepthTexture): they hold what was drawn before the sea in the same pass, the Ocean's sky
 * among it and nothing of the opaque objects drawn after it, and their depth has no object's
 * coverage at an outline. A capture without the seas is what the WebGL Ocean's shaders read, so
 * both Oceans show the same picture from the same scene.
 *
 * Both captures run in the surface's onBeforeRender (capture). The refraction renders from a copy
 * of the camera: WebGPURenderer keys its render lists by scene and camera, and a nested render with
 * the main camera would refill the list the main render is drawing from.
 *
 * Positions here are from the eye (world axes, the eye at the origin), as the reflection's matrices
 * are (SceneReflection.render); the refraction's are made so too (capture). Owns both captures, the
 * placeholder target the texture nodes hold until a capture exists, and its camera; dispose() frees them.
 */
import { Camera, DepthTexture, Matrix4, NearestFilter, RenderTarget, type Scene } from 'three';
import type { UniformNode, WebGPURenderer } from 'three/webgpu';
import { clamp, cross, dot, float, If, length, max, min, mix, normalize, screenUV, select, smoothstep, sqrt, texture, uniform, vec2, vec3, vec4 } from 'three/tsl';
import { SceneReflection } from '../render/sceneReflection';
import { SceneRefraction } from '../render/sceneRefraction';
import type { CaptureRenderer } from '../render/sceneCapture';
import { alongWaterPath, SLOPE_TAPS } from './lightNodes';
import type { FloatNode, Vec2Node, Vec3Node, Vec4Node } from './nodeTypes';

/** sceneReflection.glsl's SCENE_REFLECTION_STEPS: fixed-point steps after the first guess. */
const REFLECTION_STEPS = 2;
/** sceneReflection.glsl's SCENE_REFLECTION_EDGE: the uv width over which the reflection fades at the mirror render's edges. */
const REFLECTION_EDGE = 0.04;
/** sceneReflection.glsl's SCENE_REFLECTION_MISS: how far off the ray (a fraction of the distance along it) the found scene point may lie. */
const REFLECTION_MISS = [0.05, 0.2] as const;
/** sceneRefraction.glsl's SCENE_REFRACTION_STEPS. */
const REFRACTION_STEPS = 2;
/** ocean.frag's EDGE_FOAM_WIDTH (m of water in front of an object that foam covers) and EDGE_FOAM_SOLID (its coverage at the object). */
const EDGE_FOAM_WIDTH = 0.3;
const EDGE_FOAM_SOLID = 1.5;

type TextureNode = ReturnType<typeof texture>;

/** A lookup of `map` at uv without mipmaps, allowed in the branches a fragment takes on its own (WGSL's uniformity rule). */
function lookup(map: TextureNode, uv: Vec2Node): Vec4Node {
  return map.sample(uv).level(float(0)) as unknown as Vec4Node;
}

/**
 * Where normalized device coordinates (x, y: −1 to 1, y up) fall in a render target's texture: in
 * three's WebGPURenderer, on both backends, uv runs from the top left (as screenUV), the GLSL's
 * xy·0.5 + 0.5 with v turned over.
 */
function textureUv(ndc: Vec2Node): Vec2Node {
  return vec2(ndc.x.mul(0.5).add(0.5), float(0.5).sub(ndc.y.mul(0.5)));
}

/** A matrix uniform on a Matrix4 the captures change in place. */
function matrixUniform(matrix: Matrix4): Node4x4 {
  return uniform(matrix) as unknown as Node4x4;
}
type Node4x4 = { mul(v: Vec4Node): Vec4Node };

/** What the sea shows of the scene: which of the two it draws. */
export interface SceneLightOptions {
  reflections: boolean;
  refractions: boolean;
}

export class SceneLight {
  /** The mirror render, drawn where reflections is 'scene' (its layers say which objects are reflected). */
  readonly reflection = new SceneReflection();
  /** The capture from the eye, drawn where refractions is 'scene'. */
  readonly refraction = new SceneRefraction();
  /** Which of the two the sea draws. */
  readonly options: Readonly<SceneLightOptions>;
  /** What the texture nodes read until a capture exists: 1×1, a colour and a depth texture of the kinds the captures have. */
  private readonly placeholder: RenderTarget;
  private readonly refractionCamera = new Camera();
  private readonly eyeTranslation = new Matrix4();
  /** From the eye to the refraction capture's clip space, and back (as SceneReflection's matrices). */
  private readonly refractionToClip = new Matrix4();
  private readonly refractionFromClip = new Matrix4();
  private readonly nodes: {
    reflectionColour: TextureNode;
    reflectionDepth: TextureNode;
    reflectionShown: UniformNode<'float'>;
    refractionColour: TextureNode;
    refractionDepth: TextureNode;
    refractionCaptured: UniformNode<'float'>;
  };
  private readonly reflectionToClip: Node4x4;
  private readonly reflectionFromClip: Node4x4;
  private readonly toRefractionClip: Node4x4;
  private readonly fromRefractionClip: Node4x4;
  /** WebGPU's clip space keeps depth 0 to 1 (window depth = z_ndc); WebGL's −1 to 1 (window depth = (z_ndc + 1)/2). */
  private readonly zeroToOneDepth: boolean;

  constructor(renderer: WebGPURenderer, options: SceneLightOptions) {
    this.zeroToOneDepth = (renderer.backend as { isWebGPUBackend?: boolean }).isWebGPUBackend === true;
    this.options = { ...options };
    const depthTexture = new DepthTexture(1, 1);
    depthTexture.minFilter = depthTexture.magFilter = NearestFilter;
    this.placeholder = new RenderTarget(1, 1, { depthTexture });
    this.placeholder.texture.name = 'SceneLightPlaceholder';
    this.refractionCamera.matrixWorldAutoUpdate = false;
    const colour = this.placeholder.texture;
    this.nodes = {
      reflectionColour: texture(colour),
      reflectionDepth: texture(depthTexture),
      reflectionShown: uniform(0),
      refractionColour: texture(colour),
      refractionDepth: texture(depthTexture),
      refractionCaptured: uniform(0),
    };
    // Each its own binding: three merges texture nodes of the same texture (the placeholder) into one.
    for (const map of [this.nodes.reflectionColour, this.nodes.reflectionDepth, this.nodes.refractionColour, this.nodes.refractionDepth]) map.mergeable = false;
    this.reflectionToClip = matrixUniform(this.reflection.uniforms.sceneReflectionToClip.value);
    this.reflectionFromClip = matrixUniform(this.reflection.uniforms.sceneReflectionFromClip.value);
    this.toRefractionClip = matrixUniform(this.refractionToClip);
    this.fromRefractionClip = matrixUniform(this.refractionFromClip);
  }

  /**
   * Draws the captures the sea reads for this render of `scene` from `camera` (the surface's
   * onBeforeRender), and points the texture nodes at them; where a capture draws nothing (nothing
   * but seas in the scene, a depth buffer that is logarithmic or reversed, which these nodes do not
   * read back, a camera that is not a perspective one), the nodes show the sky.
   */
  capture(renderer: WebGPURenderer, scene: Scene, camera: Camera): void {
    const drawing = renderer as unknown as CaptureRenderer;
    const plain = renderer.logarithmicDepthBuffer !== true && renderer.reversedDepthBuffer !== true;
    const { nodes, reflection, refraction } = this;
    if (this.options.reflections) {
      if (plain) reflection.render(drawing, scene, camera);
      const shown = plain && reflection.uniforms.sceneReflectionShown.value;
      nodes.reflectionShown.value = shown ? 1 : 0;
      if (shown) {
        nodes.reflectionColour.value = reflection.uniforms.sceneReflectionColor.value!;
        nodes.reflectionDepth.value = reflection.uniforms.sceneReflectionDepth.value!;
      }
    }
    if (this.options.refractions) {
      const eye = camera.matrixWorld.elements;
      const copy = this.refractionCamera;
      copy.coordinateSystem = camera.coordinateSystem;
      copy.matrixWorld.copy(camera.matrixWorld);
      copy.matrixWorldInverse.copy(camera.matrixWorldInverse);
      copy.projectionMatrix.copy(camera.projectionMatrix);
      copy.projectionMatrixInverse.copy(camera.projectionMatrixInverse);
      copy.layers.mask = camera.layers.mask;
      if (plain && camera.projectionMatrix.elements[11] === -1) refraction.capture(drawing, scene, copy);
      const captured = plain && refraction.uniforms.sceneCaptured.value;
      nodes.refractionCaptured.value = captured ? 1 : 0;
      if (captured) {
        nodes.refractionColour.value = refraction.uniforms.sceneColour.value!;
        nodes.refractionDepth.value = refraction.uniforms.sceneDepth.value!;
        this.refractionToClip.multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse).multiply(this.eyeTranslation.makeTranslation(eye[12], eye[13], eye[14]));
        this.refractionFromClip.copy(this.refractionToClip).invert();
      }
    }
  }

  /** Frees both captures' targets and the placeholder. */
  dispose(): void {
    this.reflection.dispose();
    this.refraction.dispose();
    this.placeholder.depthTexture?.dispose();
    this.placeholder.dispose();
  }

  /** The clip-space z of a depth texel (the window depth) on this backend. */
  private ndcDepth(depth: FloatNode): FloatNode {
    return this.zeroToOneDepth ? depth : depth.mul(2).sub(1);
  }

  /** A capture's point at uv (textureUv) with depth texel `depth`, from the eye, through `fromClip`. */
  private unproject(fromClip: Node4x4, uv: Vec2Node, depth: FloatNode): Vec3Node {
    const point = fromClip.mul(vec4(uv.x.mul(2).sub(1), float(1).sub(uv.y.mul(2)), this.ndcDepth(depth), 1));
    return point.xyz.div(point.w);
  }

  /** sceneReflection.glsl's sceneReflectionUv: where a point (w = 1) or a direction (w = 0) falls in the mirror render, and its clip w. */
  private reflectionUv(fromEye: Vec4Node): Vec3Node {
    const clip = this.reflectionToClip.mul(fromEye);
    return vec3(textureUv(clip.xy.div(clip.w)), clip.w);
  }

  /** sceneReflection.glsl's sceneReflectionRayPoint: the ray's point at the distance of the scene the mirror render shows at uv, or its direction (w = 0). */
  private reflectionRayPoint(fromEye: Vec3Node, ray: Vec3Node, uv: Vec2Node): Vec4Node {
    const depth = lookup(this.nodes.reflectionDepth, uv).x;
    const scene = this.unproject(this.reflectionFromClip, uv, depth);
    const along = max(dot(scene.sub(fromEye), ray), 0);
    return select(depth.greaterThanEqual(1), vec4(ray, 0), vec4(fromEye.add(ray.mul(along)), 1));
  }

  /**
   * sceneReflection.glsl's sceneReflectionSpreadCoverage: the share of the rays the pixel's
   * unresolved slopes (σ²) reflect that meet what the mirror render shows around the converged point.
   */
  private spreadCoverage(fromEye: Vec3Node, ray: Vec3Node, along: FloatNode, variance: FloatNode): FloatNode {
    const facet = normalize(ray.sub(normalize(fromEye)));
    const cosIncident = clamp(dot(ray, facet), 0, 1);
    const crossed = cross(ray, facet);
    const across = select(dot(crossed, crossed).greaterThan(1e-8), normalize(crossed), normalize(cross(ray, vec3(1, 0, 0)))).toVar();
    const inPlane = cross(across, ray);
    const s = sqrt(variance.mul(0.5));
    let coverage: FloatNode = float(0);
    for (const [alongOffset, acrossOffset, weight] of SLOPE_TAPS) {
      const turned = normalize(ray.add(inPlane.mul(alongOffset).add(across.mul(cosIncident.mul(acrossOffset))).mul(s.mul(2))));
      const point = select(along.greaterThan(0), vec4(fromEye.add(turned.mul(along)), 1), vec4(turned, 0));
      coverage = coverage.add(lookup(this.nodes.reflectionColour, clamp(this.reflectionUv(point).xy, 0, 1)).a.mul(weight));
    }
    return coverage;
  }

  /**
   * sceneReflection.glsl's sceneReflection and reflectedRadiance: the light the sea reflects along
   * `ray` (unit, upwards) from the surface point `fromEye`, the scene's where the mirror render has
   * it (premultiplied by its coverage, faded by the pixel's sub-pixel slope variance), in front of
   * `sky`, the sky's light the sea reflects there: rgb + (1 − a)·sky.
   */
  reflectedRadiance(fromEye: Vec3Node, ray: Vec3Node, sky: Vec3Node, variance: FloatNode): Vec3Node {
    if (!this.options.reflections) return sky;
    const result = vec3(sky).toVar();
    If(this.nodes.reflectionShown.greaterThan(0.5), () => {
      const uv = this.reflectionUv(vec4(fromEye, 1)).toVar();
      for (let i = 0; i < REFLECTION_STEPS; i++) uv.assign(this.reflectionUv(this.reflectionRayPoint(fromEye, ray, clamp(uv.xy, 0, 1))));
      const inside = min(uv.xy, float(1).sub(uv.xy)).div(REFLECTION_EDGE);
      const edgeWeight = clamp(min(inside.x, inside.y), 0, 1);
      const depth = lookup(this.nodes.reflectionDepth, uv.xy).x;
      const toScene = this.unproject(this.reflectionFromClip, uv.xy, depth).sub(fromEye);
      const alongScene = dot(toScene, ray);
      const off = length(toScene.sub(ray.mul(alongScene)));
      const met = select(alongScene.greaterThan(0), float(1).sub(smoothstep(REFLECTION_MISS[0], REFLECTION_MISS[1], off.div(max(alongScene, 1e-6)))), float(0));
      // Where the mirror render shows depth: transparent objects that write none count as far away, as the sky does.
      const hasDepth = depth.lessThan(1);
      const weight = select(uv.z.greaterThan(0), edgeWeight.mul(select(hasDepth, met, float(1))), float(0)).toVar();
      const along = select(hasDepth, alongScene, float(0));
      const seen = lookup(this.nodes.reflectionColour, uv.xy).toVar();
      If(weight.greaterThan(0).and(seen.a.greaterThan(0)), () => {
        const scene = seen.mul(weight).mul(min(1, this.spreadCoverage(fromEye, ray, max(along, 0), variance).div(max(seen.a, 1e-4))));
        result.assign(scene.rgb.add(sky.mul(float(1).sub(scene.a))));
      });
    });
    return result;
  }

  /**
   * sceneRefraction.glsl's sceneThroughWater: the light the ray refracted into the water at the
   * surface point `fromEye` (its direction `refracted`) brings back, the scene under the surface
   * through the water (Beer–Lambert over the path, alongWaterPath), or `skyThroughWater` where the
   * capture has nothing (absorption σ and the deep water's `scatter` as throughWater takes them); and the edge foam's coverage where an object meets the water (ocean.frag's
   * edgeFoam, from the distance along the view from the surface to the scene behind it when that is
   * under the water). Where refractions is 'sky', the sky through the water and no edge foam.
   */
  throughWater(
    fromEye: Vec3Node,
    refracted: Vec3Node,
    skyThroughWater: Vec3Node,
    absorption: Vec3Node,
    scatter: Vec3Node,
  ): { radiance: Vec3Node; edgeFoam: FloatNode } {
    if (!this.options.refractions) return { radiance: skyThroughWater, edgeFoam: float(0) };
    const radiance = vec3(skyThroughWater).toVar();
    const edgeDistance = float(1e6).toVar();
    const { refractionColour: colour, refractionDepth: depthMap } = this.nodes;
    If(this.nodes.refractionCaptured.greaterThan(0.5), () => {
      const waterHeight = fromEye.y;
      const project = (point: Vec3Node): Vec2Node => {
        const clip = this.toRefractionClip.mul(vec4(point, 1));
        return textureUv(clip.xy.div(clip.w));
      };
      // The view depth (clip w) grows along the refracted ray at this rate: nothing the ray meets lies on the other side of the surface point's.
      const depthRate = this.toRefractionClip.mul(vec4(refracted, 0)).w;
      const viewDepth = (point: Vec3Node): FloatNode => this.toRefractionClip.mul(vec4(point, 1)).w;
      // The pixel's own place in the capture (textureUv, as screenUV is on both backends).
      const straightUv = vec2(screenUV);
      const straightDepth = lookup(depthMap, straightUv).x.toVar();
      const behind = this.unproject(this.fromRefractionClip, straightUv, straightDepth).toVar();
      If(lookup(colour, straightUv).a.greaterThan(0).and(behind.y.lessThan(waterHeight)), () => {
        edgeDistance.assign(length(behind.sub(fromEye)));
      });
      const uv = vec2(straightUv).toVar();
      const point = vec3(behind).toVar();
      const depth = float(straightDepth).toVar();
      const stopped = float(0).toVar();
      for (let i = 0; i < REFRACTION_STEPS; i++) {
        If(stopped.lessThan(0.5), () => {
          // Off the picture, the nearest point on its edge (sceneRefraction.glsl says why).
          const next = clamp(project(fromEye.add(refracted.mul(length(point.sub(fromEye))))), vec2(0, 0), vec2(1, 1)).toVar();
          const foundDepth = lookup(depthMap, next).x.toVar();
          const found = this.unproject(this.fromRefractionClip, next, foundDepth).toVar();
          // What is drawn there hides what the ray meets (above the water, or on the far side of the
          // surface point's view depth from where the ray goes): the undistorted pixel instead.
          If(found.y.greaterThan(waterHeight).or(viewDepth(found).sub(viewDepth(fromEye)).mul(depthRate).lessThan(0)), () => {
            uv.assign(straightUv);
            point.assign(behind);
            depth.assign(straightDepth);
            stopped.assign(1);
          }).Else(() => {
            uv.assign(next);
            point.assign(found);
            depth.assign(foundDepth);
          });
        });
      }
      const scene = lookup(colour, uv);
      // Above the water behind the surface, or no depth drawn (the colour's alpha is filtered across outlines): not under the water.
      const coverage = select(point.y.lessThan(waterHeight).and(depth.lessThan(1)), scene.a, float(0)).toVar();
      If(coverage.greaterThan(0), () => {
        // The capture's colour is premultiplied by its coverage: the object's own radiance is rgb/a.
        radiance.assign(mix(skyThroughWater, alongWaterPath(scene.rgb.div(coverage), length(point.sub(fromEye)), absorption, scatter), coverage));
      });
    });
    const edgeFoam = float(EDGE_FOAM_SOLID).mul(float(1).sub(smoothstep(0, EDGE_FOAM_WIDTH, edgeDistance)));
    return { radiance, edgeFoam };
  }

}
