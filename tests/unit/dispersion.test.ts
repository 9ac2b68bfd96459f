/**
 * Dispersion relation, frequency quantization, time wrapping and the phase table, each against the
 * formula it implements (Tessendorf 2001, eqs. 14, 15, 17; ω rounded to the nearest multiple of
 * 2π/T rather than down) evaluated independently here.
 */
import { describe, expect, it } from 'vitest';
import {
  angularFrequency,
  fillPhaseTable,
  frequencyIndex,
  GRAVITY,
  MAX_FREQUENCY_INDEX,
  PHASE_TABLE_SIZE,
  wrapTime,
} from '../../src/spectrum/dispersion';

const G = 9.81; // m/s², standard gravity as documented in parameters.ts

/** Wavenumbers from 1e-4 to 1e3 rad/m, log-spaced. */
const WAVENUMBERS = Array.from({ length: 141 }, (_, i) => 10 ** (-4 + i / 20));

describe('angularFrequency', () => {
  it('uses g = 9.81 m/s²', () => {
    expect(GRAVITY).toBe(G);
  });

  it('is √(g·k) in deep water', () => {
    for (const k of WAVENUMBERS) {
      // Same two roundings (g·k, √) as the formula, so a relative 1e-15 bound (≈ 4 ulp) is generous.
      expect(Math.abs(angularFrequency(k, Infinity) / Math.sqrt(G * k) - 1)).toBeLessThan(1e-15);
    }
    expect(angularFrequency(0, Infinity)).toBe(0);
  });

  it('is √(g·k·tanh(k·d)) at finite depth', () => {
    for (const depth of [0.1, 1, 5, 50, 1000]) {
      for (const k of WAVENUMBERS) {
        const want = Math.sqrt(G * k * Math.tanh(k * depth));
        // A few roundings of ~1.1e-16 each, and tanh is taken as exactly 1 once k·d > 20, where
        // 1 − tanh(k·d) ≈ 2e^{−40} ≈ 8e-18; 1e-15 relative covers both.
        expect(Math.abs(angularFrequency(k, depth) / want - 1)).toBeLessThan(1e-15);
      }
      expect(angularFrequency(0, depth)).toBe(0);
    }
  });

  it('tends to deep water for k·d ≫ 1: 1 − ω_d/ω_∞ ≈ e^{−2kd}', () => {
    // ω_d/ω_∞ = √tanh(kd) = √(1 − 2e^{−2kd} + …) = 1 − e^{−2kd} + O(e^{−4kd}).
    for (const kd of [3, 5, 8, 12, 18]) {
      const k = 0.5;
      const ratio = angularFrequency(k, kd / k) / angularFrequency(k, Infinity);
      const deficit = 1 - ratio;
      // Relative 2% of the leading term covers the O(e^{−4kd}) rest (≤ 0.25% at kd = 3) plus
      // rounding (≤ 3e-16, which matters only at kd = 18 where e^{−36} ≈ 2.3e-16; hence the + 5e-16).
      expect(Math.abs(deficit - Math.exp(-2 * kd))).toBeLessThan(0.02 * Math.exp(-2 * kd) + 5e-16);
    }
    // Continuous across the k·d = 20 switch to the deep-water branch (tanh(20) = 1 − 8e-18).
    const below = angularFrequency(1, 20 * (1 - 1e-12));
    const above = angularFrequency(1, 20 * (1 + 1e-12));
    expect(Math.abs(below / above - 1)).toBeLessThan(1e-15); // a few ulp
  });

  it('tends to shallow water for k·d ≪ 1: ω ≈ k·√(g·d)·(1 − (kd)²/6)', () => {
    // tanh(x)/x = 1 − x²/3 + …, so ω/(k√(gd)) = 1 − (kd)²/6 + O((kd)⁴).
    for (const kd of [1e-4, 1e-3, 1e-2, 0.05, 0.1]) {
      const depth = 2;
      const k = kd / depth;
      const ratio = angularFrequency(k, depth) / (k * Math.sqrt(G * depth));
      expect(ratio).toBeLessThan(1);
      // The neglected term is (19/360)(kd)⁴ < 0.06·(kd)⁴, plus ~1e-15 rounding.
      expect(Math.abs(ratio - (1 - kd ** 2 / 6))).toBeLessThan(0.06 * kd ** 4 + 1e-15);
    }
  });
});

describe('frequencyIndex', () => {
  it('rounds ω to the nearest multiple of 2π/T: |m·2π/T − ω| ≤ π/T', () => {
    let roundedUp = 0;
    let roundedDown = 0;
    for (const repeatPeriod of [1, 17.3, 200, 2000, 12345]) {
      for (const depth of [Infinity, 3]) {
        for (const k of WAVENUMBERS) {
          const m = frequencyIndex(k, { depth, repeatPeriod });
          expect(Number.isInteger(m)).toBe(true);
          expect(m).toBeGreaterThanOrEqual(0);
          const omega = Math.sqrt(G * k * Math.tanh(k * depth)); // tanh(∞) = 1
          const step = (2 * Math.PI) / repeatPeriod;
          // Half a step, loosened by relative 1e-12 for rounding in ω·T/2π (~1e-16 relative of
          // values up to ~1e6), which can only matter when ω sits halfway between two multiples.
          expect(Math.abs(m * step - omega)).toBeLessThanOrEqual((step / 2) * (1 + 1e-12) + omega * 1e-12);
          if (m * step > omega) roundedUp++;
          else if (m * step < omega) roundedDown++;
        }
      }
    }
    // Both directions occur: this is rounding to the nearest, not floor (Tessendorf's) or ceil.
    expect(roundedUp).toBeGreaterThan(100);
    expect(roundedDown).toBeGreaterThan(100);
  });

  it('halves the largest phase-speed error of rounding down: at most π/T over ω', () => {
    // The relative phase-speed error of a mode is |m·2π/T − ω|/ω ≤ (π/T)/ω: 1 % once T ≥ π/(0.01·ω).
    for (const k of [0.01, 0.1, 1, 10]) {
      const omega = Math.sqrt(G * k);
      const repeatPeriod = Math.PI / (0.01 * omega);
      const m = frequencyIndex(k, { depth: Infinity, repeatPeriod });
      expect(Math.abs((m * 2 * Math.PI) / repeatPeriod / omega - 1)).toBeLessThanOrEqual(0.01 * (1 + 1e-12));
    }
  });

  it('has room for MAX_FREQUENCY_INDEX + 1 = PHASE_TABLE_SIZE² indices', () => {
    expect(PHASE_TABLE_SIZE).toBe(256);
    expect(MAX_FREQUENCY_INDEX).toBe(PHASE_TABLE_SIZE * PHASE_TABLE_SIZE - 1);
  });
});

describe('wrapTime', () => {
  it('maps t into [0, T) with t − wrap(t) a whole number of periods', () => {
    const T = 200;
    // Values chosen so that every wrapped result is exactly representable.
    const cases: [number, number][] = [
      [0, 0],
      [37.25, 37.25],
      [199.5, 199.5],
      [200, 0],
      [437.25, 37.25],
      [-1, 199],
      [-162.75, 37.25],
      [-200, 0],
      [-400.5, 199.5],
      [1e6 * T + 37.25, 37.25], // 2e8 s, about six years
      [1e15 + 0.25, 0.25], // 1e15 = 5e12·T; the .25 is exact at this magnitude (ulp 0.125)
      [-(1e15 + 0.25), 199.75],
    ];
    for (const [t, want] of cases) expect(wrapTime(t, T) === want, `wrapTime(${t})`).toBe(true);
  });

  it('stays in [0, T) for huge and negative times, including fractional periods', () => {
    for (const T of [200, 17.3, 0.1]) {
      for (const t of [1e20, -1e20, 1e300, -1e300, 123456789.123, -123456789.123, -1e-3, -T / 3]) {
        const wrapped = wrapTime(t, T);
        expect(wrapped >= 0 && wrapped < T, `wrapTime(${t}, ${T}) = ${wrapped}`).toBe(true);
        // % is exact, so t − wrapped is an exact multiple of T whenever it is representable; for
        // |t| ≤ 1e9 the subtraction and division round by < 1e-6 of a period.
        if (Math.abs(t) < 1e9) {
          const periods = (t - wrapped) / T;
          expect(Math.abs(periods - Math.round(periods))).toBeLessThan(1e-6);
        }
      }
    }
  });
});

describe('fillPhaseTable', () => {
  /** Reference (cos, sin) of j·φ and 256·j·φ, φ = 2π·τ/T for a τ known exactly in [0, T). */
  function expectTable(table: Float32Array, turns: number): void {
    let worst = 0;
    for (let j = 0; j < PHASE_TABLE_SIZE; j++) {
      const low = 2 * Math.PI * j * turns;
      const high = 2 * Math.PI * 256 * j * turns; // ≤ 4.1e5 rad: Math.cos stays within ~1e-10
      worst = Math.max(
        worst,
        Math.abs(table[4 * j] - Math.cos(low)),
        Math.abs(table[4 * j + 1] - Math.sin(low)),
        Math.abs(table[4 * j + 2] - Math.cos(high)),
        Math.abs(table[4 * j + 3] - Math.sin(high)),
      );
    }
    // Float32 rounding of a value in [−1, 1] is ≤ 2^−25 ≈ 3e-8; the angle arithmetic adds ~1e-10.
    expect(worst).toBeLessThan(1e-7);
  }

  it('holds cos/sin of j·φ and 256·j·φ within 1e-7, for times inside, past and before [0, T)', () => {
    const T = 200;
    const table = new Float32Array(4 * PHASE_TABLE_SIZE);
    for (const [t, turns] of [
      [0, 0],
      [37.25, 37.25 / T],
      [199.875, 199.875 / T],
      [37.25 + 5000 * T, 37.25 / T], // a million seconds in: wrapped before any rounding
      [37.25 - 3 * T, 37.25 / T],
      [1e15 + 0.25, 0.25 / T],
    ]) {
      table.fill(NaN);
      fillPhaseTable(table, t, T);
      expectTable(table, turns);
    }
  });

  it('gives e^{i·m·φ} = low[m mod 256]·high[m div 256] for every m up to MAX_FREQUENCY_INDEX', () => {
    const T = 200;
    const t = 123.456;
    const table = new Float32Array(4 * PHASE_TABLE_SIZE);
    fillPhaseTable(table, t, T);
    let worst = 0;
    for (let m = 0; m <= MAX_FREQUENCY_INDEX; m++) {
      const lo = 4 * (m % 256);
      const hi = 4 * Math.floor(m / 256) + 2;
      const re = table[lo] * table[hi] - table[lo + 1] * table[hi + 1];
      const im = table[lo] * table[hi + 1] + table[lo + 1] * table[hi];
      // m·t ≤ 8.1e6 s is rounded by ≤ 1e-9 s and % is exact, so the angle is right to ~3e-11 rad.
      const angle = (2 * Math.PI * ((m * t) % T)) / T;
      worst = Math.max(worst, Math.abs(re - Math.cos(angle)), Math.abs(im - Math.sin(angle)));
    }
    // Two float32-rounded factors, each component within 3e-8, combine to ≤ ~1.2e-7.
    expect(worst).toBeLessThan(2e-7);
  });
});

describe('wrapTime edge case found in review', () => {
  it('stays below T for a tiny negative t', () => {
    expect(wrapTime(-1e-20, 200)).toBeLessThan(200);
    expect(wrapTime(-1e-20, 200)).toBeGreaterThanOrEqual(0);
  });
});
