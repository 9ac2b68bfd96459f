// One triangle that covers the target; each fragment is one texel of a simulation texture.
void main() {
  gl_Position = vec4(position.xy, 0.0, 1.0);
}
