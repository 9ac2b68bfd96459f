// Local waves, step 1 of src/layers/localWaveModel.ts, in space: the grid's move by whole texels
// (texel i takes texel i + shift, new texels 0), the absorbing sponge, and the sources' height
// changes. Writes the conjugate of η_s + iψ, the complex number the forward FFT transforms, into
// the FFT engine's input (src/fft/gpuFft.ts): its forward transform is conj(IFFT(conj z)).
#define ALONG_Z 0              // it writes what the x axis reads
#define INPUT_LAYOUT QUARTERS  // (it reads no working texture)
#include "fft/quarterLayout.glsl"

uniform highp sampler2D tState;    // (η_s, ψ, ∂η_s/∂x, ∂η_s/∂z) after the last step
uniform int sizeLog2;
uniform ivec2 shift;
uniform float dt;
uniform float cellSize;            // m
uniform float spongeWidth;         // texels
uniform float spongeEdgeRate;      // 1/s
uniform vec4 impulsePose[MAX_IMPULSES];   // (x, z) m from texel (0, 0), (cos, sin) of the heading
uniform vec4 impulseShape[MAX_IMPULSES];  // (half length, half beam, height, unused) m
uniform int impulseCount;

// Element b + s·N/4 of the line goes to layer s (quarterLayout.glsl's QUARTERS); the second working
// texture is not used.
layout(location = 0) out vec4 spectra0[4];
layout(location = 4) out vec4 spectra1[4];

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

// conj(η_s + iψ) at `texel` after the move, the sponge and the sources.
vec4 prepared(ivec2 texel, int n) {
  ivec2 from = texel + shift;
  bool inside = all(greaterThanEqual(from, ivec2(0))) && all(lessThan(from, ivec2(n)));
  vec2 value = inside ? texelFetch(tState, from, 0).xy * spongeFactor(texel, n) : vec2(0.0);
  vec2 position = vec2(texel) * cellSize;
  for (int s = 0; s < impulseCount; s++) value.x += impulseHeight(s, position);
  return vec4(value.x, -value.y, 0.0, 0.0);
}

void main() {
  ivec2 column = fragmentButterfly(sizeLog2);  // (b, row)
  ivec2 quarter = ivec2(1 << (sizeLog2 - 2), 0);
  int n = 1 << sizeLog2;
  // Fragment outputs take constant indexes only, so the four columns are written out.
  spectra0[0] = prepared(column, n);
  spectra0[1] = prepared(column + quarter, n);
  spectra0[2] = prepared(column + 2 * quarter, n);
  spectra0[3] = prepared(column + 3 * quarter, n);
  spectra1[0] = spectra1[1] = spectra1[2] = spectra1[3] = vec4(0.0);
}
