// Time evolution of the spectrum and the four packed field spectra, one texel per wave vector.
// The same computation as CpuWaveFields.evolve (src/sim/cpuWaveFields.ts); the field spectra and
// their packing are listed in src/sim/waveFieldLayout.ts.
//   h̃(k, t) = h̃0(k)·e^{iωt} + h̃0*(−k)·e^{−iωt}   (Tessendorf 2001, eq. 26)
// Each fragment evolves four wave vectors, columns b + s·N/4 of row `line`, and writes them in
// the FFT's LAYOUT_QUARTERS (quarterLayout.glsl): column b + s·N/4 to texel (b, line) of layer s.
#include "common/complex.glsl"

uniform highp sampler2D tAmplitudes;   // (h̃0(k), h̃0*(−k))
uniform highp sampler2D tWaveVectors;  // (kx, kz, 1/k, m), see src/sim/spectrum.ts
uniform highp sampler2D tPhases;       // 256×1: (e^{i·j·φ}, e^{i·256·j·φ}), see src/sim/dispersion.ts
uniform float choppiness;
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
  float d = choppiness * wave.z;  // λ/k
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
  ivec2 fragment = ivec2(gl_FragCoord.xy);
  int quarter = 1 << (sizeLog2 - 2);
  // Fragment outputs take constant indexes only, so the four columns are written out.
  evolve(fragment, displacementSpectra[0], derivativeSpectra[0]);
  evolve(fragment + ivec2(quarter, 0), displacementSpectra[1], derivativeSpectra[1]);
  evolve(fragment + ivec2(2 * quarter, 0), displacementSpectra[2], derivativeSpectra[2]);
  evolve(fragment + ivec2(3 * quarter, 0), displacementSpectra[3], derivativeSpectra[3]);
}
