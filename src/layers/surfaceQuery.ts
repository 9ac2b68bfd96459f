/**
 * Questions about the sea surface answered on the CPU from the same layers the surface draws:
 * the sum of every layer's fields (waveLayer.ts), with the horizontal parts scaled by the
 * choppiness λ, sampled bilinearly as the GPU samples them at mip level 0, the largest periodic
 * layer as the blend of its two copies cos θ·P(x) + sin θ·P(x + o) (patchBlend.ts). Newton's
 * Jacobian leaves out the blend weights' own slow gradient: the steps are a little off, the
 * converged point is not.
 */
import { blendAngle, COPY_OFFSET, largestPeriodicLayer, patchBlendUniforms } from './patchBlend';
import type { LayerFieldsOnCpu, WaveLayer } from './waveLayer';

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
}

/**
 * Height of the water surface at the world point (x, z) at time t: the height of the surface
 * point x0 that the choppy displacement moves onto (x, z), x0 + λ·D(x0) = (x, z), found by
 * Newton's method with the Jacobian of that map. Where the surface folds over itself (Jacobian ≤ 0,
 * breaking crests) several points land on (x, z) and the one nearest the start is returned.
 */
export function heightAt(layers: readonly WaveLayer[], choppiness: number, t: number, x: number, z: number): number {
  return surfacePointOver(layers, choppiness, t, x, z).height;
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
): T {
  const s = surfacePointOver(layers, choppiness, t, x, z);
  const [ax, ay, az] = [1 + choppiness * s.dxdx, s.slopeX, choppiness * s.dzdx]; // ∂P/∂x0
  const [bx, by, bz] = [choppiness * s.dxdz, s.slopeZ, 1 + choppiness * s.dzdz]; // ∂P/∂z0
  const [nx, ny, nz] = [by * az - bz * ay, bz * ax - bx * az, bx * ay - by * ax];
  const length = Math.hypot(nx, ny, nz);
  out.x = nx / length;
  out.y = ny / length;
  out.z = nz / length;
  return out;
}

const sample: SurfaceSample = { dx: 0, height: 0, dz: 0, slopeX: 0, slopeZ: 0, dxdx: 0, dzdz: 0, dxdz: 0, dzdx: 0 };

/**
 * The summed fields at the rest point x0 that the choppy displacement moves onto (x, z),
 * x0 + λ·D(x0) = (x, z), found by Newton's method with the Jacobian of that map. Where the surface
 * folds over itself (Jacobian ≤ 0, breaking crests) several points land on (x, z) and the one
 * nearest the start is taken. The result is shared: read it before the next query.
 */
function surfacePointOver(layers: readonly WaveLayer[], choppiness: number, t: number, x: number, z: number): SurfaceSample {
  const blended = prepareBlend(layers);
  let restX = x;
  let restZ = z;
  for (let iteration = 0; iteration < 20; iteration++) {
    sampleLayers(layers, blended, t, restX, restZ, sample);
    const residualX = restX + choppiness * sample.dx - x;
    const residualZ = restZ + choppiness * sample.dz - z;
    if (Math.abs(residualX) + Math.abs(residualZ) < 1e-7) break;
    const jxx = 1 + choppiness * sample.dxdx;
    const jzz = 1 + choppiness * sample.dzdz;
    const jxz = choppiness * sample.dxdz;
    const determinant = jxx * jzz - jxz * jxz;
    if (determinant > 0.05) {
      restX -= (jzz * residualX - jxz * residualZ) / determinant;
      restZ -= (jxx * residualZ - jxz * residualX) / determinant;
    } else {
      // Near a fold Newton steps explode: fall back to a damped fixed-point step.
      restX -= 0.5 * residualX;
      restZ -= 0.5 * residualZ;
    }
  }
  sampleLayers(layers, blended, t, restX, restZ, sample, true);
  return sample;
}

const blendUniforms = new Float32Array(12);

/** Which layer is drawn blended, and its blend's uniforms (patchBlend.ts); set once per query. */
function prepareBlend(layers: readonly WaveLayer[]): number {
  const blended = largestPeriodicLayer(layers);
  if (blended >= 0) patchBlendUniforms(layers[blended].frame.size, blendUniforms);
  return blended;
}

/**
 * Sums every layer's fields at the rest point (x, z) into `out`; `blended` from prepareBlend. With
 * `derivatives`, the slopes and Jacobian terms include the blend's own change too.
 */
function sampleLayers(layers: readonly WaveLayer[], blended: number, t: number, x: number, z: number, out: SurfaceSample, derivatives = false): void {
  out.dx = out.height = out.dz = out.slopeX = out.slopeZ = out.dxdx = out.dzdz = out.dxdz = out.dzdx = 0;
  layers.forEach((layer, i) => {
    const { size, origin, resolution, periodic } = layer.frame;
    const u = ((x - origin[0]) / size) * resolution;
    const v = ((z - origin[1]) / size) * resolution;
    if (!periodic && (u < 0 || v < 0 || u > resolution - 1 || v > resolution - 1)) return;
    const fields = layer.fieldsOnCpu(t);
    if (i !== blended) {
      addSample(fields, resolution, u, v, 1, out);
      return;
    }
    const theta = blendAngle(blendUniforms, x, z);
    const [copyU, copyV] = [u + COPY_OFFSET[0] * resolution, v + COPY_OFFSET[1] * resolution];
    addSample(fields, resolution, u, v, Math.cos(theta), out);
    addSample(fields, resolution, copyU, copyV, Math.sin(theta), out);
    if (!derivatives) return; // Newton's steps do without them (they converge to the same point)
    // Every field cos θ·f1 + sin θ·f2 also changes with θ: its derivative gains (−sin θ·f1 + cos θ·f2)·∇θ
    // (for the height's slope, as in ocean.vert). θ turns over hundreds of metres: a central
    // difference over 1 m is exact enough.
    const change = (c: number) =>
      -Math.sin(theta) * bilinear(fields.displacement, resolution, u, v, c) + Math.cos(theta) * bilinear(fields.displacement, resolution, copyU, copyV, c);
    const thetaX = blendAngle(blendUniforms, x + 0.5, z) - blendAngle(blendUniforms, x - 0.5, z);
    const thetaZ = blendAngle(blendUniforms, x, z + 0.5) - blendAngle(blendUniforms, x, z - 0.5);
    const [dx, height, dz] = [change(0), change(1), change(2)];
    out.slopeX += height * thetaX;
    out.slopeZ += height * thetaZ;
    out.dxdx += dx * thetaX;
    out.dzdz += dz * thetaZ;
    out.dxdz += dx * thetaZ;
    out.dzdx += dz * thetaX;
  });
}

/** Adds `weight` × the fields at texel coordinates (u, v) into `out`. */
function addSample(fields: LayerFieldsOnCpu, n: number, u: number, v: number, weight: number, out: SurfaceSample): void {
  const { displacement, derivatives } = fields;
  out.dx += weight * bilinear(displacement, n, u, v, 0);
  out.height += weight * bilinear(displacement, n, u, v, 1);
  out.dz += weight * bilinear(displacement, n, u, v, 2);
  const crossDerivative = weight * bilinear(displacement, n, u, v, 3);
  out.dxdz += crossDerivative;
  out.dzdx += crossDerivative;
  out.slopeX += weight * bilinear(derivatives, n, u, v, 0);
  out.slopeZ += weight * bilinear(derivatives, n, u, v, 1);
  out.dxdx += weight * bilinear(derivatives, n, u, v, 2);
  out.dzdz += weight * bilinear(derivatives, n, u, v, 3);
}

/**
 * Bilinear sample with wrap-around of channel c of an RGBA N×N field at continuous texel
 * coordinates (u, v), where texel (i, j) holds the field at (u, v) = (i, j) — the same
 * interpolation the GPU does for the surface (see horizonGrid.ts).
 */
function bilinear(data: Float32Array, n: number, u: number, v: number, c: number): number {
  const i0 = Math.floor(u);
  const j0 = Math.floor(v);
  const fu = u - i0;
  const fv = v - j0;
  const at = (i: number, j: number) => data[4 * ((((j % n) + n) % n) * n + (((i % n) + n) % n)) + c];
  return (1 - fv) * ((1 - fu) * at(i0, j0) + fu * at(i0 + 1, j0)) + fv * ((1 - fu) * at(i0, j0 + 1) + fu * at(i0 + 1, j0 + 1));
}
