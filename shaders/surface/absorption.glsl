// Light through the water volume (Beer–Lambert law, per colour channel): light that crosses a path
// of length L in the water is attenuated by exp(−σ·L) and replaced by in-scattered light of the
// scattering colour (the radiance of deep water itself):
//   c = c_light·e^{−σL} + c_scatter·(1 − e^{−σL})
// absorption is σ in 1/m.
vec3 alongWaterPath(vec3 light, float pathLength, vec3 absorption, vec3 scatterColour) {
  vec3 transmittance = exp(-absorption * pathLength);
  return light * transmittance + scatterColour * (1.0 - transmittance);
}

// What the ray refracted into the sea sees: the environment along it, through the water down to
// viewDepth metres (its path is viewDepth / cos of its angle from the vertical).
vec3 throughWater(vec3 environmentColour, vec3 refracted, vec3 absorption, vec3 scatterColour, float viewDepth) {
  return alongWaterPath(environmentColour, viewDepth / max(-refracted.y, 0.05), absorption, scatterColour);
}
