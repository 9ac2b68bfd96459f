// Local waves, step 1 of src/layers/localWaveModel.ts, in space: the grid's move by whole texels
// (texel i takes texel i + shift, new texels 0), the absorbing sponge, and the sources' height
// changes. Writes η_s + iψ as the complex number the forward FFT transforms.
uniform highp sampler2D tState;    // (η_s, ψ, ∂η_s/∂x, ∂η_s/∂z) after the last step
uniform ivec2 shift;
uniform float dt;
uniform float cellSize;            // m
uniform float spongeWidth;         // texels
uniform float spongeEdgeRate;      // 1/s
uniform vec4 impulsePose[MAX_IMPULSES];   // (x, z) m from texel (0, 0), (cos, sin) of the heading
uniform vec4 impulseShape[MAX_IMPULSES];  // (half length, half beam, height, unused) m
uniform int impulseCount;

layout(location = 0) out vec4 state;

// spongeFactor() of localWaveModel.ts: 0 on the edge, exp(−rate·((width − d)/width)²·Δt) within it.
float spongeFactor(ivec2 texel, int n) {
  int fromEdge = min(min(texel.x, texel.y), min(n - 1 - texel.x, n - 1 - texel.y));
  if (fromEdge == 0) return 0.0;
  float depthIn = max(spongeWidth - float(fromEdge), 0.0) / spongeWidth;
  return exp(-spongeEdgeRate * depthIn * depthIn * dt);
}

// impulseHeight() of localWaveModel.ts: height·exp(−(u/half length)² − (v/half beam)²).
float impulseHeight(int s, vec2 position) {
  vec2 offset = position - impulsePose[s].xy;
  vec2 heading = impulsePose[s].zw;
  float along = dot(offset, heading) / impulseShape[s].x;
  float across = (offset.y * heading.x - offset.x * heading.y) / impulseShape[s].y;
  return impulseShape[s].z * exp(-(along * along + across * across));
}

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int n = textureSize(tState, 0).x;
  ivec2 from = texel + shift;
  bool inside = all(greaterThanEqual(from, ivec2(0))) && all(lessThan(from, ivec2(n)));
  vec2 value = inside ? texelFetch(tState, from, 0).xy * spongeFactor(texel, n) : vec2(0.0);
  vec2 position = vec2(texel) * cellSize;
  for (int s = 0; s < impulseCount; s++) value.x += impulseHeight(s, position);
  state = vec4(value, 0.0, 0.0);
}
