// The analytic sky in the direction of this fragment, linear HDR, RGBM-encoded for
// SkyEnvironment's 8-bit cube (rgbm.glsl).
#include "sky/analyticSky.glsl"
#include "sky/rgbm.glsl"

in vec3 vDirection;
out vec4 fragColor;

void main() {
  fragColor = rgbmEncode(skyRadiance(vDirection));
}
