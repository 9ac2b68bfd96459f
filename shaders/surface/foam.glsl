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
// The pattern repeats every FOAM_PATTERN_PERIOD metres (each octave's cells fit a whole number of
// times into it), so that it can be evaluated at the rest point's place within a period: the
// caller passes the rest point from the eye plus the eye's place modulo the period, numbers that
// float32 holds to the millimetre wherever the eye is.
#define FOAM_PATTERN_PERIOD 1000.0  // metres (OceanMaterial's FOAM_PATTERN_PERIOD)

// Coverage below which nothing shows (less than one pixel in 500 would be white): not drawn.
#define FOAM_VISIBLE 0.002

uint foamHash(uvec2 cell) {
  // A 2D integer hash (PCG-style mixing): no sin(), so no loss of precision far from the origin.
  uint h = cell.x * 747796405u + cell.y * 2891336453u;
  h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
  return (h >> 22u) ^ h;
}

// Value noise in [0, 1], smooth between the corners of unit cells, of the point p·cellsPerMetre +
// shift: periodic, with FOAM_PATTERN_PERIOD·cellsPerMetre cells (a whole number) per period.
// Returns (value, ∂value/∂x, ∂value/∂z), the gradient per metre of p.
vec3 foamValueNoise(vec2 p, float cellsPerMetre, float shift) {
  vec2 q = p * cellsPerMetre + shift;
  vec2 cell = floor(q);
  vec2 f = q - cell;
  vec2 w = f * f * (3.0 - 2.0 * f);
  uint period = uint(round(FOAM_PATTERN_PERIOD * cellsPerMetre));
  uvec2 c = uvec2(ivec2(mod(cell, float(period))));
  uvec2 next = (c + 1u) % period;
  float a = float(foamHash(c)) / 4294967295.0;
  float b = float(foamHash(uvec2(next.x, c.y))) / 4294967295.0;
  float d = float(foamHash(uvec2(c.x, next.y))) / 4294967295.0;
  float e = float(foamHash(next)) / 4294967295.0;
  // value = a + (b − a)·w.x + (d − a)·w.y + (a − b − d + e)·w.x·w.y, with dw/dq = 6f(1 − f).
  float twist = a - b - d + e;
  vec2 slope = 6.0 * f * (1.0 - f) * cellsPerMetre;
  return vec3(mix(mix(a, b, w.x), mix(d, e, w.x), w.y), slope * vec2(b - a + twist * w.y, d - a + twist * w.x));
}

// The pattern: three octaves (cells of 2.5 m, 0.9 m and 0.3 m), their sum's near-normal spread
// (mean ½, deviation ≈ 0.13) stretched back over [0, 1] so that p < c covers about a fraction c.
// Returns (pattern, its gradient per metre).
vec3 foamPattern(vec2 restPoint) {
  vec3 sum = 0.55 * foamValueNoise(restPoint, 0.4, 0.0) + 0.3 * foamValueNoise(restPoint, 1.1, 17.0) +
             0.15 * foamValueNoise(restPoint, 3.3, -31.0);
  // smoothstep(0.2, 0.8, sum), and its slope 6t(1 − t)/0.6
  float t = clamp((sum.x - 0.2) / 0.6, 0.0, 1.0);
  return vec3(t * t * (3.0 - 2.0 * t), sum.yz * (6.0 * t * (1.0 - t) / 0.6));
}

// Opacity of the foam at a rest point (within a pattern period, see above), for a coverage in
// [0, 1]: inside a patch, thinner and thicker bubbles (cells of 15 cm) let some water through.
// Where a pixel spans more than the pattern's finest cells the pattern would alias into speckle: it
// fades into its average there, the coverage times the bubbles' mean opacity. restPerPixelX/Y are
// the rest point's change to the next pixel across and down (dFdx, dFdy), which the caller takes
// where every pixel runs: this runs only where there is foam, a branch in which derivatives are
// undefined (GLSL ES 3.00 §8.9), so the pattern's own change across a pixel is its gradient times
// them, not fwidth().
float foamOpacity(float coverage, vec2 restPoint, vec2 restPerPixelX, vec2 restPerPixelY) {
  const float meanBubbles = 0.825;
  vec2 footprint = abs(restPerPixelX) + abs(restPerPixelY);  // fwidth(restPoint): metres per pixel on the sea
  float detail = 1.0 - smoothstep(0.15, 0.6, max(footprint.x, footprint.y));
  if (detail <= 0.0) return meanBubbles * coverage;
  vec3 pattern = foamPattern(restPoint);
  float softness = clamp(abs(dot(pattern.yz, restPerPixelX)) + abs(dot(pattern.yz, restPerPixelY)), 0.04, 0.2);
  float bubbles = mix(0.65, 1.0, foamValueNoise(restPoint, 6.7, 5.0).x);
  float detailed = bubbles * smoothstep(pattern.x - softness, pattern.x + softness, coverage);
  return mix(meanBubbles * coverage, detailed, detail);
}

// Light leaving the foam: a white diffuse (Lambertian) surface of albedo 0.8 under the sky's light
// from above and the sun's; skyLight is the sky radiance seen along the normal.
vec3 foamRadiance(vec3 normal, vec3 sunDirection, vec3 sunRadiance, vec3 skyLight) {
  const float albedo = 0.8;
  return albedo * (skyLight + 0.08 * sunRadiance * max(dot(normal, sunDirection), 0.0));
}
