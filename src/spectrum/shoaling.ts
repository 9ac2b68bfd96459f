/**
 * Waves feeling the bottom: shoaling and depth-limited breaking, by linear wave theory.
 *
 * Group velocity (Dean & Dalrymple 1991, "Water Wave Mechanics for Engineers and Scientists",
 * §4.8, eq. 4.79; Coastal Engineering Manual (USACE 2002) II-1, Table II-1-1), with ω² = g·k·tanh(k·d)
 * (dispersion.ts; seaState.ts computes it and inverts the dispersion relation):
 *   c_g(k, d) = n·c,   c = ω/k,   n = ½·(1 + 2kd / sinh(2kd))        (n → ½ in deep water)
 *
 * Shoaling coefficient (Dean & Dalrymple 1991 §4.8, eq. 4.82; CEM II-3-2, eq. II-3-3): a wave
 * running over a slowly varying bottom keeps its frequency ω and its energy flux E·c_g, E ∝ H², so
 * its height becomes
 *   H(d) = H_ref · Ks,   Ks = √(c_g(k_ref, d_ref) / c_g(k_d, d)),   ω² = g·k·tanh(k·d) at both
 * where d_ref is the depth the spectrum was made for (the `depth` option, often deep water), k_ref
 * the mode's wave number there and k_d the same frequency's at depth d. Ks
 * first dips to ≈ 0.91 (at kd ≈ 1.2) and then grows as d^(−1/4) towards the shore (Green's law).
 * Refraction and the shortening of the waves are not modelled: the FFT's waves keep their
 * wavelength and direction everywhere.
 *
 * The FFT cannot change a wave's height per position, but it can scale a whole cascade: the surface
 * multiplies cascade c's fields by the energy-weighted mean coefficient of its band,
 *   F_c(d) = √( Σ_k |h̃0(k)|²·Ks(k, d)²  /  Σ_k |h̃0(k)|² ),
 * so that its variance at depth d is exactly what linear shoaling gives its modes. It is tabulated
 * over SHOALING_DEPTHS depths spaced evenly in log d from SHOALING_MIN_DEPTH to the depth beyond
 * which no wave of the sea feels the bottom (its longest wavelength: there Ks differs from 1 by less
 * than 10⁻⁵), and read by linear interpolation in log d, on the GPU (shaders/surface/shoaling.glsl)
 * and in the queries (here), from the same table.
 *
 * Breaking (McCowan 1894, "On the highest wave of permanent type", Phil. Mag. 38; CEM II-4-3,
 * eq. II-4-4 with κ = 0.78): no wave in water of depth d is higher than H_b = 0.78·d, so the surface
 * elevation η stays within ±0.39·d. It is limited softly: unchanged up to BREAKING_KNEE of the
 * limit, then bent smoothly (tanh) towards it; where it bends the wave is breaking and makes surf.
 */
import type { InitialSpectrum } from './initialSpectrum';
import { angularFrequency } from './dispersion';
import { groupVelocity, waveNumberFromFrequency } from './seaState';

/** Depths in each cascade's table. */
export const SHOALING_DEPTHS = 64;
/** The shallowest depth tabulated, m: shallower reads this entry (breaking limits the height there anyway). */
export const SHOALING_MIN_DEPTH = 0.05;
/** McCowan's breaker index κ = H_b / d (McCowan 1894; CEM II-4-3). */
export const BREAKER_INDEX = 0.78;
/** Fraction of the depth limit up to which the height is unchanged (the rest bends towards the limit). */
export const BREAKING_KNEE = 0.7;
/** How far below y = 0 the water surface is drawn over land (d ≤ 0), at most, m: the terrain hides it. */
export const LAND_DROP = 0.3;

/**
 * Ks of the mode of wave number k (at the reference depth) in water of depth d > 0
 * (Dean & Dalrymple 1991, eq. 4.82): the same frequency's group velocities compared.
 */
export function shoalingCoefficient(k: number, depth: number, referenceDepth: number): number {
  return Math.sqrt(groupVelocity(k, referenceDepth) / groupVelocity(waveNumberFromFrequency(angularFrequency(k, referenceDepth), depth), depth));
}

/** The tabulated depths: d_j = min·(max/min)^(j/(n−1)), and the reading of d back into a fractional j. */
export interface ShoalingDepths {
  /** log(SHOALING_MIN_DEPTH) */
  logMin: number;
  /** (n − 1) / log(max / min): entries per unit of log d */
  perLog: number;
  /** The deepest tabulated, m: from it on every factor is 1. */
  max: number;
}

/**
 * The depths to tabulate for a sea whose longest wave is `longestWavelength` (m) and whose spectrum
 * was made for `referenceDepth`: up to the shallower of the two (beyond the wavelength no wave
 * feels the bottom; at the reference depth Ks = 1 by definition).
 */
export function shoalingDepths(longestWavelength: number, referenceDepth: number): ShoalingDepths {
  const max = Math.max(Math.min(longestWavelength, referenceDepth), 2 * SHOALING_MIN_DEPTH);
  const logMin = Math.log(SHOALING_MIN_DEPTH);
  return { logMin, perLog: (SHOALING_DEPTHS - 1) / (Math.log(max) - logMin), max };
}

/** Energy-weighted wave-number bins per cascade: Ks depends on |k| only, and varies slowly with it. */
const K_BINS = 512;

/**
 * F_c(d_j) for one cascade's spectrum at every tabulated depth (the table's row), into `out` from
 * `offset`. The modes' energies are first gathered into K_BINS logarithmic bins of |k| (each at its
 * energy-weighted mean |k|; within a bin Ks changes by < 0.1 %).
 */
export function cascadeShoalingRow(spectrum: Pick<InitialSpectrum, 'resolution' | 'patchSize' | 'amplitudes'>, depths: ShoalingDepths, referenceDepth: number, out: Float32Array, offset: number): void {
  const { resolution: n, patchSize, amplitudes } = spectrum;
  const dk = (2 * Math.PI) / patchSize;
  const logKMin = Math.log(dk);
  const binsPerLog = K_BINS / (Math.log(dk * n) - logKMin); // |k| ≤ √2·(N/2)·Δk < N·Δk
  const energy = new Float64Array(K_BINS);
  const energyK = new Float64Array(K_BINS);
  let total = 0;
  for (let j = 0; j < n; j++) {
    const m = j < n / 2 ? j : j - n;
    for (let i = 0; i < n; i++) {
      const at = 4 * (j * n + i);
      const w = amplitudes[at] ** 2 + amplitudes[at + 1] ** 2 + amplitudes[at + 2] ** 2 + amplitudes[at + 3] ** 2;
      if (w === 0 || (i === 0 && j === 0)) continue; // the mean level is no wave
      const l = i < n / 2 ? i : i - n;
      const k = dk * Math.hypot(l, m);
      const bin = Math.min(K_BINS - 1, Math.max(0, Math.floor((Math.log(k) - logKMin) * binsPerLog)));
      energy[bin] += w;
      energyK[bin] += w * k;
      total += w;
    }
  }
  for (let d = 0; d < SHOALING_DEPTHS; d++) {
    const depth = d === SHOALING_DEPTHS - 1 ? depths.max : Math.exp(depths.logMin + d / depths.perLog);
    if (total === 0 || depth >= referenceDepth) {
      out[offset + d] = 1;
      continue;
    }
    let sum = 0;
    for (let b = 0; b < K_BINS; b++) {
      if (energy[b] === 0) continue;
      sum += energy[b] * shoalingCoefficient(energyK[b] / energy[b], depth, referenceDepth) ** 2;
    }
    out[offset + d] = Math.sqrt(sum / total);
  }
}

/**
 * The factor of table row `row` (SHOALING_DEPTHS entries from `offset`) at depth d: linear in
 * log d between entries, the first entry above d ≤ SHOALING_MIN_DEPTH, 1 from depths.max on.
 * shaders/surface/shoaling.glsl reads its table the same way.
 */
export function shoalingFactor(table: Float32Array, offset: number, depths: ShoalingDepths, depth: number): number {
  if (depth >= depths.max) return 1;
  const position = depth <= SHOALING_MIN_DEPTH ? 0 : (Math.log(depth) - depths.logMin) * depths.perLog;
  const j = Math.min(Math.floor(position), SHOALING_DEPTHS - 2);
  const f = position - j;
  return table[offset + j] * (1 - f) + table[offset + j + 1] * f;
}

/**
 * The surface elevation η limited to ±0.39·d (McCowan): unchanged up to the knee, then
 * knee·L + (1 − knee)·L·tanh((|η| − knee·L) / ((1 − knee)·L)), which leaves η and its slope
 * continuous and never reaches L. Over land (d ≤ 0) the water is drawn at max(d, −LAND_DROP), under
 * the ground.
 */
export function breakingHeight(height: number, depth: number): number {
  if (depth <= 0) return Math.max(depth, -LAND_DROP);
  const limit = (0.5 * BREAKER_INDEX) * depth;
  const knee = BREAKING_KNEE * limit;
  const size = Math.abs(height);
  if (size <= knee) return height;
  const bent = knee + (limit - knee) * Math.tanh(Math.min((size - knee) / (limit - knee), 10)); // as shoaling.glsl
  return height < 0 ? -bent : bent;
}

/** dη_limited/dη of breakingHeight: what the height's slopes and its velocity are multiplied by. */
export function breakingSlope(height: number, depth: number): number {
  if (depth <= 0) return 0;
  const limit = (0.5 * BREAKER_INDEX) * depth;
  const knee = BREAKING_KNEE * limit;
  const size = Math.abs(height);
  if (size <= knee) return 1;
  const t = Math.tanh(Math.min((size - knee) / (limit - knee), 10));
  return 1 - t * t;
}
