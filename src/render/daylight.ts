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

/**
 * The direct sunlight left under a cloud cover c (0 clear to 1 overcast) as a fraction of the
 * clear sky's, from Kasten & Czeplak (1980), "Solar and terrestrial radiation dependent on the
 * amount and type of cloud", Solar Energy 24: 177–189, for N oktas (c = N/8): the global
 * irradiance G(c) = G(0)·(1 − 0.75·c^3.4) and its diffuse share D/G = 0.3 + 0.7·c², so the direct
 * beam B = G − D = G(0)·(1 − 0.75·c^3.4)·0.7·(1 − c²), and under a clear sky B(0) = 0.7·G(0):
 *   B(c)/B(0) = (1 − 0.75·c^3.4)·(1 − c²)   (1 clear, 0 overcast).
 */
export function cloudSunTransmittance(cloudCover: number): number {
  return (1 - 0.75 * cloudCover ** 3.4) * (1 - cloudCover * cloudCover);
}

/**
 * The CIE standard overcast sky (Moon & Spencer 1942, "Illumination from a non-uniform sky",
 * Illuminating Engineering 37: 707–726; CIE S 011/E:2003 sky type 16): the luminance at zenith
 * angle θ is L(θ) = L_z·(1 + 2·cos θ)/3, three times brighter at the zenith than at the horizon,
 * the same in every azimuth. Returned relative to L_z, for cos θ (the direction's y, ≥ 0).
 * shaders/sky/analyticSky.glsl draws the same law (skyOvercast); this is its reference for tests.
 */
export function overcastLuminance(cosZenith: number): number {
  return (1 + 2 * Math.max(cosZenith, 0)) / 3;
}

/**
 * The overcast sky's zenith luminance relative to the solar illuminance above the atmosphere, for
 * the sun at this elevation (degrees): Krochmann & Seidl (1974), "Quantitative data on daylight
 * for illuminating engineering", Lighting Research & Technology 6(3): 165–171, L_z = 123 +
 * 8600·sin h cd/m² (h the sun's elevation, 0 below the horizon, where the twilight of skyDaylight
 * takes over), over the solar illuminance constant of 128 klx (Darula, Kittler & Gueymard 2005,
 * "Reference luminous solar constant and solar luminance for illuminance calculations", Solar
 * Energy 79: 559–565; 133.8 klx there, 128 klx in the CIE's older figure), per steradian.
 */
export function overcastZenithLuminance(sunElevationDeg: number): number {
  return (123 + 8600 * Math.max(Math.sin((sunElevationDeg * Math.PI) / 180), 0)) / 128000;
}

/** What the sky's and the sun's light come to for a sun at this elevation (degrees) under this cloud cover: the sky's uniforms. */
export interface SkyLight {
  /** skyDaylight(elevation). */
  daylight: number;
  /** The direct sunlight: the fraction of the sun's disk above the horizon times what the clouds let through. */
  sunVisibility: number;
  /** overcastZenithLuminance(elevation). */
  overcastZenith: number;
  /** cloudSunTransmittance(cloudCover). */
  cloudSun: number;
}

export function skyLight(sunElevationDeg: number, cloudCover: number): SkyLight {
  const cloudSun = cloudSunTransmittance(cloudCover);
  return {
    daylight: skyDaylight(sunElevationDeg),
    sunVisibility: sunAboveHorizon(sunElevationDeg) * cloudSun,
    overcastZenith: overcastZenithLuminance(sunElevationDeg),
    cloudSun,
  };
}
