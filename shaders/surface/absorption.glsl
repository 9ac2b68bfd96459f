// Light through the water volume (Beer–Lambert law, per colour channel): what the refracted ray
// sees is attenuated by exp(−σ·L) over its path L in the water and replaced by in-scattered
// light of the scattering colour:
//   c = c_env·e^{−σL} + c_scatter·(1 − e^{−σL})
// absorption is σ in 1/m; the path is the length of the refracted ray down to viewDepth metres.
vec3 throughWater(vec3 environmentColour, vec3 refracted, vec3 absorption, vec3 scatterColour, float viewDepth) {
  float pathLength = viewDepth / max(-refracted.y, 0.05);
  vec3 transmittance = exp(-absorption * pathLength);
  return environmentColour * transmittance + scatterColour * (1.0 - transmittance);
}
