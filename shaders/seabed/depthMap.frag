// The seabed's depth map (depthMap.vert): the height of the highest surface over the node, and
// alpha 1 where a mesh covers it (the target is cleared to alpha 0).
varying float vHeight;

void main() {
  gl_FragColor = vec4(vHeight, 0.0, 0.0, 1.0);
}
