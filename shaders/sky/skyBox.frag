// The analytic sky in the direction of this fragment, linear HDR (no tone mapping, no sRGB).
#include "sky/analyticSky.glsl"

in vec3 vDirection;
out vec4 fragColor;

void main() {
  fragColor = vec4(skyRadiance(vDirection), 1.0);
}
