/**
 * SeededRandom: reproducibility, the xoshiro128** algorithm it claims to be, and the statistics of
 * its uniform and normal deviates.
 *
 * Statistical bounds are 5 standard errors (σ of the estimate for the sample size): a correct
 * generator fails one such check with probability ~6e-7, and the seeds are fixed, so the outcome
 * never changes between runs. A biased generator (wrong scaling, a lost bit, a reused spare
 * normal) misses them by far more.
 */
import { describe, expect, it } from 'vitest';
import { SeededRandom } from '../../src/spectrum/random';

const SIGMAS = 5;

/**
 * xoshiro128** (Blackman & Vigna 2018, reference C code at prng.di.unimi.it) seeded with splitmix32
 * as random.ts describes, written independently with BigInt arithmetic mod 2^32.
 */
class ReferenceXoshiro128StarStar {
  private s: bigint[] = [];
  private static readonly MASK = 0xffffffffn;

  constructor(seed: number) {
    const M = ReferenceXoshiro128StarStar.MASK;
    let z = BigInt(seed >>> 0);
    for (let i = 0; i < 4; i++) {
      z = (z + 0x9e3779b9n) & M;
      let t = z;
      t = ((t ^ (t >> 16n)) * 0x21f0aaadn) & M;
      t = ((t ^ (t >> 15n)) * 0x735a2d97n) & M;
      this.s.push(t ^ (t >> 15n));
    }
  }

  private static rotl(x: bigint, k: bigint): bigint {
    const M = ReferenceXoshiro128StarStar.MASK;
    return ((x << k) | (x >> (32n - k))) & M;
  }

  next(): number {
    const M = ReferenceXoshiro128StarStar.MASK;
    const s = this.s;
    const result = (ReferenceXoshiro128StarStar.rotl((s[1] * 5n) & M, 7n) * 9n) & M;
    const t = (s[1] << 9n) & M;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = ReferenceXoshiro128StarStar.rotl(s[3], 11n);
    return Number(result);
  }
}

describe('SeededRandom reproducibility', () => {
  it('gives the same sequence for the same seed, across all three methods interleaved', () => {
    for (const seed of [0, 1, 42, 0xffffffff]) {
      const a = new SeededRandom(seed);
      const b = new SeededRandom(seed);
      for (let i = 0; i < 3000; i++) {
        const method = i % 3;
        const x = method === 0 ? a.nextUint32() : method === 1 ? a.nextUniform() : a.nextNormal();
        const y = method === 0 ? b.nextUint32() : method === 1 ? b.nextUniform() : b.nextNormal();
        expect(Object.is(x, y)).toBe(true);
      }
    }
  });

  it('gives different sequences for different seeds (first 64 bits of 2000 seeds all distinct)', () => {
    const seen = new Set<string>();
    const seeds = Array.from({ length: 2000 }, (_, i) => (i < 1000 ? i : 0xffffffff - (i - 1000)));
    for (const seed of seeds) {
      const random = new SeededRandom(seed);
      seen.add(`${random.nextUint32()},${random.nextUint32()}`);
    }
    expect(seen.size).toBe(seeds.length);
    // Neighbouring seeds give unrelated sequences, not shifted copies of each other.
    const a = new SeededRandom(1);
    const b = new SeededRandom(2);
    const first = Array.from({ length: 100 }, () => a.nextUint32());
    const second = new Set(Array.from({ length: 100 }, () => b.nextUint32()));
    expect(first.filter((x) => second.has(x))).toEqual([]);
  });

  it('is xoshiro128** seeded by splitmix32 (independent BigInt implementation, 10 000 outputs)', () => {
    for (const seed of [0, 1, 7, 123456789, 0xffffffff]) {
      const random = new SeededRandom(seed);
      const reference = new ReferenceXoshiro128StarStar(seed);
      for (let i = 0; i < 2000; i++) {
        const got = random.nextUint32();
        const want = reference.next();
        if (got !== want) throw new Error(`seed ${seed}, output ${i}: got ${got}, want ${want}`);
      }
    }
  });
});

describe('SeededRandom.nextUniform', () => {
  const COUNT = 200_000;

  it('lies in [0, 1) on a 2^−53 grid, each of the 53 bits set in half the draws', () => {
    const random = new SeededRandom(3);
    const bitCounts = new Array<number>(53).fill(0);
    for (let i = 0; i < COUNT; i++) {
      const u = random.nextUniform();
      if (!(u >= 0 && u < 1)) throw new Error(`uniform ${u} outside [0, 1)`);
      let scaled = u * 2 ** 53; // exact: a power-of-two scale
      if (!Number.isInteger(scaled)) throw new Error(`uniform ${u} is not a multiple of 2^-53`);
      for (let bit = 0; bit < 53; bit++) {
        bitCounts[bit] += scaled % 2;
        scaled = Math.floor(scaled / 2);
      }
    }
    // Each bit's count is Binomial(COUNT, ½); a lost or stuck bit is off by COUNT/2.
    for (const count of bitCounts) expect(Math.abs(count - COUNT / 2)).toBeLessThan(SIGMAS * Math.sqrt(COUNT / 4));
  });

  it('has mean ½, variance 1/12, and equal counts in 16 bins', () => {
    const random = new SeededRandom(4);
    const bins = new Array<number>(16).fill(0);
    let sum = 0;
    let sumSquares = 0;
    for (let i = 0; i < COUNT; i++) {
      const u = random.nextUniform();
      sum += u;
      sumSquares += (u - 0.5) ** 2;
      bins[Math.floor(u * 16)]++;
    }
    // Standard error of the mean: √(1/12 / COUNT).
    expect(Math.abs(sum / COUNT - 0.5)).toBeLessThan(SIGMAS * Math.sqrt(1 / 12 / COUNT));
    // Var of (u − ½)² is 1/80 − 1/144 = 1/180, so the variance estimate has σ = √(1/180 / COUNT).
    expect(Math.abs(sumSquares / COUNT - 1 / 12)).toBeLessThan(SIGMAS * Math.sqrt(1 / 180 / COUNT));
    // Each bin count is Binomial(COUNT, 1/16).
    for (const count of bins) {
      expect(Math.abs(count - COUNT / 16)).toBeLessThan(SIGMAS * Math.sqrt(COUNT * (1 / 16) * (15 / 16)));
    }
  });
});

describe('SeededRandom.nextNormal', () => {
  const COUNT = 200_000;
  const draws = (() => {
    const random = new SeededRandom(5);
    return Float64Array.from({ length: COUNT }, () => random.nextNormal());
  })();
  const mean = (f: (x: number, i: number) => number) => draws.reduce((s, x, i) => s + f(x, i), 0) / COUNT;

  it('has mean 0 and variance 1 (200 000 draws, 5 standard errors)', () => {
    expect(draws.every(Number.isFinite)).toBe(true);
    // Standard error of the mean of N(0, 1) draws: 1/√COUNT ≈ 0.0022.
    expect(Math.abs(mean((x) => x))).toBeLessThan(SIGMAS / Math.sqrt(COUNT));
    // Var(x²) = E[x⁴] − 1 = 2, so the second moment has standard error √(2/COUNT) ≈ 0.0032.
    expect(Math.abs(mean((x) => x * x) - 1)).toBeLessThan(SIGMAS * Math.sqrt(2 / COUNT));
  });

  it('has the normal shape: E[x⁴] = 3, P(|x| < 1) = 0.6827, P(|x| < 2) = 0.9545', () => {
    // Var(x⁴) = E[x⁸] − 9 = 105 − 9 = 96.
    expect(Math.abs(mean((x) => x ** 4) - 3)).toBeLessThan(SIGMAS * Math.sqrt(96 / COUNT));
    for (const [limit, probability] of [
      [1, 0.6826894921370859],
      [2, 0.9544997361036416],
    ]) {
      const fraction = mean((x) => (Math.abs(x) < limit ? 1 : 0));
      // A fraction of COUNT Bernoulli(p) draws has standard error √(p(1−p)/COUNT).
      const standardError = Math.sqrt((probability * (1 - probability)) / COUNT);
      expect(Math.abs(fraction - probability)).toBeLessThan(SIGMAS * standardError);
    }
  });

  it('has consecutive draws uncorrelated (the polar method returns its pair one by one)', () => {
    // Correlation of independent N(0, 1) pairs: mean of x_i·x_{i+1} ≈ 0 with standard error 1/√n.
    // Both the even (same pair) and odd (across pairs) neighbours are checked.
    for (const offset of [0, 1]) {
      let sum = 0;
      let pairs = 0;
      for (let i = offset; i + 1 < COUNT; i += 2) {
        sum += draws[i] * draws[i + 1];
        pairs++;
      }
      expect(Math.abs(sum / pairs)).toBeLessThan(SIGMAS / Math.sqrt(pairs));
    }
  });
});
