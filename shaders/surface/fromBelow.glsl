// The sea surface seen from under water (requires common/fresnel.glsl, surface/absorption.glsl and
// sky/environmentLookup.glsl). A ray from the eye going up meets the surface at cos θi = d·n (n the
// upward normal). Light from the sky comes through it, refracted by Snell's law n_w·sin θi =
// n_a·sin θt, only inside Snell's window, θi < asin(n_a/n_w) (48.6° for n_w = 1.333); outside,
// the Fresnel reflectance from water to air is 1 (total internal reflection: Born & Wolf,
// "Principles of Optics", §1.5.4) and the surface mirrors the deep water below, whose radiance is
// the in-scattered scatterColour. Then the water between the eye and the surface, pathLength metres,
// absorbs and scatters (absorption.glsl).
vec3 surfaceFromBelow(vec3 view, vec3 normal, float pathLength, float iorAir, float iorWater, vec3 absorption, vec3 scatterColour) {
  // A normal that faces away from the eye (a steep wave's far side) is bent back into view.
  float facing = dot(view, normal);
  if (facing < 0.0) normal = normalize(normal - 1.01 * facing * view);
  float cosIncident = dot(view, normal);
  float reflectance = fresnelReflectance(cosIncident, iorWater, iorAir);
  vec3 transmitted = refract(view, -normal, iorWater / iorAir);  // into the air; zero under total reflection
  vec3 sky = reflectance < 1.0 ? environmentRadiance(normalize(transmitted)) : vec3(0.0);
  vec3 surface = reflectance * scatterColour + (1.0 - reflectance) * sky;
  return alongWaterPath(surface, pathLength, absorption, scatterColour);
}
