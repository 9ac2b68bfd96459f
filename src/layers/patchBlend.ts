/**
 * Two copies of the largest cascade, blended with weights that vary slowly over the sea, so that
 * its period does not show from altitude.
 *
 * Why: every cascade is a periodic patch, and from a few kilometres up only the largest one is
 * resolved: its period showed (the rendered picture's autocorrelation at the 457 m patch size was
 * 0.63 from 4 km up, tests/browser/tiling/tiling.spec.ts). Where it is drawn, the largest cascade's field
 * P is replaced by
 *   cos θ(x) · P(x) + sin θ(x) · P(x + o),
 * P seen twice, the second copy shifted by o = (0.382, 0.618)·L (golden fractions of the patch, far
 * from any period of it). Both copies hold the same spectrum and, being far apart in the random
 * field, are uncorrelated, so cos²θ + sin²θ = 1 keeps the variance and the spectrum everywhere:
 * every wave still has its own wavenumber and its exact speed (a warp of the coordinates, tried
 * first, stretched the waves by ~5 % locally). The period goes: P(x + L) = P(x), but
 * θ(x + L) ≠ θ(x), so the sea at x and x + L correlates only as cos(θ(x) − θ(x + L)).
 *   θ(x) = Σ_j a_j · sin(k_j·x + φ_j),
 * three components with wavelengths of 1.6, 2.23 and 3.02 L in unrelated directions and
 * amplitudes near 1 rad: θ(x) − θ(x + L) spreads over several radians, and the weights change over
 * hundreds of metres (wave groups of a real sea vary on such scales), far more slowly than the
 * waves themselves. The same formula runs in the shaders (shaders/surface/waveLayers.glsl, from
 * patchBlendUniforms) and in the queries (surfaceQuery.ts); the geometry test checks they agree.
 */

import type { WaveLayer } from './waveLayer';

interface BlendComponent {
  /** Wavelength of θ's component in patch sizes of the largest cascade. */
  wavelength: number;
  /** Direction of its wave vector, degrees from +x towards +z. */
  direction: number;
  /** Amplitude, radians. */
  amplitude: number;
  /** Phase, radians. */
  phase: number;
}

const COMPONENTS: readonly BlendComponent[] = [
  { wavelength: 1.6, direction: 23, amplitude: 1.4, phase: 0.4 },
  { wavelength: 2.23, direction: 109, amplitude: 1.3, phase: 2.3 },
  { wavelength: 3.02, direction: 211, amplitude: 1.2, phase: 4.1 },
];

/** The second copy's shift, in patch sizes of the largest cascade. */
export const COPY_OFFSET: readonly [number, number] = [0.381966, 0.618034];

/**
 * Per component (kx, kz, φ, a) for a largest patch of `size` metres: the uniform vec4
 * patchBlend[3] of waveLayers.glsl, and what blendAngle reads. With an origin (x0, z0) the phases
 * are those at that point, so that θ(x0 + r) = Σ a·sin(k·r + φ): for the shader, which works in
 * metres from the eye (the phase is reduced in double precision, exact however far away).
 */
export function patchBlendUniforms<T extends Float32Array | Float64Array>(size: number, out: T, originX = 0, originZ = 0): T {
  for (let j = 0; j < COMPONENTS.length; j++) {
    const c = COMPONENTS[j];
    const k = (2 * Math.PI) / (c.wavelength * size);
    const angle = (c.direction * Math.PI) / 180;
    const [kx, kz] = [k * Math.cos(angle), k * Math.sin(angle)];
    out[4 * j] = kx;
    out[4 * j + 1] = kz;
    out[4 * j + 2] = (c.phase + kx * originX + kz * originZ) % (2 * Math.PI);
    out[4 * j + 3] = c.amplitude;
  }
  return out;
}

/** Index of the largest periodic layer, the one drawn as a blend of two copies (−1 if none). */
export function largestPeriodicLayer(layers: readonly WaveLayer[]): number {
  let largest = -1;
  layers.forEach((layer, i) => {
    if (layer.frame.periodic && (largest < 0 || layer.frame.size > layers[largest].frame.size)) largest = i;
  });
  return largest;
}

/** θ(x, z) for the given uniforms (patchBlendUniforms), radians. */
export function blendAngle(uniforms: Float32Array | Float64Array, x: number, z: number): number {
  let theta = 0;
  for (let j = 0; j < uniforms.length; j += 4) theta += uniforms[j + 3] * Math.sin(uniforms[j] * x + uniforms[j + 1] * z + uniforms[j + 2]);
  return theta;
}
