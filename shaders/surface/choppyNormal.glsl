// Surface normal of the displaced sea from the FFT derivatives (src/fft/waveFieldLayout.ts).
// A point x0 of the rest plane moves to P(x0) = (x0 + Dx, h, z0 + Dz), so its tangents are
//   ∂P/∂x0 = (1 + ∂Dx/∂x, ∂h/∂x, ∂Dx/∂z),   ∂P/∂z0 = (∂Dx/∂z, ∂h/∂z, 1 + ∂Dz/∂z)
// and the upward normal is ∂P/∂z0 × ∂P/∂x0. Without displacement this is (−∂h/∂x, 1, −∂h/∂z),
// the course report's normal (§2.2, Tessendorf 2001 eq. 20); its y component is the Jacobian.
vec3 choppyNormal(vec4 derivatives, float dxDz) {
  vec3 alongX = vec3(1.0 + derivatives.z, derivatives.x, dxDz);
  vec3 alongZ = vec3(dxDz, derivatives.y, 1.0 + derivatives.w);
  return normalize(cross(alongZ, alongX));
}
