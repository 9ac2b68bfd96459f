// Local waves, the end of a step of src/layers/localWaveModel.ts: the inverse transform's result,
// (η_s + iψ, ∂η_s/∂x + i·∂η_s/∂z), copied out of the FFT engine's working layout
// (quarterLayout.glsl's fieldAddress) as the state (η_s, ψ, ∂η_s/∂x, ∂η_s/∂z) of texel (x, z).
#define ALONG_Z 1
#define INPUT_LAYOUT QUARTERS
#include "fft/quarterLayout.glsl"

uniform highp sampler2DArray tSpectra0;
uniform int sizeLog2;

layout(location = 0) out vec4 state;

void main() {
  state = texelFetch(tSpectra0, fieldAddress(ivec2(gl_FragCoord.xy), sizeLog2), 0);
}
