// Local waves, step 3 of src/layers/localWaveModel.ts, in Fourier space: each mode turns by
// e^{−iωΔt} (the exact solution of ∂Z/∂t = −iωZ), with the 1/N² of the inverse transform, and the
// slopes' spectrum i·(kx + i·kz)·Ĥ is formed from Ĥ = (Z(k) + Z*(−k))/2, the spectrum of η_s.
#include "common/complex.glsl"
#include "common/preciseSinCos.glsl"

uniform highp sampler2D tSpectrum;  // .xy: Z(k) = FFT(η_s + iψ), bin (i, j) for k = (i, j)·2π/size
uniform float dt;
uniform float gridSize;              // m
uniform float depth;                 // m (a large number for deep water)
uniform float gravity;

layout(location = 0) out vec4 spectra;  // (Z·e^{−iωΔt}/N², i·(kx + i·kz)·Ĥ/…)

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
  return complexMultiply(texelFetch(tSpectrum, bin, 0).xy, vec2(turn.x, -turn.y)) / float(n * n);
}

void main() {
  ivec2 bin = ivec2(gl_FragCoord.xy);
  int n = textureSize(tSpectrum, 0).x;
  vec2 here = evolved(bin, n);
  vec2 mirror = evolved((ivec2(n) - bin) % n, n);
  vec2 heightSpectrum = 0.5 * (here + complexConjugate(mirror));
  // No slope at the Nyquist frequency, where +k and −k are the same bin.
  vec2 k = signedIndex(bin, n) * (6.283185307179586 / gridSize) * vec2(notEqual(bin, ivec2(n / 2)));
  spectra = vec4(here, timesI(k.x * heightSpectrum) - k.y * heightSpectrum);
}
