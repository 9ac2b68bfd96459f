/**
 * What a strong wind adds to the sea's look beyond its waves and whitecaps, from the WMO Beaufort
 * scale's descriptions of the sea (WMO-No. 306 / WMO-No. 558, as the Met Office's "Beaufort wind
 * force scale" gives them):
 *   force 7  (13.9–17.1 m/s) "foam from breaking waves begins to be blown in streaks along the
 *            direction of the wind";
 *   force 8  (17.2–20.7) "foam is blown in well-marked streaks along the direction of the wind";
 *   force 9  (20.8–24.4) "dense streaks of foam along the direction of the wind … spray may affect
 *            visibility";
 *   force 10 (24.5–28.4) "on the whole the surface of the sea takes on a white appearance … visibility
 *            affected";
 *   force 12 (≥ 32.7) "the air is filled with foam and spray; sea completely white with driving
 *            spray; visibility very seriously affected".
 * The scale gives words, not numbers: the ramps below start where the descriptions start and are
 * full where they say the sea is white; their slopes are choices of look, stated as such.
 *
 * Streaks (shaders/surface/foamStreaks.glsl): the whitecaps' own foam (foamModel.ts, calibrated to
 * Monahan & O'Muircheartaigh 1980, unchanged) drawn out downwind. The share s(U) of the foam that is
 * streaked rises linearly from 0 at the bottom of force 7 to 1 at the bottom of force 10. A streak
 * is the foam of the crests up to STREAK_LENGTH·s upwind, averaged (an average of shifted copies
 * of a field has the field's mean, so drawing out moves foam, it makes none); its pattern is
 * stretched 1 + (STREAK_ELONGATION − 1)·s times along the wind. Streak foam is old foam that the
 * wind has spread thin, which outlives the whitecap it came from: it adds STREAK_GAIN·s times the
 * whitecaps' coverage, so that at force 10 most of the sea is white.
 *
 * Spray (shaders/surface/spray.glsl): from the bottom of force 9 the air over the sea carries spray,
 * which shortens the visibility V(U) = SPRAY_VISIBILITY_AT_FORCE_12 / σ², with σ = (U − 20.8) /
 * (32.7 − 20.8) the wind's place between the bottom of force 9 and of force 12 (V ≈ 44 km in the
 * middle of force 9, 4.5 km at force 10, 1.5 km at force 11, 1 km at the bottom of force 12). The
 * extinction follows from V as the meteorological optical range defines it (WMO-No. 8, "Guide to
 * Instruments and Methods of Observation", vol. I ch. 9: the distance over which a beam's contrast
 * falls to 5 %): β = ln 20 / V = 2.996 / V. Over the crests, spindrift: a white veil of opacity
 * SPINDRIFT_OPACITY·min(σ, 1) on the highest waves.
 */
import { BEAUFORT_WIND_RANGES } from '../spectrum/presets';

/** Wind at which foam first streaks: the bottom of force 7, m/s. */
export const STREAK_ONSET_WIND = BEAUFORT_WIND_RANGES[7][0];
/** Wind at which all foam is streaked and the sea turns white: the bottom of force 10, m/s. */
export const STREAK_FULL_WIND = BEAUFORT_WIND_RANGES[10][0];
/** Wind at which spray begins: the bottom of force 9, m/s. */
export const SPRAY_ONSET_WIND = BEAUFORT_WIND_RANGES[9][0];
/** Wind of the spray's reference visibility: the bottom of force 12, m/s. */
export const SPRAY_FULL_WIND = BEAUFORT_WIND_RANGES[12][0];

/** How far upwind a fully streaked sea gathers its foam, m. */
export const STREAK_LENGTH = 40;
/** How many times the foam's pattern is stretched along the wind when fully streaked. */
export const STREAK_ELONGATION = 8;
/** Streak foam added, as a multiple of the whitecaps' coverage, when fully streaked. */
export const STREAK_GAIN = 1.5;
/** The visibility in spray at the bottom of force 12, m. */
export const SPRAY_VISIBILITY_AT_FORCE_12 = 1000;
/** The opacity of the spindrift over the highest crests at force 12. */
export const SPINDRIFT_OPACITY = 0.35;

/** The values the sea's shader takes for a wind (its uniforms of the same names). */
export interface BeaufortAppearance {
  /** Unit vector (x, z) the wind blows towards. */
  windAlong: [number, number];
  /** s(U): the share of the foam streaked, 0 … 1. */
  streakShare: number;
  /** How far upwind a streak gathers foam, m. */
  streakLength: number;
  /** How many times the foam's pattern is stretched along the wind (1: not). */
  streakElongation: number;
  /** The coverage a streak adds, as a multiple of the foam it is drawn from. */
  streakGain: number;
  /** β, the spray's extinction, 1/m (0: clear air). */
  sprayExtinction: number;
  /** The spindrift's opacity on the highest crests. */
  spindrift: number;
}

const ramp = (value: number, start: number, end: number): number => Math.min(1, Math.max(0, (value - start) / (end - start)));

/** The streaks' and the spray's values for a wind of `windSpeed` m/s at 10 m blowing towards `windDirection`° (from +x towards +z). */
export function beaufortAppearance(windSpeed: number, windDirection: number): BeaufortAppearance {
  const share = ramp(windSpeed, STREAK_ONSET_WIND, STREAK_FULL_WIND);
  const spray = Math.max(0, (windSpeed - SPRAY_ONSET_WIND) / (SPRAY_FULL_WIND - SPRAY_ONSET_WIND));
  const angle = (windDirection * Math.PI) / 180;
  return {
    windAlong: [Math.cos(angle), Math.sin(angle)],
    streakShare: share,
    streakLength: STREAK_LENGTH * share,
    streakElongation: 1 + (STREAK_ELONGATION - 1) * share,
    streakGain: STREAK_GAIN,
    sprayExtinction: spray > 0 ? (Math.log(20) * spray * spray) / SPRAY_VISIBILITY_AT_FORCE_12 : 0,
    spindrift: SPINDRIFT_OPACITY * Math.min(spray, 1),
  };
}

/** The meteorological optical range in the spray, m (Infinity in clear air): ln 20 / β. */
export function sprayVisibility(windSpeed: number): number {
  const { sprayExtinction } = beaufortAppearance(windSpeed, 0);
  return sprayExtinction > 0 ? Math.log(20) / sprayExtinction : Infinity;
}
