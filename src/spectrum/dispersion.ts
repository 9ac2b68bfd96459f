/**
 * Dispersion of gravity waves and the quantized phases of time evolution.
 *
 * ω(k) = √(g·k)              deep water            (Tessendorf 2001, eq. 14)
 * ω(k) = √(g·k·tanh(k·d))    water of depth d      (Tessendorf 2001, eq. 15)
 *
 * Repeat period T (Tessendorf 2001, eq. 17): each ω is rounded to the nearest multiple m·ω0 of
 * ω0 = 2π/T, so every mode turns a whole number of times in T and the sea at t and t + T is
 * identical. Tessendorf rounds down, which slows every wave by up to ω0/ω; rounding to the nearest
 * halves the error and centres it, and cascadeBands.ts picks each cascade's T long enough that
 * every mode's phase speed is within 1 %. Time can then be wrapped into [0, T) in double precision before any float32 sees it,
 * so the phases never lose precision however long the scene runs.
 *
 * The phase factor of a mode is e^{i·m·φ} with φ = 2π·(t mod T)/T. Both simulation paths read it
 * from one small table computed here in double precision each frame:
 *   table[j] = (e^{i·j·φ}, e^{i·256·j·φ}) for j in [0, 256),
 *   e^{i·m·φ} = table[m mod 256].low · table[m div 256].high.
 * Why a table: GLSL sin/cos are approximate (off by ~2e-4 under SwiftShader, see
 * ../shared/BROWSER.md), far above the 1e-4·RMS agreement we require between the GPU and JS paths.
 */

import { detTanh } from './deterministicMath';

/** Gravitational acceleration, m/s². */
export const GRAVITY = 9.81;

/** Entries in each half of the phase table; m < PHASE_TABLE_SIZE² is representable. */
export const PHASE_TABLE_SIZE = 256;
export const MAX_FREQUENCY_INDEX = PHASE_TABLE_SIZE * PHASE_TABLE_SIZE - 1;

export interface DispersionParameters {
  /** Water depth in metres; Infinity is deep water. */
  depth: number;
  /** Repeat period T in seconds. */
  repeatPeriod: number;
}

/** ω(k) in rad/s, unquantized. */
export function angularFrequency(k: number, depth: number): number {
  // tanh(k·d) is 1 to double precision once k·d > 20; skipping it keeps deep water exact. detTanh:
  // Math.tanh may differ between engines in the last bit, and the initial spectrum must not.
  const depthFactor = depth === Infinity || k * depth > 20 ? 1 : detTanh(k * depth);
  return Math.sqrt(GRAVITY * k * depthFactor);
}

/** The integer m with m·ω0 = ω(k) rounded to the nearest multiple of ω0 = 2π/T. */
export function frequencyIndex(k: number, params: DispersionParameters): number {
  return Math.round((angularFrequency(k, params.depth) * params.repeatPeriod) / (2 * Math.PI));
}

/** t wrapped into [0, T), also for negative t. */
export function wrapTime(t: number, repeatPeriod: number): number {
  const wrapped = t % repeatPeriod;
  if (wrapped >= 0) return wrapped;
  const shifted = wrapped + repeatPeriod;
  return shifted < repeatPeriod ? shifted : 0; // a tiny negative t rounds up to T
}

/**
 * Fills `table` (RGBA, PHASE_TABLE_SIZE texels) with (cos jφ, sin jφ, cos 256jφ, sin 256jφ) for
 * φ = 2π·(t mod T)/T. Angles are reduced in double precision before cos/sin.
 */
export function fillPhaseTable(table: Float32Array, t: number, repeatPeriod: number): void {
  const turnsPerIndex = wrapTime(t, repeatPeriod) / repeatPeriod; // φ / 2π, in [0, 1)
  for (let j = 0; j < PHASE_TABLE_SIZE; j++) {
    const low = 2 * Math.PI * fractionalPart(j * turnsPerIndex);
    const high = 2 * Math.PI * fractionalPart(j * PHASE_TABLE_SIZE * turnsPerIndex);
    table[4 * j] = Math.cos(low);
    table[4 * j + 1] = Math.sin(low);
    table[4 * j + 2] = Math.cos(high);
    table[4 * j + 3] = Math.sin(high);
  }
}

function fractionalPart(x: number): number {
  return x - Math.floor(x);
}
