/**
 * Two copies of the largest cascade, blended with weights that vary slowly over the sea, each copy
 * taken from its own place in the patch in each stripe of the sea, so that the patch's period
 * does not show from altitude.
 *
 * Why: every cascade is a periodic patch, and from a few kilometres up only the largest one is
 * resolved: its period showed (the rendered picture's autocorrelation at the 457 m patch size was
 * 0.63 from 4 km up, tests/browser/tiling/tiling.spec.ts). Where it is drawn, the largest cascade's
 * field P is replaced by
 *   cos φ(x) · P(x + o_A(x)) + sin φ(x) · P(x + o_B(x)),
 * two copies of P shifted by offsets o_A, o_B that are constant in stripes. Copies taken from
 * places far apart in the random field are uncorrelated and hold the same spectrum, so
 * cos²φ + sin²φ = 1 keeps the variance and the spectrum everywhere (the variance-preserving blend
 * of stochastic texture tiling: Heitz & Neyret 2018, "High-Performance By-Example Noise using a
 * Histogram-Preserving Blending Operator", §3, and Deliot & Heitz 2019, "Procedural Stochastic
 * Textures by Tiling and Blending", with two copies instead of three): every wave keeps its
 * wavenumber and its exact speed (a warp of the coordinates, tried first, stretched the waves by
 * ~5 % locally).
 *
 * The angle ψ(x) = κ·e·x + θ(x) is a ramp across the sea (stripes of width π/κ = L/2) bent by
 *   θ(x) = Σ_j a_j · sin(k_j·x + φ_j),
 * three components with wavelengths of 1.6, 2.23 and 3.02 L in unrelated directions and amplitudes
 * near 1 rad, which spread ψ(x + L) − ψ(x) over several radians. Copy A takes a new offset
 * where its weight is zero (ψ = π/2 + nπ), copy B where its own is (ψ = nπ): the surface stays
 * continuous, and the offsets, indexed by round(ψ/π) and floor(ψ/π), follow the R2 sequence
 * (Roberts 2018, "The Unreasonable Effectiveness of Quasirandom Sequences"), whose neighbours lie
 * far apart in the patch. The weights use φ = ψ − sin(4ψ)/4, whose gradient (1 − cos 4ψ)·∇ψ is zero
 * where an offset changes, so the slope is continuous there too.
 *
 * What the offsets change: with one offset per copy (the blend before), the sea at x and x + L was
 * made of the same two values P(x + o_A), P(x + o_B) mixed at other angles, and what the light makes
 * of the slope evenly (the glint, the sky's reflection) correlated as E[cos² Δφ] ≈ ½ whatever the
 * angles: from 4 km up R = 0.59 at the 457 m period. Where x and x + L fall in other stripes, they
 * are made of other places of the patch and correlate as unrelated seas do.
 *
 * The weights change over hundreds of metres (wave groups of a real sea vary on such scales), far
 * more slowly than the waves themselves. The same formula runs in the shaders
 * (shaders/surface/waveLayers.glsl's patchCopies, from patchBlendUniforms), in the WebGPU Ocean
 * (src/webgpu/seaNodes.ts) and in the queries (surfaceQuery.ts); the geometry test checks they agree.
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

/**
 * The ramp of ψ: its wavenumber κ in patch sizes of the largest cascade (2π: stripes L/2 wide, ψ
 * turning about as fast as θ does) and its direction, degrees from +x towards +z. Chosen so that
 * for every lag m·L of the patch's lattice up to 5 L on each axis, the share of the blend that
 * comes from the same offsets at x and x + m·L, E[1(same A)·|cos φ·cos φ'| + 1(same B)·|sin φ·sin φ'|]
 * over the plane, is at most 0.29 (at m = (−3, 2); every direction at 1° steps computed, 12° and
 * 56° best; 27°, near the lattice vector (2, 1), gave 0.80 at m = (−1, 2), and R = 0.66 there in the
 * picture from 4 km up). Its phase (radians at the world origin) is as arbitrary as θ's; it sets
 * which copies the sea near the origin shows, and the seabed spec's checks of one realisation there
 * (tests/browser/seabed: the foam band's width ratio 2.5 within 10 %, the waterline within a cell
 * of heightAt's) depend on it: phase 0 gave a ratio of 1.96 and 0.25 gave 2.01 (both failing, and
 * the waterline 1.08 and 1.02 cells off), 1.8 gives 2.62 (the fixed-offset blend: 2.36).
 */
const RAMP = { wavenumber: 2 * Math.PI, direction: 56, phase: 1.8 };

/** The R2 sequence's step (1/g, 1/g²), g the plastic number (Roberts 2018): offset n is frac(n·R2_STEP). */
const R2_STEP: readonly [number, number] = [0.7548776662466927, 0.5698402909980532];

/** Length of patchBlendUniforms' array: three θ components, the ramp, the offsets' origin (vec4 each). */
export const PATCH_BLEND_LENGTH = 20;

/**
 * For a largest patch of `size` metres, the uniform vec4 patchBlend[5] of waveLayers.glsl, and what
 * patchCopies reads: per θ component (kx, kz, φ, a); the ramp (κx, κz, ψ0, 0); the offsets' origin
 * (u, v, 0, 0). With an origin (x0, z0) the phases are those at that point, so that
 * ψ(x0 + r) = 2πM + ψ0 + κ·r + Σ a·sin(k·r + φ): for the shader, which works in metres from the eye
 * (every phase is reduced in double precision, exact however far away). The whole turns 2πM go
 * into the offsets' origin, frac(4M·R2_STEP) (copy A's offset index at ψ is 2·round(ψ/π)).
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
  const angle = (RAMP.direction * Math.PI) / 180;
  const [kx, kz] = [(RAMP.wavenumber / size) * Math.cos(angle), (RAMP.wavenumber / size) * Math.sin(angle)];
  const rampPhase = RAMP.phase + kx * originX + kz * originZ;
  const turns = Math.floor(rampPhase / (2 * Math.PI));
  out.set([kx, kz, rampPhase - 2 * Math.PI * turns, 0], 12);
  out.set([fraction(4 * turns * R2_STEP[0]), fraction(4 * turns * R2_STEP[1]), 0, 0], 16);
  return out;
}

const fraction = (v: number) => v - Math.floor(v);

/** The two copies at a rest point: weights (cos φ, sin φ), ∇φ, and offsets (patch sizes). */
export interface PatchCopies {
  cos: number;
  sin: number;
  /** ∇φ, radians per metre. */
  gradientX: number;
  gradientZ: number;
  /** Copy A's offset (u, v) and copy B's, in patch sizes, each in [0, 1). */
  offsets: [number, number, number, number];
}

/** The copies at (x, z) (metres from the uniforms' origin) for the given uniforms (patchBlendUniforms), into `out`. */
export function patchCopies(uniforms: Float32Array | Float64Array, x: number, z: number, out: PatchCopies): PatchCopies {
  let psi = uniforms[12] * x + uniforms[13] * z + uniforms[14];
  let [gradientX, gradientZ] = [uniforms[12], uniforms[13]];
  for (let j = 0; j < 12; j += 4) {
    const phase = uniforms[j] * x + uniforms[j + 1] * z + uniforms[j + 2];
    psi += uniforms[j + 3] * Math.sin(phase);
    gradientX += uniforms[j + 3] * Math.cos(phase) * uniforms[j];
    gradientZ += uniforms[j + 3] * Math.cos(phase) * uniforms[j + 1];
  }
  const phi = psi - Math.sin(4 * psi) / 4;
  const flattening = 1 - Math.cos(4 * psi);
  const indexA = 2 * Math.round(psi / Math.PI);
  const indexB = 2 * Math.floor(psi / Math.PI) + 1;
  out.cos = Math.cos(phi);
  out.sin = Math.sin(phi);
  out.gradientX = flattening * gradientX;
  out.gradientZ = flattening * gradientZ;
  out.offsets[0] = fraction(uniforms[16] + indexA * R2_STEP[0]);
  out.offsets[1] = fraction(uniforms[17] + indexA * R2_STEP[1]);
  out.offsets[2] = fraction(uniforms[16] + indexB * R2_STEP[0]);
  out.offsets[3] = fraction(uniforms[17] + indexB * R2_STEP[1]);
  return out;
}

/** A PatchCopies to fill. */
export function newPatchCopies(): PatchCopies {
  return { cos: 1, sin: 0, gradientX: 0, gradientZ: 0, offsets: [0, 0, 0, 0] };
}

/** Index of the largest periodic layer, the one drawn as a blend of two copies (−1 if none). */
export function largestPeriodicLayer(layers: readonly WaveLayer[]): number {
  let largest = -1;
  layers.forEach((layer, i) => {
    if (layer.frame.periodic && (largest < 0 || layer.frame.size > layers[largest].frame.size)) largest = i;
  });
  return largest;
}
