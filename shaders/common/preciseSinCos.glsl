// (cos x, sin x) to float32 precision. GLSL's own sin and cos are off by up to 1.9e-4 under
// SwiftShader (../shared/BROWSER.md); an error that size in every step of the local waves adds up
// to 1e-3 of their height within a second. Range reduction to r = x − q·π/2, |r| ≤ π/4 (π/2 split
// into two float32 parts, Cody & Waite 1980, "Software Manual for the Elementary Functions"), then
// the Taylor series of cos r and sin r to the terms below float32's 6e-8 at r = π/4.
vec2 preciseCosSin(float x) {
  float quadrant = floor(x * 0.6366197723675814 + 0.5);
  float r = (x - quadrant * 1.5707963705062866) + quadrant * 4.371139000186243e-8;
  float r2 = r * r;
  float c = 1.0 + r2 * (-0.5 + r2 * (1.0 / 24.0 + r2 * (-1.0 / 720.0 + r2 * (1.0 / 40320.0 - r2 / 3628800.0))));
  float s = r * (1.0 + r2 * (-1.0 / 6.0 + r2 * (1.0 / 120.0 + r2 * (-1.0 / 5040.0 + r2 / 362880.0))));
  int q = int(mod(quadrant, 4.0));
  // cos and sin of r + q·π/2.
  if (q == 0) return vec2(c, s);
  if (q == 1) return vec2(-s, c);
  if (q == 2) return vec2(-c, -s);
  return vec2(s, -c);
}
