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
