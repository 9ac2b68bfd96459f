// The sea's wave layers (src/layers/waveLayer.ts), summed: each layer's textures hold the fields of
// src/fft/waveFieldLayout.ts over a square of side layerSizes[i] (REPEAT-wrapped for FFT cascades),
// with the horizontal parts for a choppiness of 1, so the sum is scaled by `choppiness` here.
// LAYER_COUNT is a define. Sampler arrays can only be indexed by constants in GLSL ES 3.00, so
// loops over layers are unrolled by three.js (#pragma unroll_loop_start), which needs the loop's
// bound as a number: OceanMaterial writes LAYER_COUNT's value into `i < LAYER_COUNT` before
// three.js compiles the shader.
uniform sampler2D tLayerDisplacement[LAYER_COUNT];  // (Dx, h, Dz, ∂Dx/∂z)
uniform sampler2D tLayerDerivatives[LAYER_COUNT];   // (∂h/∂x, ∂h/∂z, ∂Dx/∂x, ∂Dz/∂z)
uniform float layerSizes[LAYER_COUNT];              // metres
uniform float layerLodBias[LAYER_COUNT];            // log2(finest texel / this layer's texel)
uniform float choppiness;                           // λ

// The slow warp of where the cascades are sampled, w(x) = Σ a_j·d_j·sin(k_j·x + φ_j)
// (src/layers/surfaceWarp.ts, which says why and fills surfaceWarp: per component
// (kx, kz, φ, a) then (dx, dz, 0, 0)). Returns w at the rest point, metres.
uniform vec4 surfaceWarp[6];

vec2 surfaceWarpOffset(vec2 world) {
  vec2 offset = vec2(0.0);
  for (int j = 0; j < 6; j += 2) {
    offset += surfaceWarp[j].w * sin(dot(surfaceWarp[j].xy, world) + surfaceWarp[j].z) * surfaceWarp[j + 1].xy;
  }
  return offset;
}
