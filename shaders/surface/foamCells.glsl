// Whitecaps seen from afar: where a pixel spans more sea than the foam's pattern can show
// (foam.glsl's foamPatternShown) and the sea is seen from above (foamCellOpacity says where), the
// coverage W the foam field gives is drawn as whole white cells, not as a veil of opacity W over
// every pixel. From 1 km straight down a veil of 1 %
// lifts the whole picture by about 2.5 levels and no pixel looks like a whitecap; a photograph shows
// bright specks on dark water instead.
//
// The sea is cut into square cells a few pixel footprints wide (FOAM_CELL_FOOTPRINTS), fixed on the
// rest plane (so they stay where they are from frame to frame and as the eye turns), each with a
// value u uniform in (0, 1) from a hash of its place; a cell is white where u < W. Over many cells
// the white share is E[W], the foam model's coverage (Monahan & O'Muircheartaigh 1980, through
// src/layers/foamModel.ts), and each white cell is as bright as foam close up. The edge u·(1 ± 0.1)
// fades a cell in and out as the coverage over it rises and falls, instead of switching it in one
// frame.
//
// Cell sizes are FOAM_PATTERN_PERIOD / 2^j (src/render/foamPattern.ts), so that the cells repeat
// with the pattern's period (the caller's rest point is taken modulo it); of the two sizes nearest
// to FOAM_CELL_FOOTPRINTS footprints, a share of the coarser cells that grows as the footprint
// shrinks splits into the finer. FOAM_CELL_LARGEST is a limit chosen for the picture, not a
// measured whitecap size: beyond it (towards the horizon, where a pixel spans hundreds of metres)
// the average stays, not white blocks as wide. It is large enough for the coarsest quality level
// (render scale 0.3) seen straight down from 1 km, where a pixel spans about 13 m at 480x270.
//
// Whether the cells show does not depend on the foam field's texel: on a coarse grid (quality
// 'low', 64² over 457 m) the field's texels are 7 m wide and hold a low coverage spread over them,
// which drawn as a veil left no whitecap visible from 1 km (none at 'lowest', against the 1 %
// Monahan gives at 10 m/s); as cells it is about the same share of white pixels at every level.
//
// Hash: pcg2d of Jarzynski & Olano (2020), "Hash Functions for GPU Rendering", Journal of Computer
// Graphics Techniques 9(3): 21–38.

#define FOAM_CELL_FOOTPRINTS 2.5  // a cell's side in pixel footprints, give or take a factor √2
#define FOAM_CELL_LARGEST 40.0    // metres: larger cells fade into the average coverage (up to twice this)
#define FOAM_CELL_GRAZING 0.6     // below this isotropy (sin of the angle below the horizon) no cells; all from 0.2 more

uvec2 pcg2d(uvec2 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * 1664525u;
  v.y += v.x * 1664525u;
  v ^= v >> 16u;
  v.x += v.y * 1664525u;
  v.y += v.x * 1664525u;
  v ^= v >> 16u;
  return v;
}

// The cell of 2^−j periods' side that holds `restPoint`: its hash (pcg2d of its place and j).
uvec2 foamCellHash(vec2 restPoint, int j) {
  int cells = 1 << j;  // cells a side in one period
  ivec2 cell = ivec2(floor(restPoint * (float(cells) / FOAM_PATTERN_PERIOD))) & (cells - 1);
  return pcg2d(uvec2(cell) + uvec2(0u, uint(j) << 16u));
}

// Bits of a hash as a number uniform in (0, 1): `bits` of them from `shift` up.
float foamCellUniform(uint hashed, uint shift, uint bits) {
  uint mask = (1u << bits) - 1u;
  return (float((hashed >> shift) & mask) + 0.5) / float(mask + 1u);
}

// The foam's opacity where its pattern is not drawn, for a coverage W at a rest point (modulo
// FOAM_PATTERN_PERIOD) that changes by restPerPixelX/Y to the next pixel across and down: white
// cells of mean opacity `opacity` covering a share W of the sea as the pattern fades out (where a
// pixel spans tens of centimetres). The veil opacity·W stays where the cells would be larger than
// FOAM_CELL_LARGEST, and where the sea is seen at a grazing angle: there a square cell a few pixels
// long along the view is side/long as many times wider across it (the sin of the angle below the
// horizon), a bar rather than a speck.
//
// Between the two, and between two cell sizes, a share of the cells, not of their brightness,
// changes: each cell draws, from its hash, whether it is drawn as a cell or as veil, and a cell of
// the coarser size whether it splits into the four of the finer; the mean stays opacity·W
// everywhere and no cell is drawn half-bright (grey spots).
float foamCellOpacity(float coverage, vec2 restPoint, vec2 restPerPixelX, vec2 restPerPixelY, float opacity) {
  float veil = opacity * coverage;
  float footprint = restFootprint(restPerPixelX, restPerPixelY);
  float side = FOAM_CELL_FOOTPRINTS * footprint;
  // |det| / longest²: 1 seen straight down, sin(angle below the horizon) at grazing angles.
  float longest = max(dot(restPerPixelX, restPerPixelX), dot(restPerPixelY, restPerPixelY));
  float isotropy = abs(restPerPixelX.x * restPerPixelY.y - restPerPixelX.y * restPerPixelY.x) / max(longest, 1e-12);
  float cellShare = (1.0 - foamPatternShown(footprint)) *
                    (1.0 - smoothstep(FOAM_CELL_LARGEST, 2.0 * FOAM_CELL_LARGEST, side)) *
                    smoothstep(FOAM_CELL_GRAZING, FOAM_CELL_GRAZING + 0.2, isotropy);
  if (cellShare <= 0.0) return veil;
  // Cells of P/2^j are `side` wide at j = level: j the coarser of the two sizes (side … 2·side),
  // j + 1 the finer (side/2 … side), which takes over as the footprint shrinks.
  float level = clamp(log2(FOAM_PATTERN_PERIOD / side), 0.0, 20.0);
  int j = int(floor(level));
  uvec2 hashed = foamCellHash(restPoint, j);
  if (foamCellUniform(hashed.y, 0u, 16u) < level - float(j)) hashed = foamCellHash(restPoint, j + 1);
  float u = foamCellUniform(hashed.x, 8u, 24u);  // 24 bits, as many as float32 holds
  float white = smoothstep(0.9 * u, 1.1 * u, coverage);
  return foamCellUniform(hashed.y, 16u, 16u) < cellShare ? opacity * white : veil;
}
