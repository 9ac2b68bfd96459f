// Whitecap foam on the surface: the foam field (src/layers/whitecapFoam.ts) gives the fraction of
// the surface covered near a point; this draws it as patches of white water with that coverage.
//
// Detail: a fixed pattern p(x) in rest-point coordinates (so it travels with the water), roughly
// uniform in [0, 1]; the pixel is foam where p < coverage, so on average a fraction `coverage` of
// the area is white, in patches whose number and size grow with the coverage (sparse flecks on a
// young whitecap, solid white water on a broken crest). Far away, where a pixel spans many
// patches, the opacity is the coverage itself (the foam field's mip levels average it), so nothing
// shimmers.
//
// The pattern's octaves come from two textures computed once (src/render/foamPattern.ts, which
// defines the FOAM_* constants): the coarse octave's lattice and a tile of the finer ones. Both
// repeat within the pattern's period (FOAM_PATTERN_PERIOD there): the caller passes the rest point
// from the eye plus the eye's place modulo the period, numbers that float32 holds to the millimetre
// wherever the eye is.

// Coverage below which nothing shows (less than one pixel in 500 would be white): not drawn.
#define FOAM_VISIBLE 0.002

uniform sampler2D foamCoarseLattice;  // the coarse octave's lattice values, one texel a cell
uniform sampler2D foamFineTile;       // R: the finer octaves' weighted sum; G: the bubbles

// Smooth value noise from a lattice texture (one texel a cell) with one linear lookup: placing the
// point at floor(q) + smoothstep(fract(q)) within its cell makes the filter's linear weights the
// smoothstep weights f²(3 − 2f) of value noise (Quílez, "Improved texture interpolation",
// iquilezles.org/articles/texture). Level 0 only: the coarse cells stay several pixels wide as far
// as the pattern is drawn (foamOpacity).
float smoothLattice(sampler2D lattice, float cells, vec2 q) {
  vec2 cell = floor(q);
  vec2 f = q - cell;
  return textureLod(lattice, (cell + f * f * (3.0 - 2.0 * f) + 0.5) / cells, 0.0).r;
}

// The pattern at a rest point: (p, bubbles). p is the octaves' weighted sum (mean ½, deviation
// ≈ 0.13) stretched back over [0, 1] by smoothstep(0.2, 0.8, ·), so that p < c covers about a
// fraction c; the bubbles are a noise in [0, 1]. Called where every pixel runs (the fine tile's
// mip level and the caller's fwidth(p) need the neighbours' values).
vec2 foamPattern(vec2 restPoint) {
  float coarse = smoothLattice(foamCoarseLattice, FOAM_COARSE_CELLS, restPoint * FOAM_COARSE_CELLS_PER_METRE);
  vec2 fine = texture(foamFineTile, restPoint / FOAM_FINE_TILE).rg;
  return vec2(smoothstep(0.2, 0.8, FOAM_COARSE_WEIGHT * coarse + FOAM_FINE_WEIGHT * fine.r), fine.g);
}

// Metres of sea a pixel spans where the rest point changes by restPerPixelX/Y to the next pixel
// across and down (dFdx, dFdy): fwidth(restPoint)'s larger component.
float restFootprint(vec2 restPerPixelX, vec2 restPerPixelY) {
  vec2 footprint = abs(restPerPixelX) + abs(restPerPixelY);
  return max(footprint.x, footprint.y);
}

// How much of the pattern shows where a pixel spans `footprint` metres (restFootprint): 1 near, 0
// where a pixel spans more than the pattern's finest cells, whose pattern would alias into speckle.
float foamPatternShown(float footprint) {
  return 1.0 - smoothstep(0.15, 0.6, footprint);
}

// The bubbles' mean opacity (foamOpacity's mix(0.65, 1, bubbles) over the bubbles' mean ½).
#define FOAM_MEAN_BUBBLES 0.825

// Opacity of the foam for a coverage in [0, 1], at a rest point whose pattern is `pattern`
// (foamPattern) and changes by `patternPerPixel` to the next pixel (fwidth): inside a patch,
// thinner and thicker bubbles (cells of 15 cm) let some water through. Where the pattern shows
// less (`detail`, foamPatternShown) it fades into `far`, the opacity of the foam seen from afar
// (foamCells.glsl's foamCellOpacity, whose mean is the coverage times FOAM_MEAN_BUBBLES).
float foamOpacity(float coverage, vec2 pattern, float patternPerPixel, float detail, float far) {
  if (detail <= 0.0) return far;
  // The patch's edge spread over about a pixel, so that it does not crawl as the sea moves.
  float softness = clamp(patternPerPixel, 0.04, 0.2);
  float bubbles = mix(0.65, 1.0, pattern.y);
  float detailed = bubbles * smoothstep(pattern.x - softness, pattern.x + softness, coverage);
  return mix(far, detailed, detail);
}

// Light leaving the foam: a white diffuse (Lambertian) surface of albedo 0.8 under the sky's light
// from above and the sun's; skyLight is the sky radiance seen along the normal.
vec3 foamRadiance(vec3 normal, vec3 sunDirection, vec3 sunRadiance, vec3 skyLight) {
  const float albedo = 0.8;
  return albedo * (skyLight + 0.08 * sunRadiance * max(dot(normal, sunDirection), 0.0));
}
