/**
 * The WebGPU Ocean seen from under the water, in TSL, twins of the WebGL Ocean's GLSL: the surface's
 * underside (shaders/surface/fromBelow.glsl's surfaceFromBelow: Snell's window, total internal
 * reflection outside it, Fresnel from the water side, then the water between the eye and the
 * surface), ocean.frag's choice of that shading by the side the eye is on (its eyeSide and
 * eyeInWater), and the deep water in place of the sky behind everything (shaders/sky/background.frag's
 * backgroundWater). The side is decided in JS before each draw, by the WebGL Ocean's own rule
 * (eyeSide in src/render/seaSurfaceMaterial.ts): UnderWaterEye holds it for the shaders.
 */
import { Vector3, type Camera } from 'three';
import { dot, frontFacing, length, normalize, refract, select, uniform, vec3 } from 'three/tsl';
import { BACKGROUND_WATER, backgroundWaterFor, EYE_SIDE, eyeSide } from '../render/seaSurfaceMaterial';
import { alongWaterPath, fresnelReflectance } from './lightNodes';
import type { FloatNode, Vec3Node } from './nodeTypes';

/** ocean.frag's WATERLINE_REACH: within this many metres of the eye a triangle at the waterline tells the eye's side by the face it shows. */
const WATERLINE_REACH = 5;

/** Where the eye is against the sea, as the surface's and the sky's shaders read it (set before each draw). */
export class UnderWaterEye {
  /** ocean.frag's eyeSide: an EYE_SIDE (above, below, near the surface). */
  readonly side = uniform(0);
  /** ocean.frag's eyeInWater: 1 while the eye is under the water's height over it, else 0. */
  readonly inWater = uniform(0);
  /** background.frag's backgroundWater: where the sky background shows the deep water (BACKGROUND_WATER). */
  readonly backgroundWater = uniform(0);
  private readonly position = new Vector3();

  /**
   * Takes the side of the sea `camera` is on (eyeSide: `surfaceBound` m bounds the crests and
   * troughs, `waterHeightAt` is asked between them) and what the background shows then.
   */
  place(camera: Camera, surfaceBound: number, waterHeightAt: (x: number, z: number) => number): void {
    const { side, inWater } = eyeSide(camera.getWorldPosition(this.position), surfaceBound, waterHeightAt);
    this.side.value = side;
    this.inWater.value = inWater ? 1 : 0;
    this.backgroundWater.value = backgroundWaterFor(side);
  }
}

/**
 * ocean.frag's test for the shading from below: the eye under the water, or at the surface with
 * this fragment within WATERLINE_REACH showing its back (the grid's triangles face up), or farther
 * with the eye under the water's height. `fromEye`: the fragment from the eye, world metres.
 */
export function seenFromBelow(eye: UnderWaterEye, fromEye: Vec3Node): FloatNode {
  const nearEye = dot(fromEye, fromEye).lessThan(WATERLINE_REACH * WATERLINE_REACH);
  const showsBack = select(frontFacing, 0, 1);
  const atWaterline = select(nearEye, showsBack, eye.inWater);
  return select(eye.side.equal(EYE_SIDE.below).or(eye.side.equal(EYE_SIDE.near).and(atWaterline.greaterThan(0.5))), 1, 0) as unknown as FloatNode;
}

/**
 * fromBelow.glsl's surfaceFromBelow: the surface point `fromEye` metres from the eye (`view` its
 * unit direction, `normal` the upward unit normal) seen from under the water. A ray going up meets
 * the surface at cos θi = d·n; light from above comes through only inside Snell's window,
 * θi < asin(n_a/n_w) (48.6° for n_w = 1.333; Snell 1621, Hecht, "Optics", 5th ed., §4.7.1),
 * refracted by n_w·sin θi = n_a·sin θt; outside it the Fresnel reflectance from water to air is 1
 * (total internal reflection, Born & Wolf, "Principles of Optics", §1.5.4) and the surface mirrors
 * the deep water, whose radiance is `deepWater`. Then the water between the eye and the surface
 * absorbs and scatters (alongWaterPath). `lightFromAbove`: the radiance coming down along a unit
 * direction into the air (the sky: scene refractions are not drawn here).
 */
export function surfaceFromBelow(
  view: Vec3Node,
  normal: Vec3Node,
  fromEye: Vec3Node,
  nAir: FloatNode,
  nWater: FloatNode,
  absorption: Vec3Node,
  deepWater: Vec3Node,
  lightFromAbove: (up: Vec3Node) => Vec3Node,
): Vec3Node {
  // A normal that faces away from the eye (a steep wave's far side) is bent back into view.
  const facing = dot(view, normal);
  const facingNormal = select(facing.lessThan(0), normalize(normal.sub(view.mul(facing.mul(1.01)))), normal);
  const reflectance = fresnelReflectance(dot(view, facingNormal), nWater, nAir);
  // Into the air; zero under total reflection, where no light comes through.
  const transmitted = refract(view, facingNormal.negate(), nWater.div(nAir));
  const above = select(reflectance.lessThan(1), lightFromAbove(normalize(transmitted)), vec3(0, 0, 0));
  const surface = deepWater.mul(reflectance).add(above.mul(reflectance.oneMinus()));
  return alongWaterPath(surface, length(fromEye), absorption, deepWater);
}

/**
 * background.frag: the deep water's radiance `deepWater` where the eye's side puts water behind
 * everything (BACKGROUND_WATER: everywhere under the water, below the horizon at the surface), else
 * `sky` in the unit `direction`.
 */
export function backgroundRadiance(eye: UnderWaterEye, direction: Vec3Node, deepWater: Vec3Node, sky: (direction: Vec3Node) => Vec3Node): Vec3Node {
  const water = eye.backgroundWater.equal(BACKGROUND_WATER.everywhere).or(eye.backgroundWater.equal(BACKGROUND_WATER.belowHorizon).and(direction.y.lessThan(0)));
  return select(water, deepWater, sky(direction));
}
