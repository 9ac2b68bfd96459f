// The sea surface seen from under water (requires common/fresnel.glsl, surface/absorption.glsl,
// sky/environmentLookup.glsl and, with SCENE_REFRACTIONS, surface/sceneRefraction.glsl). A ray from
// the eye going up meets the surface at cos θi = d·n (n the upward normal). Light from the sky and
// from the scene's objects above the water comes through it, refracted by Snell's law n_w·sin θi =
// n_a·sin θt, only inside Snell's window, θi < asin(n_a/n_w) (48.6° for n_w = 1.333; Snell 1621,
// Hecht, "Optics", 5th ed., §4.7.1): the whole sky above, squeezed into a cone of 97°; outside,
// the Fresnel reflectance from water to air is 1 (total internal reflection: Born & Wolf,
// "Principles of Optics", §1.5.4) and the surface mirrors the deep water below, whose radiance is
// the in-scattered scatterColour. Then the water between the eye and the surface, pathLength metres,
// absorbs and scatters (absorption.glsl).

// The light coming down through the surface at fromEye along the unit direction `up` (into the
// air): the scene's objects there in front of the sky, where the capture shows them (the option
// refractions 'scene'), else the sky.
vec3 lightFromAbove(vec3 fromEye, vec3 up) {
  vec3 sky = environmentRadiance(up);
#if SCENE_REFRACTIONS == 1
  vec4 scene = sceneAlongRay(mat3(viewMatrix) * fromEye, mat3(viewMatrix) * up);  // the eye is the view space's origin
  return scene.rgb + (1.0 - scene.a) * sky;  // premultiplied
#else
  return sky;
#endif
}

// The colour of the surface point at fromEye (from the eye, view = its direction) seen from under the water.
vec3 surfaceFromBelow(vec3 view, vec3 normal, vec3 fromEye, float iorAir, float iorWater, vec3 absorption, vec3 scatterColour) {
  // A normal that faces away from the eye (a steep wave's far side) is bent back into view.
  float facing = dot(view, normal);
  if (facing < 0.0) normal = normalize(normal - 1.01 * facing * view);
  float cosIncident = dot(view, normal);
  float reflectance = fresnelReflectance(cosIncident, iorWater, iorAir);
  vec3 transmitted = refract(view, -normal, iorWater / iorAir);  // into the air; zero under total reflection
  vec3 above = reflectance < 1.0 ? lightFromAbove(fromEye, normalize(transmitted)) : vec3(0.0);
  vec3 surface = reflectance * scatterColour + (1.0 - reflectance) * above;
  return alongWaterPath(surface, length(fromEye), absorption, scatterColour);
}
