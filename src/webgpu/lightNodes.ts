/**
 * The sea's light in TSL, twins of the WebGL Ocean's GLSL (each function names the file and
 * function it mirrors, which cite their sources): the sun's glint as a Cox–Munk lobe, the sky
 * reflected by the slopes a pixel does not resolve and the sunlight through thin crests
 * (shaders/surface/seaLighting.glsl, whose uniforms src/render/seaLighting.ts computes), the exact
 * Fresnel reflectance (shaders/common/fresnel.glsl), the light
 * from under the surface (shaders/surface/absorption.glsl) and the caustic term
 * (shaders/surface/caustics.glsl).
 */
import { clamp, cross, dot, exp, float, floor, Fn, int, length, log2, max, min, mix, normalize, pow, reflect, refract, select, sqrt, uniformArray, vec3 } from 'three/tsl';
import { SLOPE_FILTER_LEVELS, type SeaLightingValues } from '../render/seaLighting';
import type { FloatNode, Vec2Node, Vec3Node } from './nodeTypes';

/**
 * Exact Fresnel reflectance of unpolarized light, in its amplitude form (shaders/common/fresnel.glsl,
 * course report §2.2, after Tessendorf 2001 §3.3):
 *   r_s = (n1·cos θi − n2·cos θt)/(n1·cos θi + n2·cos θt),  r_p = (n2·cos θi − n1·cos θt)/(n2·cos θi + n1·cos θt),
 *   R = ½·(r_s² + r_p²), n1·sin θi = n2·sin θt; 1 beyond the critical angle.
 */
export const fresnelReflectance = Fn(([cosIncident, n1, n2]: [FloatNode, FloatNode, FloatNode]) => {
  const cosI = clamp(cosIncident, 0, 1);
  const sinT = n1.div(n2).mul(sqrt(max(float(1).sub(cosI.mul(cosI)), 0)));
  const cosT = sqrt(max(float(1).sub(sinT.mul(sinT)), 0));
  const rs = n1.mul(cosI).sub(n2.mul(cosT)).div(n1.mul(cosI).add(n2.mul(cosT)));
  const rp = n2.mul(cosI).sub(n1.mul(cosT)).div(n2.mul(cosI).add(n1.mul(cosT)));
  return select(sinT.greaterThanEqual(1), float(1), rs.mul(rs).add(rp.mul(rp)).mul(0.5));
});

/** seaLighting.glsl's footprintLevel: log2 of the larger of the rest point's steps to the next pixel, metres. */
export function footprintLevel(restPerPixelX: Vec2Node, restPerPixelY: Vec2Node): FloatNode {
  return log2(max(max(length(restPerPixelX), length(restPerPixelY)), 1e-6));
}

/**
 * seaLighting.glsl's subPixelSlopeVariance: the slopes finer than the cascades plus, per layer,
 * what its mip level at this footprint averaged away (between two levels, as trilinear filtering).
 * The table is the sea's (seaLightingValues), fixed for the material's layers and wind.
 */
export function subPixelSlopeVariance(lighting: SeaLightingValues, footprint: FloatNode): FloatNode {
  let variance: FloatNode = float(lighting.unresolvedSlopeVariance);
  lighting.layerTexels.forEach((texel, layer) => {
    const table = uniformArray(lighting.layerFilteredSlopes.slice(layer * SLOPE_FILTER_LEVELS, (layer + 1) * SLOPE_FILTER_LEVELS), 'float');
    const level = clamp(footprint.sub(Math.log2(texel)), 0, SLOPE_FILTER_LEVELS - 1);
    const below = floor(level);
    const above = min(below.add(1), SLOPE_FILTER_LEVELS - 1);
    variance = variance.add(mix(table.element(int(below)) as unknown as FloatNode, table.element(int(above)) as unknown as FloatNode, level.sub(below)));
  });
  return variance;
}

/** seaLighting.glsl's smithLambda: Smith's shadowing of Gaussian slopes (Bruneton et al. 2010, eq. 6). */
function smithLambda(cosTheta: FloatNode, variance: FloatNode): FloatNode {
  const c = clamp(cosTheta, 1e-4, 0.9999);
  const nu = c.div(sqrt(float(1).sub(c.mul(c)).mul(variance)));
  return exp(nu.mul(nu).negate()).div(nu.mul(2 * Math.sqrt(Math.PI)));
}

/**
 * seaLighting.glsl's sunGlint: the sun's light reflected towards the eye per unit of its
 * irradiance, Cox & Munk (1954) and Bruneton et al. (2010), eq. 8,
 *   L / E = F(v·h)·p(ζ_h) / (4·cos θv·cos⁴ θh·(1 + Λ(v) + Λ(l))),  p(ζ) = exp(−|ζ|²/σ²) / (π·σ²).
 */
export function sunGlint(view: Vec3Node, normal: Vec3Node, sun: Vec3Node, slopeVariance: FloatNode, n1: FloatNode, n2: FloatNode): FloatNode {
  // A mirror (no wind) keeps a finite lobe.
  const variance = max(slopeVariance, 1e-6);
  const toEye = view.negate();
  const cosView = dot(toEye, normal);
  const cosSun = dot(sun, normal);
  const halfway = normalize(toEye.add(sun));
  const cosHalf = dot(halfway, normal);
  const cos2 = cosHalf.mul(cosHalf);
  const density = exp(float(1).sub(cos2).div(cos2.mul(variance)).negate()).div(variance.mul(Math.PI));
  const shadowing = smithLambda(cosView, variance.mul(0.5)).add(smithLambda(cosSun, variance.mul(0.5))).add(1);
  const glint = fresnelReflectance(dot(toEye, halfway), n1, n2).mul(density).div(cosView.mul(cos2).mul(cos2).mul(shadowing).mul(4));
  return select(cosView.lessThanEqual(0).or(cosSun.lessThanEqual(0)), float(0), glint);
}

/** seaLighting.glsl's facingEye: a normal facing away from the eye is bent back into view, to grazing. */
export function facingEye(view: Vec3Node, normal: Vec3Node): Vec3Node {
  const facing = dot(view, normal);
  return select(facing.greaterThan(0), normalize(normal.sub(view.mul(facing.mul(1.01)))), normal);
}

/**
 * slopeTaps.glsl's slopeTap(0 … SLOPE_TAPS − 1): each tap's offset in units of s along the plane of
 * incidence and across it, and its weight (the 5-point Gauss–Hermite rule along, Abramowitz &
 * Stegun 25.4.46, its node 0 split across; the GLSL says why).
 */
const SLOPE_TAPS: readonly (readonly [number, number, number])[] = [
  [1.3556262, 0, 0.2220759],
  [-1.3556262, 0, 0.2220759],
  [2.85697, 0, 0.0112574],
  [-2.85697, 0, 0.0112574],
  [0, 1.3693064, 0.2666667],
  [0, -1.3693064, 0.2666667],
];

/**
 * seaLighting.glsl's filteredSkyReflection: the mean of R(n)·L_sky(reflect(v, n)) over the pixel's
 * unresolved Gaussian slopes, over slopeTaps.glsl's taps (SLOPE_TAPS). Returns the mean reflectance
 * and the radiance it weights.
 */
export function filteredSkyReflection(
  view: Vec3Node,
  normal: Vec3Node,
  variance: FloatNode,
  n1: FloatNode,
  n2: FloatNode,
  sky: (direction: Vec3Node) => Vec3Node,
): { reflectance: FloatNode; radiance: Vec3Node } {
  const crossed = cross(view, normal);
  const across = select(dot(crossed, crossed).greaterThan(1e-8), normalize(crossed), normalize(cross(vec3(1, 0, 0), normal))).toVar();
  const along = cross(normal, across);
  const s = sqrt(variance.mul(0.5));
  let reflected: Vec3Node = vec3(0, 0, 0);
  let weighted: FloatNode = float(0);
  for (const [alongOffset, acrossOffset, weight] of SLOPE_TAPS) {
    const tilt = along.mul(alongOffset).add(across.mul(acrossOffset));
    const facet = facingEye(view, normalize(normal.sub(tilt.mul(s))));
    const facetReflectance = fresnelReflectance(dot(view, facet).negate(), n1, n2);
    const direction = reflect(view, facet);
    // A ray reflected downwards would hit the next wave: mirrored up.
    const upwards = vec3(direction.x, direction.y.abs(), direction.z);
    reflected = reflected.add(sky(upwards).mul(facetReflectance.mul(weight)));
    weighted = weighted.add(facetReflectance.mul(weight));
  }
  return { reflectance: weighted, radiance: reflected.div(max(weighted, 1e-6)) };
}

/** seaLighting.glsl's crestHeight: how high a crest stands, 0 at the mean sea, 1 from twice the rms height up. */
export function crestHeight(heightAboveMean: FloatNode, heightRms: number): FloatNode {
  return clamp(heightAboveMean.div(2 * Math.max(heightRms, 1e-3)), 0, 1);
}

/** seaLighting.glsl's SEA_CREST_GLOW (set by eye, not measured). */
const CREST_GLOW = 4;

/**
 * seaLighting.glsl's crestGlow: sunlight through the thin tops of the waves (Mihelich & Tcheblokov,
 * GDC 2019), growing with the crest's height over twice the rms height, with (d·l)⁴ and ((1 − n·l)/2)³.
 */
export function crestGlow(view: Vec3Node, normal: Vec3Node, sun: Vec3Node, heightAboveMean: FloatNode, heightRms: number, reflectance: FloatNode, sunLight: Vec3Node, scatter: Vec3Node): Vec3Node {
  const crest = crestHeight(heightAboveMean, heightRms);
  const forward = pow(max(dot(view, sun), 0), 4);
  const thin = pow(float(0.5).sub(dot(normal, sun).mul(0.5)), 3);
  return sunLight.mul(scatter).mul(crest.mul(forward).mul(thin).mul(float(1).sub(reflectance)).mul(CREST_GLOW));
}

/**
 * absorption.glsl's alongWaterPath: light over a path of `pathLength` metres of water (Beer–Lambert,
 * per channel), c = c_light·e^{−σL} + c_scatter·(1 − e^{−σL}).
 */
export function alongWaterPath(light: Vec3Node, pathLength: FloatNode, absorption: Vec3Node, scatter: Vec3Node): Vec3Node {
  const transmittance = exp(absorption.mul(pathLength).negate());
  return light.mul(transmittance).add(scatter.mul(float(1).sub(transmittance)));
}

/**
 * absorption.glsl's throughWater: what the refracted ray sees, the environment along it through
 * viewDepth metres of water (alongWaterPath).
 */
export function throughWater(environment: Vec3Node, refracted: Vec3Node, absorption: Vec3Node, scatter: Vec3Node, viewDepth: number): Vec3Node {
  return alongWaterPath(environment, float(viewDepth).div(max(refracted.y.negate(), 0.05)), absorption, scatter);
}

/** caustics.glsl's causticBrightness (Guardado & Sánchez-Crespo, GPU Gems ch. 2): K = (t·l)^p; `eta` is n_w/n_a. */
export function causticBrightness(normal: Vec3Node, toLight: Vec3Node, eta: FloatNode, power: FloatNode): FloatNode {
  const leaving = refract(vec3(0, 1, 0), normal.negate(), eta);
  return pow(max(dot(leaving, toLight), 0), power);
}
