/**
 * The simulation's parameters: the one place that says their defaults, units, ranges and how to
 * check them. `Ocean`, the app's URL state and panel, `<fft-ocean>` and the shot CLI all read
 * SIMULATION_OPTIONS and call validateParameters; none keeps its own copy.
 *
 * Units: metres, seconds, degrees for directions (the direction waves travel towards, from +x
 * towards +z), kilometres for the fetch, g = 9.81 m/s². The sea lies in the xz plane with y up,
 * as in three.js and the course report.
 */

import { angularFrequency, MAX_FREQUENCY_INDEX } from '../spectrum/dispersion';
import {
  between,
  finiteAngle,
  isNumber,
  mergeOptions,
  oneOf,
  ParameterError,
  parseOptionText,
  type OptionRule,
} from './options';

export { ParameterError, parseDecimal } from './options';
import { cascadeBands, cascadeRepeatPeriod, fastestModeInBand, maxPatchRatio } from '../spectrum/cascadeBands';

/** Spectrum models: the report's Phillips, and the oceanographic ones (src/spectrum/frequencySpectra.ts). */
export const SPECTRUM_MODELS = ['phillips', 'pierson-moskowitz', 'jonswap', 'tma'] as const;
export type SpectrumModel = (typeof SPECTRUM_MODELS)[number];
/** Directional spreading functions (src/spectrum/spreading.ts). */
export const SPREADING_MODELS = ['cos-2s', 'mitsuyasu', 'hasselmann', 'donelan-banner'] as const;
export type SpreadingModel = (typeof SPREADING_MODELS)[number];

/** Most FFT cascades a sea can have. */
export const MAX_CASCADES = 4;

export interface SimulationParameters {
  /** Spectrum model; 'tma' is JONSWAP attenuated for the finite `depth`. @defaultValue 'jonswap' */
  spectrum: SpectrumModel;
  /** Wind speed U10 at 10 m above the sea, m/s, [0, 60]. @defaultValue 10 */
  windSpeed: number;
  /** Direction the wind blows towards, degrees from +x towards +z. @defaultValue 30 */
  windDirection: number;
  /** Fetch, the distance the wind has blown over open water, km, (0, 100000]. @defaultValue 100 */
  fetch: number;
  /** JONSWAP peak enhancement γ, [1, 10] (1 is Pierson–Moskowitz's shape). @defaultValue 3.3 */
  peakEnhancement: number;
  /**
   * Directional spreading of the wind sea. The default was measured with a wave-staff array
   * (Donelan, Hamilton & Hui 1985), with Banner's (1990) extension that keeps short waves broadly
   * spread, so the surface does not look combed. @defaultValue 'donelan-banner'
   */
  spreading: SpreadingModel;
  /** Exponent s of the 'cos-2s' spreading, [0, 1000]. @defaultValue 10 */
  spreadingExponent: number;
  /** Significant height of a swell from far away, m, [0, 30]; 0 is none. @defaultValue 0 */
  swellHeight: number;
  /** Peak period of the swell, s, (0, 40]. @defaultValue 12 */
  swellPeriod: number;
  /** Direction the swell travels towards, degrees from +x towards +z. @defaultValue 60 */
  swellDirection: number;
  /** Horvath's swell elongation ξ, [0, 1]: how much longer the swell's crests are than the wind sea's. @defaultValue 0.5 */
  swellElongation: number;
  /** Phillips spectrum amplitude A, [0, 1] (the 'phillips' model only). @defaultValue 2e-6 */
  amplitude: number;
  /** Length ℓ in metres below which waves are suppressed by exp(−k²ℓ²), [0, 10]; 0 turns it off. @defaultValue 0.01 */
  smallWaveCutoff: number;
  /** Water depth in metres (> 0); Infinity is deep water. @defaultValue Infinity */
  depth: number;
  /** Samples per side of each cascade's patch, a power of two in [16, 1024]. @defaultValue 256 */
  resolution: number;
  /**
   * Sides of the cascades' square patches in metres, ascending, 1 to MAX_CASCADES of them, each at
   * least twice the one before (src/spectrum/cascadeBands.ts splits the spectrum between them).
   * @defaultValue [13.7, 79.3, 457]
   */
  patchSizes: number[];
  /** Seconds after which the sea repeats, at least (> 0, at most 100000). @defaultValue 200 */
  repeatPeriod: number;
  /** Horizontal displacement scale λ, [0, 4]: 0 is a plain height field, larger sharpens crests. @defaultValue 1 */
  choppiness: number;
  /** Seed of the random initial spectrum, an integer in [0, 2³² − 1]. @defaultValue 1 */
  seed: number;
  /**
   * Whitecap foam made where crests fold, as a multiple of the physical amount (src/layers/foamModel.ts:
   * none below Beaufort 3, then the coverage of Monahan & O'Muircheartaigh 1980), [0, 10]; 0 is none.
   * @defaultValue 1
   */
  foamAmount: number;
  /** Seconds over which whitecap foam fades to 1/e, [0.1, 30]. @defaultValue 3 */
  foamPersistence: number;
}

export function isPowerOfTwo(n: number): boolean {
  return Number.isInteger(n) && n > 0 && (n & (n - 1)) === 0;
}

/** The one table of rules, units and allowed values. Keys in the order docs and URLs list them. */
export const SIMULATION_OPTIONS: { readonly [K in keyof SimulationParameters]: OptionRule } = {
  spectrum: { type: 'choice', unit: '', allowed: `one of ${SPECTRUM_MODELS.join(', ')}`, check: oneOf(SPECTRUM_MODELS), choices: SPECTRUM_MODELS },
  windSpeed: { type: 'number', unit: 'm/s', allowed: 'a speed in m/s from 0 to 60', check: between(0, 60) },
  windDirection: { type: 'number', unit: '°', allowed: 'a finite angle in degrees (at most 1e6 in size)', check: finiteAngle },
  fetch: { type: 'number', unit: 'km', allowed: 'a distance in km > 0 and at most 100000', check: (v) => isNumber(v) && v > 0 && v <= 1e5 },
  peakEnhancement: { type: 'number', unit: '', allowed: 'a number from 1 to 10', check: between(1, 10) },
  spreading: { type: 'choice', unit: '', allowed: `one of ${SPREADING_MODELS.join(', ')}`, check: oneOf(SPREADING_MODELS), choices: SPREADING_MODELS },
  spreadingExponent: { type: 'number', unit: '', allowed: 'a number from 0 to 1000', check: between(0, 1000) },
  swellHeight: { type: 'number', unit: 'm', allowed: 'a height in metres from 0 to 30', check: between(0, 30) },
  swellPeriod: { type: 'number', unit: 's', allowed: 'a period in seconds > 0 and at most 40', check: (v) => isNumber(v) && v > 0 && v <= 40 },
  swellDirection: { type: 'number', unit: '°', allowed: 'a finite angle in degrees (at most 1e6 in size)', check: finiteAngle },
  swellElongation: { type: 'number', unit: '', allowed: 'a number from 0 to 1', check: between(0, 1) },
  amplitude: { type: 'number', unit: '', allowed: 'a number from 0 to 1', check: between(0, 1) },
  smallWaveCutoff: { type: 'number', unit: 'm', allowed: 'a length in metres from 0 to 10 (0 turns it off)', check: between(0, 10) },
  depth: { type: 'number', unit: 'm', allowed: 'a depth in metres > 0, or Infinity (written "deep") for deep water', check: (v) => isNumber(v) && v > 0 },
  resolution: {
    type: 'number',
    unit: '',
    allowed: 'a power of two from 16 to 1024',
    check: (v) => isNumber(v) && isPowerOfTwo(v) && v >= 16 && v <= 1024,
  },
  patchSizes: {
    type: 'numbers',
    unit: 'm',
    allowed: `1 to ${MAX_CASCADES} sizes in metres from 1 to 100000, ascending, each at least twice the one before`,
    check: (v) =>
      Array.isArray(v) &&
      v.length >= 1 &&
      v.length <= MAX_CASCADES &&
      v.every((size, i) => isNumber(size) && size >= 1 && size <= 1e5 && (i === 0 || size >= 2 * v[i - 1])),
  },
  repeatPeriod: { type: 'number', unit: 's', allowed: 'a number of seconds > 0 and at most 100000', check: (v) => isNumber(v) && v > 0 && v <= 1e5 },
  choppiness: { type: 'number', unit: '', allowed: 'a number from 0 to 4', check: between(0, 4) },
  seed: { type: 'number', unit: '', allowed: 'an integer from 0 to 4294967295', check: (v) => isNumber(v) && Number.isInteger(v) && v >= 0 && v <= 0xffffffff },
  foamAmount: { type: 'number', unit: '', allowed: 'a number from 0 to 10 (0 turns foam off)', check: between(0, 10) },
  foamPersistence: { type: 'number', unit: 's', allowed: 'a number of seconds from 0.1 to 30', check: between(0.1, 30) },
};

export const DEFAULT_PARAMETERS: Readonly<SimulationParameters> = Object.freeze({
  spectrum: 'jonswap',
  windSpeed: 10,
  windDirection: 30,
  fetch: 100,
  peakEnhancement: 3.3,
  spreading: 'donelan-banner',
  spreadingExponent: 10,
  swellHeight: 0,
  swellPeriod: 12,
  swellDirection: 60,
  swellElongation: 0.5,
  amplitude: 2e-6,
  smallWaveCutoff: 0.01,
  depth: Infinity,
  resolution: 256,
  // Ratios of about 5.8 that are not whole numbers: the patches never line up, so the sum does not
  // tile, and each cascade's band (cascadeBands.ts) sits well inside its grid.
  patchSizes: Object.freeze([13.7, 79.3, 457]) as unknown as number[],
  repeatPeriod: 200,
  choppiness: 1,
  seed: 1,
  foamAmount: 1,
  foamPersistence: 3,
} satisfies SimulationParameters);

/** Parameters that the cascades' spectra do not depend on (the surface's shader, the foam): changing them rebuilds nothing. */
export const SHADER_ONLY_PARAMETERS: readonly (keyof SimulationParameters)[] = ['choppiness', 'foamAmount', 'foamPersistence'];

/**
 * Merges `changes` over `base` and checks every value; throws a ParameterError naming the first bad
 * one, so a caller that catches it can keep running on `base`.
 */
export function validateParameters(
  changes: Partial<SimulationParameters>,
  base: Readonly<SimulationParameters> = DEFAULT_PARAMETERS,
): SimulationParameters {
  const merged = mergeOptions(SIMULATION_OPTIONS, changes, base);
  checkCombination(merged);
  return merged;
}

/** Checks what no single value shows: each cascade's band fits its grid, and its frequencies fit the phase table. */
function checkCombination(params: SimulationParameters): void {
  const ratio = maxPatchRatio(params.resolution);
  if (params.patchSizes.some((size, i) => i > 0 && size > ratio * params.patchSizes[i - 1])) {
    throw new ParameterError(
      'patchSizes',
      params.patchSizes,
      `sizes whose neighbours differ by at most ${ratio}× at resolution ${params.resolution} ` +
        '(cascadeBands.ts: the band boundary must lie inside both grids)',
    );
  }
  for (const band of cascadeBands(params.patchSizes, params.resolution)) {
    const period = cascadeRepeatPeriod(band, params);
    const fastestK = fastestModeInBand(band, params.resolution);
    const fastest = Math.round((angularFrequency(fastestK, params.depth) * period) / (2 * Math.PI));
    if (fastest > MAX_FREQUENCY_INDEX) {
      throw new ParameterError(
        'repeatPeriod',
        params.repeatPeriod,
        `shorter with resolution ${params.resolution} and patch ${band.patchSize} m at depth ${params.depth === Infinity ? 'deep' : `${params.depth} m`} ` +
          `(the fastest wave's frequency index would be ${fastest}, above ${MAX_FREQUENCY_INDEX})`,
      );
    }
  }
}

/**
 * Reads one simulation parameter as written in text (a URL, an attribute, a command line): see
 * parseOptionText. Throws a ParameterError that names it and quotes the text.
 */
export function parseParameterText<K extends keyof SimulationParameters>(key: K, text: string): SimulationParameters[K] {
  return parseOptionText(SIMULATION_OPTIONS, key, text) as SimulationParameters[K];
}
