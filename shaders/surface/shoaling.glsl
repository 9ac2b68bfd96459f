// The shore (src/layers/shore.ts): the seabed's depth under the rest point and, per wave layer, its
// shoaling factor F_layer(d), then the height limited by breaking. The formulas and their sources
// are in src/spectrum/shoaling.ts (linear shoaling Ks = √(c_g,ref / c_g(d)), Dean & Dalrymple 1991
// eq. 4.82; McCowan's 1894 limit H ≤ 0.78·d); the queries (surfaceQuery.ts) apply the same ones to
// the same tables. Included only with the SEABED define.
uniform sampler2D tSeabed;          // (depth m, slope |∇d|) at the map's nodes, RG32F, read with texelFetch
uniform vec4 seabedFrame;           // (eye's node coordinates x, z; nodes per metre x, z), see Shore.setEye
uniform vec2 seabedNodes;           // nodes along x and z
uniform float seabedOutsideDepth;   // the `depth` option (1e30 for deep water)
uniform sampler2D tShoaling;        // F: SHOALING_DEPTHS depths (x) × LAYER_COUNT layers (y), R32F
uniform vec3 shoalingDepths;        // (log of the shallowest depth, entries per unit of log d, the deepest)
uniform float breakerDepth;         // Hs / 0.78: where the sea's significant wave breaks, m

#define SHOALING_DEPTHS 64
#define SHOALING_MIN_DEPTH 0.05
#define BREAKER_INDEX 0.78
#define BREAKING_KNEE 0.7
#define LAND_DROP 0.3

// Depth (m) and the bottom's slope |∇d| under the point `fromEye` (metres from the eye): bilinear
// between the map's nodes (SeabedMap.depthAt, slopeAt), the `depth` option and a flat bottom outside it.
vec2 seabedAt(vec2 fromEye) {
  vec2 node = seabedFrame.xy + fromEye * seabedFrame.zw;
  if (any(lessThan(node, vec2(0.0))) || any(greaterThan(node, seabedNodes - 1.0))) return vec2(seabedOutsideDepth, 0.0);
  ivec2 cell = min(ivec2(floor(node)), ivec2(seabedNodes) - 2);
  vec2 f = node - vec2(cell);
  vec2 d00 = texelFetch(tSeabed, cell, 0).rg;
  vec2 d10 = texelFetch(tSeabed, cell + ivec2(1, 0), 0).rg;
  vec2 d01 = texelFetch(tSeabed, cell + ivec2(0, 1), 0).rg;
  vec2 d11 = texelFetch(tSeabed, cell + ivec2(1, 1), 0).rg;
  return mix(mix(d00, d10, f.x), mix(d01, d11, f.x), f.y);
}

// F of layer `layer` at depth d: linear in log d between the table's entries (shoalingFactor in
// shoaling.ts), its first entry for d ≤ SHOALING_MIN_DEPTH, 1 from the deepest tabulated on.
float shoalingFactor(int layer, float depth) {
  if (depth >= shoalingDepths.z) return 1.0;
  float position = depth <= SHOALING_MIN_DEPTH ? 0.0 : (log(depth) - shoalingDepths.x) * shoalingDepths.y;
  int j = min(int(floor(position)), SHOALING_DEPTHS - 2);
  float f = position - float(j);
  return mix(texelFetch(tShoaling, ivec2(j, layer), 0).r, texelFetch(tShoaling, ivec2(j + 1, layer), 0).r, f);
}

// The height η limited to ±0.39·d (McCowan), softly: unchanged up to the knee, then bent by tanh
// towards the limit (breakingHeight in shoaling.ts); over land (d ≤ 0) at max(d, −LAND_DROP).
// Returns (limited η, dη_limited/dη, how far past the knee 0..1: the surf).
vec3 breaking(float height, float depth) {
  if (depth <= 0.0) return vec3(max(depth, -LAND_DROP), 0.0, 0.0);
  float limit = 0.5 * BREAKER_INDEX * depth;
  float knee = BREAKING_KNEE * limit;
  float size = abs(height);
  if (size <= knee) return vec3(height, 1.0, 0.0);
  // tanh of a large argument overflows in some GLSL implementations (e^x/e^x): 1 from 10 on in float32.
  float t = tanh(min((size - knee) / (limit - knee), 10.0));
  return vec3(sign(height) * (knee + (limit - knee) * t), 1.0 - t * t, t);
}

// Foam coverage the shore adds: the surf where a wave breaks (`surf`, from breaking()), and a band
// along the shoreline over the surf zone, from the waterline out to where the sea's significant
// wave breaks (d < Hs/0.78): on a gentle beach it is wide, under a cliff a thin line.
float shoreFoam(float depth, float surf) {
  if (depth <= 0.0) return 0.0;
  float band = 1.0 - smoothstep(0.0, breakerDepth, depth);
  return clamp(0.6 * surf + 0.3 * band * band, 0.0, 1.0);
}
