// Shows one channel of a field texture over one patch with a colour map: the report's Figures 1–5
// drawn from the real textures. value / scale maps [-1, 1] to the colour map.
uniform sampler2D tField;
uniform vec4 channelMask;  // picks the channel: dot(texel, channelMask)
uniform float scale;
uniform bool diverging;    // blue–white–red for signed fields; grey (the report's Figure 3) otherwise

in vec2 vUv;
out vec4 fragColor;

void main() {
  float value = clamp(dot(texture(tField, vUv), channelMask) / scale, -1.0, 1.0);
  vec3 colour = diverging
      ? (value < 0.0 ? mix(vec3(1.0), vec3(0.15, 0.3, 0.85), -value) : mix(vec3(1.0), vec3(0.85, 0.2, 0.15), value))
      : vec3(0.5 + 0.5 * value);
  fragColor = vec4(colour, 1.0);
}
