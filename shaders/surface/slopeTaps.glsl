// The taps that average over a pixel's sub-pixel slopes, Gaussian with variance s² along and across
// the plane of incidence (seaLighting.glsl's filteredSkyReflection and sceneReflection.glsl's
// sceneReflectionSpreadCoverage). Along the plane, where the reflected light changes most (the
// reflected ray's height in the sky, the Fresnel factor, the bend of facets turned away from the
// eye), the 5-point Gauss–Hermite rule: nodes 0, ±1.3556·s, ±2.8570·s, weights 0.5333, 0.2221,
// 0.0113, exact to the 9th moment (Abramowitz & Stegun 25.4.46 and Table 25.10, scaled to a unit
// normal). Across it, the node 0 is split into ±s/√0.5333 (weights 0.2667 each), which keeps the
// second moment. Why five nodes along: the 3-point rule (exact to the 5th moment) is 0.04 low in
// the mean reflectance 8° above grazing at σ² ≈ 0.05 (the 5-point rule 0.02), which leaves a
// coarse grid's sea, whose slopes are mostly in these taps, 3.4 levels darker near the eye than a
// fine grid's (tests/browser/lighting).
#define SLOPE_TAPS 6

// Tap `tap` (0 … SLOPE_TAPS − 1): its offset in units of s along the plane of incidence (x) and
// across it (y), and its weight (z).
vec3 slopeTap(int tap) {
  float side = tap % 2 == 0 ? 1.0 : -1.0;
  int node = tap / 2;
  if (node == 0) return vec3(side * 1.3556262, 0.0, 0.2220759);
  if (node == 1) return vec3(side * 2.8569700, 0.0, 0.0112574);
  return vec3(0.0, side * 1.3693064, 0.2666667);
}
