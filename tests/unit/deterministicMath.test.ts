/**
 * detExp, detLog, detCosSinDegrees and the functions built on them (detExpm1, detPow, detTanh,
 * detSech, detAtan, detAtan2, detLogGamma) against the engine's Math functions.
 *
 * Accuracy is measured in units in the last place (ulp): the distance between two doubles counted
 * in representable doubles. One ulp is at most 2^−52 ≈ 2.2e-16 of the value, so "≤ n ulp" means a
 * relative error of at most n·2.2e-16, also for subnormal results, where a relative bound would be
 * meaningless. Inputs come from a small local generator (mulberry32), not from src/spectrum/random.ts,
 * so these tests do not depend on the code they would help to debug.
 */
import { describe, expect, it } from 'vitest';
import {
  detAtan,
  detAtan2,
  detCosSinDegrees,
  detExp,
  detExpm1,
  detLog,
  detLogGamma,
  detPow,
  detSech,
  detTanh,
} from '../../src/spectrum/deterministicMath';

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

/** Throws, naming the input, if got is more than `ulps` from want. */
function expectUlps(name: string, input: unknown, got: number, want: number, ulps: number): void {
  if (!(ulpDistance(got, want) <= ulps)) throw new Error(`${name}(${String(input)}) = ${got}, Math gives ${want}`);
}

/** A number of random sign with magnitude 10^e, e uniform in [lowExponent, highExponent]. */
function randomMagnitude(uniform: () => number, lowExponent: number, highExponent: number): number {
  const magnitude = 10 ** (lowExponent + (highExponent - lowExponent) * uniform());
  return uniform() < 0.5 ? -magnitude : magnitude;
}

describe('detExpm1', () => {
  // Observed: ≤ 2 ulp. Allowed 3: the series' Horner steps round (≤ ~1.5 ulp), Math.expm1 may be
  // 1 ulp off; beyond |x| = 1, e^x − 1 adds detExp's 2 ulp times e/(e − 1). A missing series term
  // or a cancelling e^x − 1 near 0 gives errors of millions of ulp.
  it('agrees with Math.expm1 to ≤ 3 ulp from 1e-300 to 700 in magnitude', () => {
    const uniform = makeUniform(11);
    for (let i = 0; i < 100_000; i++) {
      const x = randomMagnitude(uniform, -300, Math.log10(700));
      expectUlps('detExpm1', x, detExpm1(x), Math.expm1(x), 3);
      const near = 2 * uniform() - 1; // |x| ≤ 1, the series
      expectUlps('detExpm1', near, detExpm1(near), Math.expm1(near), 3);
    }
  });

  it('is right at the edges', () => {
    expect(Object.is(detExpm1(0), 0)).toBe(true);
    expect(Object.is(detExpm1(-0), -0)).toBe(true);
    for (const x of [1, -1, 1 + 2 ** -52, -1 - 2 ** -52, 5e-324, 1e-17]) expectUlps('detExpm1', x, detExpm1(x), Math.expm1(x), 3);
    expect(detExpm1(-Infinity)).toBe(-1);
    expect(detExpm1(-800)).toBe(-1);
    expect(detExpm1(Infinity)).toBe(Infinity);
    expect(detExpm1(NaN)).toBeNaN();
  });
});

describe('detPow', () => {
  // x^y = e^{y·ln x}: the ≤ 4 ulp of detLog and the rounding of the product are an absolute error of
  // ≤ 5·2^−53·|y·ln x| in the exponent, which e^(·) turns into the same relative error, i.e.
  // ≤ 2.5·|y·ln x| ulp; plus detExp's 2 ulp and Math.pow's 1. Allowed: 3 + 2.5·|y·ln x| ulp.
  function allowedUlps(x: number, y: number): number {
    return 3 + 2.5 * Math.abs(y * Math.log(x));
  }

  it('agrees with Math.pow within 3 + 2.5·|y·ln x| ulp for the exponents spectra use and beyond', () => {
    const uniform = makeUniform(12);
    for (let i = 0; i < 100_000; i++) {
      const x = 10 ** (-6 + 12 * uniform());
      const y = -8 + 16 * uniform();
      expectUlps(`detPow(${x}, ·)`, y, detPow(x, y), Math.pow(x, y), allowedUlps(x, y));
    }
    for (const [x, y] of [
      [0.95, 1.3],
      [2.5, -0.567],
      [1.6, -1.3],
      [0.5, 4.06],
      [17040.5, -0.22],
      [1e-300, 0.5],
      [7, 300],
    ]) {
      expectUlps(`detPow(${x}, ·)`, y, detPow(x, y), Math.pow(x, y), allowedUlps(x, y));
    }
  });

  it('is exact where Math.pow is defined exactly: y = 0, x = 1, x = 0, x = ∞', () => {
    for (const y of [0, -0]) for (const x of [0, 0.3, 1, 7, Infinity]) expect(detPow(x, y)).toBe(1);
    for (const y of [-3, 0.5, 2.5, 1e300]) expect(detPow(1, y)).toBe(1);
    for (const y of [0.5, 2, 5, 1e-300]) expect(detPow(0, y)).toBe(0);
    for (const y of [-0.5, -2.5]) expect(detPow(0, y)).toBe(Infinity);
    expect(detPow(Infinity, 2)).toBe(Infinity);
    expect(detPow(Infinity, -2)).toBe(0);
    expect(detPow(-2, 0.5)).toBeNaN(); // negative bases are not supported
    expect(detPow(NaN, 2)).toBeNaN();
    expect(detPow(2, NaN)).toBeNaN();
    expect(detPow(1e-200, 2)).toBe(0); // underflows like Math.pow
    expect(detPow(1e200, 2)).toBe(Infinity);
  });
});

describe('detTanh and detSech', () => {
  // Observed: ≤ 3 ulp for both. Allowed 4: expm1's 3 ulp largely cancel in −e/(e + 2) (both carry
  // the same e), plus a division; sech = 2e/(1 + e²) rounds 3 times after detExp's 2 ulp, and the
  // reference 1/Math.cosh rounds twice itself. A wrong sign or a cancelling formula near 0 is far off.
  it('tanh agrees with Math.tanh to ≤ 4 ulp from 1e-300 to 30 in magnitude, and is odd', () => {
    const uniform = makeUniform(13);
    for (let i = 0; i < 100_000; i++) {
      const x = randomMagnitude(uniform, -300, Math.log10(30));
      expectUlps('detTanh', x, detTanh(x), Math.tanh(x), 4);
      if (detTanh(-x) !== -detTanh(x)) throw new Error(`detTanh is not odd at ${x}`);
    }
  });

  it('tanh is right at the edges', () => {
    expect(Object.is(detTanh(0), 0)).toBe(true);
    expect(Object.is(detTanh(-0), -0)).toBe(true);
    for (const x of [22, 23, 100, Infinity]) {
      expect(detTanh(x)).toBe(1);
      expect(detTanh(-x)).toBe(-1);
    }
    for (const x of [21.9, 18.7, 1e-8, 0.5493061443340549]) expectUlps('detTanh', x, detTanh(x), Math.tanh(x), 4);
    expect(detTanh(NaN)).toBeNaN();
  });

  it('sech agrees with 1/Math.cosh to ≤ 4 ulp over |x| ≤ 700, is even, and never overflows', () => {
    const uniform = makeUniform(14);
    for (let i = 0; i < 100_000; i++) {
      const x = randomMagnitude(uniform, -300, Math.log10(700));
      expectUlps('detSech', x, detSech(x), 1 / Math.cosh(x), 4);
      if (detSech(-x) !== detSech(x)) throw new Error(`detSech is not even at ${x}`);
    }
    expect(detSech(0)).toBe(1);
    // Beyond |x| ≈ 710, cosh overflows but sech = 2e^{−|x|} is still a (subnormal) number.
    expectUlps('detSech', 720, detSech(720), 2 * Math.exp(-720), 4);
    expect(detSech(800)).toBe(0);
    expect(detSech(Infinity)).toBe(0);
    expect(detSech(NaN)).toBeNaN();
  });
});

describe('detAtan and detAtan2', () => {
  // Observed: ≤ 1 ulp (atan), ≤ 2 ulp (atan2). Allowed 2 and 3: the reduced argument t rounds once
  // (atan' ≤ 1 keeps that below 1 ulp of the result), the series and the split constants add < 1 ulp;
  // atan2 adds the rounding of y/x and, in the left half plane, of π − angle.
  it('atan agrees with Math.atan to ≤ 2 ulp over every magnitude, and is odd', () => {
    const uniform = makeUniform(15);
    for (let i = 0; i < 100_000; i++) {
      const x = randomMagnitude(uniform, -300, 300);
      expectUlps('detAtan', x, detAtan(x), Math.atan(x), 2);
      const moderate = randomMagnitude(uniform, -2, 2); // every reduction interval
      expectUlps('detAtan', moderate, detAtan(moderate), Math.atan(moderate), 2);
      if (detAtan(-moderate) !== -detAtan(moderate)) throw new Error(`detAtan is not odd at ${moderate}`);
    }
  });

  it('atan is right at the reduction breakpoints and the edges', () => {
    for (const b of [7 / 16, 11 / 16, 19 / 16, 39 / 16, 0.5, 1, 1.5]) {
      for (const x of [b, b * (1 - 2 ** -52), b * (1 + 2 ** -52)]) {
        expectUlps('detAtan', x, detAtan(x), Math.atan(x), 2);
        expectUlps('detAtan', -x, detAtan(-x), Math.atan(-x), 2);
      }
    }
    expect(detAtan(1)).toBe(Math.PI / 4);
    expect(detAtan(Infinity)).toBe(Math.PI / 2);
    expect(detAtan(-Infinity)).toBe(-Math.PI / 2);
    expect(Object.is(detAtan(-0), -0)).toBe(true);
    expect(detAtan(NaN)).toBeNaN();
  });

  it('atan2 agrees with Math.atan2 to ≤ 3 ulp in all four quadrants', () => {
    const uniform = makeUniform(16);
    for (let i = 0; i < 100_000; i++) {
      const y = randomMagnitude(uniform, -10, 10);
      const x = randomMagnitude(uniform, -10, 10);
      expectUlps(`detAtan2(${y}, ·)`, x, detAtan2(y, x), Math.atan2(y, x), 3);
      const angle = 2 * Math.PI * uniform(); // directions all round, as the spreading needs
      const [c, s] = [Math.cos(angle), Math.sin(angle)];
      expectUlps(`detAtan2(${s}, ·)`, c, detAtan2(s, c), Math.atan2(s, c), 3);
    }
  });

  it('atan2 has Math.atan2’s values on the axes, at ±0 and at ±∞', () => {
    const special = [0, -0, 1, -1, 2.5, -2.5, Infinity, -Infinity];
    for (const y of special) {
      for (const x of special) {
        const want = Math.atan2(y, x);
        const got = detAtan2(y, x);
        expect(Object.is(got, want) || ulpDistance(got, want) <= 1, `atan2(${y}, ${x}) = ${got}, Math gives ${want}`).toBe(
          true,
        );
      }
    }
    expect(detAtan2(NaN, 1)).toBeNaN();
    expect(detAtan2(1, NaN)).toBeNaN();
  });
});

describe('detLogGamma', () => {
  // ln Γ from mpmath's loggamma at 40 digits, rounded to double.
  const REFERENCE: [number, number][] = [
    [1e-5, 11.512919692895826],
    [0.1, 2.252712651734206],
    [0.5, 0.5723649429247001], // ln √π
    [1.5, -0.12078223763524522],
    [2.5, 0.2846828704729192],
    [3.7, 1.4280723266653879],
    [9.99, 12.779315214350193], // just below the Stirling threshold 10
    [10, 12.801827480081469],
    [10.5, 13.940625219403763],
    [33.3, 82.60372358165495],
    [100.5, 361.4355404677776],
    [1e4, 82099.71749644238],
    [1e6, 12815504.569147611],
  ];

  // Observed: ≤ 2e-15 absolute (near x = 1, 2 where ln Γ crosses 0, the shift product's detLog and
  // the Stirling sum cancel), ≤ 2 ulp relative for large x. Allowed: 4e-15·max(1, |ln Γ|).
  it('matches mpmath within 4e-15·max(1, |ln Γ|)', () => {
    for (const [x, want] of REFERENCE) {
      expect(Math.abs(detLogGamma(x) - want), `lnΓ(${x})`).toBeLessThanOrEqual(4e-15 * Math.max(1, Math.abs(want)));
    }
  });

  it('satisfies Γ(n) = (n − 1)! and Γ(x + 1) = x·Γ(x)', () => {
    let factorial = 1;
    for (let n = 1; n <= 30; n++) {
      // (n − 1)! is exact in double up to 22!, and within 1 ulp beyond.
      const want = Math.log(factorial);
      expect(Math.abs(detLogGamma(n) - want)).toBeLessThanOrEqual(4e-15 * Math.max(1, want));
      factorial *= n;
    }
    const uniform = makeUniform(17);
    for (let i = 0; i < 10_000; i++) {
      const x = 0.01 + 50 * uniform();
      const step = detLogGamma(x + 1) - detLogGamma(x) - Math.log(x);
      const allowed = 1e-14 * Math.max(1, Math.abs(detLogGamma(x + 1)));
      if (!(Math.abs(step) <= allowed)) throw new Error(`Γ(x + 1) ≠ x·Γ(x) at ${x}`);
    }
  });

  it('is right at the edges', () => {
    expect(detLogGamma(0)).toBe(Infinity);
    expect(detLogGamma(Infinity)).toBe(Infinity);
    expect(detLogGamma(-1)).toBeNaN();
    expect(detLogGamma(NaN)).toBeNaN();
    expect(Math.abs(detLogGamma(1e-300) - 690.7755278982137)).toBeLessThan(1e-12); // ≈ −ln x
  });
});
