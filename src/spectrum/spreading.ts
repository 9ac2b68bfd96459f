/**
 * Directional spreading D(ω, θ): how the variance at frequency ω is shared among directions θ
 * (radians, measured from the mean direction, in (−π, π]), with ∫_{−π}^{π} D dθ = 1 exactly, D
 * symmetric in θ and largest at θ = 0. The sea's variance at (ω, θ) is S(ω)·D(ω, θ).
 *
 * Deterministic arithmetic only (deterministicMath.ts), as for the frequency spectra.
 */
import type { SpreadingModel } from '../parameters/parameters';
import { detExp, detLogGamma, detPow, detSech, detTanh } from './deterministicMath';
import { GRAVITY } from './dispersion';

const SQRT_PI = 1.7724538509055159; // √π, from mpmath

/**
 * The normalisation of cos-2s (Longuet-Higgins, Cartwright & Smith 1963):
 *   ∫_{−π}^{π} cos^{2s}(θ/2) dθ = 2∫_{−π/2}^{π/2} cos^{2s}u du = 2√π·Γ(s + ½)/Γ(s + 1),
 * so D = Γ(s + 1)/(2√π·Γ(s + ½))·cos^{2s}(θ/2) (equal, by Legendre's duplication formula, to the
 * often quoted 2^{2s−1}·Γ²(s + 1)/(π·Γ(2s + 1))). The Γ ratio is taken through ln Γ, so it neither
 * overflows for large s nor needs a numerical integral per call. s = 0 gives 1/(2π), isotropic.
 */
export function cos2sNormalization(s: number): number {
  // The last value is remembered: a fixed 'cos-2s' exponent asks for the same s at every wave vector.
  if (s !== lastExponent) {
    lastExponent = s;
    lastNormalization = detExp(detLogGamma(s + 1) - detLogGamma(s + 0.5)) / (2 * SQRT_PI);
  }
  return lastNormalization;
}
let lastExponent = NaN;
let lastNormalization = NaN;

/**
 * |cos(θ/2)| for θ in (−π, π], deterministic: the Taylor series of cos u, |u| = |θ/2| ≤ π/2, whose
 * 13th term (π/2)^26/26! ≈ 2e-22 is negligible. Absolute error ≲ 2e-16 (tests/unit/spreading.test.ts).
 */
function halfAngleCosine(theta: number): number {
  const u2 = 0.25 * theta * theta;
  let series = 1;
  for (let n = 26; n >= 2; n -= 2) series = 1 - (u2 / (n * (n - 1))) * series;
  return Math.abs(series);
}

/** cos-2s spreading with exponent s ≥ 0: D = N(s)·|cos(θ/2)|^{2s}. */
export function cos2s(theta: number, s: number): number {
  return cos2sNormalization(s) * detPow(halfAngleCosine(theta), 2 * s);
}

/**
 * Mitsuyasu et al. (1975): s = s_p·(ω/ωp)⁵ for ω ≤ ωp and s_p·(ω/ωp)^−2.5 above, with
 * s_p = 11.5·(ωp·U10/g)^−2.5 (their s_max). Needs U10 > 0.
 */
export function mitsuyasuExponent(omega: number, peakFrequency: number, windSpeed: number): number {
  const peakExponent = 11.5 * detPow((peakFrequency * windSpeed) / GRAVITY, -2.5);
  const x = omega / peakFrequency;
  return peakExponent * detPow(x, x <= 1 ? 5 : -2.5);
}

/**
 * Hasselmann, Dunckel & Ewing (1980): s = 6.97·(ω/ωp)^4.06 for ω < 1.05·ωp, and
 * 9.77·(ω/ωp)^μ above, μ = −2.33 − 1.45·(U10/cp − 1.17), cp = g/ωp the deep-water phase speed at
 * the peak. The switch is at 1.05·ωp as in the paper (f < 1.05·f_m), where both laws nearly agree.
 */
export function hasselmannExponent(omega: number, peakFrequency: number, windSpeed: number): number {
  const x = omega / peakFrequency;
  if (x < 1.05) return 6.97 * detPow(x, 4.06);
  const peakPhaseSpeed = GRAVITY / peakFrequency;
  const mu = -2.33 - 1.45 * (windSpeed / peakPhaseSpeed - 1.17);
  return 9.77 * detPow(x, mu);
}

/**
 * β of Donelan, Hamilton & Hui (1985): 2.61·(ω/ωp)^1.3 for ω/ωp < 0.95 (they fitted
 * 0.56 < ω/ωp; it is used below too), 2.28·(ω/ωp)^−1.3 for 0.95 ≤ ω/ωp < 1.6, and beyond 1.6
 * Banner's (1990) extension 10^{−0.4 + 0.8393·exp(−0.567·ln((ω/ωp)²))}.
 */
export function donelanBannerBeta(omegaOverPeak: number): number {
  const x = omegaOverPeak;
  if (x < 0.95) return 2.61 * detPow(x, 1.3);
  if (x < 1.6) return 2.28 * detPow(x, -1.3);
  const exponent = -0.4 + 0.8393 * detPow(x * x, -0.567); // exp(−0.567·ln x²) = (x²)^−0.567
  return detExp(exponent * Math.LN10); // Math.LN10 is a constant fixed by ECMAScript
}

/**
 * Donelan-Banner spreading D = β·sech²(βθ)/(2·tanh(βπ)). On the whole line (β/2)·sech²(βθ) integrates
 * to 1, but over (−π, π] only to tanh(βπ); dividing by it makes ∫_{−π}^{π} D dθ = 1 exactly. As
 * β → 0 (far below the peak) β/tanh(βπ) → 1/π: D becomes isotropic, 1/(2π).
 */
export function donelanBanner(theta: number, omega: number, peakFrequency: number): number {
  const beta = donelanBannerBeta(omega / peakFrequency);
  const sech = detSech(beta * theta);
  const scale = beta * Math.PI > 1e-8 ? beta / (2 * detTanh(beta * Math.PI)) : 1 / (2 * Math.PI);
  return scale * sech * sech;
}

/**
 * Horvath (2015, "Empirical directional wave spectra for computer graphics", DigiPro) elongates
 * a cos-2s spreading for swell: s' = s + 16·tanh(ωp/ω)·ξ², swell amount ξ in [0, 1]. The added
 * exponent is largest below the peak, where swell is longest-crested.
 */
export function horvathElongation(s: number, omega: number, peakFrequency: number, swellAmount: number): number {
  return s + 16 * detTanh(peakFrequency / omega) * swellAmount * swellAmount;
}

export interface SpreadingOptions {
  model: SpreadingModel;
  /** Peak angular frequency ωp of the wind sea, rad/s. */
  peakFrequency: number;
  /** U10, m/s (> 0 for 'mitsuyasu' and 'hasselmann'). */
  windSpeed: number;
  /** s for 'cos-2s'. */
  exponent: number;
}

/** D(ω, θ) of the chosen model; θ in radians from the mean direction. */
export function directionalSpreading(theta: number, omega: number, options: SpreadingOptions): number {
  const { model, peakFrequency, windSpeed } = options;
  switch (model) {
    case 'cos-2s':
      return cos2s(theta, options.exponent);
    case 'mitsuyasu':
      return cos2s(theta, mitsuyasuExponent(omega, peakFrequency, windSpeed));
    case 'hasselmann':
      return cos2s(theta, hasselmannExponent(omega, peakFrequency, windSpeed));
    case 'donelan-banner':
      return donelanBanner(theta, omega, peakFrequency);
  }
}
