// One radix-2 pass of a Stockham FFT (Stockham 1966; Van Loan, "Computational Frameworks for the
// Fast Fourier Transform" (1992), §1.7) along x or z (ALONG_Z), for the two complex numbers of each
// texel, forward (direction −1: e^{−2πi·…}) or inverse without the 1/N (direction +1). The pass takes
// sub-transforms of length p to 2p; output element j = g·2p + t·p + r (r < p, t = 0 or 1) is
//   out[j] = in[g·p + r] ± w·in[g·p + r + N/2],   w = e^{±2πi·r/2p},   + for t = 0, − for t = 1,
// and after log2 N passes the result is in natural order. The twiddles come from a table computed in
// double precision in JS (GLSL sin/cos are ~2e-4 off under SwiftShader: ../shared/BROWSER.md).
#include "fft/butterfly.glsl"

uniform highp sampler2D tInput;
uniform highp sampler2D tTwiddles;  // N×1: (cos 2πm/N, sin 2πm/N)
uniform int subtransformLog2;       // log2 p
uniform float direction;            // −1 forward, +1 inverse

layout(location = 0) out vec4 result;

vec4 element(int index, int line) {
  return texelFetch(tInput, ALONG_Z == 1 ? ivec2(line, index) : ivec2(index, line), 0);
}

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int j = ALONG_Z == 1 ? texel.y : texel.x;
  int line = ALONG_Z == 1 ? texel.x : texel.y;
  int n = textureSize(tInput, 0).x;
  int p = 1 << subtransformLog2;
  int r = j & (p - 1);
  int first = (j >> (subtransformLog2 + 1)) * p + r;
  vec2 twiddle = texelFetch(tTwiddles, ivec2(r * (n >> (subtransformLog2 + 1)), 0), 0).xy;
  vec4 twiddled = times(element(first + n / 2, line), vec2(twiddle.x, direction * twiddle.y));
  vec4 a = element(first, line);
  result = ((j >> subtransformLog2) & 1) == 0 ? a + twiddled : a - twiddled;
}
