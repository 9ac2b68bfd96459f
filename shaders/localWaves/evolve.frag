// Local waves, step 3 of src/layers/localWaveModel.ts, in Fourier space: each mode turns by
// e^{−iωΔt} (the exact solution of ∂Z/∂t = −iωZ), with the 1/N² of the inverse transform, and the
// slopes' spectrum i·(kx + i·kz)·Ĥ is formed from Ĥ = (Z(k) + Z*(−k))/2, the spectrum of η_s.
// Reads the forward transform from the FFT engine (src/fft/gpuFft.ts) and writes the input of the
// inverse one, both in its working layout (quarterLayout.glsl).
#include "common/complex.glsl"
#include "common/preciseSinCos.glsl"
#define ALONG_Z 0              // it writes what the x axis reads
#define INPUT_LAYOUT QUARTERS  // (it reads the result with fieldAddress)
#include "fft/quarterLayout.glsl"

uniform highp sampler2DArray tSpectrum;  // .xy: conj Z(k), Z = FFT(η_s + iψ), bin (i, j) for k = (i, j)·2π/size
uniform int sizeLog2;
uniform float dt;
uniform float gridSize;              // m
uniform float depth;                 // m (a large number for deep water)
uniform float gravity;

// Element b + s·N/4 of the line goes to layer s: (Z·e^{−iωΔt}/N², i·(kx + i·kz)·Ĥ/…); the second
// working texture is not used.
layout(location = 0) out vec4 spectra0[4];
layout(location = 4) out vec4 spectra1[4];

// Signed wavenumber index of bin i of N: i below N/2, i − N above (signedIndex in localWaveModel.ts).
vec2 signedIndex(ivec2 bin, int n) {
  return vec2(bin.x < n / 2 ? bin.x : bin.x - n, bin.y < n / 2 ? bin.y : bin.y - n);
}

// Z(bin) turned by e^{−iωΔt}/N², ω = √(g·k·tanh(k·d)) (Tessendorf 2001, eq. 15).
vec2 evolved(ivec2 bin, int n) {
  vec2 k = signedIndex(bin, n) * (6.283185307179586 / gridSize);
  float wavenumber = length(k);
  float omega = sqrt(gravity * wavenumber * tanh(min(wavenumber * depth, 20.0)));
  vec2 turn = preciseCosSin(omega * dt);
  vec2 z = complexConjugate(texelFetch(tSpectrum, fieldAddress(bin, sizeLog2), 0).xy);
  return complexMultiply(z, vec2(turn.x, -turn.y)) / float(n * n);
}

vec4 spectra(ivec2 bin, int n) {
  vec2 here = evolved(bin, n);
  vec2 mirror = evolved((ivec2(n) - bin) % n, n);
  vec2 heightSpectrum = 0.5 * (here + complexConjugate(mirror));
  // No slope at the Nyquist frequency, where +k and −k are the same bin.
  vec2 k = signedIndex(bin, n) * (6.283185307179586 / gridSize) * vec2(notEqual(bin, ivec2(n / 2)));
  return vec4(here, timesI(k.x * heightSpectrum) - k.y * heightSpectrum);
}

void main() {
  ivec2 column = fragmentButterfly(sizeLog2);  // (b, row)
  ivec2 quarter = ivec2(1 << (sizeLog2 - 2), 0);
  int n = 1 << sizeLog2;
  // Fragment outputs take constant indexes only, so the four columns are written out.
  spectra0[0] = spectra(column, n);
  spectra0[1] = spectra(column + quarter, n);
  spectra0[2] = spectra(column + 2 * quarter, n);
  spectra0[3] = spectra(column + 3 * quarter, n);
  spectra1[0] = spectra1[1] = spectra1[2] = spectra1[3] = vec4(0.0);
}
