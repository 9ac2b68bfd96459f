// What the ray refracted into the water meets in the scene (requires surface/absorption.glsl).
// The scene without the sea is drawn each frame from the same camera (src/render/sceneRefraction.ts)
// into sceneColour (cleared to alpha 0) and sceneDepth; this finds where the refracted ray meets
// it in screen space and brings that light back through the water.
//
// The ray from the surface point P goes along t = refract(d, n, n_a/n_w) (Snell's law,
// n_a·sin θi = n_w·sin θt). The scene point B it meets is found by fixed-point iteration on the
// path length L: start with the scene point straight behind P (B0, on the view ray), then
// B_{k+1} = the scene point drawn where P + t·L_k is seen, L_{k+1} = |B_{k+1} − P|. It is exact
// when the scene is locally flat (a bed or a hull's side: P + t·L* lies on it and is drawn where
// it is) and within a few per cent after two steps at the angles a view down into the water has.
// The light from B crosses L metres of water (alongWaterPath: Beer–Lambert with the in-scattered
// deep-water colour filling in).
uniform sampler2D sceneColour;
uniform sampler2D sceneDepth;
uniform bool sceneCaptured;        // false where no capture was drawn this frame (quality 'lowest')
uniform mat4 sceneProjection;      // the camera's projection matrix at the capture
uniform mat4 sceneProjectionInverse;
uniform vec4 sceneViewport;        // the drawing's viewport in pixels: x, y, 1/width, 1/height
uniform int sceneDepthMode;        // SCENE_DEPTH_* below: how the depth buffer stores depth
uniform float sceneLogDepthRange;  // log2(far + 1), for the logarithmic depth buffer
#define SCENE_DEPTH_STANDARD 0     // window depth = (z_ndc + 1)/2
#define SCENE_DEPTH_REVERSED 1     // window depth = z_ndc (reversed depth, clip control 0..1)
#define SCENE_DEPTH_LOGARITHMIC 2  // window depth = log2(1 + w)/log2(far + 1) (three.js logdepthbuf)
#define SCENE_REFRACTION_STEPS 2
#define SCENE_MARCH_STEPS 24   // even steps across the screen along a ray (sceneAlongRay)
#define SCENE_MARCH_REFINE 5   // halvings of the step where the ray passes behind the scene

// The view-space point drawn into the capture at screen position uv (0..1), whose depth texel
// there is `depth`.
vec3 capturedViewPoint(vec2 uv, float depth) {
  float ndcZ = depth * 2.0 - 1.0;
  if (sceneDepthMode == SCENE_DEPTH_REVERSED) ndcZ = depth;
  if (sceneDepthMode == SCENE_DEPTH_LOGARITHMIC) {
    float w = exp2(depth * sceneLogDepthRange) - 1.0;  // distance in front of the eye, −z_view
    ndcZ = (sceneProjection[2][2] * -w + sceneProjection[3][2]) / w;
  }
  vec4 point = sceneProjectionInverse * vec4(uv * 2.0 - 1.0, ndcZ, 1.0);
  return point.xyz / point.w;
}

// The view-space point drawn into the capture at uv.
vec3 capturedViewPoint(vec2 uv) {
  return capturedViewPoint(uv, texture(sceneDepth, uv).r);
}

// Whether a depth texel of the capture is still the cleared far value: nothing was drawn there.
bool capturedNothing(float depth) {
  return sceneDepthMode == SCENE_DEPTH_REVERSED ? depth <= 0.0 : depth >= 1.0;
}

// Where a view-space point is drawn on the screen (0..1).
vec2 screenPosition(vec3 viewPoint) {
  vec4 clip = sceneProjection * vec4(viewPoint, 1.0);
  return clip.xy / clip.w * 0.5 + 0.5;
}

// The height above the eye of a view-space point: its world offset from the eye is R^T·v (the view
// rotation R = mat3(viewMatrix) is orthogonal), whose y is v·(R's second column).
float heightAboveEye(vec3 viewPoint) {
  return dot(mat3(viewMatrix)[1], viewPoint);
}

// The light refracted into the water at the surface point surfaceView (view space, with refracted
// its refracted direction there, also in view space) brings back: the scene under the surface
// through the water, or skyThroughWater (throughWater of the sky) where the capture has nothing.
// edgeDistance gets the distance along the view from the surface to the scene behind it when that
// is under the water (the water's edge on an object), else a large number.
vec3 sceneThroughWater(vec3 surfaceView, vec3 refracted, vec2 pixel, vec3 skyThroughWater, vec3 absorption, vec3 scatterColour, out float edgeDistance) {
  edgeDistance = 1e6;
  if (!sceneCaptured) return skyThroughWater;
  float waterHeight = heightAboveEye(surfaceView);
  vec2 straightUv = (pixel - sceneViewport.xy) * sceneViewport.zw;
  // Each depth texel is read once: the one the ray ends on is kept for the coverage below.
  float straightDepth = texture(sceneDepth, straightUv).r;
  vec3 behind = capturedViewPoint(straightUv, straightDepth);
  // The sea is drawn over what is in front of it, so the scene straight behind is behind the surface
  // up to the capture's resolution; only what is under the water shows through it.
  bool straightCovered = texture(sceneColour, straightUv).a > 0.0 && heightAboveEye(behind) < waterHeight;
  if (straightCovered) edgeDistance = length(behind - surfaceView);
  vec2 uv = straightUv;
  vec3 point = behind;
  float depth = straightDepth;
  for (int i = 0; i < SCENE_REFRACTION_STEPS; i++) {
    // Off the picture, the nearest point on its edge: the scene there goes on much as at its edge
    // (a bed), where the undistorted pixel's longer path would show a seam.
    vec2 next = clamp(screenPosition(surfaceView + refracted * length(point - surfaceView)), vec2(0.0), vec2(1.0));
    float foundDepth = texture(sceneDepth, next).r;
    vec3 found = capturedViewPoint(next, foundDepth);
    // What is drawn there may hide what the ray meets: an object above the water (in front of
    // what lies under it), or one on the far side of the surface point's depth from where the ray
    // goes (its view depth only grows, or only shrinks, along P + s·t, s > 0: nothing the ray meets
    // lies on the other side; the near face of an object under the water, seen from the water
    // beyond its top edge, would otherwise show its colour there as a halo). The undistorted
    // pixel instead: the scene straight behind the surface point.
    if (heightAboveEye(found) > waterHeight || (found.z - surfaceView.z) * refracted.z < 0.0) {
      uv = straightUv;
      point = behind;
      depth = straightDepth;
      break;
    }
    uv = next;
    point = found;
    depth = foundDepth;
  }
  vec4 scene = texture(sceneColour, uv);
  // Something drawn above the water behind the surface (a mast beyond it) is not under it, and
  // where the depth (read without filtering) shows nothing drawn, the colour's alpha (filtered
  // across an object's outline) is not an object there: taken, the deep water's colour of the
  // far point drew dark lines along the outlines of objects under the water.
  float coverage = heightAboveEye(point) < waterHeight && !capturedNothing(depth) ? scene.a : 0.0;
  if (coverage == 0.0) return skyThroughWater;
  // The capture's colour is premultiplied by its coverage (drawn over transparent black, and
  // filtered linearly at an object's outline): the object's own radiance is rgb/a.
  return mix(skyThroughWater, alongWaterPath(scene.rgb / coverage, length(point - surfaceView), absorption, scatterColour), coverage);
}

// The scene's radiance along the ray from the view-space point `origin` in the unit direction `ray`,
// premultiplied by its coverage, in alpha (0: the ray leaves the picture or meets nothing drawn), where the
// iteration above has no scene point to start from: the light seen in Snell's window from under
// the water, whose straight-behind point is the sky. A screen-space march (McGuire & Mara 2014,
// "Efficient GPU screen-space ray tracing", JCGT 3(4)): even steps in the picture from the origin's
// pixel towards the far point's, clipped to the picture, where the ray's depth is found exactly
// by interpolating 1/depth, which is linear on the screen under a perspective projection. Where
// the ray passes behind what the capture shows, the step is halved SCENE_MARCH_REFINE times; a
// crossing counts where the depths then agree within 2 % (the ray meets that surface, not one that
// passed behind it) and the point is above the water at `origin` (what the ray in the air can meet).
vec4 sceneAlongRay(vec3 origin, vec3 ray) {
  if (!sceneCaptured) return vec4(0.0);
  float near = sceneProjection[3][2] / (sceneProjection[2][2] - 1.0);
  float far = sceneProjection[3][2] / (sceneProjection[2][2] + 1.0);
  // As far as the far plane, and no nearer the eye than its near plane.
  float reach = 0.9 * far;
  if (ray.z > 0.0) reach = min(reach, (-1.01 * near - origin.z) / ray.z);
  if (reach <= 0.0) return vec4(0.0);
  vec3 end = origin + ray * reach;
  vec2 uvStart = screenPosition(origin);
  vec2 uvEnd = screenPosition(end);
  // Clip the segment to the picture: the largest fraction f at which mix(uvStart, uvEnd, f) is in it.
  vec2 span = uvEnd - uvStart;
  vec2 room = mix(-uvStart, 1.0 - uvStart, step(0.0, span));
  float fitX = abs(span.x) > 1e-6 ? room.x / span.x : 1.0;
  float fitY = abs(span.y) > 1e-6 ? room.y / span.y : 1.0;
  float last = clamp(min(fitX, fitY), 0.0, 1.0);
  float inverseStart = 1.0 / -origin.z;
  float inverseEnd = 1.0 / -end.z;
  float waterHeight = heightAboveEye(origin);
  float before = 0.0;
  for (int i = 1; i <= SCENE_MARCH_STEPS; i++) {
    float f = last * float(i) / float(SCENE_MARCH_STEPS);
    vec2 uv = mix(uvStart, uvEnd, f);
    float rayDepth = 1.0 / mix(inverseStart, inverseEnd, f);
    if (rayDepth < -capturedViewPoint(uv).z) {
      before = f;
      continue;
    }
    // Behind what is drawn here: halve the step towards the crossing.
    float after = f;
    for (int k = 0; k < SCENE_MARCH_REFINE; k++) {
      float middle = 0.5 * (before + after);
      if (1.0 / mix(inverseStart, inverseEnd, middle) < -capturedViewPoint(mix(uvStart, uvEnd, middle)).z) before = middle;
      else after = middle;
    }
    uv = mix(uvStart, uvEnd, after);
    vec3 found = capturedViewPoint(uv);
    rayDepth = 1.0 / mix(inverseStart, inverseEnd, after);
    if (abs(rayDepth + found.z) < 0.02 * rayDepth && heightAboveEye(found) >= waterHeight) return texture(sceneColour, uv);
    before = f;
  }
  return vec4(0.0);
}
