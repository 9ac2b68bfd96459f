// Dither for an 8-bit picture: a smooth gradient (the overcast sky) written to 8 bits steps by whole
// levels in bands several pixels wide, which the eye sees as lines. Adding noise of a triangular
// distribution over ±1 level before the rounding makes the error noise whose mean and variance do
// not depend on the value (Lipshitz, Wannamaker & Vanderkooy 1992, "Quantization and dither: a
// theoretical survey", J. Audio Eng. Soc. 40(5)): no band remains, only a grain of about half a
// level. The noise is Jimenez's interleaved gradient noise ("Next generation post processing in
// Call of Duty: Advanced Warfare", SIGGRAPH 2014), two samples at offset pixels summed for the
// triangle; it is fixed in screen space, so a still picture stays the same.

float interleavedGradientNoise(vec2 pixel) {
  return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}

// `colour`: the picture's value as it is written (tone mapped and encoded), in [0, 1]; `step`: one
// level of the target, 1/255 for 8 bits (0 into a float target: nothing to round).
vec3 dither(vec3 colour, vec2 pixel, float step) {
  float triangle = interleavedGradientNoise(pixel) + interleavedGradientNoise(pixel + vec2(113.0, 71.0)) - 1.0;
  return colour + triangle * step;
}
