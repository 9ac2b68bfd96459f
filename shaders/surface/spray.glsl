// Spray and spindrift over a sea from Beaufort force 9 (src/render/beaufortAppearance.ts gives the
// values from the wind and cites the WMO scale: force 9 "spray may affect visibility", force 10
// "visibility affected", force 12 "the air is filled with foam and spray").
//
// The spray is a haze of extinction β (1/m) between the eye and the sea: what is d metres away
// keeps e^{−βd} of its contrast (Koschmieder's law; β = ln 20 / V for a visibility V, the WMO's
// meteorological optical range), the rest is the light the spray scatters, taken as the sky's at the
// horizon in the view's azimuth, so that the far sea fades into the horizon sky without a seam.
// Spindrift: a white veil, up to `spindrift` opaque, over the crests that stand highest (their
// crestHeight, seaLighting.glsl).

uniform float sprayExtinction;  // β, 1/m; 0 in clear air
uniform float spindrift;        // the veil's opacity on the highest crests

vec3 throughSpray(vec3 colour, vec3 fromEye, float heightAboveMean, vec3 horizonSky) {
  if (sprayExtinction <= 0.0) return colour;  // uniform: below force 9 nothing is computed
  float crest = crestHeight(heightAboveMean);
  colour = mix(colour, horizonSky, spindrift * crest * crest);
  return mix(horizonSky, colour, exp(-sprayExtinction * length(fromEye)));
}
