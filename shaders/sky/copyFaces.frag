// A loaded face set (six sRGB images, a three.js CubeTexture) copied into SkyEnvironment's cube,
// RGBM-encoded (rgbm.glsl), so that everything samples one kind of cube.
//
// three.js samples cube textures made from images with x mirrored (cube-map images follow the
// left-handed RenderMan convention, three.js is right-handed) but cube render targets unmirrored:
// the mirror is undone here, once, so the copy agrees with sunDirection like the generated sky.
#include "sky/rgbm.glsl"

uniform samplerCube tFaces;

in vec3 vDirection;
out vec4 fragColor;

void main() {
  // Level 0: the cube target has the faces' resolution. The sRGB faces decode to linear here.
  fragColor = rgbmEncode(textureLod(tFaces, vec3(-vDirection.x, vDirection.yz), 0.0).rgb);
}
