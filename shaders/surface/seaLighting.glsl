// The sea's light from the slopes a pixel's normal does not show (src/render/seaLighting.ts): the
// glint as a microfacet lobe of Gaussian slopes, the sky reflected by those slopes, and the sunlight
// through thin crests. Needs common/fresnel.glsl, sky/environmentLookup.glsl, surface/slopeTaps.glsl
// and LAYER_COUNT.

#define SEA_PI 3.141592653589793
// SLOPE_FILTER_LEVELS (seaLighting.ts) is a define.
uniform float unresolvedSlopeVariance;                                // σ²_CM(U) − Σ σ²_resolved
uniform float layerFilteredSlopes[LAYER_COUNT * SLOPE_FILTER_LEVELS];  // per layer and mip level
uniform float layerTexels[LAYER_COUNT];                               // metres
uniform float waveHeightRms;                                          // metres

// The pixel's footprint on the rest plane as log2 of metres: the larger of its two screen axes'
// steps, as texture() takes ρ (GLSL ES 3.00 §8.9) when ocean.frag reads the layers' derivatives:
// at footprint − log2(texel) in each (reading them with textureLod at that level gave the same
// band means under SwiftShader).
float footprintLevel(vec2 restPerPixelX, vec2 restPerPixelY) {
  return log2(max(max(length(restPerPixelX), length(restPerPixelY)), 1e-6));
}

// The mean square slope σ² of the surface within this pixel around its normal: the slopes finer
// than the grid, plus, for each layer, what the mip level its derivatives were read at averaged
// away (between two levels, as trilinear filtering mixes them).
float subPixelSlopeVariance(float footprint) {
  float variance = unresolvedSlopeVariance;
  for (int layer = 0; layer < LAYER_COUNT; layer++) {
    float level = clamp(footprint - log2(layerTexels[layer]), 0.0, float(SLOPE_FILTER_LEVELS - 1));
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
float sunGlint(vec3 view, vec3 normal, vec3 sun, float slopeVariance, float n1, float n2) {
  // A mirror (no wind) reflects the sun only where h = n exactly: the lobe stays finite.
  float variance = max(slopeVariance, 1e-6);
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

// A normal that faces away from the eye (behind a steep crest, or a facet of the slopes below) is
// bent back into view, to grazing.
vec3 facingEye(vec3 view, vec3 normal) {
  float facing = dot(view, normal);
  return facing > 0.0 ? normalize(normal - 1.01 * facing * view) : normal;
}

// The sky reflected by the pixel's facets: the mean of R(n)·L_sky(reflect(v, n)) over the
// Gaussian slopes around the pixel's normal. Each facet counts by its share of the rest plane, as
// the slopes the grid resolves do (a pixel's normal is read at its rest point, whichever way it
// faces), so that the light does not change where the grid stops resolving them; facets facing
// away are bent to grazing, as the pixel's own normal is (facingEye). The slopes have
// variance s² = σ²/2 along and across the view, averaged over by the taps of slopeTaps.glsl; with
// σ² = 0 the mirror's reflection. Returns the mean reflectance in `reflectance` and the reflected
// radiance it weights, so that reflectance·sky is the mean.
vec3 filteredSkyReflection(vec3 view, vec3 normal, float variance, float n1, float n2, out float reflectance) {
  vec3 across = cross(view, normal);
  across = dot(across, across) > 1e-8 ? normalize(across) : normalize(cross(vec3(1.0, 0.0, 0.0), normal));
  vec3 along = cross(normal, across);
  float s = sqrt(0.5 * variance);
  vec3 reflected = vec3(0.0);
  float weightedReflectance = 0.0;
  for (int i = 0; i < SLOPE_TAPS; i++) {
    vec3 tap = slopeTap(i);
    vec3 facet = facingEye(view, normalize(normal - s * (tap.x * along + tap.y * across)));
    float facetReflectance = fresnelReflectance(-dot(view, facet), n1, n2);
    vec3 direction = reflect(view, facet);
    direction.y = abs(direction.y);  // a ray reflected downwards would hit the next wave: mirror it
    reflected += tap.z * facetReflectance * environmentRadiance(direction);
    weightedReflectance += tap.z * facetReflectance;
  }
  reflectance = weightedReflectance;
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
#define SEA_CREST_GLOW 4.0
// How high a crest stands: its height above the mean over twice the sea's rms height, in [0, 1]
// (the crest glow here and the spindrift, spray.glsl).
float crestHeight(float heightAboveMean) {
  return clamp(heightAboveMean / (2.0 * max(waveHeightRms, 1e-3)), 0.0, 1.0);
}
vec3 crestGlow(vec3 view, vec3 normal, vec3 sun, float heightAboveMean, float reflectance, vec3 sunLight, vec3 scatter) {
  float crest = crestHeight(heightAboveMean);
  float forward = pow(max(dot(view, sun), 0.0), 4.0);
  float thin = pow(0.5 - 0.5 * dot(normal, sun), 3.0);
  return SEA_CREST_GLOW * crest * forward * thin * (1.0 - reflectance) * sunLight * scatter;
}
