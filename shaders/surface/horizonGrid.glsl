// Where a vertex of the horizon grid lies on the rest plane (src/render/horizonGrid.ts).
// Rings of square grids around the camera, each with cells twice the size of the one inside it.
// A ring's centre is snapped to twice its cell size, so every vertex sits on a fixed world grid
// point: vertices are anchored in world space and nothing swims when the camera moves.
// ringFrames[r] = (centre x, centre z, cell size, mip level) from JS in double precision, the centre
// relative to the eye: positions here are metres from the eye (x, z), which float32 holds as well
// 10 000 km from the world origin as next to it (the mip level is that of the finest layer's
// texels; waveLayers.glsl finds each layer's); ringOffsets[r] = (centre_r − centre_{r+1}) / cell_{r+1}
// (whole numbers). Vertices on a ring's outer edge are moved onto the next ring's grid (the odd
// ones onto their even neighbour) and computed in that ring's frame, with the same arithmetic as
// the next ring's own vertices, so the two rings meet with no crack.
// The geometry's `position` attribute (declared by three.js) holds grid coordinates, not metres:
// (x, z) in cells from the ring centre, and the ring index. (It must be called position: three.js
// builds wireframes and draw ranges from that attribute.)
attribute float farScale;   // 1, or a large factor for the skirt that reaches the horizon

#define SKIRT_LOD 1000.0  // beyond any mip level: GL clamps to the last one

uniform vec4 ringFrames[RING_COUNT + 1];
uniform vec2 ringOffsets[RING_COUNT + 1];
uniform float halfRingCells;  // cells from a ring's centre to its edge

struct GridPoint {
  vec2 fromEye;    // rest position (x, z) from the eye's, metres
  vec2 fromCentre; // rest position from the centre of the ring whose frame placed it, metres
  int frameRing;   // that ring (the next one out for a vertex on a ring's outer edge)
  float lod;       // mip level of the finest layer matching the cell size
  float ring;      // the ring whose mesh holds the vertex
};

GridPoint horizonGridPoint() {
  int ring = int(position.z);
  vec2 cells = position.xy;
  if (max(abs(cells.x), abs(cells.y)) == halfRingCells) {
    // On the outer edge: into the next ring's frame (cells there are twice as large).
    cells = ringOffsets[ring] + (cells - mod(cells, 2.0)) * 0.5;
    ring += 1;
  }
  vec4 frame = ringFrames[ring];
  vec2 metres = cells * (frame.z * farScale);
  GridPoint point;
  point.fromEye = frame.xy + metres;
  point.fromCentre = metres;
  point.frameRing = ring;
  point.lod = farScale > 1.0 ? SKIRT_LOD : frame.w;  // the skirt samples the coarsest mip: flat, mean sea
  point.ring = position.z;
  return point;
}
