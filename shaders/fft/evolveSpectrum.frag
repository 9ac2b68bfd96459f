// Time evolution of the spectrum and the four packed field spectra, one texel per wave vector.
// The same computation as CpuWaveFields.evolve (src/fft/cpuWaveFields.ts); the field spectra and
// their packing are listed in src/fft/waveFieldLayout.ts.
//   h̃(k, t) = h̃0(k)·e^{iωt} + h̃0*(−k)·e^{−iωt}   (Tessendorf 2001, eq. 26)
// Each fragment evolves four wave vectors, columns b + s·N/4 of row `line`, and writes them in
// the FFT's QUARTERS layout (quarterLayout.glsl): column b + s·N/4 to texel (b, line) of layer s.
// With FIRST_RADIX2 (log2 N odd) it also does the first FFT pass along x, radix 2 (fftPass.frag),
// whose two butterflies take exactly these four columns, and writes the AFTER_RADIX2 layout:
// one pass fewer.
#include "common/complex.glsl"
#include "fft/butterfly.glsl"
#define ALONG_Z 0              // it writes what the x axis reads
#define INPUT_LAYOUT QUARTERS  // (it reads no working texture)
#include "fft/quarterLayout.glsl"

uniform highp sampler2D tAmplitudes;   // (h̃0(k), h̃0*(−k))
uniform highp sampler2D tWaveVectors;  // (kx, kz, 1/k, m), see src/spectrum/initialSpectrum.ts
uniform highp sampler2D tPhases;       // 256×1: (e^{i·j·φ}, e^{i·256·j·φ}), see src/spectrum/dispersion.ts
uniform int sizeLog2;

layout(location = 0) out vec4 displacementSpectra[4];  // (Dx + i·h, Dz + i·∂Dx/∂z)
layout(location = 4) out vec4 derivativeSpectra[4];    // (∂h/∂x + i·∂h/∂z, ∂Dx/∂x + i·∂Dz/∂z)

void evolve(ivec2 texel, out vec4 displacement, out vec4 derivatives) {
  vec4 amplitudes = texelFetch(tAmplitudes, texel, 0);
  vec4 wave = texelFetch(tWaveVectors, texel, 0);
  int m = int(wave.w);
  // e^{iωt} = e^{i·(m mod 256)·φ} · e^{i·256·(m div 256)·φ}, both factors exact from double precision.
  vec2 phase = complexMultiply(texelFetch(tPhases, ivec2(m & 255, 0), 0).xy,
                               texelFetch(tPhases, ivec2(m >> 8, 0), 0).zw);
  vec2 h = complexMultiply(amplitudes.xy, phase) + complexMultiply(amplitudes.zw, complexConjugate(phase));

  float kx = wave.x;
  float kz = wave.y;
  float d = wave.z;  // λ/k with λ = 1: the surface scales by the choppiness (waveFieldLayout.ts)
  vec2 slopeX = timesI(kx * h);   // i·kx·h̃
  vec2 slopeZ = timesI(kz * h);   // i·kz·h̃
  vec2 dispX = d * slopeX;        // i·λ·kx/k·h̃
  vec2 dispZ = d * slopeZ;
  vec2 dispXZ = -d * kx * kz * h; // −λ·kx·kz/k·h̃
  vec2 dispXX = -d * kx * kx * h;
  vec2 dispZZ = -d * kz * kz * h;

  // F + i·G packs two real fields into one complex transform.
  displacement = vec4(dispX + timesI(h), dispZ + timesI(dispXZ));
  derivatives = vec4(slopeX + timesI(slopeZ), dispXX + timesI(dispZZ));
}

void main() {
  ivec2 column = fragmentButterfly(sizeLog2);  // (b, row)
  ivec2 quarter = ivec2(1 << (sizeLog2 - 2), 0);
  // Fragment outputs take constant indexes only, so the four columns are written out.
  vec4 displacement0, displacement1, displacement2, displacement3;
  vec4 derivatives0, derivatives1, derivatives2, derivatives3;
  evolve(column, displacement0, derivatives0);
  evolve(column + quarter, displacement1, derivatives1);
  evolve(column + 2 * quarter, displacement2, derivatives2);
  evolve(column + 3 * quarter, displacement3, derivatives3);
#if FIRST_RADIX2
  // Butterflies i = b (columns b, b + N/2) and i = b + N/4 (columns b + N/4, b + 3N/4).
  butterfly2(displacement0, displacement2, displacementSpectra[0], displacementSpectra[1]);
  butterfly2(displacement1, displacement3, displacementSpectra[2], displacementSpectra[3]);
  butterfly2(derivatives0, derivatives2, derivativeSpectra[0], derivativeSpectra[1]);
  butterfly2(derivatives1, derivatives3, derivativeSpectra[2], derivativeSpectra[3]);
#else
  displacementSpectra[0] = displacement0;
  displacementSpectra[1] = displacement1;
  displacementSpectra[2] = displacement2;
  displacementSpectra[3] = displacement3;
  derivativeSpectra[0] = derivatives0;
  derivativeSpectra[1] = derivatives1;
  derivativeSpectra[2] = derivatives2;
  derivativeSpectra[3] = derivatives3;
#endif
}
