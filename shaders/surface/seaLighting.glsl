// The sea's light from the slopes a pixel's normal does not show (src/render/seaLighting.ts): the
// glint as a microfacet lobe of Gaussian slopes, the sky reflected by those slopes, and the sunlight
// through thin crests. Needs common/fresnel.glsl, sky/environmentLookup.glsl and LAYER_COUNT.

#define SEA_PI 3.141592653589793
// SLOPE_FILTER_LEVELS (seaLighting.ts) is a define.
uniform float unresolvedSlopeVariance;                                // σ²_CM(U) − Σ σ²_resolved
uniform float layerFilteredSlopes[LAYER_COUNT * SLOPE_FILTER_LEVELS];  // per layer and mip level
uniform float layerTexels[LAYER_COUNT];                               // metres
uniform float waveHeightRms;                                          // metres

// The mean square slope σ² of the surface within this pixel around its normal: the slopes finer
// than the grid, plus, for each layer, what the mip level its derivatives were read at averaged
// away. The level is the one texture() took (GLSL ES 3.00 §8.9: λ = log2 ρ, ρ the larger of the
// two screen axes' texel steps), from the rest point's change to the next pixel (metres) over the
// layer's texel; between two levels, as trilinear filtering mixes them.
float subPixelSlopeVariance(vec2 restPerPixelX, vec2 restPerPixelY) {
  float footprint = max(length(restPerPixelX), length(restPerPixelY));
  float variance = unresolvedSlopeVariance;
  for (int layer = 0; layer < LAYER_COUNT; layer++) {
    float level = clamp(log2(max(footprint / layerTexels[layer], 1e-6)), 0.0, float(SLOPE_FILTER_LEVELS - 1));
    int below = int(level);
    int above = min(below + 1, SLOPE_FILTER_LEVELS - 1);
    int row = layer * SLOPE_FILTER_LEVELS;
    variance += mix(layerFilteredSlopes[row + below], layerFilteredSlopes[row + above], level - float(below));
  }
  return variance;
}

// Smith's shadowing of Gaussian slopes, Λ(μ) ≈ e^(−ν²) / (2ν√π), ν = μ / (σ_d·√(2(1 − μ²))), σ_d² the
// slope variance along the direction's azimuth (σ²/2 for isotropic slopes), after Bruneton et al.
// (2010), eq. 6, in their code's approximate form (exact within a few per cent where it matters,
// ν > 0.5).
float smithLambda(float cosTheta, float variance) {
  float c = clamp(cosTheta, 1e-4, 0.9999);
  float nu = c / sqrt((1.0 - c * c) * variance);
  return exp(-nu * nu) / (2.0 * nu * sqrt(SEA_PI));
}

// The sun's light reflected towards the eye per unit of the sun's irradiance E (on a plane facing
// it): Cox & Munk (1954) and Bruneton et al. (2010), eq. 8,
//   L / E = F(v·h)·p(ζ_h) / (4·cos θv·cos⁴ θh·(1 + Λ(v) + Λ(l))),
// with h the half vector, θh its angle from the pixel's normal, ζ_h = tan θh its slope and p the
// isotropic Gaussian density of slopes of mean square σ²: p(ζ) = exp(−|ζ|²/σ²) / (π·σ²).
float sunGlint(vec3 view, vec3 normal, vec3 sun, float variance, float n1, float n2) {
  vec3 toEye = -view;
  float cosView = dot(toEye, normal);
  float cosSun = dot(sun, normal);
  if (cosView <= 0.0 || cosSun <= 0.0) return 0.0;
  vec3 halfway = normalize(toEye + sun);
  float cosHalf = dot(halfway, normal);
  float cos2 = cosHalf * cosHalf;
  float density = exp(-(1.0 - cos2) / (cos2 * variance)) / (SEA_PI * variance);
  float shadowing = 1.0 + smithLambda(cosView, 0.5 * variance) + smithLambda(cosSun, 0.5 * variance);
  return fresnelReflectance(dot(toEye, halfway), n1, n2) * density / (4.0 * cosView * cos2 * cos2 * shadowing);
}

// The sky reflected by the pixel's facets: the mean of R(n)·L_sky(reflect(v, n)) over the
// Gaussian slopes around the pixel's normal, each facet weighted by the area it shows the eye,
// max(0, −v·n) / (n·N) (the visible normals' distribution: Heitz 2014, "Understanding the
// masking-shadowing function in microfacet-based BRDFs", JCGT 3(2), eq. 2). The mean over slopes
// of variance s² = σ²/2 per axis is taken by the 4-point cross rule, nodes (±√2·s, 0) and (0, ±√2·s)
// of weight ¼ (its second moments are the Gaussian's and its odd ones vanish, as the Gaussian's
// do), along and across the view. Returns the
// mean reflectance in `reflectance` and the reflected radiance it weights, so that reflectance·sky
// is the mean; with σ² = 0 it is the mirror's reflection.
vec3 filteredSkyReflection(vec3 view, vec3 normal, float variance, float n1, float n2, out float reflectance) {
  vec3 across = cross(view, normal);
  across = dot(across, across) > 1e-8 ? normalize(across) : normalize(cross(vec3(1.0, 0.0, 0.0), normal));
  vec3 along = cross(normal, across);
  float node = sqrt(variance);  // √2·s
  vec3 reflected = vec3(0.0);
  float weightedReflectance = 0.0;
  float shown = 0.0;
  for (int tap = 0; tap < 4; tap++) {
    float side = tap % 2 == 0 ? 1.0 : -1.0;
    vec3 tilt = tap < 2 ? along : across;
    vec3 facet = normalize(normal - side * node * tilt);
    float area = max(-dot(view, facet), 0.0) / dot(facet, normal);
    float facetReflectance = fresnelReflectance(-dot(view, facet), n1, n2);
    vec3 direction = reflect(view, facet);
    direction.y = abs(direction.y);  // a ray reflected downwards would hit the next wave: mirror it
    reflected += area * facetReflectance * environmentRadiance(direction);
    weightedReflectance += area * facetReflectance;
    shown += area;
  }
  reflectance = weightedReflectance / max(shown, 1e-6);
  return reflected / max(weightedReflectance, 1e-6);
}

// Sunlight through the thin tops of the waves, seen against the sun (subsurface scattering), after
// Mihelich & Tcheblokov, "Wakes, Explosions and Lighting: Interactive Water Simulation in Atlas"
// (GDC 2019): it grows with the crest's height above the mean (here in units of twice the sea's rms
// height, where the thin tops are), with the forward scattering towards an eye that looks at the
// sun, (d·l)⁴, and with the facet turning away from the sun, ((1 − n·l)/2)³, where the light crosses
// the least water; it leaves the water through the surface (1 − R) in the colour the water scatters.
// SEA_CREST_GLOW: how much of the sun's irradiance such a crest sends back, set by eye against
// photographs of backlit swell (a tuning, not a measured value).
#define SEA_CREST_GLOW 2.0
vec3 crestGlow(vec3 view, vec3 normal, vec3 sun, float heightAboveMean, float reflectance, vec3 sunLight, vec3 scatter) {
  float crest = clamp(heightAboveMean / (2.0 * max(waveHeightRms, 1e-3)), 0.0, 1.0);
  float forward = pow(max(dot(view, sun), 0.0), 4.0);
  float thin = pow(0.5 - 0.5 * dot(normal, sun), 3.0);
  return SEA_CREST_GLOW * crest * forward * thin * (1.0 - reflectance) * sunLight * scatter;
}
