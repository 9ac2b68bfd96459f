// Local waves, the end of a step of src/layers/localWaveModel.ts: the inverse transform's result,
// (η_s + iψ, ∂η_s/∂x + i·∂η_s/∂z), copied out of the FFT engine's working layout
// (quarterLayout.glsl's fieldAddress) as the state (η_s, ψ, ∂η_s/∂x, ∂η_s/∂z) of texel (x, z),
// held at zero over land (the wet mask, localWaterUnder in localWaveModel.ts).
#define ALONG_Z 1
#define INPUT_LAYOUT QUARTERS
#include "fft/quarterLayout.glsl"

uniform highp sampler2DArray tSpectra0;
uniform int sizeLog2;
uniform highp sampler2D tWet;  // 1 on water, 0 on land, a texel per grid texel (R32F)
uniform bool landUnder;        // false: no land under the grid (tWet is not read)

layout(location = 0) out vec4 state;

void main() {
  ivec2 here = ivec2(gl_FragCoord.xy);
  state = texelFetch(tSpectra0, fieldAddress(here, sizeLog2), 0);
  if (landUnder) state *= texelFetch(tWet, here, 0).r;
}
