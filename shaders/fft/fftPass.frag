// One pass of an inverse Stockham FFT (Stockham 1966; radix-4 as in Govindaraju et al. 2008,
// "High performance discrete Fourier transforms on graphics processors"), in the butterfly form:
// each fragment computes one whole butterfly and writes its outputs to four layers of the working
// textures (quarterLayout.glsl). Each working texture holds two complex fields per texel; the two
// together hold the four packed spectra of src/fft/waveFieldLayout.ts.
//
// RADIX (4 or 2), RADIX_LOG2, ALONG_Z (0 or 1) and INPUT_LAYOUT (quarterLayout.glsl) are defined
// with it. A pass takes sub-transforms of length p to length P = p·RADIX. Radix 4, butterfly
// i = g·p + r (r < p) of a line:
//   a_s = in[i + s·N/4] · e^{2πi·s·r/P},   s = 0 … 3
//   out[g·P + r + t·p] = Σ_s a_s · e^{2πi·s·t/4} = Σ_s a_s · i^{s·t},   t = 0 … 3   → layer t
// Radix 2 runs only as the first pass of an axis (p = 1), when log2 N is odd (along x the
// cascades' evolveSpectrum.frag does it); the fragment does the two butterflies i = b and i = b + N/4:
//   out[2i] = in[i] + in[i + N/2],  out[2i + 1] = in[i] − in[i + N/2]   → layers 2h, 2h + 1
// The twiddle comes from a table of e^{2πi·j/N} that JS computed in double precision: GLSL sin/cos
// are approximate (about 2e-4 off under SwiftShader, see ../shared/BROWSER.md).
#include "common/complex.glsl"
#include "fft/butterfly.glsl"
#include "fft/quarterLayout.glsl"

uniform highp sampler2DArray tSpectra0;
uniform highp sampler2DArray tSpectra1;
uniform highp sampler2D tTwiddles;  // N×1: (cos 2πj/N, sin 2πj/N)
uniform int sizeLog2;               // log2 N
uniform int subtransformLog2;       // log2 p

layout(location = 0) out vec4 spectra0[4];  // layer t of the next tSpectra0
layout(location = 4) out vec4 spectra1[4];  // layer t of the next tSpectra1

struct Element {
  vec4 spectra0;
  vec4 spectra1;
};

// Element b + s·N/4 of the fragment's line.
Element load(QuarterAddresses addresses, int s) {
  ivec3 at = quarterAddress(addresses, s, sizeLog2);
  return Element(texelFetch(tSpectra0, at, 0), texelFetch(tSpectra1, at, 0));
}

void main() {
  // Butterfly b of line `line` (z for the x axis, x for the z axis); see quarterLayout.glsl.
  ivec2 butterfly = fragmentButterfly(sizeLog2);
  int b = butterfly.x, line = butterfly.y;
  QuarterAddresses addresses = quarterAddresses(b, line, sizeLog2, subtransformLog2);
#if RADIX == 4
  // e^{2πi·r/P} = table[r·N/P], exact from double precision; its powers by complex products
  // (float32 rounding, ~1e-7, instead of one more texture fetch each).
  int r = b & ((1 << subtransformLog2) - 1);
  vec2 w1 = texelFetch(tTwiddles, ivec2(r << (sizeLog2 - subtransformLog2 - RADIX_LOG2), 0), 0).xy;
  vec2 w2 = complexMultiply(w1, w1);
  vec2 w3 = complexMultiply(w2, w1);
  Element a0 = load(addresses, 0), a1 = load(addresses, 1), a2 = load(addresses, 2), a3 = load(addresses, 3);
  // (Fragment outputs take constant indexes only.)
  butterfly4(a0.spectra0, a1.spectra0, a2.spectra0, a3.spectra0, w1, w2, w3,
             spectra0[0], spectra0[1], spectra0[2], spectra0[3]);
  butterfly4(a0.spectra1, a1.spectra1, a2.spectra1, a3.spectra1, w1, w2, w3,
             spectra1[0], spectra1[1], spectra1[2], spectra1[3]);
#else
  Element first0 = load(addresses, 0), second0 = load(addresses, 2);  // h = 0: in[b], in[b + N/2]
  Element first1 = load(addresses, 1), second1 = load(addresses, 3);  // h = 1: in[b + N/4], in[b + 3N/4]
  butterfly2(first0.spectra0, second0.spectra0, spectra0[0], spectra0[1]);
  butterfly2(first1.spectra0, second1.spectra0, spectra0[2], spectra0[3]);
  butterfly2(first0.spectra1, second0.spectra1, spectra1[0], spectra1[1]);
  butterfly2(first1.spectra1, second1.spectra1, spectra1[2], spectra1[3]);
#endif
}
