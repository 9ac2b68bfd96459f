// One step of the whitecap foam model of src/layers/foamModel.ts (which cites its sources), for
// each texel of the foam field (the largest cascade's patch, texel (i, j) at (i, j)·size/M):
//   J = (1 + λ·ΣDx,x)(1 + λ·ΣDz,z) − (λ·ΣDx,z)²   over every cascade (Tessendorf 2001 §4.6)
//   C = clamp((J_START − J) / (J_START − J_FULL), 0, 1)
//   F ← min(1, F·decay + gain·C),   decay = e^{−Δt/τ}, gain = R·τ·(1 − decay)
// J_START, J_FULL and R are the sea's, from its Jacobian statistics (calibrateFoam in foamModel.ts).
// Each cascade is read at its texel nearest to the foam texel's point, index
// floor(i·texelScale + ½) mod N, in float32 as nearestTexels() in foamModel.ts computes it.
// LAYER_COUNT is a define; the loop is unrolled (see shaders/surface/waveLayers.glsl why).
uniform highp sampler2D tPreviousFoam;
uniform highp sampler2D tLayerDisplacement[LAYER_COUNT];  // (Dx, h, Dz, ∂Dx/∂z)
uniform highp sampler2D tLayerDerivatives[LAYER_COUNT];   // (∂h/∂x, ∂h/∂z, ∂Dx/∂x, ∂Dz/∂z)
uniform float layerTexelScale[LAYER_COUNT];  // the layer's texels per foam texel
uniform int layerResolution[LAYER_COUNT];
uniform float choppiness;
uniform float jacobianStart;  // J_START of the sea (foamModel.ts' calibrateFoam)
uniform float jacobianFull;   // J_FULL of the sea
uniform float decay;
uniform float gain;

layout(location = 0) out vec4 foam;  // (coverage, 0, 0, 1): the red-only target keeps the coverage

ivec2 nearestTexel(ivec2 texel, float scale, int resolution) {
  return ivec2(floor(vec2(texel) * scale + 0.5)) % resolution;
}

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec3 terms = vec3(0.0);  // Σ (Dx,x, Dz,z, Dx,z)
  #pragma unroll_loop_start
  for (int i = 0; i < LAYER_COUNT; i++) {
    {  // a scope per unrolled copy
      ivec2 at = nearestTexel(texel, layerTexelScale[ i ], layerResolution[ i ]);
      terms += vec3(texelFetch(tLayerDerivatives[ i ], at, 0).zw, texelFetch(tLayerDisplacement[ i ], at, 0).w);
    }
  }
  #pragma unroll_loop_end
  float jacobian = (1.0 + choppiness * terms.x) * (1.0 + choppiness * terms.y) - choppiness * choppiness * terms.z * terms.z;
  float folding = clamp((jacobianStart - jacobian) / (jacobianStart - jacobianFull), 0.0, 1.0);
  float previous = texelFetch(tPreviousFoam, texel, 0).r;
  foam = vec4(min(1.0, previous * decay + gain * folding), 0.0, 0.0, 1.0);
}
