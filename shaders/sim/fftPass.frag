// One pass of an inverse Stockham FFT (Stockham 1966; the gather form of Govindaraju et al. 2008,
// "High performance discrete Fourier transforms on graphics processors") along x or z, of radix
// RADIX (2 or 4), over two render targets that each hold two complex fields per texel.
//
// RADIX_LOG2 is defined with it. A pass takes sub-transforms of length p to length P = p·RADIX.
// For output index o:
//   r = o mod P,  i = (o div P)·p + (r mod p),
//   out[o] = Σ_s in[i + s·N/RADIX] · e^{+2πi·s·r/P},  s = 0 … RADIX−1.
// The twiddle comes from a table of e^{2πi·j/N} that JS computed in double precision: GLSL sin/cos
// are approximate (about 2e-4 off under SwiftShader, see ../shared/BROWSER.md).
#include "common/complex.glsl"

uniform highp sampler2D tSpectra0;
uniform highp sampler2D tSpectra1;
uniform highp sampler2D tTwiddles;  // N×1: (cos 2πj/N, sin 2πj/N)
uniform int sizeLog2;               // log2 N
uniform int subtransformLog2;       // log2 p
uniform bool alongZ;                // false: along x (texture columns); true: along z (rows)

layout(location = 0) out vec4 out0;
layout(location = 1) out vec4 out1;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int o = alongZ ? texel.y : texel.x;
  // All lengths are powers of two, so divisions and remainders are shifts and masks (integer
  // division is slow where the GPU is emulated, as under SwiftShader).
  int spanLog2 = subtransformLog2 + RADIX_LOG2;  // P = p·RADIX
  int r = o & ((1 << spanLog2) - 1);
  int i = ((o >> spanLog2) << subtransformLog2) | (r & ((1 << subtransformLog2) - 1));
  int stride = 1 << (sizeLog2 - RADIX_LOG2);      // N / RADIX
  // e^{2πi·r/P} = table[r·N/P], exact from double precision; its powers by complex products
  // (float32 rounding, ~1e-7, instead of one more texture fetch each).
  vec2 twiddle = texelFetch(tTwiddles, ivec2(r << (sizeLog2 - spanLog2), 0), 0).xy;

  ivec2 from = alongZ ? ivec2(texel.x, i) : ivec2(i, texel.y);
  vec4 sum0 = texelFetch(tSpectra0, from, 0);  // s = 0: twiddle 1
  vec4 sum1 = texelFetch(tSpectra1, from, 0);
  vec2 power = vec2(1.0, 0.0);
  for (int s = 1; s < RADIX; s++) {
    power = complexMultiply(power, twiddle);  // e^{2πi·s·r/P}
    from = alongZ ? ivec2(texel.x, i + s * stride) : ivec2(i + s * stride, texel.y);
    vec4 a = texelFetch(tSpectra0, from, 0);
    vec4 b = texelFetch(tSpectra1, from, 0);
    sum0 += vec4(complexMultiply(a.xy, power), complexMultiply(a.zw, power));
    sum1 += vec4(complexMultiply(b.xy, power), complexMultiply(b.zw, power));
  }
  out0 = sum0;
  out1 = sum1;
}
