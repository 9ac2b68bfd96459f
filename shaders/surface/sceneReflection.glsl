// The scene reflected in the waves (src/render/sceneReflection.ts renders it): the radiance along
// the reflected ray R from the drawn surface point P, looked up in a render of the scene from the
// eye mirrored in the plane y = 0 (a planar mirror, as three.js's Reflector, but read along the
// waves' own rays), premultiplied by how much of the pixel the scene covers (alpha 0 where it
// shows nothing, and the sky shows instead).
//
// The ray meets the scene at Q = P + t·R. On a calm sea (P on y = 0, R the mirror image of the
// view ray) the mirror camera sees Q through P itself, for every t; on waves it does not, and t is
// found by fixed-point iteration on the mirror render's depth: start from the scene point the
// mirror camera sees through P, take t as its distance along R, look again where P + t·R falls.
// Each step corrects the image's place for the wave's height and slope, so the reflection rides
// on the displaced surface and bends with it (the iteration of parallax mapping: Policarpo,
// Oliveira & Comba 2005, "Real-time relief mapping on arbitrary polygonal surfaces", §3).
//
// Positions are from the eye (vFromEye), as the matrices are (SceneReflection.render).
#include "sky/environmentLookup.glsl"

uniform sampler2D sceneReflectionColor;  // linear radiance × coverage, coverage in alpha
uniform sampler2D sceneReflectionDepth;
uniform mat4 sceneReflectionToClip;       // from the eye to the mirror camera's clip space
uniform mat4 sceneReflectionFromClip;     // its inverse
uniform bool sceneReflectionShown;        // false: nothing to read this render (see sceneReflection.ts)

// Fixed-point steps after the first guess (each a depth lookup).
#define SCENE_REFLECTION_STEPS 2
// The width (in uv) over which the reflection fades at the mirror render's edges, where rays bent
// by the waves leave what it saw: the sky takes over without a seam.
#define SCENE_REFLECTION_EDGE 0.04

// Where a point (w = 1) or a direction (w = 0, the point at infinity) falls in the mirror render;
// z < 0 when it is behind the mirror camera.
vec3 sceneReflectionUv(vec4 fromEye) {
  vec4 clip = sceneReflectionToClip * fromEye;
  return vec3(clip.xy / clip.w * 0.5 + 0.5, clip.w);
}

// The point of the ray P + t·R at the distance of the scene the mirror render shows at `uv`
// (its depth unprojected), or the ray's direction (w = 0) where it shows nothing.
vec4 sceneReflectionRayPoint(vec3 fromEye, vec3 ray, vec2 uv) {
  float depth = texture(sceneReflectionDepth, uv).r;
  if (depth >= 1.0) return vec4(ray, 0.0);
  vec4 scene = sceneReflectionFromClip * vec4(vec3(uv, depth) * 2.0 - 1.0, 1.0);
  float t = max(dot(scene.xyz / scene.w - fromEye, ray), 0.0);
  return vec4(fromEye + t * ray, 1.0);
}

// How far (as a fraction of the distance along the ray) the scene point the last lookup shows may
// lie off the ray and still count as met: beyond, the iteration did not converge on that object
// (it is elsewhere, e.g. in front of the surface point) and the sky shows instead.
#define SCENE_REFLECTION_MISS vec2(0.05, 0.2)

// The slopes a pixel's normal does not show (seaLighting.glsl's subPixelSlopeVariance, σ²) spread
// the rays its facets reflect: a facet tilted by ε in the plane of incidence turns the reflected ray
// by 2ε, one tilted by ε across it by 2ε·cos θi (the law of reflection). Returns the share of those
// rays that meet what the mirror render shows, read around the converged point Q at the distance
// `along` it lies along R (0: it shows nothing there, and the rays are read at infinity) in the rays
// of the Gaussian spread's taps (slopeTaps.glsl, as filteredSkyReflection takes them for the sky),
// s² = σ²/2 per axis. On calm water (σ² = 0) every ray is R.
float sceneReflectionSpreadCoverage(vec3 fromEye, vec3 ray, float along, float variance) {
  vec3 facet = normalize(ray - normalize(fromEye));  // the normal that reflects the view into R
  float cosIncident = clamp(dot(ray, facet), 0.0, 1.0);
  vec3 across = cross(ray, facet);
  across = dot(across, across) > 1e-8 ? normalize(across) : normalize(cross(ray, vec3(1.0, 0.0, 0.0)));
  vec3 inPlane = cross(across, ray);
  float s = sqrt(0.5 * variance);
  float coverage = 0.0;
  for (int i = 0; i < SLOPE_TAPS; i++) {
    vec3 tap = slopeTap(i);
    vec3 turned = normalize(ray + 2.0 * s * (tap.x * inPlane + tap.y * cosIncident * across));
    vec4 point = along > 0.0 ? vec4(fromEye + along * turned, 1.0) : vec4(turned, 0.0);
    coverage += tap.z * texture(sceneReflectionColor, clamp(sceneReflectionUv(point).xy, 0.0, 1.0)).a;
  }
  return coverage;
}

// The scene's radiance along `ray` (unit, upwards) from the surface point `fromEye`, premultiplied
// by its coverage (alpha): blend as rgb + (1 − a)·sky. `variance`, the pixel's sub-pixel slope
// variance σ², fades it to the share of the pixel's facets whose rays meet the scene there
// (sceneReflectionSpreadCoverage; never above what R alone sees): a lone crest pixel whose ray
// alone grazes an object, a speckle among its neighbours, keeps only that share, while the
// reflection's body, where the spread rays meet the object too, stays whole. It is not spread into
// pixels whose own ray misses: the colour is R's.
vec4 sceneReflection(vec3 fromEye, vec3 ray, float variance) {
  if (!sceneReflectionShown) return vec4(0.0);
  vec3 uv = sceneReflectionUv(vec4(fromEye, 1.0));
  for (int i = 0; i < SCENE_REFLECTION_STEPS; i++) {
    uv = sceneReflectionUv(sceneReflectionRayPoint(fromEye, ray, clamp(uv.xy, 0.0, 1.0)));
  }
  if (uv.z <= 0.0) return vec4(0.0);
  vec2 inside = min(uv.xy, 1.0 - uv.xy) / SCENE_REFLECTION_EDGE;
  float weight = clamp(min(inside.x, inside.y), 0.0, 1.0);
  // Whether the ray meets what the mirror render shows there (where it shows depth: transparent
  // objects that write none are taken as far away, as the sky is).
  float depth = texture(sceneReflectionDepth, uv.xy).r;
  float along = 0.0;
  if (depth < 1.0) {
    vec4 scene = sceneReflectionFromClip * vec4(vec3(uv.xy, depth) * 2.0 - 1.0, 1.0);
    vec3 toScene = scene.xyz / scene.w - fromEye;
    along = dot(toScene, ray);
    float off = length(toScene - along * ray);
    weight *= along > 0.0 ? 1.0 - smoothstep(SCENE_REFLECTION_MISS.x, SCENE_REFLECTION_MISS.y, off / along) : 0.0;
  }
  vec4 seen = texture(sceneReflectionColor, uv.xy);
  // The result is weight·seen times a factor: 0 where the converged ray shows nothing or fades out,
  // most of the sea, which so skips the spread's six lookups.
  if (weight == 0.0 || seen == vec4(0.0)) return vec4(0.0);
  return weight * seen * min(1.0, sceneReflectionSpreadCoverage(fromEye, ray, max(along, 0.0), variance) / max(seen.a, 1e-4));
}

// The light the sea reflects along `ray` (unit, upwards) from `fromEye`: the scene's where the
// mirror render has it (premultiplied by its coverage, faded by the sub-pixel slope variance
// `variance`), in front of `sky`, the sky's light the sea reflects there (SCENE_REFLECTIONS: the
// option reflections, 'scene').
vec3 reflectedRadiance(vec3 fromEye, vec3 ray, vec3 sky, float variance) {
#if SCENE_REFLECTIONS
  vec4 scene = sceneReflection(fromEye, ray, variance);
  return scene.rgb + (1.0 - scene.a) * sky;
#else
  return sky;
#endif
}
