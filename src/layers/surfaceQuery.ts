/**
 * Questions about the sea surface answered on the CPU from the same layers the surface draws:
 * the sum of every layer's fields (waveLayer.ts), with the horizontal parts scaled by the
 * choppiness λ, sampled bilinearly as the GPU samples them at mip level 0, the largest periodic
 * layer as the blend of its two copies cos θ·P(x) + sin θ·P(x + o) (patchBlend.ts). Newton's
 * Jacobian is the gradient of the bilinear interpolation itself with the blend weights' own slow
 * gradient, so the steps converge quadratically (without it they converge linearly, and the
 * stop after a step under 1 mm left a 20 m/s sea's heights up to 3.1 µm off, now 0.22 µm:
 * tests/unit/surfaceQuery.test.ts).
 *
 * Each layer gives its fields for a time close to the one asked (waveLayer.ts: usually those a
 * worker finished a frame ago, cascadeQueryFields.ts); the displacement is carried to the time asked by its
 * velocity, D(t) ≈ D(t0) + (t − t0)·∂D/∂t (first order; the derivatives and velocities are those at
 * t0, a frame old at most LONGEST_CARRY).
 *
 * Over a seabed (shore.ts) each layer's fields are multiplied by its shoaling factor F_layer(d) at
 * the rest point and the height is then limited by breaking at the depth under the surface point (src/spectrum/shoaling.ts), exactly as
 * shaders/surface/shoaling.glsl does for the drawn surface. The factors' own change over the sea
 * (the bottom's slope) is left out of the derivatives, on the GPU too.
 */
import { breakingHeight, breakingSlope } from '../spectrum/shoaling';
import { blendAngle, COPY_OFFSET, largestPeriodicLayer, patchBlendUniforms } from './patchBlend';
import type { LayerFrame, LayerQueryFields, WaveLayer } from './waveLayer';

/** The depth under a point and each layer's shoaling factor at a depth (shore.ts); null: no seabed. */
export interface SurfaceShore {
  depthAt(x: number, z: number): number;
  /** F of layers[layer] at depth d. */
  layerFactor(layer: number, depth: number): number;
  /** The swash level ζ_t (m) at (x, z) of depth d where the sea's height before shoaling is `deepHeight`. */
  swashLevel(deepHeight: number, x: number, z: number, depth: number): number;
}

/** The summed fields at one rest point: displacement, slopes and the Jacobian terms of the choppy map. */
interface SurfaceSample {
  dx: number;
  height: number;
  dz: number;
  /** ∂h/∂x, ∂h/∂z, with the blend weights' own change (see sampleLayers) */
  slopeX: number;
  slopeZ: number;
  /** ∂Dx/∂x, ∂Dz/∂z, ∂Dx/∂z; ∂Dz/∂x (the fields' ∂Dx/∂z, plus the blend's own change) */
  dxdx: number;
  dzdz: number;
  dxdz: number;
  dzdx: number;
  /** The rest point these are the fields of (set by surfacePointOver). */
  restX: number;
  restZ: number;
  /** dη_limited/dη of the breaking limit there (1 without a seabed; set by surfacePointOver). */
  breaking: number;
  /**
   * Over a seabed (set by surfacePointOver): the water column's depth under the point, the swash
   * level that raised it, the sea's height there before shoaling, and the shoaled height before the
   * breaking limit.
   */
  column: number;
  swash: number;
  deepHeight: number;
  sea: number;
}

/**
 * Height of the water surface at the world point (x, z) at time t: the height of the surface
 * point x0 that the choppy displacement moves onto (x, z), x0 + λ·D(x0) = (x, z), found by
 * Newton's method with the Jacobian of that map. Where the surface folds over itself (Jacobian ≤ 0,
 * breaking crests) several points land on (x, z) and the one nearest the start is returned.
 */
export function heightAt(layers: readonly WaveLayer[], choppiness: number, t: number, x: number, z: number, shore: SurfaceShore | null = null): number {
  return surfacePointOver(layers, choppiness, t, x, z, FIELDS.height, shore).height;
}

/**
 * Upward unit normal of the water surface over the world point (x, z) at time t, written into
 * `out`: at the rest point x0 that heightAt finds, the surface P(x0) = (x0 + λ·Dx, h, z0 + λ·Dz)
 * has the tangents ∂P/∂x0 = (1 + λ·Dx,x, h,x, λ·Dx,z) and ∂P/∂z0 = (λ·Dx,z, h,z, 1 + λ·Dz,z), and
 * the normal ∂P/∂z0 × ∂P/∂x0 (shaders/surface/choppyNormal.glsl draws the same one, without the
 * small part that comes from the blend's turning weights, patchBlend.ts).
 */
export function normalAt<T extends { x: number; y: number; z: number }>(
  layers: readonly WaveLayer[],
  choppiness: number,
  t: number,
  x: number,
  z: number,
  out: T,
  shore: SurfaceShore | null = null,
): T {
  const s = surfacePointOver(layers, choppiness, t, x, z, FIELDS.all, shore);
  // ∂P/∂x0 = (ax, ay, az), ∂P/∂z0 = (bx, by, bz)
  const ax = 1 + choppiness * s.dxdx;
  const ay = s.slopeX;
  const az = choppiness * s.dzdx;
  const bx = choppiness * s.dxdz;
  const by = s.slopeZ;
  const bz = 1 + choppiness * s.dzdz;
  const nx = by * az - bz * ay;
  const ny = bz * ax - bx * az;
  const nz = bx * ay - by * ax;
  const length = Math.sqrt(nx * nx + ny * ny + nz * nz);
  out.x = nx / length;
  out.y = ny / length;
  out.z = nz / length;
  return out;
}

/**
 * Velocity (m/s) of the water surface over the world point (x, z) at time t, written into `out`:
 * the surface particle at the rest point x0 that heightAt finds moves with ∂P/∂t =
 * (λ·∂Dx/∂t, ∂h/∂t, λ·∂Dz/∂t) (each layer's queryFields(t).velocities(), summed and blended as the fields
 * are; the blend's weights do not change with time). For the Airy waves of linear theory this is
 * the orbital velocity of the particles at the surface (Dean & Dalrymple 1991, §4.4; for one deep-
 * water wave of amplitude A at λ = 1, a circle at speed A·ω).
 */
export function velocityAt<T extends { x: number; y: number; z: number }>(
  layers: readonly WaveLayer[],
  choppiness: number,
  t: number,
  x: number,
  z: number,
  out: T,
  shore: SurfaceShore | null = null,
): T {
  // Over a seabed the breaking limit's slope at the height there scales the vertical velocity (chain rule).
  const rest = surfacePointOver(layers, choppiness, t, x, z, shore === null ? FIELDS.newton : FIELDS.height, shore);
  const blended = prepareBlend(layers);
  const depth = shore === null ? 0 : shore.depthAt(rest.restX, rest.restZ);
  velocity.x = velocity.y = velocity.z = velocity.deepY = 0;
  for (let i = 0; i < layers.length; i++) {
    const fields = layers[i].queryFields(t);
    const n = fields.resolution;
    const at = layerTexel(layers[i].frame, n, rest.restX, rest.restZ);
    if (at === null) continue;
    const texels = fields.velocities();
    const factor = shore === null ? 1 : shore.layerFactor(i, depth);
    if (i !== blended) {
      addVelocity(texels, n, at.u, at.v, factor, 1);
      continue;
    }
    const theta = blendAngle(blendUniforms, rest.restX, rest.restZ);
    addVelocity(texels, n, at.u, at.v, factor * Math.cos(theta), Math.cos(theta));
    addVelocity(texels, n, at.u + COPY_OFFSET[0] * n, at.v + COPY_OFFSET[1] * n, factor * Math.sin(theta), Math.sin(theta));
  }
  out.x = choppiness * velocity.x;
  out.y = shore === null ? velocity.y : shoreHeightRate(rest, shore, x, z);
  out.z = choppiness * velocity.z;
  return out;
}

/**
 * ∂h/∂t of the surface over a seabed at (x, z), h = ζ_t + η_limited(η, D), D = d + ζ_t (the column):
 * ∂η_limited/∂η·∂η/∂t + (1 + ∂η_limited/∂D)·∂ζ_t/∂t. ζ_t is linear in the sea's height before
 * shoaling (swash.ts), so its rate is exactly ζ_t(η_deep + ∂η_deep/∂t·1 s) − ζ_t; ∂η_limited/∂D
 * is a central difference over COLUMN_STEP.
 */
function shoreHeightRate(rest: SurfaceSample, shore: SurfaceShore, x: number, z: number): number {
  const swashRate = shore.swashLevel(rest.deepHeight + velocity.deepY, x, z, rest.column - rest.swash) - rest.swash;
  const rate = rest.breaking * velocity.y;
  if (swashRate === 0) return rate;
  const columnSlope = (breakingHeight(rest.sea, rest.column + COLUMN_STEP) - breakingHeight(rest.sea, rest.column - COLUMN_STEP)) / (2 * COLUMN_STEP);
  return rate + (1 + columnSlope) * swashRate;
}

/** m: the limit bends over tenths of the depth; a millimetre resolves it. */
const COLUMN_STEP = 1e-3;

const velocity = { x: 0, y: 0, z: 0, deepY: 0 };

/**
 * Adds `weight` × the velocity texels' (∂Dx/∂t, ∂h/∂t, ∂Dz/∂t) at texel coordinates (u, v), and
 * `deepWeight` × ∂h/∂t to the sea's vertical velocity before shoaling (deepY).
 */
function addVelocity(texels: Float32Array, n: number, u: number, v: number, weight: number, deepWeight: number): void {
  placeTaps(primary, n, u, v);
  velocity.x += weight * tap(texels, primary, 0);
  const rate = tap(texels, primary, 1);
  velocity.y += weight * rate;
  velocity.deepY += deepWeight * rate;
  velocity.z += weight * tap(texels, primary, 2);
}

const texel = { u: 0, v: 0 };

/**
 * Continuous texel coordinates of the world point (x, z) in a layer's query fields of `resolution`
 * texels a side over its frame, or null outside a local layer.
 */
function layerTexel(frame: LayerFrame, resolution: number, x: number, z: number): { u: number; v: number } | null {
  const { size, origin, periodic } = frame;
  texel.u = ((x - origin[0]) / size) * resolution;
  texel.v = ((z - origin[1]) / size) * resolution;
  if (!periodic && (texel.u < 0 || texel.v < 0 || texel.u > resolution - 1 || texel.v > resolution - 1)) return null;
  return texel;
}

const sample: SurfaceSample = { dx: 0, height: 0, dz: 0, slopeX: 0, slopeZ: 0, dxdx: 0, dzdz: 0, dxdz: 0, dzdx: 0, restX: 0, restZ: 0, breaking: 1, column: 0, swash: 0, deepHeight: 0, sea: 0 };
/** The sea's fields before shoaling, for the swash. */
const deepSample: SurfaceSample = { ...sample };

/**
 * The summed fields at the rest point x0 that the choppy displacement moves onto (x, z),
 * x0 + λ·D(x0) = (x, z), found by Newton's method with the Jacobian of that map. Where the surface
 * folds over itself (Jacobian ≤ 0, breaking crests) several points land on (x, z) and the one
 * nearest the start is taken. The result is shared: read it before the next query.
 */
function surfacePointOver(layers: readonly WaveLayer[], choppiness: number, t: number, x: number, z: number, what: number, shore: SurfaceShore | null): SurfaceSample {
  const blended = prepareBlend(layers);
  let restX = x;
  let restZ = z;
  for (let iteration = 0; iteration < 20; iteration++) {
    sampleLayers(layers, blended, t, restX, restZ, sample, FIELDS.newton, shore);
    const residualX = restX + choppiness * sample.dx - x;
    const residualZ = restZ + choppiness * sample.dz - z;
    if (Math.abs(residualX) + Math.abs(residualZ) < 1e-6) break; // a micrometre
    // The Jacobian of x0 ↦ x0 + λ·D(x0), D as sampled (bilinear): not symmetric in general.
    const jxx = 1 + choppiness * sample.dxdx;
    const jxz = choppiness * sample.dxdz;
    const jzx = choppiness * sample.dzdx;
    const jzz = 1 + choppiness * sample.dzdz;
    const determinant = jxx * jzz - jxz * jzx;
    if (determinant > 0.05) {
      const stepX = (jzz * residualX - jxz * residualZ) / determinant;
      const stepZ = (jxx * residualZ - jzx * residualX) / determinant;
      restX -= stepX;
      restZ -= stepZ;
      // Newton converges quadratically (the Jacobian is the interpolation's own): after a step of
      // 1 mm the point is within ~10 µm (measured over a three-cascade sea), where the height
      // differs by that times the slope; sampling again would cost a fifth of the query.
      if (Math.abs(stepX) + Math.abs(stepZ) < 1e-3) break;
    } else {
      // Near a fold Newton steps explode: fall back to a damped fixed-point step.
      restX -= 0.5 * residualX;
      restZ -= 0.5 * residualZ;
    }
  }
  if (what !== FIELDS.newton) sampleLayers(layers, blended, t, restX, restZ, sample, what, shore);
  sample.restX = restX;
  sample.restZ = restZ;
  sample.breaking = 1;
  if (shore !== null && what !== FIELDS.newton) {
    // McCowan's limit (shoaling.ts) for the water column under the surface point (x, z), raised by
    // the swash level (swash.ts) the waves ride on, as ocean.vert draws it; the slopes follow its derivative.
    sampleLayers(layers, blended, t, restX, restZ, deepSample, FIELDS.height, null);
    const depth = shore.depthAt(x, z);
    sample.deepHeight = deepSample.height;
    sample.swash = shore.swashLevel(deepSample.height, x, z, depth);
    sample.column = depth + sample.swash;
    const raw = sample.height;
    sample.sea = raw;
    sample.height = sample.swash + breakingHeight(raw, sample.column);
    sample.breaking = breakingSlope(raw, sample.column);
    sample.slopeX *= sample.breaking;
    sample.slopeZ *= sample.breaking;
  }
  return sample;
}

/**
 * What sampleLayers sums: what Newton's steps need (the horizontal displacement and its Jacobian),
 * the height alone, or all fields; the Jacobian and slopes with the blend weights' own change.
 */
const FIELDS = { newton: 0, height: 1, all: 2 } as const;

// Double precision: θ's phases reach 10⁵ rad 10 000 km away, where float32 wave numbers would put them off by 0.005 rad.
const blendUniforms = new Float64Array(12);

/** Which layer is drawn blended, and its blend's uniforms (patchBlend.ts); set once per query. */
function prepareBlend(layers: readonly WaveLayer[]): number {
  // The same list as the last query (the usual case): the same blend.
  if (layers === blendFor.layers && (blendFor.blended < 0 || layers[blendFor.blended].frame.size === blendFor.size)) return blendFor.blended;
  const blended = largestPeriodicLayer(layers);
  if (blended >= 0) patchBlendUniforms(layers[blended].frame.size, blendUniforms);
  blendFor.layers = layers;
  blendFor.blended = blended;
  blendFor.size = blended >= 0 ? layers[blended].frame.size : 0;
  return blended;
}

/** The layer list prepareBlend last prepared, its blended layer and that layer's size. */
const blendFor: { layers: readonly WaveLayer[] | null; blended: number; size: number } = { layers: null, blended: -1, size: 0 };

/**
 * Sums every layer's fields at the rest point (x, z) into `out`, `what` of them (FIELDS); `blended`
 * from prepareBlend. The slopes and Jacobian terms (FIELDS.newton, FIELDS.all) include the blend's own change.
 */
function sampleLayers(layers: readonly WaveLayer[], blended: number, t: number, x: number, z: number, out: SurfaceSample, what: number, shore: SurfaceShore | null): void {
  const depth = shore === null ? 0 : shore.depthAt(x, z);
  out.dx = out.height = out.dz = out.slopeX = out.slopeZ = out.dxdx = out.dzdz = out.dxdz = out.dzdx = 0;
  for (let i = 0; i < layers.length; i++) {
    if (what === FIELDS.newton && !layers[i].movesSideways) continue; // nothing Newton's steps need
    const query = layers[i].queryFields(t);
    const { resolution } = query;
    const at = layerTexel(layers[i].frame, resolution, x, z);
    if (at === null) continue;
    const { size } = layers[i].frame;
    const fields = carried(query, t);
    // The layer's shoaling factor (1 without a seabed: every product below is then exact).
    const factor = shore === null ? 1 : shore.layerFactor(i, depth);
    placeTaps(primary, resolution, at.u, at.v);
    if (i !== blended) {
      addFields(what, fields, primary, factor, resolution / size, out);
      continue;
    }
    placeTaps(copy, resolution, at.u + COPY_OFFSET[0] * resolution, at.v + COPY_OFFSET[1] * resolution);
    const theta = blendAngle(blendUniforms, x, z);
    const cos = factor * Math.cos(theta);
    const sin = factor * Math.sin(theta);
    addFields(what, fields, primary, cos, resolution / size, out);
    addFields(what, fields, copy, sin, resolution / size, out);
    if (what === FIELDS.height) continue;
    // Every field cos θ·f1 + sin θ·f2 also changes with θ: its derivative gains (−sin θ·f1 + cos θ·f2)·∇θ
    // (for the height's slope, as in ocean.vert). θ turns over hundreds of metres: a central
    // difference over 1 m is exact enough.
    const dx = -sin * displacementTap(fields, primary, 0) + cos * displacementTap(fields, copy, 0);
    const height = -sin * displacementTap(fields, primary, 1) + cos * displacementTap(fields, copy, 1);
    const dz = -sin * displacementTap(fields, primary, 2) + cos * displacementTap(fields, copy, 2);
    const thetaX = blendAngle(blendUniforms, x + 0.5, z) - blendAngle(blendUniforms, x - 0.5, z);
    const thetaZ = blendAngle(blendUniforms, x, z + 0.5) - blendAngle(blendUniforms, x, z - 0.5);
    out.slopeX += height * thetaX;
    out.slopeZ += height * thetaZ;
    out.dxdx += dx * thetaX;
    out.dzdz += dz * thetaZ;
    out.dxdz += dx * thetaZ;
    out.dzdx += dz * thetaX;
  }
}

/** A layer's query fields and how far (s) their displacement is carried to the time asked. */
interface CarriedFields {
  fields: LayerQueryFields;
  /** t − fields.time */
  carry: number;
  /** The fields' velocities, or null when they are for the time asked (nothing to carry). */
  velocities: Float32Array | null;
}

const carriedFields: CarriedFields = { fields: null!, carry: 0, velocities: null };

/** `fields` to be carried to time t (shared: read before the next call). */
function carried(fields: LayerQueryFields, t: number): CarriedFields {
  carriedFields.fields = fields;
  carriedFields.carry = t - fields.time;
  carriedFields.velocities = t === fields.time ? null : fields.velocities();
  return carriedFields;
}

/** Displacement texel channel `index` (into the RGBA array), carried to the time asked. */
function displacementAt(fields: CarriedFields, index: number): number {
  const value = fields.fields.displacement[index];
  return fields.velocities === null ? value : value + fields.carry * fields.velocities[index];
}

/** Channel c of the displacement at the taps, carried to the time asked. */
function displacementTap(fields: CarriedFields, taps: Taps, c: number): number {
  const value = tap(fields.fields.displacement, taps, c);
  return fields.velocities === null ? value : value + fields.carry * tap(fields.velocities, taps, c);
}

/** Adds `weight` × every field at the taps into `out`. */
function addSample(fields: CarriedFields, taps: Taps, weight: number, out: SurfaceSample): void {
  const { derivatives } = fields.fields;
  out.dx += weight * displacementTap(fields, taps, 0);
  out.height += weight * displacementTap(fields, taps, 1);
  out.dz += weight * displacementTap(fields, taps, 2);
  const crossDerivative = weight * displacementTap(fields, taps, 3);
  out.dxdz += crossDerivative;
  out.dzdx += crossDerivative;
  out.slopeX += weight * tap(derivatives, taps, 0);
  out.slopeZ += weight * tap(derivatives, taps, 1);
  out.dxdx += weight * tap(derivatives, taps, 2);
  out.dzdz += weight * tap(derivatives, taps, 3);
}

/**
 * Adds `weight` × what Newton's steps need into `out`: the horizontal displacement at the taps and
 * the exact gradient of its bilinear interpolation (not the derivative fields, which the
 * interpolation does not quite follow between texels: with them Newton converges only linearly).
 * Two of the eight channels, at the same four texels.
 */
function addSideways(fields: CarriedFields, taps: Taps, weight: number, texelsPerMetre: number, out: SurfaceSample): void {
  const { fu, fv } = taps;
  const perMetre = weight * texelsPerMetre;
  for (let c = 0; c <= 2; c += 2) {
    const f00 = displacementAt(fields, taps.at00 + c);
    const f10 = displacementAt(fields, taps.at10 + c);
    const f01 = displacementAt(fields, taps.at01 + c);
    const f11 = displacementAt(fields, taps.at11 + c);
    const value = weight * (taps.w00 * f00 + taps.w10 * f10 + taps.w01 * f01 + taps.w11 * f11);
    const alongX = perMetre * ((1 - fv) * (f10 - f00) + fv * (f11 - f01));
    const alongZ = perMetre * ((1 - fu) * (f01 - f00) + fu * (f11 - f10));
    if (c === 0) {
      out.dx += value;
      out.dxdx += alongX;
      out.dxdz += alongZ;
    } else {
      out.dz += value;
      out.dzdx += alongX;
      out.dzdz += alongZ;
    }
  }
}

/** Adds `weight` × `what` of the fields (FIELDS) at the taps into `out`. */
function addFields(what: number, fields: CarriedFields, taps: Taps, weight: number, texelsPerMetre: number, out: SurfaceSample): void {
  if (what === FIELDS.newton) addSideways(fields, taps, weight, texelsPerMetre, out);
  else if (what === FIELDS.height) out.height += weight * displacementTap(fields, taps, 1);
  else addSample(fields, taps, weight, out);
}

/**
 * The four texels and weights of a bilinear sample with wrap-around of an RGBA N×N field at
 * continuous texel coordinates (u, v), where texel (i, j) holds the field at (u, v) = (i, j): the
 * same interpolation the GPU does for the surface (see horizonGrid.ts). Placed once per point and
 * layer, then read for each channel.
 */
interface Taps {
  /** Indices of channel 0 of texels (i, j), (i + 1, j), (i, j + 1), (i + 1, j + 1). */
  at00: number;
  at10: number;
  at01: number;
  at11: number;
  w00: number;
  w10: number;
  w01: number;
  w11: number;
  /** Where the point lies between the texels, 0 to 1 along u and v. */
  fu: number;
  fv: number;
}

const primary: Taps = { at00: 0, at10: 0, at01: 0, at11: 0, w00: 0, w10: 0, w01: 0, w11: 0, fu: 0, fv: 0 };
const copy: Taps = { ...primary };

function placeTaps(taps: Taps, n: number, u: number, v: number): void {
  const i0 = Math.floor(u);
  const j0 = Math.floor(v);
  const fu = u - i0;
  const fv = v - j0;
  // Columns and rows wrapped into [0, n): n is a power of two, so a mask does it for any 32-bit
  // integer (two's complement wraps negatives too); beyond that, the slower remainder.
  const mask = n - 1;
  const small = Math.abs(i0) < 0x40000000 && Math.abs(j0) < 0x40000000;
  const column0 = small ? i0 & mask : ((i0 % n) + n) % n;
  const row0 = small ? j0 & mask : ((j0 % n) + n) % n;
  const column1 = (column0 + 1) & mask;
  const row1 = (row0 + 1) & mask;
  taps.at00 = 4 * (row0 * n + column0);
  taps.at10 = 4 * (row0 * n + column1);
  taps.at01 = 4 * (row1 * n + column0);
  taps.at11 = 4 * (row1 * n + column1);
  taps.w00 = (1 - fv) * (1 - fu);
  taps.w10 = (1 - fv) * fu;
  taps.w01 = fv * (1 - fu);
  taps.w11 = fv * fu;
  taps.fu = fu;
  taps.fv = fv;
}

/** Channel c of an RGBA field at the taps. */
function tap(data: Float32Array, taps: Taps, c: number): number {
  return taps.w00 * data[taps.at00 + c] + taps.w10 * data[taps.at10 + c] + taps.w01 * data[taps.at01 + c] + taps.w11 * data[taps.at11 + c];
}
