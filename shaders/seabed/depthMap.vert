// The seabed's depth map (src/layers/seabed.ts): a mesh seen straight from above, an orthographic
// projection along −y onto the map's nodes, node (i, j) at the centre of pixel (i, j); the height
// goes into the depth buffer so that the highest surface over a node is the one kept.
uniform vec4 mapFrame;     // (xMin, zMin, nodes per metre along x, along z)
uniform vec2 mapNodes;     // nodes (pixels) along x and z
uniform vec2 heightRange;  // lowest and highest y of the meshes, m (a metre of margin)
varying float vHeight;

void main() {
  vec4 world = modelMatrix * vec4(position, 1.0);
  vHeight = world.y;
  vec2 node = (world.xz - mapFrame.xy) * mapFrame.zw;
  vec2 clip = (node + 0.5) / mapNodes * 2.0 - 1.0;
  // Higher is nearer: clip depth −1 at the highest, +1 at the lowest (the depth test keeps the least).
  float depth = 1.0 - 2.0 * (world.y - heightRange.x) / (heightRange.y - heightRange.x);
  gl_Position = vec4(clip, depth, 1.0);
}
