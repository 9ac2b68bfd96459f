/**
 * detExp, detLog and detCosSinDegrees against the engine's Math functions.
 *
 * Accuracy is measured in units in the last place (ulp): the distance between two doubles counted
 * in representable doubles. One ulp is at most 2^−52 ≈ 2.2e-16 of the value, so "≤ n ulp" means a
 * relative error of at most n·2.2e-16, also for subnormal results, where a relative bound would be
 * meaningless. Inputs come from a small local generator (mulberry32), not from src/spectrum/random.ts,
 * so these tests do not depend on the code they would help to debug.
 */
import { describe, expect, it } from 'vitest';
import { detCosSinDegrees, detExp, detLog } from '../../src/spectrum/deterministicMath';

const view = new DataView(new ArrayBuffer(8));

/** The double's position on a line where consecutive doubles are consecutive integers. */
function orderedBits(x: number): bigint {
  view.setFloat64(0, x);
  const bits = view.getBigInt64(0);
  return bits < 0n ? -(bits & 0x7fffffffffffffffn) : bits;
}

function ulpDistance(a: number, b: number): number {
  const d = orderedBits(a) - orderedBits(b);
  return Number(d < 0n ? -d : d);
}

/** mulberry32: a tiny seeded generator, uniform in [0, 1). */
function makeUniform(seed: number): () => number {
  let s = seed | 0;
  return () => {
    s = (s + 0x6d2b79f5) | 0;
    let t = Math.imul(s ^ (s >>> 15), 1 | s);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** A double with uniformly random bits, positive, finite: covers every exponent incl. subnormals. */
function randomPositiveDouble(uniform: () => number): number {
  view.setUint32(0, Math.floor(uniform() * 0x7ff00000));
  view.setUint32(4, Math.floor(uniform() * 4294967296));
  return view.getFloat64(0);
}

// Observed: detExp is within 1 ulp of V8's Math.exp. Allowed: 2 ulp (relative ≤ 4.4e-16), since
// Math.exp itself may be 1 ulp off and detExp rounds the series once more. A wrong constant, a
// missing series term that matters or a wrong 2^n split gives errors of many ulp.
const EXP_ULPS = 2;
// Observed: detLog is within 3 ulp of Math.log (near x = 1, where ln x is small). Allowed: 4 ulp
// (relative ≤ 8.9e-16): s = (m−1)/(m+1), 2s(1+series) and the final sum round ~3 times, plus
// Math.log's own ≤ 1 ulp.
const LOG_ULPS = 4;

describe('detExp', () => {
  function expectCloseToMathExp(x: number): void {
    const got = detExp(x);
    const want = Math.exp(x);
    if (ulpDistance(got, want) > EXP_ULPS) throw new Error(`detExp(${x}) = ${got}, Math.exp gives ${want}`);
  }

  it('agrees with Math.exp to ≤ 2 ulp over the whole finite range, incl. subnormal results', () => {
    const uniform = makeUniform(1);
    for (let i = 0; i < 100_000; i++) {
      expectCloseToMathExp(-745.13 + uniform() * (709.78 + 745.13)); // every result magnitude
      expectCloseToMathExp(2 * uniform() - 1); // |x| ≤ 1, where the reduction n = 0 or ±1
      expectCloseToMathExp(-745.13 + uniform() * (745.13 - 708.4)); // results below 2^−1022
    }
  });

  it('is right at the edges', () => {
    expect(detExp(0)).toBe(1);
    expect(detExp(-0)).toBe(1);
    for (const x of [5e-324, -5e-324, 1e-300, -1e-300, 1e-17, -1e-17, 2 ** -30, 1, -1, Math.LN2, 0.5 * Math.LN2]) {
      expectCloseToMathExp(x);
    }
    for (const x of [700, 709, 709.78, -700, -708.39, -708.4, -720, -744.4, -745.1]) expectCloseToMathExp(x);
    // Beyond the smallest subnormal result, e^x rounds to 0.
    for (const x of [-745.2, -746, -1000, -1e300, -Infinity]) {
      expect(detExp(x)).toBe(0);
      expect(Math.exp(x)).toBe(0);
    }
    for (const x of [710, 1000, Infinity]) expect(detExp(x)).toBe(Infinity);
    expect(detExp(NaN)).toBeNaN();
  });

  it('agrees at whole and half multiples of ln 2, where the range reduction changes n', () => {
    for (let n = -1074; n <= 1023; n++) {
      expectCloseToMathExp(n * Math.LN2);
      if (n < 1023) expectCloseToMathExp((n + 0.5) * Math.LN2);
    }
  });
});

describe('detLog', () => {
  function expectCloseToMathLog(x: number): void {
    const got = detLog(x);
    const want = Math.log(x);
    if (ulpDistance(got, want) > LOG_ULPS) throw new Error(`detLog(${x}) = ${got}, Math.log gives ${want}`);
  }

  it('agrees with Math.log to ≤ 4 ulp for doubles of every exponent, incl. subnormals', () => {
    const uniform = makeUniform(2);
    for (let i = 0; i < 100_000; i++) {
      expectCloseToMathLog(randomPositiveDouble(uniform));
      expectCloseToMathLog(0.5 + 1.5 * uniform()); // around 1, where ln x is small and cancels
      expectCloseToMathLog(0.99 + 0.02 * uniform());
      expectCloseToMathLog(uniform() * 2.2250738585072014e-308); // subnormal inputs
    }
  });

  it('is right at the edges', () => {
    expect(detLog(1)).toBe(0);
    const tiny = [5e-324, 1e-320, 2.225073858507201e-308, 2.2250738585072014e-308, 1e-300];
    const huge = [1e300, 1.7976931348623157e308];
    const nearOne = [1 + 2 ** -52, 1 - 2 ** -53, 1 + 1e-10, 1 - 1e-10, Math.SQRT2, Math.SQRT1_2, 2, 0.5];
    for (const x of [...tiny, ...huge, ...nearOne]) expectCloseToMathLog(x);
    for (let e = -1074; e <= 1023; e++) expectCloseToMathLog(2 ** e);
    expect(detLog(0)).toBe(-Infinity);
    expect(detLog(-0)).toBe(-Infinity);
    expect(detLog(Infinity)).toBe(Infinity);
    expect(detLog(-1)).toBeNaN();
    expect(detLog(-Infinity)).toBeNaN();
    expect(detLog(NaN)).toBeNaN();
  });
});

describe('detCosSinDegrees', () => {
  // π/180 = RAD_HI + RAD_LO: RAD_HI is the double nearest π/180, RAD_LO the rest (from mpmath at
  // 300 bits). The reference angle below is therefore correct to ~1e-31 rad, so the comparison
  // measures detCosSinDegrees alone. (Math.cos(deg·Math.PI/180) itself is off by up to ~1.5e-15
  // near 360° because of the two roundings in deg·π/180, which would swamp a 1e-15 bound.)
  const RAD_HI = 0.017453292519943295;
  const RAD_LO = 2.9486522708701687e-19;
  const SPLITTER = 134217729; // 2^27 + 1, Veltkamp splitting

  /** a·b = product + error exactly (Dekker's two-product without FMA). */
  function twoProduct(a: number, b: number): [number, number] {
    const product = a * b;
    const split = (x: number): [number, number] => {
      const c = SPLITTER * x;
      const high = c - (c - x);
      return [high, x - high];
    };
    const [ah, al] = split(a);
    const [bh, bl] = split(b);
    const error = ah * bh - product + ah * bl + al * bh + al * bl;
    return [product, error];
  }

  function referenceCosSin(degrees: number): [number, number] {
    // % is exact in IEEE-754 and cos, sin have period 360°, so this reduction loses nothing.
    const a = degrees % 360;
    const [p, e] = twoProduct(a, RAD_HI);
    const correction = e + a * RAD_LO; // angle = p + correction, |correction| < 1e-15
    const c = Math.cos(p);
    const s = Math.sin(p);
    return [c - s * correction, s + c * correction];
  }

  // Observed: ≤ 3.4e-16. Allowed: 1e-15 absolute (the bound): the radian conversion rounds
  // twice (≤ 2·0.79·1.1e-16) and Math.cos/sin may be 1 ulp off; a wrong quadrant, mirror or series
  // coefficient gives errors ≥ 1e-10.
  const TOLERANCE = 1e-15;

  function expectClose(degrees: number): void {
    const [c, s] = detCosSinDegrees(degrees);
    const [rc, rs] = referenceCosSin(degrees);
    if (!(Math.abs(c - rc) <= TOLERANCE && Math.abs(s - rs) <= TOLERANCE)) {
      throw new Error(`detCosSinDegrees(${degrees}) = [${c}, ${s}], reference [${rc}, ${rs}]`);
    }
  }

  it('the reference itself is right: it agrees with plain Math.cos/sin to 2e-15', () => {
    const uniform = makeUniform(3);
    for (let i = 0; i < 1000; i++) {
      const d = 360 * uniform();
      const [rc, rs] = referenceCosSin(d);
      // Plain conversion is off by ≤ ~1.5e-15 rad (see above), so 2e-15 is its bound.
      expect(Math.abs(rc - Math.cos((d * Math.PI) / 180))).toBeLessThan(2e-15);
      expect(Math.abs(rs - Math.sin((d * Math.PI) / 180))).toBeLessThan(2e-15);
    }
  });

  it('matches cos and sin within 1e-15 over [−720°, 720°] and beyond 360°', () => {
    const uniform = makeUniform(4);
    for (let i = 0; i < 100_000; i++) {
      expectClose(1440 * uniform() - 720);
      expectClose(90 * uniform()); // first quadrant, both sides of the 45° mirror
      expectClose(1e6 * uniform()); // many turns
    }
    for (const d of [1e-10, 44.999999999999, 45, 45.000000000001, 89.99999999999999, 135, 225, 315]) {
      expectClose(d);
      expectClose(-d);
    }
    expectClose(1e-300);
    for (const d of [360.5, 1000, 3601.25, 12345.678, 1e15 + 0.5, 1e300]) {
      expectClose(d);
      expectClose(-d);
    }
  });

  it('is exact at multiples of 90°, also negative and beyond 360°', () => {
    const want: [number, number][] = [
      [1, 0],
      [0, 1],
      [-1, 0],
      [0, -1],
    ];
    for (let quarter = -12; quarter <= 12; quarter++) {
      for (const turns of [0, 1000, -1000]) {
        const [c, s] = detCosSinDegrees(90 * quarter + 360 * turns);
        const [wc, ws] = want[((quarter % 4) + 4) % 4];
        // === so that −0 counts as 0 (cos 90° comes out as −0, which is exact).
        expect(c === wc && s === ws, `angle ${90 * quarter + 360 * turns}: [${c}, ${s}]`).toBe(true);
      }
    }
  });

  it('is even in cos and odd in sin for negative angles', () => {
    const uniform = makeUniform(5);
    for (let i = 0; i < 10_000; i++) {
      const d = 720 * uniform();
      const [c, s] = detCosSinDegrees(d);
      const [cn, sn] = detCosSinDegrees(-d);
      // Both sides are within 1e-15 of exact, so they are within 2e-15 of each other.
      expect(Math.abs(cn - c)).toBeLessThanOrEqual(2e-15);
      expect(Math.abs(sn + s)).toBeLessThanOrEqual(2e-15);
    }
  });
});

describe('edge cases found in review', () => {
  it('detCosSinDegrees handles tiny negative angles (which round up to 360°)', () => {
    for (const d of [-1e-20, -1e-300, -2e-14]) {
      const [c, s] = detCosSinDegrees(d);
      expect(Math.abs(c - 1)).toBeLessThan(1e-15);
      expect(Math.abs(s)).toBeLessThan(1e-12);
    }
  });

  it('detExp stays finite up to ln(Number.MAX_VALUE) = 709.782712893384', () => {
    for (const x of [709.781, 709.782, 709.7827128933]) {
      expect(Math.abs(detExp(x) / Math.exp(x) - 1)).toBeLessThan(5e-16);
    }
  });
});
