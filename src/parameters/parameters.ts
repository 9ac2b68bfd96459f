/**
 * The simulation's parameters, their defaults, and the one place that checks them.
 *
 * Units: metres, seconds, degrees for directions; g = 9.81 m/s². The sea lies in the xz plane with
 * y up, as in three.js and the course report.
 */

import { angularFrequency, frequencyIndex, MAX_FREQUENCY_INDEX } from '../spectrum/dispersion';

export interface SimulationParameters {
  /** Samples per side of the simulated patch, a power of two in [16, 1024]. @defaultValue 256 */
  resolution: number;
  /** Side of the square simulated patch in metres (> 0). @defaultValue 250 */
  patchSize: number;
  /** Wind speed |w| in m/s (≥ 0, at most 100). @defaultValue 12 */
  windSpeed: number;
  /** Direction the wind blows towards, in degrees from +x towards +z. @defaultValue 30 */
  windDirection: number;
  /** Phillips spectrum amplitude A (≥ 0). @defaultValue 2e-6 */
  amplitude: number;
  /** Length ℓ in metres below which waves are suppressed by exp(−k²ℓ²); 0 turns it off. @defaultValue 0.1 */
  smallWaveCutoff: number;
  /** Water depth in metres (> 0); Infinity is deep water. @defaultValue Infinity */
  depth: number;
  /** Seconds after which the whole sea repeats exactly (> 0). @defaultValue 200 */
  repeatPeriod: number;
  /** Horizontal displacement scale λ (≥ 0): 0 is a plain height field, larger sharpens crests. @defaultValue 1 */
  choppiness: number;
  /** Seed of the random initial spectrum, an integer in [0, 2³² − 1]. @defaultValue 1 */
  seed: number;
}

export const DEFAULT_PARAMETERS: Readonly<SimulationParameters> = Object.freeze({
  resolution: 256,
  patchSize: 250,
  windSpeed: 12,
  windDirection: 30,
  amplitude: 2e-6,
  smallWaveCutoff: 0.1,
  depth: Infinity,
  repeatPeriod: 200,
  choppiness: 1,
  seed: 1,
});

/** Thrown for a parameter outside what is allowed; `parameter` names it. */
export class ParameterError extends Error {
  constructor(
    readonly parameter: string,
    readonly value: unknown,
    allowed: string,
  ) {
    super(`${parameter} must be ${allowed}; got ${String(value)}`);
    this.name = 'ParameterError';
  }
}

export function isPowerOfTwo(n: number): boolean {
  return Number.isInteger(n) && n > 0 && (n & (n - 1)) === 0;
}

type Check = (value: number) => boolean;
const finite: Check = (v) => Number.isFinite(v);
const RULES: { [K in keyof SimulationParameters]: [Check, string] } = {
  resolution: [(v) => isPowerOfTwo(v) && v >= 16 && v <= 1024, 'a power of two from 16 to 1024'],
  patchSize: [(v) => finite(v) && v > 0, 'a finite number of metres > 0'],
  windSpeed: [(v) => finite(v) && v >= 0 && v <= 100, 'a finite speed in m/s from 0 to 100'],
  windDirection: [finite, 'a finite angle in degrees'],
  amplitude: [(v) => finite(v) && v >= 0, 'a finite number ≥ 0'],
  smallWaveCutoff: [(v) => finite(v) && v >= 0, 'a finite length in metres ≥ 0 (0 turns it off)'],
  depth: [(v) => v > 0, 'a depth in metres > 0, or Infinity for deep water'],
  repeatPeriod: [(v) => finite(v) && v > 0, 'a finite number of seconds > 0'],
  choppiness: [(v) => finite(v) && v >= 0, 'a finite number ≥ 0'],
  seed: [(v) => Number.isInteger(v) && v >= 0 && v <= 0xffffffff, 'an integer from 0 to 4294967295'],
};

/**
 * Merges `changes` over `base` and checks every value; throws a ParameterError naming the first bad
 * one, so a caller that catches it can keep running on `base`.
 */
export function validateParameters(
  changes: Partial<SimulationParameters>,
  base: Readonly<SimulationParameters> = DEFAULT_PARAMETERS,
): SimulationParameters {
  const merged: SimulationParameters = { ...base };
  for (const key of Object.keys(changes) as (keyof SimulationParameters)[]) {
    const rule = Object.hasOwn(RULES, key) ? RULES[key] : undefined;
    if (!rule) throw new ParameterError(String(key), changes[key], `one of ${Object.keys(RULES).join(', ')}`);
    const value = changes[key];
    if (typeof value !== 'number' || !rule[0](value)) throw new ParameterError(key, value, rule[1]);
    merged[key] = value;
  }
  // The fastest mode sits at the corner of the grid, |k| = √2·π·N / patchSize.
  const fastestK = (Math.SQRT2 * Math.PI * merged.resolution) / merged.patchSize;
  const fastest = frequencyIndex(fastestK, merged);
  if (fastest > MAX_FREQUENCY_INDEX) {
    // T at which the fastest index would reach MAX + 1, less a second so the advice is accepted.
    const longest = ((MAX_FREQUENCY_INDEX + 1) * 2 * Math.PI) / angularFrequency(fastestK, merged.depth);
    throw new ParameterError(
      'repeatPeriod',
      merged.repeatPeriod,
      `at most ${Math.ceil(longest) - 1} s with resolution ${merged.resolution} and patchSize ${merged.patchSize} ` +
        `(the fastest wave's frequency index would be ${fastest}, above ${MAX_FREQUENCY_INDEX})`,
    );
  }
  return merged;
}
