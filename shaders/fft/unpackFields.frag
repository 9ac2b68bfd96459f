// The last pass of the GPU path: copies the fields out of the FFT's working layout
// (quarterLayout.glsl's fieldAddress) into ordinary N×N textures, which the surface samples with
// REPEAT wrapping, linear filtering and mipmaps.
#define ALONG_Z 1
#define INPUT_LAYOUT QUARTERS
#include "fft/quarterLayout.glsl"

uniform highp sampler2DArray tSpectra0;
uniform highp sampler2DArray tSpectra1;
uniform int sizeLog2;

layout(location = 0) out vec4 displacement;  // (Dx, h, Dz, ∂Dx/∂z)
layout(location = 1) out vec4 derivatives;   // (∂h/∂x, ∂h/∂z, ∂Dx/∂x, ∂Dz/∂z)

void main() {
  ivec3 at = fieldAddress(ivec2(gl_FragCoord.xy), sizeLog2);  // texel (x, z)
  // The transform of F + i·G is f + i·g (waveFieldLayout.ts), so the packed complex pairs are
  // already the fields in texture order: (Dx + i·h, Dz + i·∂Dx/∂z) = (Dx, h, Dz, ∂Dx/∂z), etc.
  displacement = texelFetch(tSpectra0, at, 0);
  derivatives = texelFetch(tSpectra1, at, 0);
}
