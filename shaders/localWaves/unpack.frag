// Local waves: the state after a step, (η_s, ψ, ∂η_s/∂x, ∂η_s/∂z), as the two field textures of a
// wave layer (src/fft/waveFieldLayout.ts): vertical motion only.
uniform highp sampler2D tState;

layout(location = 0) out vec4 displacement;  // (Dx, h, Dz, ∂Dx/∂z)
layout(location = 1) out vec4 derivatives;   // (∂h/∂x, ∂h/∂z, ∂Dx/∂x, ∂Dz/∂z)

void main() {
  vec4 state = texelFetch(tState, ivec2(gl_FragCoord.xy), 0);
  displacement = vec4(0.0, state.x, 0.0, 0.0);
  derivatives = vec4(state.zw, 0.0, 0.0);
}
