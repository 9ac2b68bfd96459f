// One pass of an inverse Stockham FFT (Stockham 1966; the gather form of Govindaraju et al. 2008,
// "High performance discrete Fourier transforms on graphics processors") along x or z, of radix
// RADIX (2 or 4), over two render targets that each hold two complex fields per texel.
//
// A pass takes sub-transforms of length p to length P = p·RADIX. For output index o:
//   r = o mod P,  i = (o div P)·p + (r mod p),
//   out[o] = Σ_s in[i + s·N/RADIX] · e^{+2πi·s·r/P},  s = 0 … RADIX−1.
// Twiddles come from a table of e^{2πi·j/N} that JS computed in double precision: GLSL sin/cos
// are approximate (about 2e-4 off under SwiftShader, see ../shared/BROWSER.md).
#include "common/complex.glsl"

uniform highp sampler2D tSpectra0;
uniform highp sampler2D tSpectra1;
uniform highp sampler2D tTwiddles;  // N×1: (cos 2πj/N, sin 2πj/N)
uniform int size;                   // N
uniform int subtransformSize;       // p
uniform bool alongZ;                // false: along x (texture columns); true: along z (rows)

layout(location = 0) out vec4 out0;
layout(location = 1) out vec4 out1;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int o = alongZ ? texel.y : texel.x;
  int span = subtransformSize * RADIX;  // P
  int r = o % span;
  int i = (o / span) * subtransformSize + r % subtransformSize;
  int stride = size / RADIX;
  int twiddleStep = r * (size / span);  // e^{2πi·r/P} = table[r·N/P]

  vec4 sum0 = vec4(0.0);
  vec4 sum1 = vec4(0.0);
  for (int s = 0; s < RADIX; s++) {
    int source = i + s * stride;
    ivec2 from = alongZ ? ivec2(texel.x, source) : ivec2(source, texel.y);
    vec2 twiddle = texelFetch(tTwiddles, ivec2((s * twiddleStep) % size, 0), 0).xy;
    vec4 a = texelFetch(tSpectra0, from, 0);
    vec4 b = texelFetch(tSpectra1, from, 0);
    sum0 += vec4(complexMultiply(a.xy, twiddle), complexMultiply(a.zw, twiddle));
    sum1 += vec4(complexMultiply(b.xy, twiddle), complexMultiply(b.zw, twiddle));
  }
  out0 = sum0;
  out1 = sum1;
}
