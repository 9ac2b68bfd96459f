/**
 * Complex numbers as vec2(real, imaginary) in TSL: the twin of shaders/common/complex.glsl, for the
 * compute shaders of the WebGPU backend (computeFft.ts, computeSpectrum.ts).
 */
import { vec2 } from 'three/tsl';
import type { Vec2Node } from '../webgpu/nodeTypes';

/** a·b */
export function complexMultiply(a: Vec2Node, b: Vec2Node): Vec2Node {
  return vec2(a.x.mul(b.x).sub(a.y.mul(b.y)), a.x.mul(b.y).add(a.y.mul(b.x)));
}

/** conj(a) */
export function complexConjugate(a: Vec2Node): Vec2Node {
  return vec2(a.x, a.y.negate());
}

/** i·a */
export function timesI(a: Vec2Node): Vec2Node {
  return vec2(a.y.negate(), a.x);
}
