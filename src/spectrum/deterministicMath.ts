/**
 * exp and log built from IEEE-754 double arithmetic alone.
 *
 * Why: ECMAScript lets each engine approximate Math.exp and Math.log in its own way, so a spectrum
 * built with them could differ in the last bit between browsers or machines. The initial spectrum
 * h̃0 must be bit-identical everywhere for a given seed (reproducible scenes and screenshots), so the
 * two functions it needs are evaluated here with +, −, ×, ÷ and Math.sqrt only, which IEEE-754 and
 * ECMAScript define exactly (JS never fuses multiply-adds). They agree with Math.exp / Math.log to
 * within a few units in the last place (tests/unit/deterministicMath.test.ts).
 */

const LN2_HI = 6.93147180369123816490e-1; // ln 2 split in two so that n·LN2_HI is exact
const LN2_LO = 1.90821492927058770002e-10;
const INV_LN2 = 1.44269504088896338700;

const bits = new DataView(new ArrayBuffer(8));

/** 2^n for an integer n in [-1022, 1023], built from its bit pattern (exact). */
function powerOfTwo(n: number): number {
  bits.setUint32(0, (n + 1023) << 20);
  bits.setUint32(4, 0);
  return bits.getFloat64(0);
}

/** e^x, deterministic. */
export function detExp(x: number): number {
  if (Number.isNaN(x)) return NaN;
  if (x > 709.782712893384) return Infinity; // ln(Number.MAX_VALUE)
  if (x < -745.2) return 0;
  // x = n·ln2 + r with |r| ≤ ln2/2, then e^x = 2^n·e^r and e^r by its Taylor series (Horner).
  const n = Math.round(x * INV_LN2);
  const r = x - n * LN2_HI - n * LN2_LO;
  let series = 1;
  for (let term = 17; term >= 1; term--) series = 1 + (r / term) * series;
  // Split 2^n in two factors so that subnormal results (n < −1022) are still reached.
  const half = n >> 1;
  return series * powerOfTwo(half) * powerOfTwo(n - half);
}

/** Natural logarithm for x > 0, deterministic. */
export function detLog(x: number): number {
  if (!(x > 0)) return x === 0 ? -Infinity : NaN;
  if (x === Infinity) return Infinity;
  // x = m·2^e with m in [√½, √2): read e from the exponent bits (normalising subnormals first).
  let scaleExponent = 0;
  if (x < 2.2250738585072014e-308) {
    x *= 18014398509481984; // 2^54
    scaleExponent = -54;
  }
  bits.setFloat64(0, x);
  const high = bits.getUint32(0);
  let e = ((high >>> 20) & 0x7ff) - 1023;
  bits.setUint32(0, (high & 0x800fffff) | (1023 << 20));
  let m = bits.getFloat64(0);
  if (m > Math.SQRT2) {
    m *= 0.5;
    e += 1;
  }
  e += scaleExponent;
  // ln m = 2·atanh(s) with s = (m − 1)/(m + 1), |s| ≤ 0.172: the odd series converges fast.
  const s = (m - 1) / (m + 1);
  const s2 = s * s;
  let series = 0;
  for (let power = 27; power >= 3; power -= 2) series = (series + 1 / power) * s2;
  const lnM = 2 * s * (1 + series);
  return e * LN2_HI + (e * LN2_LO + lnM);
}

/** [cos, sin] of an angle in degrees, deterministic (exact at multiples of 90°). */
export function detCosSinDegrees(degrees: number): [number, number] {
  // Reduce to [0, 360) exactly (% is exact in IEEE-754), then to an octant angle in [0°, 45°].
  let a = degrees % 360;
  if (a < 0) a += 360;
  if (a >= 360) a = 0; // a tiny negative angle rounds up to 360 above
  const quadrant = Math.floor(a / 90);
  a -= 90 * quadrant;
  const mirrored = a > 45;
  const r = ((mirrored ? 90 - a : a) * Math.PI) / 180; // |r| ≤ π/4
  const r2 = r * r;
  let cosSeries = 1;
  let sinSeries = 1;
  for (let n = 20; n >= 2; n -= 2) {
    cosSeries = 1 - (r2 / (n * (n - 1))) * cosSeries;
    sinSeries = 1 - (r2 / ((n + 1) * n)) * sinSeries;
  }
  const c0 = mirrored ? r * sinSeries : cosSeries;
  const s0 = mirrored ? cosSeries : r * sinSeries;
  // Rotate by the quadrant: (c, s) → (−s, c) per 90°.
  const byQuadrant: [number, number][] = [
    [c0, s0],
    [-s0, c0],
    [-c0, -s0],
    [s0, -c0],
  ];
  return byQuadrant[quadrant];
}
