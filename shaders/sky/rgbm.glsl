// RGBM: linear HDR radiance in an 8-bit RGBA texel, rgb·M with a shared multiplier M = a·RANGE
// (the encoding of Karis's "RGBM color encoding", 2009, used by Unreal and once by three.js).
//
// Why: SkyEnvironment's cube is sampled by every sea pixel (twice) and every sky pixel. Under
// SwiftShader an 8-bit cube samples several times faster than a half-float one (CHANGELOG.md,
// performance history, "The single-patch core"), and a plain 8-bit cube cannot hold HDR. RGBM
// keeps 8 bits of precision relative to each texel's brightest channel: the deep-water blue
// (0.004–0.035) and the sky (0.05–2) both keep their gradients. Radiance above RANGE clips: only the sun disk and the glow just around
// it, which tone mapping shows as white anyway, and the sea adds the sun's glint analytically.
// Bilinear filtering of (rgb, a) is not exactly filtering of radiance; the error is confined to
// texels where the multiplier jumps.
//
// The alpha holds √(M/RANGE), not M/RANGE: bilinear filtering between two texels whose multipliers
// differ by a step ΔM is off by about f(1 − f)·L·(ΔM/M)² (f the filter's weight, L the radiance),
// and a smooth gradient crosses a step every few texels, so the error draws lines along the
// gradient's contours (the faint horizontal bands of the overcast sky). With M/RANGE in alpha, an
// overcast sky of L ≈ 1 has a = 8/255 and ΔM/M = 1/8: 0.4 % of L, a level of the 8-bit picture;
// with its square root a = 45/255 and ΔM/M ≈ 2/45: 0.05 %.
const float SKY_RGBM_RANGE = 32.0;

vec4 rgbmEncode(vec3 radiance) {
  vec3 clipped = clamp(radiance, 0.0, SKY_RGBM_RANGE);
  float root = sqrt(max(max(clipped.r, clipped.g), max(clipped.b, 1e-6)) / SKY_RGBM_RANGE);
  root = ceil(root * 255.0) / 255.0;  // round up, so rgb stays ≤ 1
  return vec4(clipped / (root * root * SKY_RGBM_RANGE), root);
}

vec3 rgbmDecode(vec4 texel) {
  return texel.rgb * (texel.a * texel.a * SKY_RGBM_RANGE);
}
