// One inspector tile: a field texture drawn over one patch with a colour map, straight from the
// texture the simulation wrote (the course report's Figures 1–5, live).
//   value = dot(texel, channelMask), or the Jacobian J = (1 + ∂Dx/∂x)(1 + ∂Dz/∂z) − (∂Dx/∂z)²
//   (Tessendorf 2001 §4.6) when JACOBIAN is set, from tField = derivatives, tSecond = displacement;
//   shown as (value − offset) / scale, clamped to [−1, 1]; LOG_SCALE shows log10(value) instead.
uniform sampler2D tField;
uniform sampler2D tSecond;
uniform vec4 channelMask;
uniform float offset;
uniform float scale;
uniform bool diverging;   // blue–white–red for signed fields; grey (the report's Figure 3) otherwise
uniform bool centred;     // spectra: k = 0 in the middle, magnified by zoom (energy sits at small k)
uniform float zoom;

in vec2 vUv;
out vec4 fragColor;

void main() {
  vec2 uv = centred ? (vUv - 0.5) / zoom : vUv;  // FFT order: k = 0 is texel 0, REPEAT wraps −k
#ifdef JACOBIAN
  vec4 d = texture(tField, uv);
  float dxDz = texture(tSecond, uv).w;
  float raw = (1.0 + d.z) * (1.0 + d.w) - dxDz * dxDz;
#else
  float raw = dot(texture(tField, uv), channelMask);
#endif
#ifdef LOG_SCALE
  raw = log(max(raw, 1e-30)) / log(10.0);
#endif
  float value = clamp((raw - offset) / scale, -1.0, 1.0);
  vec3 colour = diverging
      ? (value < 0.0 ? mix(vec3(1.0), vec3(0.15, 0.3, 0.85), -value) : mix(vec3(1.0), vec3(0.85, 0.2, 0.15), value))
      : vec3(0.5 + 0.5 * value);
  fragColor = vec4(colour, 1.0);
}
