// The analytic sky: skyRadiance(direction) is the linear-RGB radiance seen in a world direction
// (unit vector, y up). SkyEnvironment (src/render/skyEnvironment.ts) renders it into a cube map;
// scripts/make-skybox-faces.mjs is a JS port of this file's clear sky, cloudCover 0 (keep the two in
// step — the browser test tests/browser/sky/sky.spec.ts compares the shipped faces with this shader
// in many directions).
//
// Above the horizon, single scattering after Hoffman & Preetham, "Rendering Outdoor Light
// Scattering in Real Time" (GDC 2002), the model also behind three.js's Sky object: the
// in-scattered radiance along a view ray is
//   L = E_sun · T̄_sun · (τR·ΦR(γ) + τM·ΦM(γ)) / τ · (1 − e^(−τ·m_view)),   τ = τR + τM + τO
// where E_sun is the sun's irradiance above the atmosphere, γ the angle between the view and the
// sun, τR, τM the zenith optical depths of Rayleigh and Mie scattering and τO of ozone absorption,
// ΦR the Rayleigh phase function 3/(16π)(1 + cos²γ), ΦM the Henyey–Greenstein phase function
// (Mie), and m the relative air mass of Kasten & Young (1989).
// T̄_sun = (1 − e^(−τ·m_sun)) / (τ·m_sun) is the sunlight's transmittance averaged over an
// exponential atmosphere's scattering heights (scattering ∝ density, and the sun's optical depth
// to height h is τ·m_sun·e^(−h/H)); the sun disk itself gets the ground value e^(−τ·m_sun).
// Short rays (zenith, 1 − e^(−τ) ≈ τ) are blue because τR ∝ λ⁻⁴; long rays saturate
// (1 − e^(−τ) → 1) to the paler, brighter horizon haze; Mie scattering adds the glow around the
// sun; a low sun reddens everything through T̄_sun, and ozone, which absorbs orange and green
// (the Chappuis band), keeps the zenith blue when it does. One scale height per species, one
// transmittance per ray and no multiple scattering (so the zenith is darker than a real one) are
// the model's simplifications. It is physically flavoured, not a validated daylight model.
//
// The sun disk (0.8° across, limb-darkened, with a soft edge) has an artistic radiance of
// SKY_SUN_DISK_GAIN × E_sun·T_sun rather than the physical ~E_sun / 6.8e-5 sr: that would
// overflow half floats and turn every mip-filtered rough reflection into a firefly.
//
// Below the horizon is the ocean's depth, which refracted rays sample: the report models it as a
// very dark blue (skyDeepWaterColor). The sky, evaluated at the horizon for rays below it, fades
// into that colour over the 4° below the horizon, so reflections at grazing angles (which often
// point a little below the horizon on a rough sea) show no seam. The fade is geometric (linear in
// log radiance): even in perceived brightness, and blue from the start, where a linear mix of the
// warm-white haze with the dark blue passes through a band of muddy greys.

uniform vec3 skySunDirection;   // unit, y up; the direction towards the sun
uniform vec3 skySunColor;       // linear RGB colour of sunlight above the atmosphere
uniform float skySunIntensity;  // E_sun: scales sky and sun together
uniform vec3 skyDeepWaterColor; // linear RGB radiance of the deep water below the horizon
uniform float skyDaylight;      // the sky's light as a fraction of the day's (src/render/daylight.ts)
uniform float skyCloudCover;    // 0 clear … 1 overcast: the weight of the overcast sky below
uniform float skyOvercastZenith; // the overcast zenith's luminance per unit of E_sun (daylight.ts, Krochmann & Seidl 1974)
uniform float skyCloudSun;      // the direct sunlight the clouds let through (daylight.ts, Kasten & Czeplak 1980)

const float SKY_PI = 3.141592653589793;
// Zenith optical depths at sea level (β·H) for 680, 550 and 440 nm: Rayleigh β = (5.8, 13.5,
// 33.1)e-6 /m with H = 8 km, Mie β = 21e-6 /m with H = 1.2 km (Bruneton & Neyret, "Precomputed
// Atmospheric Scattering", 2008); their Mie anisotropy g = 0.8.
const vec3 SKY_RAYLEIGH_DEPTH = vec3(0.0464, 0.108, 0.2648);
const float SKY_MIE_DEPTH = 0.021;
const float SKY_MIE_G = 0.8;
// Ozone absorption β = (0.650, 1.881, 0.085)e-6 /m over its 15 km equivalent thickness (Bruneton,
// "A Qualitative and Quantitative Evaluation of 8 Clear Sky Models", 2017, and his reference code).
const vec3 SKY_OZONE_DEPTH = vec3(0.00975, 0.0282, 0.00128);
const float SKY_SUN_RADIUS = 0.00698;      // 0.4° (the real sun is 0.27°; a little larger reads better)
const float SKY_SUN_EDGE = 0.00175;        // the disk fades out over ±0.1° around its radius
const float SKY_SUN_DISK_GAIN = 40.0;
const float SKY_HORIZON_BLEND = 0.0698;    // sin 4°: the water colour is reached 4° below the horizon

// Relative optical air mass for a ray at sinElevation above the horizon (Kasten & Young 1989):
// 1 at the zenith, about 38 at the horizon. Rays below the horizon use the horizon's.
float skyAirMass(float sinElevation) {
  float s = clamp(sinElevation, 0.0, 1.0);
  float elevationDegrees = degrees(asin(s));
  return 1.0 / (s + 0.50572 * pow(elevationDegrees + 6.07995, -1.6364));
}

vec3 skyRadiance(vec3 direction) {
  vec3 d = normalize(direction);
  float skyWeight = smoothstep(-SKY_HORIZON_BLEND, 0.0, d.y);
  // The sun sets: below the horizon it lights the sky less and less, through twilight into the
  // night (src/render/daylight.ts), and the water with it.
  vec3 deepWater = skyDeepWaterColor * skyDaylight;
  if (skyWeight <= 0.0) return deepWater;
  vec3 sun = normalize(skySunDirection);
  vec3 depth = SKY_RAYLEIGH_DEPTH + SKY_MIE_DEPTH + SKY_OZONE_DEPTH; // extinction, τ

  vec3 sunIrradiance = skySunColor * skySunIntensity;
  vec3 sunDepth = depth * skyAirMass(sun.y);
  vec3 sunTransmittance = exp(-sunDepth);                             // to the ground: the disk
  vec3 scatteredTransmittance = (1.0 - sunTransmittance) / sunDepth;  // T̄_sun: to the scatterers
  sunIrradiance *= skyDaylight;

  // γ from the chord |d − sun| = 2 sin(γ/2), which stays accurate near the sun where acos does not.
  float gamma = 2.0 * asin(clamp(0.5 * distance(d, sun), 0.0, 1.0));
  float cosGamma = cos(gamma);
  float rayleighPhase = 3.0 / (16.0 * SKY_PI) * (1.0 + cosGamma * cosGamma);
  float g2 = SKY_MIE_G * SKY_MIE_G;
  float miePhase = (1.0 - g2) / (4.0 * SKY_PI * pow(1.0 + g2 - 2.0 * SKY_MIE_G * cosGamma, 1.5));

  vec3 scattering = (SKY_RAYLEIGH_DEPTH * rayleighPhase + SKY_MIE_DEPTH * miePhase) / depth;
  vec3 inScattered = sunIrradiance * scatteredTransmittance * scattering * (1.0 - exp(-depth * skyAirMass(d.y)));

  // Sun disk with limb darkening I(μ) = 1 − 0.6(1 − μ), hidden by the horizon.
  float r = min(gamma / SKY_SUN_RADIUS, 1.0);
  float limb = 1.0 - 0.6 * (1.0 - sqrt(1.0 - r * r));
  float disk = (1.0 - smoothstep(SKY_SUN_RADIUS - SKY_SUN_EDGE, SKY_SUN_RADIUS + SKY_SUN_EDGE, gamma)) * limb;
  disk *= smoothstep(-SKY_SUN_EDGE, SKY_SUN_EDGE, d.y);
  vec3 sky = inScattered + SKY_SUN_DISK_GAIN * skyCloudSun * disk * sunIrradiance * sunTransmittance;
  // Clouds: towards the CIE standard overcast sky (Moon & Spencer 1942), grey and the same in every
  // azimuth, L(θ) = L_z·(1 + 2·cos θ)/3 with θ from the zenith, three times brighter overhead than
  // at the horizon. The clear sky's own scattering, and its sun disk, fade under it.
  vec3 overcast = sunIrradiance * skyOvercastZenith * (1.0 + 2.0 * max(d.y, 0.0)) / 3.0;
  sky = mix(sky, overcast, skyCloudCover);

  if (skyWeight >= 1.0) return sky;
  const vec3 darkest = vec3(1e-6); // keeps log finite (a sky with the sun far below the horizon is 0)
  return exp(mix(log(max(deepWater, darkest)), log(max(sky, darkest)), skyWeight));
}
