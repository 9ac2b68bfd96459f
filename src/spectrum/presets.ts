/**
 * Named sea states, and the Beaufort scale as sea states.
 *
 * Beaufort forces: the wind-speed ranges at 10 m of the WMO Beaufort scale table (as reproduced in
 * WMO-No. 558, "Manual on Marine Meteorological Services"), in m/s:
 *   0: 0–0.2   1: 0.3–1.5   2: 1.6–3.3   3: 3.4–5.4   4: 5.5–7.9   5: 8.0–10.7   6: 10.8–13.8
 *   7: 13.9–17.1   8: 17.2–20.7   9: 20.8–24.4   10: 24.5–28.4   11: 28.5–32.6   12: ≥ 32.7
 * The same table gives the "probable wave height" in the open sea (m): –, 0.1, 0.2, 0.6, 1, 2, 3,
 * 4, 5.5, 7, 9, 11.5, 14 for forces 0–12 (tests/unit/presets.test.ts compares with it).
 */
import { DEFAULT_PARAMETERS, type SimulationParameters } from '../parameters/parameters';
import { GRAVITY } from './dispersion';
import { SEA_STATE_KEYS, windSeaPeakFrequency } from './seaState';
import { ParameterError } from '../parameters/options';

/** [lowest, highest] wind speed of each Beaufort force, m/s (WMO, above). */
export const BEAUFORT_WIND_RANGES: readonly (readonly [number, number])[] = [
  [0, 0.2],
  [0.3, 1.5],
  [1.6, 3.3],
  [3.4, 5.4],
  [5.5, 7.9],
  [8.0, 10.7],
  [10.8, 13.8],
  [13.9, 17.1],
  [17.2, 20.7],
  [20.8, 24.4],
  [24.5, 28.4],
  [28.5, 32.6],
  // Force 12 has no upper bound; 36.8 m/s makes its middle one force-11 width (4.1 m/s) above 32.7.
  [32.7, 36.8],
];

/**
 * Fetch of the Beaufort sea states, km. An open-ocean wind field is a few hundred km across, and a
 * wind that blows over it is fetch-limited long before it could reach Pierson-Moskowitz's fully
 * developed sea (which, at 12 m/s, takes ≈ 250 km; at force 12, ≈ 2 400 km). With unlimited fetch
 * PM's Hs = 0.21·U19.5²/g is twice the WMO probable height at force 12 (28 m vs 14 m); with 500 km
 * JONSWAP the light winds are fully developed (the fetch law is capped there) and the gales are not.
 */
export const BEAUFORT_FETCH_KM = 500;

/** Wind speed at the middle of a Beaufort force's range, m/s. */
export function beaufortWindSpeed(force: number): number {
  if (!(Number.isInteger(force) && force >= 0 && force <= 12)) {
    throw new ParameterError('Beaufort force', force, 'an integer from 0 to 12');
  }
  const [low, high] = BEAUFORT_WIND_RANGES[force];
  return (low + high) / 2;
}

/**
 * A whole sea state: `changes` over the default sea state (every sea-state parameter is set, so a
 * preset gives the same sea whatever was set before), with cascade patch sizes that follow its
 * longest waves: the largest patch 7.6 peak wavelengths (the default sea's 457 m at λp = 60 m), so
 * the low-frequency flank of the spectrum (down to half the peak frequency, a quarter of its k) is
 * simulated, in [50, 5000] m; the others each 5.77 times smaller, as the defaults, three of them,
 * or four when the third would be over 20 m (then the finest waves near the eye are still there).
 */
function seaPreset(changes: Partial<SimulationParameters>): Partial<SimulationParameters> {
  const sea = { ...DEFAULT_PARAMETERS, ...SEA_STATE_DEFAULTS, ...changes };
  const periods = [sea.windSpeed > 0 ? (2 * Math.PI) / windSeaPeakFrequency(sea) : 0, sea.swellHeight > 0 ? sea.swellPeriod : 0];
  const peakWavelength = (GRAVITY * Math.max(...periods) ** 2) / (2 * Math.PI); // deep water, λ = gT²/2π
  const largest = Math.min(5000, Math.max(50, 7.6 * peakWavelength));
  const count = largest / 5.77 ** 2 > 20 ? 4 : 3;
  const patchSizes = Array.from({ length: count }, (_, i) => Number((largest / 5.77 ** (count - 1 - i)).toPrecision(3)));
  return { ...SEA_STATE_DEFAULTS, ...changes, patchSizes };
}

/** Every sea-state parameter at its default: what a preset does not set. */
const SEA_STATE_DEFAULTS: Partial<SimulationParameters> = Object.fromEntries(
  SEA_STATE_KEYS.map((key) => [key, DEFAULT_PARAMETERS[key]]),
);

/** The Beaufort force from which a preset's sky is overcast (presetCloudCover): force 8, a gale. */
export const OVERCAST_FROM_FORCE = 8;

/**
 * The cloud cover (SunOptions.cloudCover, a sun option, so not part of the preset itself, which
 * Ocean.setParameters takes) that the app shows with a preset: overcast, 1, from a gale (force 8,
 * 17.2 m/s) up, else clear, 0. Not a law of the sea: gales blow round deep depressions, whose
 * fronts and cloud shields usually cover the sky, and a storm under a clear blue sky does not read
 * as one (issue 26). Users of the library can pair them the same way:
 *   ocean.setParameters(SEA_PRESETS.storm); ocean.setSun({ cloudCover: presetCloudCover(SEA_PRESETS.storm) });
 */
export function presetCloudCover(preset: Partial<SimulationParameters>): number {
  return (preset.windSpeed ?? DEFAULT_PARAMETERS.windSpeed) >= BEAUFORT_WIND_RANGES[OVERCAST_FROM_FORCE][0] ? 1 : 0;
}

/** A JONSWAP sea for a Beaufort force: the middle of its wind range, blowing over 500 km. */
export function beaufortPreset(force: number): Partial<SimulationParameters> {
  return seaPreset({ spectrum: 'jonswap', windSpeed: beaufortWindSpeed(force), fetch: BEAUFORT_FETCH_KM });
}

/** Named sea states. */
export const SEA_PRESETS: Readonly<Record<string, Partial<SimulationParameters>>> = Object.freeze({
  /** Beaufort 2, a light breeze over a long fetch: small wavelets. */
  calm: seaPreset({ spectrum: 'jonswap', windSpeed: 3, fetch: 500 }),
  /** Beaufort 4–5 over 100 km: moderate waves with some white horses. */
  breeze: seaPreset({ spectrum: 'jonswap', windSpeed: 8, fetch: 100 }),
  /** Beaufort 10, a storm over 500 km: fetch-limited JONSWAP, high waves. */
  storm: seaPreset({ spectrum: 'jonswap', windSpeed: 25, fetch: 500 }),
  /** A light wind sea on a 2.5 m, 14 s ocean swell from another direction, strongly elongated. */
  'long swell': seaPreset({ spectrum: 'jonswap', windSpeed: 4, fetch: 50, swellHeight: 2.5, swellPeriod: 14, swellDirection: 75, swellElongation: 1 }),
  /** A bay 5 m deep with a 5 km fetch: TMA, short steep waves in finite depth. */
  'shallow bay': seaPreset({ spectrum: 'tma', windSpeed: 12, fetch: 5, depth: 5 }),
});
