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
// texels where the multiplier jumps (the sun's edge).
const float SKY_RGBM_RANGE = 32.0;

vec4 rgbmEncode(vec3 radiance) {
  vec3 clipped = clamp(radiance, 0.0, SKY_RGBM_RANGE);
  float multiplier = max(max(clipped.r, clipped.g), max(clipped.b, 1e-6)) / SKY_RGBM_RANGE;
  multiplier = ceil(multiplier * 255.0) / 255.0;  // round up, so rgb stays ≤ 1
  return vec4(clipped / (multiplier * SKY_RGBM_RANGE), multiplier);
}

vec3 rgbmDecode(vec4 texel) {
  return texel.rgb * (texel.a * SKY_RGBM_RANGE);
}
