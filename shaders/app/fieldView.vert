// A quad in normalized device coordinates with texture coordinates, for field views.
out vec2 vUv;

void main() {
  vUv = uv;
  gl_Position = vec4(position.xy, 0.0, 1.0);
}
