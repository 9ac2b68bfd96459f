// Ocean surface, fragment stage: the course report's shading model (§2.2–2.4),
//   c = R·c_reflected + T·c_refracted + K·c_caustic  (+ the sun's specular glint),
// with R the exact Fresnel reflectance, c_reflected / c_refracted sampled from the environment
// cubemap along reflect() / refract(), the refracted light attenuated in the water volume, and K
// Guardado's caustic term; then whitecap foam over it (foam.glsl). The reflection shows the scene's
// objects too (sceneReflection.glsl) where the option reflections is 'scene'.
#include "common/fresnel.glsl"
#include "surface/choppyNormal.glsl"
#include "surface/caustics.glsl"
#include "surface/absorption.glsl"
#include "sky/environmentLookup.glsl"
#include "surface/slopeTaps.glsl"
#include "surface/sceneReflection.glsl"
#include "surface/waveLayers.glsl"
#include "surface/seaLighting.glsl"
#include "surface/foam.glsl"
#include "surface/foamCells.glsl"
#include "surface/foamStreaks.glsl"
#include "surface/spray.glsl"
#if SCENE_REFRACTIONS == 1
#include "surface/sceneRefraction.glsl"
#endif
#include "surface/fromBelow.glsl"
#ifdef SEABED
varying float vShoaling[LAYER_COUNT];  // see ocean.vert
varying float vBreakingSlope;
varying float vShoreFoam;
#endif
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>

uniform vec3 sunDirection;     // towards the sun
uniform vec3 sunColor;        // the sun's irradiance at the sea (OceanMaterial)
// As the sun sets (src/render/daylight.ts, shared with the sky): the sky's light as a fraction of
// the day's, which the water scatters back, and the fraction of the sun's disk above the horizon,
// which makes the glint and the caustics.
uniform float skyDaylight;
uniform float skySunVisibility;
uniform float iorAir;
uniform float iorWater;
uniform vec3 absorption;
uniform vec3 scatterColor;
uniform float viewDepth;
uniform float causticPower;
uniform vec3 causticColor;
uniform float heightScale;     // metres shown as full white in the height mode
// Where the eye is (OceanSurface.eyeSide): EYE_ABOVE in the air, EYE_BELOW in the water, EYE_NEAR
// at the surface, where the near plane may cross it: there the triangles near the eye tell by the
// side they show it, and farther ones (sub-pixel slivers at grazing angles) follow eyeInWater,
// whether the eye itself is under the water's height.
uniform int eyeSide;
uniform bool eyeInWater;
#define WATERLINE_REACH 5.0  // metres
#define EDGE_FOAM_WIDTH 0.3  // metres of water in front of an object that foam covers, at the waterline
#define EDGE_FOAM_SOLID 1.5  // the edge foam's coverage at the object
#define EYE_ABOVE 0
#define EYE_BELOW 1
#define EYE_NEAR 2

varying vec2 vLayerUv[LAYER_COUNT];
varying float vCrossDerivative;  // λ·Σ ∂Dx/∂z, see ocean.vert
varying vec2 vBlend;             // the largest layer's two copies' weights, see ocean.vert
varying vec2 vBlendSlope;
varying float vFoam;             // foam coverage, see ocean.vert
#ifdef HULL_FOAM_LAYER
uniform sampler2D tHullFoam;     // the hulls' foam coverage in .r (src/layers/hullFoam.ts), over layer HULL_FOAM_LAYER's grid
#endif
varying vec3 vFromEye;                // see ocean.vert
centroid varying vec2 vRestFromEye;   // see ocean.vert
uniform vec2 foamPatternOrigin;       // the eye's (x, z) modulo FOAM_PATTERN_PERIOD (OceanMaterial.setEye)
flat varying float vRing;
flat varying vec3 vInnerRing;  // see ocean.vert
varying float vLod;
#ifdef CAPTURE_POSITIONS
uniform bool captureRestPoint;
#endif

// SHADING_MODE (defined by OceanMaterial, the index in its SHADING_MODES) is one of:
#define SHADING_FULL 0
#define SHADING_FRESNEL_CONSTANT 1  // report Figure 7
#define SHADING_REFLECTION 2        // report Figure 10, left
#define SHADING_REFRACTION 3        // report Figure 10, middle
#define SHADING_CAUSTICS 4          // report Figure 9, left
#define SHADING_HEIGHT 5            // report Figure 3

void main() {
  // First, so that every path below writes the same depth (ocean.vert).
  #include <logdepthbuf_fragment>
  // The foam's pattern and the rest point's and the pattern's change to the next pixel (foam.glsl),
  // taken before any branch: derivatives are defined only where every pixel of a 2×2 quad runs the
  // same code.
  vec2 restPerPixelX = dFdx(vRestFromEye), restPerPixelY = dFdy(vRestFromEye);
  vec2 foamRestPoint = streakPatternPoint(vRestFromEye) + foamPatternOrigin;
  vec2 foamDetail = foamPattern(foamRestPoint);
  float foamDetailPerPixel = fwidth(foamDetail.x);
#ifdef CAPTURE_POSITIONS
  // Geometry test: the displaced position with the foam the shore adds there (0 without a seabed), or
  // the rest point with its mip level and ring (from the eye).
#ifdef SEABED
  float capturedShoreFoam = vShoreFoam;
#else
  float capturedShoreFoam = 0.0;
#endif
  gl_FragColor = captureRestPoint ? vec4(vRestFromEye, vLod, vRing) : vec4(vFromEye, capturedShoreFoam);
  return;
#endif
  // Each point of the rest plane is drawn by exactly one ring: a ring overlaps the one inside it
  // by a cell (so that no gap opens whichever way their centres snapped) and drops that overlap.
  vec2 fromInner = abs(vRestFromEye - vInnerRing.xy);
  if (max(fromInner.x, fromInner.y) < vInnerRing.z) discard;

  vec4 derivatives = vec4(0.0);  // Σ (∂h/∂x, ∂h/∂z, ∂Dx/∂x, ∂Dz/∂z)
  #pragma unroll_loop_start
  for (int i = 0; i < LAYER_COUNT - 1; i++) {
#ifdef SEABED
    derivatives += vShoaling[ i ] * texture(tLayerDerivatives[ i ], vLayerUv[ i ]);
#else
    derivatives += texture(tLayerDerivatives[ i ], vLayerUv[ i ]);
#endif
  }
  #pragma unroll_loop_end
  // The largest layer, blended from its two copies (src/layers/patchBlend.ts).
  vec2 largestUv = vLayerUv[LAYER_COUNT - 1];
#ifdef SEABED
  // Each layer shoals by its factor and the height's slopes follow the breaking limit (shoaling.glsl).
  derivatives += vShoaling[LAYER_COUNT - 1] * (vBlend.x * texture(tLayerDerivatives[LAYER_COUNT - 1], largestUv) +
                                               vBlend.y * texture(tLayerDerivatives[LAYER_COUNT - 1], largestUv + copyOffset));
  derivatives.xy = (derivatives.xy + vBlendSlope) * vBreakingSlope;
#else
  derivatives += vBlend.x * texture(tLayerDerivatives[LAYER_COUNT - 1], largestUv) +
                 vBlend.y * texture(tLayerDerivatives[LAYER_COUNT - 1], largestUv + copyOffset);
  derivatives.xy += vBlendSlope;
#endif
  derivatives.zw *= choppiness;
  float dxDz = vCrossDerivative;
  vec3 normal = choppyNormal(derivatives, dxDz);
  vec3 view = normalize(vFromEye);  // d, from the eye to the surface
  normal = facingEye(view, normal);  // seaLighting.glsl
  float cosIncident = -dot(view, normal);

  float reflectance = fresnelReflectance(cosIncident, iorAir, iorWater);
  vec3 reflected = reflect(view, normal);
  reflected.y = abs(reflected.y);  // a ray reflected downwards would hit the next wave: mirror it
  vec3 refracted = refract(view, normal, iorAir / iorWater);
  float caustic = causticBrightness(normal, sunDirection, iorWater / iorAir, causticPower);

  // The report's false-colour figures are shown exactly, without tone mapping or colour space
  // conversion (its OpenGL output had none); radiance is tone-mapped as in the full picture.
#if SHADING_MODE == SHADING_FRESNEL_CONSTANT
  gl_FragColor = vec4(mix(vec3(0.0, 0.3, 0.4), vec3(0.64, 0.84, 1.0), reflectance), 1.0);
#elif SHADING_MODE == SHADING_CAUSTICS
  gl_FragColor = vec4(vec3(caustic), 1.0);
#elif SHADING_MODE == SHADING_HEIGHT
  gl_FragColor = vec4(vec3(clamp(0.5 + 0.5 * (vFromEye.y + cameraPosition.y) / heightScale, 0.0, 1.0)), 1.0);
#else
  vec3 deepWater = skyDaylight * scatterColor;  // the light deep water scatters back, as the sky gives it
  vec3 sunLight = skySunVisibility * sunColor;
  #if SHADING_MODE == SHADING_REFLECTION
  vec3 colour = reflectedRadiance(vFromEye, reflected, environmentRadiance(reflected), 0.0);
  #elif SHADING_MODE == SHADING_REFRACTION
  vec3 colour = throughWater(environmentRadiance(refracted), refracted, absorption, deepWater, viewDepth);
  #else
  // Seen from below: the horizon grid's triangles face up (counter-clockwise seen from above), so
  // from under the water they show their back.
  bool nearEye = dot(vFromEye, vFromEye) < WATERLINE_REACH * WATERLINE_REACH;
  if (eyeSide == EYE_BELOW || (eyeSide == EYE_NEAR && (nearEye ? !gl_FrontFacing : eyeInWater))) {
    gl_FragColor = vec4(surfaceFromBelow(view, choppyNormal(derivatives, dxDz), vFromEye, iorAir, iorWater, absorption, deepWater), 1.0);
    #include <tonemapping_fragment>
    #include <colorspace_fragment>
    return;
  }
  // The slopes this pixel's normal does not show spread the sky's reflection and the glint (seaLighting.glsl).
  float slopeVariance = subPixelSlopeVariance(footprintLevel(restPerPixelX, restPerPixelY));
  // The scene's objects in front of the sky, seen along the reflected ray (sceneReflection.glsl).
  vec3 sky = reflectedRadiance(vFromEye, reflected, filteredSkyReflection(view, normal, slopeVariance, iorAir, iorWater, reflectance), slopeVariance);
  vec3 water = throughWater(environmentRadiance(refracted), refracted, absorption, deepWater, viewDepth);
  #if SCENE_REFRACTIONS == 1
  // What lies under the surface (sceneRefraction.glsl); where an object meets the water, a line of
  // foam as wide as EDGE_FOAM_WIDTH along the view: a coverage above 1 at the object (solid white
  // whatever the foam's pattern there), falling to patches and none at EDGE_FOAM_WIDTH.
  float edgeDistance;
  vec3 surfaceView = mat3(viewMatrix) * vFromEye;  // the eye is the view space's origin
  water = sceneThroughWater(surfaceView, mat3(viewMatrix) * refracted, gl_FragCoord.xy, water, absorption, deepWater, edgeDistance);
  float edgeFoam = EDGE_FOAM_SOLID * (1.0 - smoothstep(0.0, EDGE_FOAM_WIDTH, edgeDistance));
  #else
  float edgeFoam = 0.0;
  #endif
  vec3 glint = sunLight * sunGlint(view, normal, sunDirection, slopeVariance, iorAir, iorWater);
  vec3 colour = reflectance * sky + (1.0 - reflectance) * water + caustic * skySunVisibility * causticColor + glint;
  colour += crestGlow(view, normal, sunDirection, vFromEye.y + cameraPosition.y, reflectance, sunLight, scatterColor);
  // The foam coverage: where its pattern shows, read for each pixel (the vertex stage's,
  // interpolated linearly over triangles whose cells are as large as the coverage's texels, ended a
  // patch in a triangle's straight edge); farther, the vertex stage's, at the vertex's mip level.
  float footprint = restFootprint(restPerPixelX, restPerPixelY);
  float foamShown = foamPatternShown(footprint);
  float pixelFoam = blendedFoam(vBlend, texture(tFoam, largestUv).r, texture(tFoam, largestUv + copyOffset).r);
#ifdef SEABED
  pixelFoam = min(pixelFoam + vShoreFoam, 1.0);
#endif
  pixelFoam = streakedFoam(tFoam, largestUv, vBlend, layerSizes[LAYER_COUNT - 1], pixelFoam);
  float foamCoverage = mix(streakedMeanFoam(vFoam), pixelFoam, foamShown);
#ifdef HULL_FOAM_LAYER
  // The foam of hulls under way (src/layers/hullFoam.ts), over the local waves' grid, joined to the
  // whitecaps' as two independent coverages are: 1 − (1 − a)(1 − b).
  float hullFoam = texture(tHullFoam, vLayerUv[HULL_FOAM_LAYER]).r;
  foamCoverage = 1.0 - (1.0 - foamCoverage) * (1.0 - hullFoam);
#endif
  foamCoverage = max(foamCoverage, edgeFoam);
  // Most of the sea has no foam: it pays for the foam's light only where there is (the pattern, two
  // texture lookups, is taken above for every pixel: its fwidth needs the neighbours).
  if (foamCoverage > FOAM_VISIBLE) {
    // Where the pattern does not show, whole white cells with the coverage's share (foamCells.glsl).
    float far = foamShown < 1.0 ? foamCellOpacity(foamCoverage, foamRestPoint, restPerPixelX, restPerPixelY,
                                                      layerSizes[LAYER_COUNT - 1] / float(textureSize(tFoam, 0).x), FOAM_MEAN_BUBBLES) : 0.0;
    float opacity = foamOpacity(foamCoverage, foamDetail, foamDetailPerPixel, foamShown, far);
    if (opacity > 0.0) colour = mix(colour, foamRadiance(normal, sunDirection, sunLight, environmentRadiance(normal)), min(opacity, 1.0));
  }
  colour = throughSpray(colour, vFromEye, vFromEye.y + cameraPosition.y, environmentRadiance(normalize(vec3(view.x, 0.0, view.z))));
  #endif
  gl_FragColor = vec4(colour, 1.0);
  #include <tonemapping_fragment>
  #include <colorspace_fragment>
  #include <fog_fragment>
#endif
}
