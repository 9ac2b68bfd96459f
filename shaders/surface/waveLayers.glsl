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
// Whitecap foam (src/layers/whitecapFoam.ts): coverage in .r over the largest layer's patch, with
// its size and texels, so it is sampled with the largest layer's coordinates and mip level.
uniform sampler2D tFoam;

// The largest cascade is drawn twice and blended (src/layers/patchBlend.ts says why and fills
// these): cos θ·P(x) + sin θ·P(x + o), θ(x) = Σ a_j·sin(k_j·x + φ_j), patchBlend[j] = (kx, kz, φ, a)
// with the phase φ_j at the eye (the origin of the positions here, see horizonGrid.glsl), copyOffset
// = o in the largest layer's texture coordinates.
uniform vec4 patchBlend[3];
uniform vec2 copyOffset;

// (cos θ, sin θ, ∂θ/∂x, ∂θ/∂z) at the rest point `fromEye` (metres from the eye).
vec4 blendWeights(vec2 fromEye) {
  float theta = 0.0;
  vec2 gradient = vec2(0.0);
  for (int j = 0; j < 3; j++) {
    float phase = dot(patchBlend[j].xy, fromEye) + patchBlend[j].z;
    theta += patchBlend[j].w * sin(phase);
    gradient += patchBlend[j].w * cos(phase) * patchBlend[j].xy;
  }
  return vec4(cos(theta), sin(theta), gradient);
}

// The foam coverage from its two copies' values at x and x + o (the largest layer's patch), with
// `blend` = (cos θ, sin θ): weights cos²θ + sin²θ = 1, so a uniform coverage stays itself.
float blendedFoam(vec2 blend, float first, float copy) {
  return blend.x * blend.x * first + blend.y * blend.y * copy;
}
