// Reads SkyEnvironment's cube (src/render/skyEnvironment.ts) in a world direction (y up): linear
// HDR radiance, for the sky background and for materials that sample it themselves (reflections,
// refraction into the deep water). The cube is RGBM-encoded 8-bit (rgbm.glsl), without mipmaps.
#include "sky/rgbm.glsl"

uniform samplerCube skyEnvironment;

vec3 environmentRadiance(vec3 direction) {
  return rgbmDecode(textureLod(skyEnvironment, direction, 0.0));
}
