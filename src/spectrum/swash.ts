/**
 * Swash: the water running up and down a beach with the incoming waves, so that the waterline
 * moves instead of staying where the still water meets the ground.
 *
 * Its scale is Stockdon, Holman, Howd & Sallenger (2006), "Empirical parameterization of setup,
 * swash, and runup", Coastal Engineering 53, 573–588, fitted to ten field experiments, with H0 the
 * deep-water significant wave height, L0 = g·Tp²/(2π) the deep-water wavelength of the peak period
 * and β the foreshore slope:
 *   setup        η̄ = 0.35·β·√(H0·L0)                                   (eq. 10)
 *   swash        S  = √(H0·L0·(0.563·β² + 0.004))                         (eq. 11–12: the incident
 *                     band 0.75·β·√(H0·L0) and the infragravity band 0.06·√(H0·L0) in quadrature)
 *   2 % runup    R2 = 1.1·(η̄ + S/2)                                       (eq. 19)
 * S is a significant height, four standard deviations of the shoreline's elevation. The sea has no
 * wave groups of its own to drive the infragravity band, so the whole swash follows the incident
 * waves' phase: the shoreline's level is
 *   ζ = η̄ + (S / Hs)·η_deep
 * with η_deep the sea's elevation at the point before shoaling (standard deviation Hs/4, so ζ's is
 * S/4 and ζ exceeds η̄ + S/2 about as often as a Gaussian exceeds 2σ).
 *
 * The level acts where the ground is within reach of it: fully over land and in water shallower
 * than SWASH_FULL·S, fading to nothing at SWASH_END·S (a smoothstep), so that the waves further out
 * are the shoaled, breaking sea alone. The surface there is ζ_t (the faded level) plus the sea's
 * elevation limited by breaking in the water column d + ζ_t (breakingHeight): where the column is
 * empty, the beach is dry and the water is drawn under it.
 * β is clamped to MAX_BEACH_SLOPE: a steeper bottom is a cliff or a wall, not one of the beaches
 * the fit was made on, and the setup would grow without bound.
 */
import { GRAVITY } from './dispersion';

/** Beach slopes above this are taken as this (see above). */
export const MAX_BEACH_SLOPE = 0.2;
/** Depths (in units of S) up to which the swash level acts fully, and where it has faded out. */
export const SWASH_FULL = 0.5;
export const SWASH_END = 1.5;

/** Stockdon et al. 2006's setup η̄ (eq. 10) and significant swash S (eq. 11–12), m. */
export interface SwashScale {
  setup: number;
  swash: number;
}

/**
 * √(H0·L0), m: the scale of every Stockdon term; 0 without waves (Hs or Tp 0).
 * L0 = g·Tp²/(2π), the deep-water wavelength (Dean & Dalrymple 1991, eq. 3.35).
 */
export function swashLength(significantHeight: number, peakPeriod: number): number {
  if (!(significantHeight > 0 && peakPeriod > 0)) return 0;
  return Math.sqrt(significantHeight * ((GRAVITY * peakPeriod * peakPeriod) / (2 * Math.PI)));
}

/** Setup and swash on a beach of slope β for the sea of scale √(H0·L0) (swashLength). */
export function swashScale(length: number, slope: number, out: SwashScale = { setup: 0, swash: 0 }): SwashScale {
  const beta = Math.min(Math.abs(slope), MAX_BEACH_SLOPE);
  out.setup = 0.35 * beta * length;
  out.swash = length * Math.sqrt(0.563 * beta * beta + 0.004);
  return out;
}

/** Stockdon et al. 2006's 2 % runup R2 (eq. 19), m above still water. */
export function runup2(length: number, slope: number): number {
  const { setup, swash } = swashScale(length, slope);
  return 1.1 * (setup + 0.5 * swash);
}

const scale: SwashScale = { setup: 0, swash: 0 };

/**
 * The swash level ζ_t at a point of depth d (m) and beach slope β, the sea's deep-water elevation
 * there η_deep, for a sea of scale `length` (swashLength) and significant height Hs: ζ faded out
 * with depth (see above). shaders/surface/swash.glsl is the same formula.
 */
export function swashLevel(deepHeight: number, depth: number, slope: number, length: number, significantHeight: number): number {
  if (length === 0) return 0;
  const { setup, swash } = swashScale(length, slope, scale);
  const level = setup + (swash / significantHeight) * deepHeight;
  return level * (1 - smoothstep(SWASH_FULL * swash, SWASH_END * swash, depth));
}

/** GLSL's smoothstep. */
function smoothstep(from: number, to: number, x: number): number {
  const t = Math.min(Math.max((x - from) / (to - from), 0), 1);
  return t * t * (3 - 2 * t);
}
