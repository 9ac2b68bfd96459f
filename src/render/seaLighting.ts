/**
 * The slopes the grid does not show, as light (shaders/surface/seaLighting.glsl): the sea's mean
 * square slope σ² is split into what the cascades draw as normals and what they cannot, and the
 * shading spreads the glint and the sky's reflection over the rest (Bruneton, Neyret & Holzschuch
 * 2010, "Real-time realistic ocean lighting using seamless transitions from geometry to BRDF",
 * Computer Graphics Forum 29(2), §4). Two parts are missing from a pixel's normal:
 *  - the waves shorter than the finest cascade's texels: σ²_CM(U) − Σ_cascades σ²_resolved, with
 *    σ²_CM Cox & Munk's measured mean square slope of the clean sea (below), so that resolved +
 *    unresolved = Cox–Munk whatever the grid, the number of cascades or the quality level;
 *  - the slopes the cascades do carry but that mip-mapping averages away at the pixel's footprint:
 *    per cascade and mip level L, E[s²] − E[s]² over the 2^L × 2^L texels a level-L texel averages,
 *    from the cascade's own spectrum (filteredSlopeVariance), so the far sea keeps the brightness
 *    of its waves instead of going flat.
 */
import { FftCascade } from '../layers/fftCascade';
import type { WaveLayer } from '../layers/waveLayer';
import type { InitialSpectrum } from '../spectrum/initialSpectrum';

/**
 * The sun's irradiance at the sea on a plane facing it, linear RGB (for the glint, the foam and the
 * crests' glow): the sky's E_sun·T_sun for a sun ~30° high (shaders/sky/analyticSky.glsl).
 */
export const SEA_SUN_COLOR: readonly [number, number, number] = [12, 11, 9.5];

/**
 * How deep (m) the ray refracted into the sea is followed through the water before the deep water's
 * own colour takes over (absorption.glsl's viewDepth, along the vertical).
 */
export const VIEW_DEPTH = 4;

/**
 * Mip levels per layer in the table of filtered slope variance: 0 … 11 covers N up to 2048 (the
 * last levels of a smaller grid hold its whole variance: its 1×1 level keeps only the mean).
 */
export const SLOPE_FILTER_LEVELS = 12;

/**
 * Cox & Munk (1954), "Measurement of the roughness of the sea surface from photographs of the sun's
 * glitter", J. Opt. Soc. Am. 44(11): 838–850, eq. for the clean surface: σ² = 0.003 + 5.12·10⁻³·U
 * (U the wind speed in m/s at 12.5 m above the sea, valid to about 14 m/s and used beyond; the
 * fit's rms deviation is 0.004). The Ocean's wind speed is at 10 m: under a neutral logarithmic
 * profile U12.5 is 1–2 % more, well inside the fit's scatter, so U10 is used as it is. Without
 * wind there are no ripples (as seaState reports 0): a mirror, not the fit's intercept.
 */
export function coxMunkMeanSquareSlope(windSpeed: number): number {
  return windSpeed > 0 ? 0.003 + 5.12e-3 * windSpeed : 0;
}

/** What one cascade's spectrum gives the lighting: its slope variance and how mip-mapping filters it. */
export interface CascadeSlopes {
  /** Σ k²·(|h̃0(k)|² + |h̃0(−k)|²): the mean square slope of the cascade's normals (by Parseval). */
  resolved: number;
  /** The height variance Σ (|h̃0(k)|² + |h̃0(−k)|²), m². */
  heightVariance: number;
  /** [L]: the slope variance that level L of the mip chain has averaged away, E[s²] − E[s]². */
  filtered: Float32Array;
}

/**
 * A cascade's slope variance per mip level. A level-L texel is the mean of M × M texels (M = 2^L,
 * the box filter of generateMipmap and of cpuFieldTextures' levels), which scales a mode k by the
 * discrete box's response D_M(kx·Δ)·D_M(kz·Δ), D_M(x) = sin(M·x/2) / (M·sin(x/2)), Δ the texel
 * (Oppenheim & Schafer, "Discrete-Time Signal Processing", the moving average's frequency
 * response). The slope variance it keeps is Σ k²·P(k)·D², the rest, Σ k²·P(k)·(1 − D²), is what the
 * pixel's normal no longer shows.
 */
export function cascadeSlopes(spectrum: Pick<InitialSpectrum, 'amplitudes' | 'waveVectors' | 'resolution' | 'patchSize'>): CascadeSlopes {
  const { amplitudes, waveVectors, resolution, patchSize } = spectrum;
  // kx·Δ = 2π·n/N for the mode's integer frequency n: the response depends on n and L only.
  const responses = Array.from({ length: SLOPE_FILTER_LEVELS }, (_, level) => {
    const width = Math.min(2 ** level, resolution);
    return Float64Array.from({ length: resolution }, (_, n) => boxResponse((2 * Math.PI * n) / resolution, width));
  });
  const toIndex = patchSize / (2 * Math.PI);
  const filtered = new Float32Array(SLOPE_FILTER_LEVELS);
  const sums = new Float64Array(SLOPE_FILTER_LEVELS);
  let resolved = 0;
  let heightVariance = 0;
  for (let at = 0; at < amplitudes.length; at += 4) {
    const power = amplitudes[at] ** 2 + amplitudes[at + 1] ** 2 + amplitudes[at + 2] ** 2 + amplitudes[at + 3] ** 2;
    if (power === 0) continue;
    const kx = waveVectors[at];
    const kz = waveVectors[at + 1];
    const slope = (kx * kx + kz * kz) * power;
    resolved += slope;
    heightVariance += power;
    const nx = (Math.round(kx * toIndex) + resolution) % resolution;
    const nz = (Math.round(kz * toIndex) + resolution) % resolution;
    for (let level = 1; level < SLOPE_FILTER_LEVELS; level++) {
      const kept = responses[level][nx] * responses[level][nz];
      sums[level] += slope * (1 - kept * kept);
    }
  }
  sums.forEach((sum, level) => (filtered[level] = sum));
  return { resolved, heightVariance, filtered };
}

/** D_M(x) = sin(M·x/2) / (M·sin(x/2)), 1 at x = 0. */
function boxResponse(x: number, width: number): number {
  const half = Math.sin(x / 2);
  return Math.abs(half) < 1e-12 ? 1 : Math.sin((width * x) / 2) / (width * half);
}

/** The slopes of every layer, cached per spectrum (a spectrum never changes; a new sea makes new ones). */
const slopesOfSpectrum = new WeakMap<InitialSpectrum, CascadeSlopes>();

function slopesOf(layer: WaveLayer): CascadeSlopes | null {
  if (!(layer instanceof FftCascade)) return null;
  let slopes = slopesOfSpectrum.get(layer.spectrum);
  if (slopes === undefined) slopesOfSpectrum.set(layer.spectrum, (slopes = cascadeSlopes(layer.spectrum)));
  return slopes;
}

/** The uniforms of seaLighting.glsl for a sea, as OceanMaterial binds them. */
export interface SeaLightingValues {
  /** σ²_CM(U) − Σ σ²_resolved, never below 0: the slopes finer than every cascade. */
  unresolvedSlopeVariance: number;
  /** [layer · SLOPE_FILTER_LEVELS + L]: the filtered variance of each layer at level L (0 for a layer that is not a cascade). */
  layerFilteredSlopes: number[];
  /** Each layer's texel, metres (its mip level at a pixel is log2(footprint / texel)). */
  layerTexels: number[];
  /** √(Σ height variance) of the cascades, m: the scale of "high above the mean" for the crests' glow. */
  heightRms: number;
}

/**
 * seaLighting.glsl's uniforms for these layers under this wind: the cascades' share of Cox–Munk's
 * slope and the rest. Layers that are not FFT cascades (local waves, user layers) add nothing to
 * the resolved variance and are not mip-mapped.
 */
export function seaLightingValues(layers: readonly WaveLayer[], windSpeed: number): SeaLightingValues {
  let resolved = 0;
  let heightVariance = 0;
  const layerFilteredSlopes: number[] = [];
  const layerTexels: number[] = [];
  for (const layer of layers) {
    const slopes = slopesOf(layer);
    resolved += slopes?.resolved ?? 0;
    heightVariance += slopes?.heightVariance ?? 0;
    for (let level = 0; level < SLOPE_FILTER_LEVELS; level++) layerFilteredSlopes.push(slopes?.filtered[level] ?? 0);
    layerTexels.push(layer.frame.size / layer.frame.resolution);
  }
  return {
    unresolvedSlopeVariance: Math.max(0, coxMunkMeanSquareSlope(windSpeed) - resolved),
    layerFilteredSlopes,
    layerTexels,
    heightRms: Math.sqrt(heightVariance),
  };
}
