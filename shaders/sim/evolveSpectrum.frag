// Time evolution of the spectrum and the four packed field spectra, one texel per wave vector.
// The same computation as CpuWaveFields.evolve (src/sim/cpuWaveFields.ts); the field spectra and
// their packing are listed in src/sim/waveFieldLayout.ts.
//   h̃(k, t) = h̃0(k)·e^{iωt} + h̃0*(−k)·e^{−iωt}   (Tessendorf 2001, eq. 26)
#include "common/complex.glsl"

uniform highp sampler2D tAmplitudes;   // (h̃0(k), h̃0*(−k))
uniform highp sampler2D tWaveVectors;  // (kx, kz, 1/k, m), see src/sim/spectrum.ts
uniform highp sampler2D tPhases;       // 256×1: (e^{i·j·φ}, e^{i·256·j·φ}), see src/sim/dispersion.ts
uniform float choppiness;

layout(location = 0) out vec4 displacementSpectra;  // (Dx + i·h, Dz + i·∂Dx/∂z)
layout(location = 1) out vec4 derivativeSpectra;    // (∂h/∂x + i·∂h/∂z, ∂Dx/∂x + i·∂Dz/∂z)

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
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
  displacementSpectra = vec4(dispX + timesI(h), dispZ + timesI(dispXZ));
  derivativeSpectra = vec4(slopeX + timesI(slopeZ), dispXX + timesI(dispZZ));
}
