// Caustic brightness after Guardado & Sánchez-Crespo, "Rendering water caustics", GPU Gems ch. 2
// (course report §2.3): a vertical ray from below leaves the water through the surface with normal
// n, refracting by Snell's law; where it then points at the light it is bright:
//   K = (t · l)^p
// normal points out of the water (up); iorWater is n_w/n_a.
float causticBrightness(vec3 normal, vec3 toLight, float iorWater, float power) {
  vec3 leaving = refract(vec3(0.0, 1.0, 0.0), -normal, iorWater);  // zero when totally reflected
  return pow(max(dot(leaving, toLight), 0.0), power);
}
