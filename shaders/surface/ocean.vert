// Ocean surface, vertex stage: a horizon-grid vertex displaced by the sum of the wave layers,
// P = x0 + Σ (λ·Dx, h, λ·Dz) sampled at the rest point x0 (src/fft/waveFieldLayout.ts), the
// largest cascade as a blend of two copies (src/layers/patchBlend.ts).
// Positions are metres from the eye (horizonGrid.glsl), never world coordinates: at 10⁷ m from the
// origin float32 would hold those only to a metre. The view matrix's rotation then takes them to
// view space (its translation, −eye, is what was already subtracted, in double precision in JS).
#include "surface/horizonGrid.glsl"
#include "surface/waveLayers.glsl"
#ifdef SEABED
#include "surface/shoaling.glsl"
#include "surface/swash.glsl"
// Each layer's shoaling factor at the rest point, for the fragment stage's slopes; the breaking
// limit's dη_limited/dη there; the foam the shore adds (shoaling.glsl).
varying float vShoaling[LAYER_COUNT];
varying float vBreakingSlope;
varying float vShoreFoam;
#endif

// Texture coordinate of each ring centre in each layer, (centre / size + ½ texel) mod 1, computed in
// double precision in JS (RingFrames): [ring · LAYER_COUNT + layer].
uniform vec2 ringLayerUvOrigins[(RING_COUNT + 1) * LAYER_COUNT];

varying vec2 vLayerUv[LAYER_COUNT];  // each layer's coordinates of the rest point, for the fragment stage
// λ·Σ ∂Dx/∂z (= ∂Dz/∂x), the cross term of the choppy map's Jacobian, for the normal. Per vertex
// (it comes with the displacement fetch, .w) and interpolated: the fragment stage then fetches one
// texture per layer instead of two. It is a second-order correction of the normal; its value at
// the vertex's mip level is all the detail it needs.
varying float vCrossDerivative;
// The blend's weights (cos θ, sin θ), and the part of the height's slope that comes from their
// change, (−sin θ·h1 + cos θ·h2)·∇θ (h1, h2 the two copies' heights): both vary over hundreds of
// metres and are interpolated.
varying vec2 vBlend;
varying vec2 vBlendSlope;
// The foam coverage, per vertex at the vertex's mip level, for the far sea (the fragment stage
// takes its own where the foam's pattern shows, ocean.frag): far away a pixel spans metres and
// the mip level averages it.
varying float vFoam;
varying vec3 vFromEye;  // the displaced point from the eye, metres
// The rest point (x, z) from the eye's. centroid: with multisampling, a pixel only partly covered by
// a triangle must not evaluate the rest point outside it (the ring-overlap test in ocean.frag would
// then keep a dropped triangle).
centroid varying vec2 vRestFromEye;
flat varying float vRing;
// (centre x, centre z, half side less a hair) of the ring inside this vertex's ring, whose area
// ocean.frag drops; a negative half side for ring 0. Per vertex (flat: one ring per triangle)
// rather than looked up per fragment.
flat varying vec3 vInnerRing;
varying float vLod;
#include <fog_pars_vertex>
#include <logdepthbuf_pars_vertex>
#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
// three's logdepthbuf_vertex asks this of its <common> chunk, which the sea's shaders leave out.
bool isPerspectiveMatrix(mat4 m) {
  return m[2][3] == -1.0;
}
#endif
#ifdef CAPTURE_POSITIONS
uniform float captureWidth;
uniform float captureHeight;
#endif

void main() {
  GridPoint point = horizonGridPoint();
  vec4 blend = blendWeights(point.fromEye);
  vec4 displacement = vec4(0.0);
#ifdef SEABED
  float depth = seabedAt(point.fromEye).x;
  float deepHeight = 0.0;  // the sea's height before shoaling: what the swash follows (swash.glsl)
  vec4 layerDisplacement;  // declared out here: the unrolled loop's bodies share one scope
#endif
  #pragma unroll_loop_start
  for (int i = 0; i < LAYER_COUNT; i++) {
    vLayerUv[ i ] = ringLayerUvOrigins[point.frameRing * LAYER_COUNT + UNROLLED_LOOP_INDEX] + point.fromCentre / layerSizes[ i ];
#ifdef SEABED
    vShoaling[ i ] = shoalingFactor(UNROLLED_LOOP_INDEX, depth);
    layerDisplacement = textureLod(tLayerDisplacement[ i ], vLayerUv[ i ], point.lod + layerLodBias[ i ]);
    displacement += vShoaling[ i ] * layerDisplacement;
    deepHeight += layerDisplacement.y;
#else
    displacement += textureLod(tLayerDisplacement[ i ], vLayerUv[ i ], point.lod + layerLodBias[ i ]);
#endif
  }
  #pragma unroll_loop_end
  // The largest layer went in once with weight 1: make it cos θ·P(x) + sin θ·P(x + o).
  float largestLod = point.lod + layerLodBias[LAYER_COUNT - 1];
  vec4 first = textureLod(tLayerDisplacement[LAYER_COUNT - 1], vLayerUv[LAYER_COUNT - 1], largestLod);
  vec4 copy = textureLod(tLayerDisplacement[LAYER_COUNT - 1], vLayerUv[LAYER_COUNT - 1] + copyOffset, largestLod);
#ifdef SEABED
  // The largest layer's copies, and their blend's slope, shoal with it.
  float largestShoaling = vShoaling[LAYER_COUNT - 1];
  displacement += largestShoaling * ((blend.x - 1.0) * first + blend.y * copy);
  deepHeight += (blend.x - 1.0) * first.y + blend.y * copy.y;
#else
  displacement += (blend.x - 1.0) * first + blend.y * copy;
#endif
  vBlend = blend.xy;
  vFoam = blendedFoam(blend.xy, textureLod(tFoam, vLayerUv[LAYER_COUNT - 1], largestLod).r,
                      textureLod(tFoam, vLayerUv[LAYER_COUNT - 1] + copyOffset, largestLod).r);
  vBlendSlope = (blend.x * copy.y - blend.y * first.y) * blend.zw;
#ifdef SEABED
  vBlendSlope *= largestShoaling;
#endif
  displacement.xzw *= choppiness;
#ifdef SEABED
  // Breaking is limited by the water column under the surface point, where the rest point moved to:
  // the depth there raised by the swash level ζ_t, on which the waves ride (swash.glsl).
  vec2 column = seabedAt(point.fromEye + displacement.xz);
  float swash = swashLevel(deepHeight, column.x, column.y);
  float columnDepth = column.x + swash;
  vec3 broken = breaking(displacement.y, columnDepth);
  displacement.y = swash + broken.x;
  vBreakingSlope = broken.y;
  vShoreFoam = shoreFoam(columnDepth, broken.z);
  vFoam = clamp(vFoam + vShoreFoam, 0.0, 1.0);
#endif
  vCrossDerivative = displacement.w;
  vec3 fromEye = vec3(point.fromEye.x, -cameraPosition.y, point.fromEye.y) + displacement.xyz;
  vFromEye = fromEye;
  vRestFromEye = point.fromEye;
  vRing = point.ring;
  int ring = int(point.ring);
  vec4 inner = ringFrames[max(ring - 1, 0)];
  vInnerRing = ring > 0 ? vec3(inner.xy, halfRingCells * inner.z * (1.0 - 1e-4)) : vec3(0.0, 0.0, -1.0);
  vLod = point.lod;
#ifdef CAPTURE_POSITIONS
  // Geometry test (tests/browser/ocean/ocean.spec.ts): one texel per vertex in a float target.
  float texel = float(gl_VertexID);
  vec2 target = vec2(mod(texel, captureWidth), floor(texel / captureWidth)) + 0.5;
  gl_Position = vec4(target / vec2(captureWidth, captureHeight) * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = 1.0;
#else
  vec4 mvPosition = vec4(mat3(viewMatrix) * fromEye, 1.0);
  gl_Position = projectionMatrix * mvPosition;
  #include <fog_vertex>
#endif
  // With the renderer's logarithmicDepthBuffer, the depth three's own materials write: else a
  // floating object's submerged part would be compared with a different depth and show through.
  #include <logdepthbuf_vertex>
}
