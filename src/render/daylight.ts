/**
 * How much light the sky and the sun still give as the sun sets, so that the sky, the sea and the
 * objects on it darken together (SkyEnvironment sets these as uniforms; SunLight scales its lights).
 *
 * Twilight: under a clear sky the horizontal illuminance falls from about 400 lx at sunset to
 * 3.4 lx at the end of civil twilight, the sun 6° below the horizon (AMS Glossary of Meteorology,
 * "civil twilight": ~585–410 lx to ~3.5–2 lx), that is by 10^(2.07/6) ≈ 0.345 decades per degree,
 * and it keeps falling as fast until the clear moonless night's 0.002 lx of airglow and starlight
 * (Schlyter, "Radiometry and photometry in astronomy", table of illuminances), 5e-6 of the sunset
 * value, reached at about −15°. Above the horizon the sky model itself dims and reddens a low sun
 * (its air mass), so this is 1 there.
 */

const TWILIGHT_DECADES_PER_DEGREE = Math.log10(400 / 3.4) / 6;
const NIGHT_OF_SUNSET = 0.002 / 400;
/** The sun disk's angular radius as the sky draws it (SKY_SUN_RADIUS in shaders/sky/analyticSky.glsl), degrees. */
const SUN_DISK_RADIUS_DEGREES = 0.4;

/** The sky's light (and so the light the sea scatters back) as a fraction of the day's, for a sun at this elevation (degrees). */
export function skyDaylight(sunElevationDeg: number): number {
  return Math.max(10 ** (TWILIGHT_DECADES_PER_DEGREE * Math.min(sunElevationDeg, 0)), NIGHT_OF_SUNSET);
}

/**
 * The fraction of the sun's disk above the horizon (smoothly, over its diameter): the direct
 * sunlight that makes the glint, the caustics and the sunny side of a buoy.
 */
export function sunAboveHorizon(sunElevationDeg: number): number {
  const t = Math.min(Math.max((sunElevationDeg + SUN_DISK_RADIUS_DEGREES) / (2 * SUN_DISK_RADIUS_DEGREES), 0), 1);
  return t * t * (3 - 2 * t);
}
