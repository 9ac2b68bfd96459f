/**
 * A slow, non-periodic warp of where the FFT cascades are sampled: the sea at the world point x
 * shows the cascades' fields at x + w(x). Why: every cascade is a periodic patch, and from a few
 * kilometres up the one that holds the visible waves shows its period (the picture's
 * autocorrelation at the patch size reached 0.63 from 4 km, tests/browser/tiling.spec.ts). Real
 * wave fields are not periodic; large-scale currents and gusts bend and shift them over
 * kilometres. w shifts the pattern by a few tens of metres over a patch size, which decorrelates
 * the copies, while it stretches any local wave by at most WARP_MAX_STRAIN (a few per cent), far
 * below what the eye sees or the dispersion relation cares about (the fields keep their own ω(k)).
 *
 *   w(x) = Σ_j a_j · d_j · sin(k_j·x + φ_j)
 *
 * with wavelengths of 1.7–3.1 km in unrelated directions (never a common period) and displacement
 * directions d_j at 60–120° to k_j, so that the warp both stretches and shears. The same formula runs in the
 * vertex shader (shaders/surface/waveLayers.glsl, from SURFACE_WARP_UNIFORMS) and in the queries
 * (surfaceQuery.ts); the geometry test checks that the two agree.
 */

interface WarpComponent {
  /** Wavelength of the warp, m. */
  wavelength: number;
  /** Direction of its wave vector, degrees from +x towards +z. */
  direction: number;
  /** Direction it displaces along, degrees. */
  displacementDirection: number;
  /** Amplitude, m. */
  amplitude: number;
  /** Phase, radians. */
  phase: number;
}

const COMPONENTS: readonly WarpComponent[] = [
  { wavelength: 1733, direction: 17, displacementDirection: 113, amplitude: 14, phase: 0.3 },
  { wavelength: 2389, direction: 131, displacementDirection: 47, amplitude: 17, phase: 2.1 },
  { wavelength: 3109, direction: 253, displacementDirection: 181, amplitude: 19, phase: 4.4 },
];

/** The largest stretch or shear the warp can make, Σ a_j·|k_j| (a bound on |∇w|). */
export const WARP_MAX_STRAIN = COMPONENTS.reduce((sum, c) => sum + (c.amplitude * 2 * Math.PI) / c.wavelength, 0);

const radians = (degrees: number) => (degrees * Math.PI) / 180;

/** Per component: (kx, kz, phase, amplitude) and (dx, dz, 0, 0), for uniform vec4 surfaceWarp[6]. */
export const SURFACE_WARP_UNIFORMS = new Float32Array(
  COMPONENTS.flatMap((c) => {
    const k = (2 * Math.PI) / c.wavelength;
    return [
      k * Math.cos(radians(c.direction)),
      k * Math.sin(radians(c.direction)),
      c.phase,
      c.amplitude,
      Math.cos(radians(c.displacementDirection)),
      Math.sin(radians(c.displacementDirection)),
      0,
      0,
    ];
  }),
);

/** w(x, z) into out, m. */
export function surfaceWarp(x: number, z: number, out: [number, number]): [number, number] {
  out[0] = 0;
  out[1] = 0;
  const u = SURFACE_WARP_UNIFORMS;
  for (let j = 0; j < u.length; j += 8) {
    const s = u[j + 3] * Math.sin(u[j] * x + u[j + 1] * z + u[j + 2]);
    out[0] += s * u[j + 4];
    out[1] += s * u[j + 5];
  }
  return out;
}
