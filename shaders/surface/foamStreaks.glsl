// Foam streaks along the wind, from Beaufort force 7 (src/render/beaufortAppearance.ts gives the
// values from the wind and cites the WMO scale's descriptions): the whitecaps' foam (foam.glsl's
// coverage, calibrated to Monahan & O'Muircheartaigh 1980) drawn out downwind.
//
//   F_drawn(x) = (1/n)·Σ_i F(x − s_i·ŵ),  s_i = (i + ½)·L/n   the foam of the crests up to L upwind;
//   coverage   = (1 − s)·F + s·(1 + G)·F_drawn                  s the streaked share, G the gain.
// The mean of F_drawn is F's (shifted copies of a field have its mean): the streaks move foam
// downwind, and add s·G times the whitecaps' coverage, the old foam that outlives them.
// The foam's pattern is stretched E times along ŵ (streakPatternPoint), so its patches are lines.

uniform vec2 windAlong;          // ŵ, unit (x, z), the way the wind blows
uniform float streakShare;       // s, 0 below force 7
uniform float streakLength;      // L, m
uniform float streakElongation;  // E, ≥ 1
uniform float streakGain;        // G

#define STREAK_TAPS 6

// A rest point (m) in the streaked pattern's coordinates: its distance along the wind divided by E.
vec2 streakPatternPoint(vec2 rest) {
  float along = dot(rest, windAlong);
  return rest - (1.0 - 1.0 / streakElongation) * along * windAlong;
}

// The coverage with streaks, where the foam field (over the largest layer's patch, `patchSize` m,
// read at uv and at its blended copy's uv + copyOffset, waveLayers.glsl) is `foam` at the point.
float streakedFoam(sampler2D field, vec2 uv, vec2 blend, float patchSize, float foam) {
  if (streakShare <= 0.0) return foam;  // uniform: below force 7 no pixel pays for the taps
  vec2 upwind = -windAlong * streakLength / (float(STREAK_TAPS) * patchSize);
  float drawn = 0.0;
  for (int i = 0; i < STREAK_TAPS; i++) {
    vec2 at = uv + (float(i) + 0.5) * upwind;
    drawn += blendedFoam(blend, texture(field, at).r, texture(field, at + copyOffset).r);
  }
  return mix(foam, (1.0 + streakGain) * drawn / float(STREAK_TAPS), streakShare);
}

// Far away, where the coverage is the field's mean over the pixel (ocean.vert's vFoam): the mean of
// the streaked coverage, (1 + s·G)·F.
float streakedMeanFoam(float foam) {
  return (1.0 + streakShare * streakGain) * foam;
}
