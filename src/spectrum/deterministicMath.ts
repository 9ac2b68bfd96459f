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

/*
 * Functions the physical spectra need (frequencySpectra.ts, spreading.ts, seaState.ts), built on
 * detExp and detLog or directly from IEEE arithmetic, for the same reason as above: the initial
 * spectrum must not depend on the engine's Math.pow, Math.tanh, Math.atan2 or Math.cosh.
 */

/** e^x − 1, deterministic; accurate also for small |x|, where detExp(x) − 1 would cancel. */
export function detExpm1(x: number): number {
  if (Number.isNaN(x)) return NaN;
  // Beyond |x| = 1 the cancellation in e^x − 1 costs at most a factor e/(e − 1) ≈ 1.6.
  if (x > 1 || x < -1) return detExp(x) - 1;
  // Taylor series x·(1 + x/2·(1 + x/3·(…))): for |x| ≤ 1 the term x^20/20! is below 2^−61·x.
  let series = 1;
  for (let term = 20; term >= 2; term--) series = 1 + (x / term) * series;
  return x * series;
}

/**
 * x^y for x ≥ 0, deterministic: e^{y·ln x}. The rounding of y·ln x is magnified by e^(·), so the
 * relative error is about |y·ln x|·2^−52 plus a few ulp (tests/unit/deterministicMath.test.ts);
 * fine for spectra, whose exponents are small. Negative x gives NaN (not needed here).
 */
export function detPow(x: number, y: number): number {
  if (Number.isNaN(x) || Number.isNaN(y)) return NaN;
  if (y === 0 || x === 1) return 1;
  if (x < 0) return NaN;
  if (x === 0) return y > 0 ? 0 : Infinity;
  if (x === Infinity) return y > 0 ? Infinity : 0;
  return detExp(y * detLog(x));
}

/** tanh x, deterministic: −expm1(−2|x|)/(expm1(−2|x|) + 2), which cancels nowhere. */
export function detTanh(x: number): number {
  if (Number.isNaN(x) || x === 0) return x; // keeps the sign of −0, like Math.tanh
  const a = Math.abs(x);
  if (a > 22) return x < 0 ? -1 : 1; // tanh 22 = 1 − 1.6e-19 rounds to 1
  const e = detExpm1(-2 * a);
  const magnitude = -e / (e + 2);
  return x < 0 ? -magnitude : magnitude;
}

/** sech x = 1/cosh x, deterministic: 2e^{−|x|}/(1 + e^{−2|x|}), which never overflows. */
export function detSech(x: number): number {
  if (Number.isNaN(x)) return NaN;
  const e = detExp(-Math.abs(x));
  return (2 * e) / (1 + e * e);
}

// atan at the reduction points 1/2, 1, 3/2 and ∞, each split into the nearest double and the rest
// (from mpmath at 50 digits), so adding a reduced atan loses nothing to the constant.
const ATAN_HI = [0.4636476090008061, 0.7853981633974483, 0.982793723247329, 1.5707963267948966];
const ATAN_LO = [2.2698777452961687e-17, 3.061616997868383e-17, 1.3903311031230998e-17, 6.123233995736766e-17];
const PI_HI = 3.141592653589793;
const PI_LO = 1.2246467991473532e-16;

/** atan t for |t| ≤ 7/16 by its Taylor series t − t³/3 + t⁵/5 − …, leading term kept exact. */
function atanSeries(t: number): number {
  const z = t * t; // ≤ 0.192, so 26 terms reach below 2^−60
  let tail = 0;
  for (let n = 26; n >= 1; n--) tail = (n % 2 === 0 ? 1 : -1) / (2 * n + 1) + z * tail;
  return t + t * (z * tail);
}

/**
 * atan x, deterministic. |x| is reduced to |t| ≤ 7/16 with atan x = atan c + atan((x − c)/(1 + c·x))
 * for c = 1/2, 1, 3/2, or atan x = π/2 − atan(1/x) beyond 39/16 (the breakpoints of fdlibm's atan).
 */
export function detAtan(x: number): number {
  if (Number.isNaN(x) || x === 0) return x; // keeps the sign of −0, like Math.atan
  const a = Math.abs(x);
  let result: number;
  if (a < 7 / 16) result = atanSeries(a);
  else {
    let index: number;
    let t: number;
    if (a < 11 / 16) [index, t] = [0, (2 * a - 1) / (2 + a)];
    else if (a < 19 / 16) [index, t] = [1, (a - 1) / (a + 1)];
    else if (a < 39 / 16) [index, t] = [2, (a - 1.5) / (1 + 1.5 * a)];
    else [index, t] = [3, -1 / a];
    result = ATAN_HI[index] + (ATAN_LO[index] + atanSeries(t));
  }
  return x < 0 ? -result : result;
}

/** atan2(y, x) in (−π, π], deterministic, with Math.atan2's signs at ±0 and ±∞. */
export function detAtan2(y: number, x: number): number {
  if (Number.isNaN(x) || Number.isNaN(y)) return NaN;
  const ay = Math.abs(y);
  const ax = Math.abs(x);
  let angle: number; // in [0, π/2], the angle of (|x|, |y|)
  if (ay === Infinity && ax === Infinity) angle = ATAN_HI[1] + ATAN_LO[1];
  else if (ay <= ax) angle = ax === 0 ? 0 : detAtan(ay / ax);
  else angle = ATAN_HI[3] - (detAtan(ax / ay) - ATAN_LO[3]);
  const leftHalf = x < 0 || Object.is(x, -0);
  if (leftHalf) angle = PI_HI - (angle - PI_LO);
  const lowerHalf = y < 0 || Object.is(y, -0);
  return lowerHalf ? -angle : angle;
}

const HALF_LN_2PI = 0.9189385332046728; // ½·ln 2π, from mpmath

/**
 * ln Γ(x) for x > 0, deterministic. Γ(x) = Γ(x + n)/(x·(x+1)···(x+n−1)) moves the argument to
 * z ≥ 10, where Stirling's series (Abramowitz & Stegun 6.1.40, Bernoulli terms up to B14) is
 * accurate to 3e-17 relative. Absolute error ≲ 1e-15·max(1, |ln Γ|) (tests).
 */
export function detLogGamma(x: number): number {
  if (!(x > 0)) return x === 0 ? Infinity : NaN;
  if (x === Infinity) return Infinity;
  let z = x;
  let shiftProduct = 1;
  while (z < 10) {
    shiftProduct *= z;
    z += 1;
  }
  const inverse = 1 / z;
  const inverse2 = inverse * inverse;
  // 1/(12z) − 1/(360z³) + 1/(1260z⁵) − 1/(1680z⁷) + 1/(1188z⁹) − 691/(360360z¹¹) + 1/(156z¹³), by Horner
  // in 1/z² from the last term: B_2n/(2n(2n − 1)) with alternating signs.
  const coefficients = [1 / 12, 1 / 360, 1 / 1260, 1 / 1680, 1 / 1188, 691 / 360360, 1 / 156];
  let tail = 0;
  for (let n = coefficients.length - 1; n >= 0; n--) tail = coefficients[n] - inverse2 * tail;
  const series = inverse * tail;
  const lnGammaZ = (z - 0.5) * detLog(z) - z + HALF_LN_2PI + series;
  return shiftProduct === 1 ? lnGammaZ : lnGammaZ - detLog(shiftProduct);
}
