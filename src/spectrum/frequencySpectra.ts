/**
 * One-sided frequency spectra of the sea surface height, S(ω) in m²·s/rad, with ∫₀^∞ S dω = m0,
 * the variance of the height (so the significant wave height is Hs = 4·√m0).
 *
 * Units: ω in rad/s, wind speed U10 in m/s at 10 m height, fetch in km, depth in m, g = 9.81 m/s².
 * Only +, −, ×, ÷, Math.sqrt and deterministicMath.ts are used, so that the initial spectrum built
 * from these is bit-identical in every JS engine (see deterministicMath.ts).
 *
 * Every spectrum here is αg²ω⁻⁵·exp(−(5/4)(ωp/ω)⁴)·(peak enhancement), evaluated as a function of
 * x = ω/ωp; `rearFace` returns 0 where the exponential underflows, so that ω⁻⁵ → ∞ never meets
 * exp(…) = 0 (which would give NaN) for tiny ω.
 */
import { detExp, detPow } from './deterministicMath';
import { GRAVITY } from './dispersion';

/** Pierson & Moskowitz (1964): Phillips' constant α and the shape constant β. */
export const PM_ALPHA = 8.1e-3;
export const PM_BETA = 0.74;

/**
 * U19.5 ≈ 1.026·U10: the logarithmic wind profile at neutral stability with a drag coefficient of
 * 1.3e-3 (Stewart, "Introduction to Physical Oceanography", 2008, eq. 16.29).
 */
export const U19_5_PER_U10 = 1.026;

/** JONSWAP mean peak enhancement and peak widths (Hasselmann et al. 1973). */
export const JONSWAP_GAMMA = 3.3;
export const JONSWAP_SIGMA_BELOW_PEAK = 0.07;
export const JONSWAP_SIGMA_ABOVE_PEAK = 0.09;

/** exp(−(5/4)·x⁻⁴)·x⁻⁵ at x = ω/ωp, the Pierson-Moskowitz shape that every spectrum here shares. */
function rearFace(x: number): number {
  if (!(x > 0)) return 0;
  const x2 = x * x;
  const exponent = 1.25 / (x2 * x2);
  if (exponent > 745) return 0; // e^−745 underflows to 0 anyway; x⁻⁵ may be Infinity here
  return detExp(-exponent) / (x2 * x2 * x);
}

/**
 * Peak of the Pierson-Moskowitz spectrum: dS/dω = 0 gives ωp = (4β/5)^{1/4}·g/U19.5 = 0.877·g/U19.5
 * (Stewart 2008, eq. 16.30). The exact constant is used, so that ωp is the argmax of piersonMoskowitz.
 */
export function piersonMoskowitzPeakFrequency(windSpeed: number): number {
  return (detPow((4 * PM_BETA) / 5, 0.25) * GRAVITY) / (U19_5_PER_U10 * windSpeed);
}

/**
 * Pierson & Moskowitz (1964), a fully developed sea (Stewart 2008, §16.3):
 *   S(ω) = α·g²/ω⁵·exp(−β·(ω0/ω)⁴),  ω0 = g/U19.5,  α = 8.1e-3,  β = 0.74.
 * It has m0 = α·U19.5⁴/(4β·g²) = 2.74e-3·U19.5⁴/g² and Hs = 0.21·U19.5²/g (eqs. 16.32–16.33).
 * Written with x = ω/ωp: β(ω0/ω)⁴ = (5/4)·x⁻⁴ because ωp⁴ = (4β/5)·ω0⁴.
 */
export function piersonMoskowitz(omega: number, windSpeed: number): number {
  if (!(windSpeed > 0)) return 0; // no wind, no waves
  const peak = piersonMoskowitzPeakFrequency(windSpeed);
  return ((PM_ALPHA * GRAVITY * GRAVITY) / peakPower5(peak)) * rearFace(omega / peak);
}

function peakPower5(peak: number): number {
  const p2 = peak * peak;
  return p2 * p2 * peak;
}

/**
 * The JONSWAP peak enhancement γ^r, r = exp(−(ω − ωp)²/(2σ²ωp²)) with σ = 0.07 for ω ≤ ωp and 0.09
 * above (Hasselmann et al. 1973, as quoted by Stewart 2008 §16.3).
 */
export function peakEnhancement(x: number, gamma: number): number {
  if (gamma === 1) return 1;
  const sigma = x <= 1 ? JONSWAP_SIGMA_BELOW_PEAK : JONSWAP_SIGMA_ABOVE_PEAK;
  const d = (x - 1) / sigma;
  // Far from the peak r < e^−45, r·ln γ < 2e-17 even for γ = MAX_VALUE, and γ^r rounds to exactly 1:
  // returning 1 there gives the same bits and skips two exponentials for most wave vectors.
  if (0.5 * d * d > 45) return 1;
  return detPow(gamma, detExp(-0.5 * d * d));
}

/** JONSWAP with given α and ωp: α·g²/ω⁵·exp(−(5/4)(ωp/ω)⁴)·γ^r (Hasselmann et al. 1973). */
export function jonswapShape(omega: number, alpha: number, peakFrequency: number, gamma: number): number {
  if (!(alpha > 0 && peakFrequency > 0)) return 0;
  const x = omega / peakFrequency;
  const face = rearFace(x);
  if (face === 0) return 0;
  return ((alpha * GRAVITY * GRAVITY) / peakPower5(peakFrequency)) * face * peakEnhancement(x, gamma);
}

/**
 * Dimensionless fetch gF/U10² at which the JONSWAP fetch law's ωp falls to Pierson-Moskowitz's:
 * 22·(g/U10)·χ^{−1/3} = 0.877·g/(1.026·U10) gives χ = (22·1.026/0.877)³ ≈ 1.70e4.
 */
export const FULLY_DEVELOPED_FETCH = (() => {
  const root = (22 * U19_5_PER_U10) / detPow((4 * PM_BETA) / 5, 0.25);
  return root * root * root;
})();

export interface JonswapParameters {
  /** Phillips' constant α of the fetch law. */
  alpha: number;
  /** Peak angular frequency ωp, rad/s. */
  peakFrequency: number;
}

/**
 * The JONSWAP fetch laws (Hasselmann et al. 1973, as given by Stewart 2008 §16.3), F in metres:
 *   α = 0.076·(U10²/(F·g))^0.22,   ωp = 22·(g²/(U10·F))^{1/3}.
 * Beyond full development the fetch laws would keep lowering ωp and α, although a sea cannot grow
 * past Pierson-Moskowitz's: the dimensionless fetch χ = gF/U10² is capped at FULLY_DEVELOPED_FETCH,
 * where ωp equals the PM peak (and α = 0.0089, close to PM's 0.0081). So fetch beyond full
 * development gives exactly PM's peak frequency (the max below makes it exact, not just to rounding).
 */
export function jonswapParameters(windSpeed: number, fetchKm: number): JonswapParameters {
  if (!(windSpeed > 0)) return { alpha: 0, peakFrequency: Infinity };
  const fetch = 1000 * fetchKm;
  const chi = Math.min((GRAVITY * fetch) / (windSpeed * windSpeed), FULLY_DEVELOPED_FETCH);
  const alpha = 0.076 * detPow(chi, -0.22);
  const fetchPeak = 22 * (GRAVITY / windSpeed) * detPow(chi, -1 / 3); // (g²/(U·F))^{1/3} = (g/U)·χ^{−1/3}
  return { alpha, peakFrequency: Math.max(fetchPeak, piersonMoskowitzPeakFrequency(windSpeed)) };
}

/** JONSWAP for wind speed U10 (m/s) and fetch (km), see jonswapParameters. */
export function jonswap(omega: number, windSpeed: number, fetchKm: number, gamma = JONSWAP_GAMMA): number {
  const { alpha, peakFrequency } = jonswapParameters(windSpeed, fetchKm);
  return jonswapShape(omega, alpha, peakFrequency, gamma);
}

/**
 * Kitaigorodskii's depth factor Φ(ω_h), ω_h = ω·√(d/g), in the piecewise form used by the TMA
 * spectrum (Bouws, Günther, Rosenthal & Vincent 1985, after Thompson & Vincent 1983):
 *   Φ = ½·ω_h² for ω_h ≤ 1,   1 − ½·(2 − ω_h)² for 1 < ω_h < 2,   1 for ω_h ≥ 2.
 * TMA = JONSWAP × Φ. Deep water (d = Infinity) gives 1.
 */
export function tmaFactor(omega: number, depth: number): number {
  if (depth === Infinity) return 1;
  const omegaH = omega * Math.sqrt(depth / GRAVITY);
  if (omegaH <= 1) return 0.5 * omegaH * omegaH;
  if (omegaH < 2) return 1 - 0.5 * (2 - omegaH) * (2 - omegaH);
  return 1;
}

/**
 * ∫₀^∞ x⁻⁵·exp(−(5/4)x⁻⁴)·γ^{r(x)} dx, so that a JONSWAP spectrum has m0 = α·g²/ωp⁴·I(γ); I(1) = 1/5.
 * With u = x⁻⁴ (x⁻⁵dx = −du/4) it is ¼∫₀^∞ e^{−5u/4}·γ^{r(u^{−1/4})} du, a smooth integrand: composite
 * Simpson on [0, 40] (e^{−50} is negligible) with step 0.01, a node at the kink u = 1 where σ changes.
 * Fixed nodes and deterministic functions, so the result is the same in every engine.
 */
export function jonswapShapeIntegral(gamma: number): number {
  const end = 40;
  const intervals = 4000;
  const h = end / intervals;
  const integrand = (u: number) => {
    const x = u === 0 ? Infinity : 1 / Math.sqrt(Math.sqrt(u));
    return detExp(-1.25 * u) * (x === Infinity ? 1 : peakEnhancement(x, gamma));
  };
  let sum = integrand(0) + integrand(end);
  for (let i = 1; i < intervals; i++) sum += (i % 2 === 1 ? 4 : 2) * integrand(i * h);
  return 0.25 * ((sum * h) / 3);
}

/**
 * Swell: a JONSWAP shape with peak period Tp, scaled so that 4·√m0 = Hs exactly. With x = ω/ωp,
 *   S(ω) = (Hs²/16)/(ωp·I(γ)) · x⁻⁵·exp(−(5/4)x⁻⁴)·γ^r,   so ∫S dω = (Hs²/16)·∫(…)dx/I(γ) = Hs²/16.
 * γ = 3.3, the JONSWAP mean: its peak is already much narrower than PM's, and a swell's narrowness
 * shows mostly in direction, which the swell's Horvath elongation (spreading.ts) takes care of.
 */
export const SWELL_GAMMA = JONSWAP_GAMMA;
const SWELL_SHAPE_INTEGRAL = jonswapShapeIntegral(SWELL_GAMMA);

export function swell(omega: number, significantHeight: number, peakPeriod: number): number {
  if (!(significantHeight > 0)) return 0;
  const peak = (2 * Math.PI) / peakPeriod;
  const x = omega / peak;
  const face = rearFace(x);
  if (face === 0) return 0;
  const m0 = (significantHeight * significantHeight) / 16;
  return (m0 / (peak * SWELL_SHAPE_INTEGRAL)) * face * peakEnhancement(x, SWELL_GAMMA);
}
