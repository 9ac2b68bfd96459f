// Swash (src/spectrum/swash.ts, where the sources are): the level ζ the water runs up and down a
// beach to, from Stockdon et al. 2006's setup η̄ = 0.35·β·√(H0·L0) (eq. 10) and significant swash
// S = √(H0·L0·(0.563·β² + 0.004)) (eq. 11–12), following the sea's deep-water elevation:
// ζ = η̄ + (S/Hs)·η_deep, faded out between SWASH_FULL·S and SWASH_END·S of depth. Included with
// shoaling.glsl (the SEABED define).
uniform vec2 swashSea;  // (√(H0·L0) m, Hs m): Shore.prepare; x = 0 without waves (no swash)

#define MAX_BEACH_SLOPE 0.2
#define SWASH_FULL 0.5
#define SWASH_END 1.5

// ζ_t at depth d (m) on a bottom of slope β, where the sea's elevation before shoaling is `deepHeight`.
float swashLevel(float deepHeight, float depth, float slope) {
  if (swashSea.x == 0.0) return 0.0;
  float beta = min(abs(slope), MAX_BEACH_SLOPE);
  float setup = 0.35 * beta * swashSea.x;
  float swash = swashSea.x * sqrt(0.563 * beta * beta + 0.004);
  float level = setup + (swash / swashSea.y) * deepHeight;
  return level * (1.0 - smoothstep(SWASH_FULL * swash, SWASH_END * swash, depth));
}
