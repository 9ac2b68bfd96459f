/**
 * The sea state: a wind sea (Phillips, Pierson-Moskowitz, JONSWAP or TMA, with a directional
 * spreading) plus an optional swell, as the wave-number spectrum Ψ(k) the simulation samples per
 * wave vector, and as the summary Hs/Tp that a user reads.
 *
 * Ψ(k) in m⁴ is the variance of the waves travelling TOWARDS k̂ per unit area of the wave-number
 * plane, so Σ Ψ·Δk² over a grid ≈ m0 = ∫S dω. It comes from the directional spectrum S(ω)·D(ω, θ)
 * by the Jacobian of (ω, θ) → (kx, kz): dkx·dkz = k·dk·dθ and dω = c_g·dk, so
 *   Ψ(k) = S(ω)·D(ω, θ)·c_g/k       (Holthuijsen 2007, "Waves in Oceanic and Coastal Waters", §3.5).
 * Every spectrum is multiplied by exp(−k²ℓ²) for the small-wave cutoff ℓ (Tessendorf 2001, eq. 24).
 *
 * A note for the simulation: with h̃(k,t) = h̃0(k)e^{iωt} + h̃0*(−k)e^{−iωt} and h = Σh̃e^{ik·x}, the
 * term h̃0(k)e^{i(k·x+ωt)} travels towards −k. A cell k of side Δk therefore carries the waves towards
 * k̂ in h̃0(−k) and its partner: ⟨|h̃0(k)|²⟩ = Ψ(−k)·Δk²/2 gives the variance Ψ(k)·Δk² towards k̂.
 *
 * Determinism: only IEEE arithmetic and deterministicMath.ts.
 *
 * The parameters, their defaults and their checks are those of src/parameters/parameters.ts.
 */
import { ParameterError, validateParameters, type SimulationParameters } from '../parameters/parameters';
import { detAtan2, detCosSinDegrees, detExp, detExpm1, detLog, detPow, detTanh } from './deterministicMath';
import { angularFrequency, GRAVITY } from './dispersion';
import {
  jonswapParameters,
  jonswapShape,
  piersonMoskowitz,
  piersonMoskowitzPeakFrequency,
  swell,
  tmaFactor,
} from './frequencySpectra';
import { phillips } from './phillips';
import { cos2s, directionalSpreading, horvathElongation, type SpreadingOptions } from './spreading';

/** The parameters a sea state depends on (the rest of SimulationParameters is the grid's). */
export const SEA_STATE_KEYS = [
  'spectrum',
  'windSpeed',
  'windDirection',
  'fetch',
  'peakEnhancement',
  'depth',
  'spreading',
  'spreadingExponent',
  'swellHeight',
  'swellPeriod',
  'swellDirection',
  'swellElongation',
  'amplitude',
  'smallWaveCutoff',
] as const satisfies readonly (keyof SimulationParameters)[];
export type SeaStateParameters = Pick<SimulationParameters, (typeof SEA_STATE_KEYS)[number]>;

/**
 * The swell's cos-2s exponent before Horvath's elongation: 10, Goda's s_max for wind waves ("Random
 * Seas and Design of Maritime Structures", 2000, §2.3), since a swell is never broader than the sea
 * that raised it. ξ = 1 then adds 16·tanh(1) ≈ 12 at the peak, s ≈ 22, close to Goda's 25 for swell
 * with a short decay distance.
 */
export const SWELL_BASE_EXPONENT = 10;

// ————— Dispersion, in deterministic arithmetic —————

/** 1 + 2kd/sinh(2kd), twice the ratio n = c_g/c of group to phase speed. */
function groupFactor(k: number, depth: number): number {
  if (depth === Infinity || k * depth > 20) return 1; // 2kd/sinh(2kd) < 4e-16 there
  const x = 2 * k * depth;
  if (x < 1e-150) return 2;
  // x/sinh x = 2x·e^{−x}/(1 − e^{−2x}), with expm1 so that small x does not cancel.
  return 1 + (-2 * x * detExp(-x)) / detExpm1(-2 * x);
}

/**
 * Group velocity c_g = dω/dk = (ω/2k)·(1 + 2kd/sinh 2kd), from differentiating ω² = g·k·tanh(kd)
 * (Holthuijsen 2007, ch. 5: c_g = n·c with n = ½(1 + 2kd/sinh 2kd)). Deep water: c_g = ω/2k.
 */
export function groupVelocity(k: number, depth: number): number {
  return (angularFrequency(k, depth) / (2 * k)) * groupFactor(k, depth);
}

/**
 * k(ω): the inverse of the dispersion relation. Deep water: k = ω²/g. Finite depth: Fenton & McKee's
 * (1990) explicit approximation kd ≈ k∞d·coth((k∞d)^{3/4})^{2/3} (within 2 %), then Newton steps
 * on ω² − g·k·tanh(kd), whose convergence is quadratic from there.
 */
export function waveNumberFromFrequency(omega: number, depth: number): number {
  const deep = (omega * omega) / GRAVITY;
  if (depth === Infinity || deep * depth > 20 || !(omega > 0)) return deep;
  const deepDepth = deep * depth;
  // Shallow limit: k∞d < 1e-16 means kd = √(k∞d) < 1e-8, where tanh kd = kd to double precision,
  // so ω² = g·k²·d exactly (and the steps below would meet 0/0 once ω² underflows).
  if (deepDepth < 1e-16) return omega / Math.sqrt(GRAVITY * depth);
  let k = deep * detPow(1 / detTanh(detPow(deepDepth, 0.75)), 2 / 3);
  for (let step = 0; step < 6; step++) {
    const t = detTanh(k * depth);
    const residual = GRAVITY * k * t - omega * omega;
    const slope = GRAVITY * (t + k * depth * (1 - t * t));
    k -= residual / slope;
  }
  return k;
}

// ————— The wind sea and the swell as frequency spectra —————

interface DerivedSeaState {
  /** α and ωp of the wind sea (α unused for PM and Phillips). */
  windAlpha: number;
  windPeak: number;
  wind: [number, number];
  windSpreading: SpreadingOptions;
  swell: [number, number];
  swellPeak: number;
}

function deriveSeaState(p: SeaStateParameters): DerivedSeaState {
  let windPeak = piersonMoskowitzPeakFrequency(p.windSpeed);
  let windAlpha = 0;
  if (p.spectrum === 'jonswap' || p.spectrum === 'tma') {
    ({ alpha: windAlpha, peakFrequency: windPeak } = jonswapParameters(p.windSpeed, p.fetch));
  }
  return {
    windAlpha,
    windPeak,
    wind: detCosSinDegrees(p.windDirection),
    windSpreading: { model: p.spreading, peakFrequency: windPeak, windSpeed: p.windSpeed, exponent: p.spreadingExponent },
    swell: detCosSinDegrees(p.swellDirection),
    swellPeak: (2 * Math.PI) / p.swellPeriod,
  };
}

let cachedParameters: SeaStateParameters | undefined;
let cachedDerived: DerivedSeaState | undefined;

/** Whether a and b hold the same sea state. */
function sameSeaState(a: SeaStateParameters, b: SeaStateParameters): boolean {
  return SEA_STATE_KEYS.every((key) => a[key] === b[key]);
}

/** deriveSeaState, remembered for the last parameter values (the simulation asks N² times in a row). */
function derived(p: SeaStateParameters): DerivedSeaState {
  if (cachedParameters && cachedDerived && sameSeaState(cachedParameters, p)) return cachedDerived;
  cachedDerived = deriveSeaState(p);
  cachedParameters = { ...p };
  return cachedDerived;
}

/** The wind sea's S(ω), without swell and without the small-wave cutoff (not for 'phillips'). */
export function windSeaFrequencySpectrum(omega: number, p: SeaStateParameters): number {
  return windSea(omega, p, derived(p));
}

function windSea(omega: number, p: SeaStateParameters, d: DerivedSeaState): number {
  if (!(p.windSpeed > 0)) return 0;
  switch (p.spectrum) {
    case 'pierson-moskowitz':
      return piersonMoskowitz(omega, p.windSpeed);
    case 'jonswap':
      return jonswapShape(omega, d.windAlpha, d.windPeak, p.peakEnhancement);
    case 'tma':
      return jonswapShape(omega, d.windAlpha, d.windPeak, p.peakEnhancement) * tmaFactor(omega, p.depth);
    case 'phillips':
      throw new Error('windSeaFrequencySpectrum: use frequencySpectrum for the Phillips spectrum');
  }
}

/** The wind sea's peak frequency ωp, rad/s (the spreading models are scaled by it). */
export function windSeaPeakFrequency(p: SeaStateParameters): number {
  return derived(p).windPeak;
}

/** The swell's spreading: cos-2s with Horvath's elongation of the base exponent. */
function swellSpreading(theta: number, omega: number, p: SeaStateParameters, swellPeak: number): number {
  return cos2s(theta, horvathElongation(SWELL_BASE_EXPONENT, omega, swellPeak, p.swellElongation));
}

function smallWaveFactor(k: number, cutoff: number): number {
  return cutoff > 0 ? detExp(-k * k * cutoff * cutoff) : 1;
}

/**
 * Phillips as a frequency spectrum. Ψ = 2·P·(L/2π)² (see waveNumberSpectrum) and P's angular factor
 * |k̂·ŵ|² integrates to π over directions, so S(ω) = (k/c_g)·∫Ψ dθ = (k/c_g)·2π·(L/2π)²·P(k·ŵ).
 */
function phillipsFrequencySpectrum(omega: number, p: SeaStateParameters, patchSize: number): number {
  const k = waveNumberFromFrequency(omega, p.depth);
  if (!(k > 0 && k < Infinity)) return 0;
  const [wx, wz] = derived(p).wind;
  const scale = patchSize / (2 * Math.PI);
  const alongWind = phillips(k * wx, k * wz, p);
  if (alongWind === 0) return 0;
  return (k / groupVelocity(k, p.depth)) * 2 * Math.PI * scale * scale * alongWind;
}

/**
 * S(ω) of the whole sea in m²·s/rad: wind sea (× TMA for 'tma') + swell, times the small-wave cutoff
 * exp(−k(ω)²ℓ²) so that ∫S dω is the variance the simulation's Ψ holds. The swell is not multiplied
 * by the TMA factor: swellHeight is the swell's Hs where the sea is. 'phillips' needs the patch size.
 */
export function frequencySpectrum(omega: number, p: SeaStateParameters, phillipsPatchSize?: number): number {
  if (!(omega > 0)) return 0;
  if (p.spectrum === 'phillips') {
    if (phillipsPatchSize === undefined) {
      throw new ParameterError('phillipsPatchSize', phillipsPatchSize, "a patch side in metres > 0 for spectrum 'phillips'");
    }
    return phillipsFrequencySpectrum(omega, p, phillipsPatchSize); // P includes the cutoff
  }
  const total = windSea(omega, p, derived(p)) + swell(omega, p.swellHeight, p.swellPeriod);
  if (total === 0) return 0;
  return total * smallWaveFactor(waveNumberFromFrequency(omega, p.depth), p.smallWaveCutoff);
}

// ————— The wave-number spectrum —————

/** |k| without overflow or underflow in kx² + kz² (no Math.hypot: its accuracy is engine-defined). */
function magnitude(kx: number, kz: number): number {
  const largest = Math.max(Math.abs(kx), Math.abs(kz));
  if (largest === 0 || largest === Infinity) return largest;
  const a = kx / largest;
  const b = kz / largest;
  return largest * Math.sqrt(a * a + b * b);
}

/** The angle θ in (−π, π] between k and the unit vector (ux, uz). */
function angleFrom(kx: number, kz: number, [ux, uz]: [number, number]): number {
  return detAtan2(kz * ux - kx * uz, kx * ux + kz * uz);
}

/**
 * Ψ(k) in m⁴ for the wave vector (kx, kz) in rad/m (see the top of this file): wind sea with its
 * spreading about windDirection, plus swell about swellDirection. For 'phillips',
 * Ψ = 2·P(k)·(L/2π)² with P the report's Phillips spectrum (initialSpectrum.ts) and L =
 * phillipsPatchSize: a patch of side L has Δk = 2π/L, so Σ Ψ·Δk² = Σ 2P, the variance of Tessendorf's
 * h (each cell holds h̃0(k) and h̃0*(−k), each of mean square P). Phillips has its own symmetric
 * spreading |k̂·ŵ|² and ignores swell and `spreading`. Ψ(0) = 0; never NaN for valid parameters.
 */
export function waveNumberSpectrum(kx: number, kz: number, p: SeaStateParameters, phillipsPatchSize: number): number {
  return spectrumOf(kx, kz, p, p.spectrum === 'phillips' ? null : derived(p), phillipsPatchSize);
}

/**
 * waveNumberSpectrum for fixed parameters (a copy of p as it is now): what the simulation samples
 * N² times, without comparing the parameters with the last ones at every sample.
 */
export function fixedWaveNumberSpectrum(p: SeaStateParameters, phillipsPatchSize: number): (kx: number, kz: number) => number {
  const fixed = { ...p };
  const d = fixed.spectrum === 'phillips' ? null : deriveSeaState(fixed);
  return (kx, kz) => spectrumOf(kx, kz, fixed, d, phillipsPatchSize);
}

/** waveNumberSpectrum with the derived sea state given (null for 'phillips'). */
function spectrumOf(kx: number, kz: number, p: SeaStateParameters, d: DerivedSeaState | null, phillipsPatchSize: number): number {
  const k = magnitude(kx, kz);
  if (k === 0 || !(k < Infinity)) return 0;
  if (d === null) {
    const scale = phillipsPatchSize / (2 * Math.PI);
    return 2 * phillips(kx, kz, p) * (scale * scale);
  }
  const omega = angularFrequency(k, p.depth);
  let variance = 0; // S·D of wind sea and swell, m²·s/rad per radian
  const wind = windSea(omega, p, d);
  if (wind > 0) variance += wind * directionalSpreading(angleFrom(kx, kz, d.wind), omega, d.windSpreading);
  const swellSpectrum = swell(omega, p.swellHeight, p.swellPeriod);
  if (swellSpectrum > 0) variance += swellSpectrum * swellSpreading(angleFrom(kx, kz, d.swell), omega, p, d.swellPeak);
  if (variance === 0) return 0;
  // c_g/k = (ω/2k)/k·(1 + 2kd/sinh 2kd), divided in this order so that k² cannot underflow.
  const jacobian = (omega / (2 * k) / k) * groupFactor(k, p.depth);
  return variance * jacobian * smallWaveFactor(k, p.smallWaveCutoff);
}

// ————— Summary: moments, Hs and Tp —————

export interface SpectralMoments {
  /** m0 = ∫S dω, the variance of the surface height, m². */
  m0: number;
  /** ωp, the argmax of S(ω), rad/s; 0 when there are no waves. */
  peakFrequency: number;
  /** ∫k(ω)²·S(ω) dω, the variance of the slope of the modelled surface (with its small-wave cutoff). */
  slopeVariance: number;
}

/** Step in ln ω: 0.002 puts 35 samples within one σ = 0.07 of a JONSWAP peak. */
const LOG_FREQUENCY_STEP = 0.002;

/**
 * m0 and ωp of frequencySpectrum by Simpson's rule in t = ln ω (m0 = ∫S(e^t)·e^t dt) from a fifth of
 * the lowest peak (where exp(−(5/4)·5⁴) ≈ 1e-340 has cut every spectrum here off) to 200 times the
 * highest (the ω⁻⁵ tail beyond holds 1.25/200⁴ ≈ 8e-10 of m0). The largest sample is then refined by
 * a golden-section search between its neighbours: a parabola through three samples would be biased
 * at a JONSWAP peak, where σ jumps from 0.07 to 0.09 and the curvature with it.
 */
export function spectralMoments(p: SeaStateParameters, phillipsPatchSize?: number): SpectralMoments {
  const peaks: number[] = [];
  if (p.windSpeed > 0) peaks.push(p.spectrum === 'phillips' ? GRAVITY / p.windSpeed : windSeaPeakFrequency(p));
  if (p.spectrum !== 'phillips' && p.swellHeight > 0) peaks.push((2 * Math.PI) / p.swellPeriod);
  if (peaks.length === 0) return { m0: 0, peakFrequency: 0, slopeVariance: 0 };
  const spectrumAt = (t: number) => frequencySpectrum(detExp(t), p, phillipsPatchSize);
  const start = detLog(0.2 * Math.min(...peaks));
  const end = detLog(200 * Math.max(...peaks));
  const intervals = 2 * Math.ceil((end - start) / (2 * LOG_FREQUENCY_STEP));
  const h = (end - start) / intervals;
  let sum = 0;
  let slopeSum = 0;
  let best = 0;
  let bestValue = 0;
  for (let i = 0; i <= intervals; i++) {
    const t = start + i * h;
    const value = spectrumAt(t);
    const weight = (i === 0 || i === intervals ? 1 : i % 2 === 1 ? 4 : 2) * value * detExp(t);
    sum += weight;
    if (weight > 0) {
      const k = waveNumberFromFrequency(detExp(t), p.depth);
      slopeSum += weight * k * k;
    }
    if (value > bestValue) [best, bestValue] = [i, value];
  }
  if (!(bestValue > 0)) return { m0: 0, peakFrequency: 0, slopeVariance: 0 };
  const peak = goldenSectionMaximum(spectrumAt, start + (best - 1) * h, start + (best + 1) * h);
  return { m0: (sum * h) / 3, peakFrequency: detExp(peak), slopeVariance: (slopeSum * h) / 3 };
}

/** The argmax of f on [a, b], f unimodal there, to 3e-13 of b − a (60 golden-section steps). */
function goldenSectionMaximum(f: (t: number) => number, a: number, b: number): number {
  const ratio = (Math.sqrt(5) - 1) / 2;
  let c = b - ratio * (b - a);
  let d = a + ratio * (b - a);
  let fc = f(c);
  let fd = f(d);
  for (let step = 0; step < 60; step++) {
    if (fc > fd) {
      // The maximum lies in [a, d]: d becomes the upper end, c the new inner point on the right.
      [b, d, fd] = [d, c, fc];
      c = b - ratio * (b - a);
      fc = f(c);
    } else {
      [a, c, fc] = [c, d, fd];
      d = a + ratio * (b - a);
      fd = f(d);
    }
  }
  return (a + b) / 2;
}

// ————— The slopes of the waves shorter than the small-wave cutoff —————

/** Elfouhaily et al.'s gravity-capillary wave number k_m = 370 rad/m and its phase speed c_m = 0.23 m/s. */
const CAPILLARY_PEAK = 370;
const CAPILLARY_PEAK_SPEED = 0.23;

/**
 * u*, m/s, from U10 by Wu (1982), "Wind-stress coefficients over sea surface from breeze to
 * hurricane", J. Geophys. Res. 87(C12): 9704–9706: C_D = (0.8 + 0.065·U10)·10⁻³, u* = √C_D·U10.
 */
export function frictionVelocity(windSpeed: number): number {
  return Math.sqrt((0.8 + 0.065 * windSpeed) * 1e-3) * windSpeed;
}

/**
 * The omnidirectional curvature spectrum B(k) = k³·S(k) of Elfouhaily, Chapron, Katsaros &
 * Vandemark (1997), "A unified directional spectrum for long and short wind-driven waves",
 * J. Geophys. Res. 102(C7): 15781–15796, eqs. 32–44 (deep water): B = B_l + B_h with
 *   B_l = ½·α_p·(c_p/c)·F_p,  α_p = 6·10⁻³·√Ω,
 *   F_p = L_PM·J_p·exp(−(Ω/√10)·(√(k/k_p) − 1)),  L_PM = exp(−(5/4)(k_p/k)²),  J_p = γ^Γ,
 *   γ = 1.7 (0.84 ≤ Ω < 1), 1.7 + 6·log10 Ω (1 ≤ Ω ≤ 5),  Γ = exp(−(√(k/k_p) − 1)²/(2σ²)),
 *   σ = 0.08·(1 + 4·Ω⁻³);
 *   B_h = ½·α_m·(c_m/c)·F_m,  F_m = L_PM·J_p·exp(−¼(k/k_m − 1)²),
 *   α_m = 10⁻²·(1 + ln(u* / c_m)) for u* ≤ c_m, 10⁻²·(1 + 3·ln(u* / c_m)) above;
 *   c(k) = √((g/k)·(1 + (k/k_m)²)),  k_p = g·(Ω/U10)²  (Ω = U10/c_p, the inverse wave age).
 */
export function elfouhailyCurvature(k: number, windSpeed: number, inverseWaveAge: number): number {
  const omega = Math.min(5, Math.max(0.84, inverseWaveAge));
  const peak = (GRAVITY * omega * omega) / (windSpeed * windSpeed);
  const peakSpeed = Math.sqrt(GRAVITY / peak);
  const speed = Math.sqrt((GRAVITY / k) * (1 + (k * k) / (CAPILLARY_PEAK * CAPILLARY_PEAK)));
  const gamma = omega < 1 ? 1.7 : 1.7 + (6 * detLog(omega)) / detLog(10);
  const sigma = 0.08 * (1 + 4 / (omega * omega * omega));
  const root = Math.sqrt(k / peak) - 1;
  const shape = detExp((-1.25 * peak * peak) / (k * k)) * detPow(gamma, detExp((-root * root) / (2 * sigma * sigma)));
  const long = 0.5 * 6e-3 * Math.sqrt(omega) * (peakSpeed / speed) * shape * detExp((-omega / Math.sqrt(10)) * root);
  const uStar = frictionVelocity(windSpeed);
  const ratio = detLog(uStar / CAPILLARY_PEAK_SPEED);
  const alphaM = 1e-2 * (uStar <= CAPILLARY_PEAK_SPEED ? 1 + ratio : 1 + 3 * ratio);
  const short = 0.5 * alphaM * (CAPILLARY_PEAK_SPEED / speed) * shape * detExp(-0.25 * (k / CAPILLARY_PEAK - 1) * (k / CAPILLARY_PEAK - 1));
  return long + short;
}

/**
 * The slope variance of the waves the small-wave cutoff ℓ takes out of the model: the share
 * 1 − exp(−k²ℓ²) of Elfouhaily et al.'s spectrum (elfouhailyCurvature), ∫(1 − e^{−k²ℓ²})·B(k)/k dk,
 * by Simpson's rule in ln k from k = 0.01/ℓ (where the share is 10⁻⁴) to 30·k_m (where
 * exp(−¼(k/k_m − 1)²) < 10⁻⁹³), steps of 0.01. 0 without wind or without a cutoff (then the model
 * keeps every wave up to 200 peak frequencies: see spectralMoments).
 */
export function unresolvedSlopeVariance(windSpeed: number, peakFrequency: number, cutoff: number): number {
  if (!(windSpeed > 0 && peakFrequency > 0 && cutoff > 0)) return 0;
  const inverseWaveAge = (windSpeed * peakFrequency) / GRAVITY; // U10/c_p, c_p = g/ωp in deep water
  const [start, end] = [detLog(0.01 / cutoff), detLog(30 * CAPILLARY_PEAK)];
  if (!(end > start)) return 0;
  const intervals = 2 * Math.ceil((end - start) / 0.02);
  const h = (end - start) / intervals;
  let sum = 0;
  for (let i = 0; i <= intervals; i++) {
    const k = detExp(start + i * h);
    const share = -detExpm1(-k * k * cutoff * cutoff);
    sum += (i === 0 || i === intervals ? 1 : i % 2 === 1 ? 4 : 2) * share * elfouhailyCurvature(k, windSpeed, inverseWaveAge);
  }
  return (sum * h) / 3;
}

/**
 * Hs = 4·√m0 and Tp = 2π/ωp of the sea state that these parameters describe (DEFAULT_PARAMETERS
 * for every one not given; Tp = 0 when there are no waves), and the mean square slope of the whole
 * surface: the model spectrum's ∫k²·S dω (with its small-wave cutoff ℓ) plus the slopes of the
 * waves the cutoff removes, from Elfouhaily et al.'s (1997) gravity-capillary spectrum
 * (unresolvedSlopeVariance). The model's own tail ends at ℓ (1 cm by default), well short of the
 * capillary waves that carry about half of the slope that sun glitter shows (Cox & Munk 1954):
 *   seaState({ spectrum: 'jonswap', windSpeed: 17, fetch: 300 })
 * A bad or unknown option throws a ParameterError naming it (validateParameters). Phillips' Ψ
 * depends on the largest patch (patchSizes), as in the simulation.
 */
export function seaState(options: Partial<SimulationParameters> = {}): { significantWaveHeight: number; peakPeriod: number; meanSquareSlope: number } {
  const parameters = validateParameters(options);
  const { m0, peakFrequency, slopeVariance } = spectralMoments(parameters, parameters.patchSizes[parameters.patchSizes.length - 1]);
  const windPeak = parameters.windSpeed > 0 ? (parameters.spectrum === 'phillips' ? GRAVITY / parameters.windSpeed : windSeaPeakFrequency(parameters)) : 0;
  return {
    significantWaveHeight: 4 * Math.sqrt(m0),
    peakPeriod: peakFrequency > 0 ? (2 * Math.PI) / peakFrequency : 0,
    meanSquareSlope: slopeVariance + unresolvedSlopeVariance(parameters.windSpeed, windPeak, parameters.smallWaveCutoff),
  };
}
