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
// these): cos φ·P(x + o_A) + sin φ·P(x + o_B), φ = ψ − sin(4ψ)/4, ψ(x) = κ·x + ψ0 + Σ a_j·sin(k_j·x + φ_j),
// each copy's offset constant between the lines where its weight is zero. patchBlend[j] = (kx, kz,
// φ, a) for j < 3 with the phase φ_j at the eye (the origin of the positions here, see
// horizonGrid.glsl), patchBlend[3] = (κx, κz, ψ0, 0), patchBlend[4].xy = the offsets' origin.
uniform vec4 patchBlend[5];
// The R2 sequence's step (Roberts 2018), patchBlend.ts's R2_STEP: offset n is frac(origin + n·step).
#define COPY_OFFSET_STEP vec2(0.7548776662466927, 0.5698402909980532)

// The two copies at the rest point `fromEye` (metres from the eye): weights = (cos φ, sin φ, ∇φ),
// offsets = (o_A, o_B) in the largest layer's texture coordinates.
struct PatchCopies {
  vec4 weights;
  vec4 offsets;
};
PatchCopies patchCopies(vec2 fromEye) {
  float psi = dot(patchBlend[3].xy, fromEye) + patchBlend[3].z;
  vec2 gradient = patchBlend[3].xy;
  for (int j = 0; j < 3; j++) {
    float phase = dot(patchBlend[j].xy, fromEye) + patchBlend[j].z;
    psi += patchBlend[j].w * sin(phase);
    gradient += patchBlend[j].w * cos(phase) * patchBlend[j].xy;
  }
  float phi = psi - 0.25 * sin(4.0 * psi);
  float indexA = 2.0 * floor(psi / 3.141592653589793 + 0.5);
  float indexB = 2.0 * floor(psi / 3.141592653589793) + 1.0;
  PatchCopies copies;
  copies.weights = vec4(cos(phi), sin(phi), (1.0 - cos(4.0 * psi)) * gradient);
  copies.offsets = fract(patchBlend[4].xyxy + vec4(indexA * COPY_OFFSET_STEP, indexB * COPY_OFFSET_STEP));
  return copies;
}

// The foam coverage from its two copies' values at x + o_A and x + o_B (the largest layer's patch),
// with `blend` = (cos φ, sin φ): weights cos²φ + sin²φ = 1, so a uniform coverage stays itself.
float blendedFoam(vec2 blend, float first, float copy) {
  return blend.x * blend.x * first + blend.y * blend.y * copy;
}
