/**
 * The whitecap foam drawn on the WebGPU Ocean's surface, TSL twins of the WebGL Ocean's GLSL, each
 * function naming the file and function it mirrors (which cite their sources):
 *   shaders/surface/foam.glsl         the foam's patches, bubbles and light (its pattern's textures
 *                                     and constants from src/render/foamPattern.ts, shared);
 *   shaders/surface/foamCells.glsl    whole white cells where a pixel spans more than a foam texel;
 *   shaders/surface/foamStreaks.glsl  the foam drawn out downwind from force 7;
 *   shaders/surface/spray.glsl        the spray's haze and the spindrift from force 9;
 *   shaders/surface/waveLayers.glsl   blendedFoam, the largest patch's two copies.
 * The GLSL reads the streaks' and the spray's values as uniforms and skips them below their force
 * by a uniform branch; here they are numbers of the material, which is made again when the wind
 * changes, and what a calm wind does not draw is left out of the material.
 * FoamShading owns the pattern's two textures and the pattern's origin; dispose() frees them.
 */
import { Vector2, type Texture } from 'three';
import type { UniformNode } from 'three/webgpu';
import { abs, clamp, dot, exp, float, floor, int, length, log2, max, mix, select, smoothstep, texture, uint, uniform, uvec2, vec2 } from 'three/tsl';
import { FOAM_PATTERN_CONSTANTS, foamPatternOrigin, foamPatternTextures } from '../render/foamPattern';
import type { BeaufortAppearance } from '../render/beaufortAppearance';
import { crestHeight } from './lightNodes';
import type { FloatNode, IntNode, UintNode, Vec2Node, Vec3Node } from './nodeTypes';

/**
 * The GLSL's constants: foam.glsl's FOAM_VISIBLE (coverage below which nothing shows) and
 * FOAM_MEAN_BUBBLES (the bubbles' mean opacity), foamCells.glsl's FOAM_CELL_FOOTPRINTS,
 * FOAM_CELL_LARGEST (m) and FOAM_CELL_GRAZING, foamStreaks.glsl's STREAK_TAPS.
 */
export const [FOAM_VISIBLE, FOAM_MEAN_BUBBLES] = [0.002, 0.825];
const [FOAM_CELL_FOOTPRINTS, FOAM_CELL_LARGEST, FOAM_CELL_GRAZING, STREAK_TAPS] = [2.5, 16, 0.6, 6];

/** The foam pattern's textures, shared by the Ocean's materials, and its origin under the eye. */
export class FoamShading {
  readonly coarse: Texture;
  readonly fine: Texture;
  /** foamPatternOrigin: the eye's (x, z) in the streaked pattern's coordinates modulo its period (ocean.frag's uniform). */
  readonly origin: UniformNode<'vec2'> = uniform(new Vector2());

  constructor() {
    ({ coarse: this.coarse, fine: this.fine } = foamPatternTextures());
  }

  /** Places the pattern's origin for an eye at (x, z) m and the wind's look (OceanMaterial.setEye). */
  setEye(x: number, z: number, look: BeaufortAppearance): void {
    foamPatternOrigin(x, z, look.windAlong[0], look.windAlong[1], look.streakElongation, this.origin.value as Vector2);
  }

  dispose(): void {
    this.coarse.dispose();
    this.fine.dispose();
  }
}

/** waveLayers.glsl's blendedFoam: the coverage of the largest patch's two copies weighted cos²θ and sin²θ. */
export function blendedFoam(blend: Vec2Node, first: FloatNode, copy: FloatNode): FloatNode {
  return blend.x.mul(blend.x).mul(first).add(blend.y.mul(blend.y).mul(copy));
}

/** foam.glsl's smoothLattice: smooth value noise from a lattice texture of `cells` texels a side, one linear lookup. */
function smoothLattice(lattice: Texture, cells: number, q: Vec2Node): FloatNode {
  const cell = floor(q);
  const f = q.sub(cell);
  return texture(lattice, cell.add(f.mul(f).mul(f.mul(-2).add(3))).add(0.5).div(cells)).level(float(0)).r;
}

/** foam.glsl's foamPattern: (p, bubbles) at a rest point (m, modulo the pattern's period). */
export function foamPattern(shading: FoamShading, restPoint: Vec2Node): Vec2Node {
  const c = FOAM_PATTERN_CONSTANTS;
  const coarse = smoothLattice(shading.coarse, c.FOAM_COARSE_CELLS, restPoint.mul(c.FOAM_COARSE_CELLS_PER_METRE));
  const fine = texture(shading.fine, restPoint.div(c.FOAM_FINE_TILE));
  return vec2(smoothstep(0.2, 0.8, coarse.mul(c.FOAM_COARSE_WEIGHT).add(fine.r.mul(c.FOAM_FINE_WEIGHT))), fine.g);
}

/** foam.glsl's restFootprint: metres of sea a pixel spans, fwidth(restPoint)'s larger component. */
export function restFootprint(restPerPixelX: Vec2Node, restPerPixelY: Vec2Node): FloatNode {
  const footprint = abs(restPerPixelX).add(abs(restPerPixelY));
  return max(footprint.x, footprint.y);
}

/** foam.glsl's foamPatternShown: 1 near, 0 where a pixel spans more than the pattern's finest cells. */
export function foamPatternShown(footprint: FloatNode): FloatNode {
  return float(1).sub(smoothstep(0.15, 0.6, footprint));
}

/** foam.glsl's foamOpacity: the patches' opacity where the pattern shows (`detail`), fading into `far`. */
export function foamOpacity(coverage: FloatNode, pattern: Vec2Node, patternPerPixel: FloatNode, detail: FloatNode, far: FloatNode): FloatNode {
  const softness = clamp(patternPerPixel, 0.04, 0.2);
  const bubbles = mix(float(0.65), float(1), pattern.y);
  const detailed = bubbles.mul(smoothstep(pattern.x.sub(softness), pattern.x.add(softness), coverage));
  return select(detail.lessThanEqual(0), far, mix(far, detailed, detail));
}

/** foam.glsl's foamRadiance: a white Lambertian surface of albedo 0.8 under the sky (seen along the normal) and the sun. */
export function foamRadiance(normal: Vec3Node, sunDirection: Vec3Node, sunRadiance: Vec3Node, skyLight: Vec3Node): Vec3Node {
  return skyLight.add(sunRadiance.mul(max(dot(normal, sunDirection), 0).mul(0.08))).mul(0.8);
}

/** foamCells.glsl's pcg2d (Jarzynski & Olano 2020), in 32-bit unsigned arithmetic that wraps as the GLSL's does. */
function pcg2d(x: UintNode, y: UintNode): ReturnType<typeof uvec2> {
  const a = uint(1664525);
  const vx = x.mul(a).add(uint(1013904223)).toVar();
  const vy = y.mul(a).add(uint(1013904223)).toVar();
  for (let round = 0; round < 2; round++) {
    vx.addAssign(vy.mul(a));
    vy.addAssign(vx.mul(a));
    vx.assign(vx.bitXor(vx.shiftRight(uint(16))));
    vy.assign(vy.bitXor(vy.shiftRight(uint(16))));
  }
  return uvec2(vx, vy);
}

/** foamCells.glsl's foamCellHash: the hash of the cell of 2^−j periods' side that holds `restPoint`. */
function foamCellHash(restPoint: Vec2Node, j: IntNode): ReturnType<typeof uvec2> {
  // WGSL shifts by a u32 only.
  const cells = int(1).shiftLeft(uint(j) as unknown as IntNode);
  const perMetre = float(cells).div(FOAM_PATTERN_CONSTANTS.FOAM_PATTERN_PERIOD);
  const mask = cells.sub(1);
  const x = int(floor(restPoint.x.mul(perMetre))).bitAnd(mask);
  const y = int(floor(restPoint.y.mul(perMetre))).bitAnd(mask);
  return pcg2d(uint(x), uint(y).add(uint(j).shiftLeft(uint(16))));
}

/** foamCells.glsl's foamCellUniform: `bits` bits of a hash from `shift` up as a number uniform in (0, 1). */
function foamCellUniform(hashed: UintNode, shift: number, bits: number): FloatNode {
  const values = 2 ** bits;
  return float(hashed.shiftRight(uint(shift)).bitAnd(uint(values - 1))).add(0.5).div(values);
}

/**
 * foamCells.glsl's foamCellOpacity: white cells of mean opacity `opacity` covering a share W of the
 * sea where a pixel spans more than the foam field's texel (`foamTexel` m), the veil opacity·W
 * where the cells would be too large or seen at a grazing angle; a share of the cells changes
 * between the two, and between two cell sizes.
 */
export function foamCellOpacity(coverage: FloatNode, restPoint: Vec2Node, restPerPixelX: Vec2Node, restPerPixelY: Vec2Node, foamTexel: number, opacity: number): FloatNode {
  const veil = coverage.mul(opacity);
  const footprint = restFootprint(restPerPixelX, restPerPixelY);
  const side = footprint.mul(FOAM_CELL_FOOTPRINTS);
  const longest = max(dot(restPerPixelX, restPerPixelX), dot(restPerPixelY, restPerPixelY));
  const isotropy = abs(restPerPixelX.x.mul(restPerPixelY.y).sub(restPerPixelX.y.mul(restPerPixelY.x))).div(max(longest, 1e-12));
  const cellShare = smoothstep(0.5 * foamTexel, 1.5 * foamTexel, footprint)
    .mul(float(1).sub(smoothstep(FOAM_CELL_LARGEST, 2 * FOAM_CELL_LARGEST, side)))
    .mul(smoothstep(FOAM_CELL_GRAZING, FOAM_CELL_GRAZING + 0.2, isotropy))
    .toVar();
  const level = clamp(log2(float(FOAM_PATTERN_CONSTANTS.FOAM_PATTERN_PERIOD).div(side)), 0, 20).toVar();
  const j = int(floor(level)).toVar();
  const coarser = foamCellHash(restPoint, j).toVar();
  const hashed = select(foamCellUniform(coarser.y, 0, 16).lessThan(level.sub(float(j))), foamCellHash(restPoint, j.add(1)), coarser).toVar();
  const u = foamCellUniform(hashed.x, 8, 24);
  const white = smoothstep(u.mul(0.9), u.mul(1.1), coverage);
  return select(cellShare.lessThanEqual(0).or(foamCellUniform(hashed.y, 16, 16).greaterThanEqual(cellShare)), veil, white.mul(opacity));
}

/** foamStreaks.glsl's streakPatternPoint: a rest point in the streaked pattern's coordinates. */
export function streakPatternPoint(rest: Vec2Node, look: BeaufortAppearance): Vec2Node {
  if (look.streakShare <= 0) return rest;
  const wind = vec2(...look.windAlong);
  return rest.sub(wind.mul(dot(rest, wind).mul(1 - 1 / look.streakElongation)));
}

/**
 * foamStreaks.glsl's streakedFoam: the coverage `foam` at the largest patch's `uv` (and its copy's,
 * + copyOffset, weighted by `blend`) with the foam of the crests up to L upwind drawn over it.
 */
export function streakedFoam(field: Texture, uv: Vec2Node, copyOffset: Vec2Node, blend: Vec2Node, patchSize: number, foam: FloatNode, look: BeaufortAppearance): FloatNode {
  if (look.streakShare <= 0) return foam;
  const scale = -look.streakLength / (STREAK_TAPS * patchSize);
  let drawn: FloatNode = float(0);
  for (let i = 0; i < STREAK_TAPS; i++) {
    const at = uv.add(vec2(look.windAlong[0] * scale * (i + 0.5), look.windAlong[1] * scale * (i + 0.5)));
    drawn = drawn.add(blendedFoam(blend, texture(field, at).r, texture(field, at.add(copyOffset)).r));
  }
  return mix(foam, drawn.mul((1 + look.streakGain) / STREAK_TAPS), look.streakShare);
}

/** foamStreaks.glsl's streakedMeanFoam: the mean of the streaked coverage, (1 + s·G)·F. */
export function streakedMeanFoam(foam: FloatNode, look: BeaufortAppearance): FloatNode {
  return look.streakShare <= 0 ? foam : foam.mul(1 + look.streakShare * look.streakGain);
}

/**
 * spray.glsl's throughSpray: the spindrift's veil over the highest crests, then the haze of
 * extinction β between the eye and the sea (Koschmieder's law), scattering the horizon's sky.
 */
export function throughSpray(colour: Vec3Node, fromEye: Vec3Node, heightAboveMean: FloatNode, heightRms: number, horizonSky: Vec3Node, look: BeaufortAppearance): Vec3Node {
  if (look.sprayExtinction <= 0) return colour;
  const crest = crestHeight(heightAboveMean, heightRms);
  const veiled = mix(colour, horizonSky, crest.mul(crest).mul(look.spindrift));
  return mix(horizonSky, veiled, exp(length(fromEye).mul(-look.sprayExtinction)));
}
