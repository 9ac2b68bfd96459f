// The FFT butterflies of fftPass.frag (and the first one, fused into evolveSpectrum.frag when
// log2 N is odd), on texels that hold two complex numbers each (vec4 = two vec2).
#include "common/complex.glsl"

// Both complex numbers of a texel times the same complex factor.
vec4 times(vec4 pair, vec2 factor) {
  return vec4(complexMultiply(pair.xy, factor), complexMultiply(pair.zw, factor));
}

// The radix-4 butterfly for both complex numbers of a texel: y_t = Σ_s a_s·w^s·i^{s·t}, as two
// 2-point stages (i^{s·t} is ±1 or ±i, so no multiplications).
void butterfly4(vec4 a0, vec4 a1, vec4 a2, vec4 a3, vec2 w1, vec2 w2, vec2 w3,
                out vec4 y0, out vec4 y1, out vec4 y2, out vec4 y3) {
  vec4 x1 = times(a1, w1), x2 = times(a2, w2), x3 = times(a3, w3);
  vec4 sum02 = a0 + x2, difference02 = a0 - x2;
  vec4 sum13 = x1 + x3, difference13 = x1 - x3;
  vec4 iDifference13 = vec4(-difference13.y, difference13.x, -difference13.w, difference13.z);
  y0 = sum02 + sum13;
  y1 = difference02 + iDifference13;
  y2 = sum02 - sum13;
  y3 = difference02 - iDifference13;
}

// The radix-2 butterfly (twiddle 1, p = 1) for both complex numbers of a texel.
void butterfly2(vec4 a0, vec4 a1, out vec4 y0, out vec4 y1) {
  y0 = a0 + a1;
  y1 = a0 - a1;
}
