// The sky behind everything, as SkyEnvironment's cube holds it (environmentLookup.glsl).
#include "sky/environmentLookup.glsl"
#include "output/dither.glsl"

// backgroundWater (BACKGROUND_WATER in src/render/skyBackground.ts): 0 the sky everywhere; 1 the
// deep water below the horizon (the eye at the surface: from above every downward ray meets the sea,
// from below every upward one does, so what the sea leaves below the horizon is seen from inside
// the water); 2 the deep water everywhere (the eye under the water: only gaps of the far surface).
uniform int backgroundWater;
uniform vec3 deepWater;  // the radiance of deep water in daylight (the sea's scatterColor)
uniform float skyDaylight;  // the sky's light as a fraction of the day's (src/render/daylight.ts)
uniform float ditherStep;   // a level of the target: 1/255 into 8 bits, 0 into floats (SkyBackground)
varying vec3 vDirection;

void main() {
  vec3 direction = normalize(vDirection);
  bool inWater = backgroundWater == 2 || (backgroundWater == 1 && direction.y < 0.0);
  gl_FragColor = vec4(inWater ? skyDaylight * deepWater : environmentRadiance(direction), 1.0);
  #include <tonemapping_fragment>
  #include <colorspace_fragment>
  // The sky's gradients are the smoothest in the picture: without it they band (dither.glsl).
  gl_FragColor.rgb = dither(gl_FragColor.rgb, gl_FragCoord.xy, ditherStep);
}
