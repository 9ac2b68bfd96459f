// The sky behind everything, as SkyEnvironment's cube holds it (environmentLookup.glsl).
#include "sky/environmentLookup.glsl"

varying vec3 vDirection;

void main() {
  gl_FragColor = vec4(environmentRadiance(normalize(vDirection)), 1.0);
  #include <tonemapping_fragment>
  #include <colorspace_fragment>
}
