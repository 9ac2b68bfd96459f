/**
 * Frequency spectra S(ω) against the published closed forms: Pierson-Moskowitz's Hs and ωp
 * (Stewart, "Introduction to Physical Oceanography", 2008, eqs. 16.29–16.33), the JONSWAP fetch
 * laws (Stewart §16.3), the JONSWAP/PM variance ratio (DNV-RP-C205 §3.5.5), the TMA depth factor
 * (Bouws et al. 1985) and the swell's requested Hs. Integrals and maxima are computed here with
 * Math functions, independently of the module.
 */
import { describe, expect, it } from 'vitest';
import {
  FULLY_DEVELOPED_FETCH,
  jonswap,
  jonswapParameters,
  jonswapShape,
  jonswapShapeIntegral,
  piersonMoskowitz,
  piersonMoskowitzPeakFrequency,
  swell,
  tmaFactor,
} from '../../src/spectrum/frequencySpectra';

const G = 9.81;

/** ∫S dω by Simpson's rule in ln ω over [lo, hi], 20 000 intervals (step ≤ 6e-4 in ln ω here). */
function integrate(spectrum: (omega: number) => number, lo = 1e-3, hi = 1e3): number {
  const n = 20_000;
  const a = Math.log(lo);
  const h = (Math.log(hi) - a) / n;
  let sum = 0;
  for (let i = 0; i <= n; i++) {
    const omega = Math.exp(a + i * h);
    const weight = i === 0 || i === n ? 1 : i % 2 === 1 ? 4 : 2;
    sum += weight * spectrum(omega) * omega;
  }
  return (sum * h) / 3;
}

/** argmax of a unimodal S on [lo, hi] by golden-section search, to 1e-10 relative. */
function argmax(spectrum: (omega: number) => number, lo: number, hi: number): number {
  const ratio = (Math.sqrt(5) - 1) / 2;
  let [a, b] = [lo, hi];
  while (b - a > 1e-10 * b) {
    const c = b - ratio * (b - a);
    const d = a + ratio * (b - a);
    if (spectrum(c) > spectrum(d)) b = d;
    else a = c;
  }
  return (a + b) / 2;
}

const relative = (got: number, want: number) => Math.abs(got / want - 1);

describe('piersonMoskowitz', () => {
  const WIND_SPEEDS = [3, 7, 10, 15, 20, 30, 45];

  it('has Hs = 0.21·U19.5²/g (Stewart 2008, eq. 16.33) within 1 %, U19.5 = 1.026·U10 (eq. 16.29)', () => {
    for (const u10 of WIND_SPEEDS) {
      const u195 = 1.026 * u10;
      const hs = 4 * Math.sqrt(integrate((w) => piersonMoskowitz(w, u10)));
      expect(relative(hs, (0.21 * u195 ** 2) / G), `U10 = ${u10}`).toBeLessThan(0.01);
      // Stewart's second form, Hs ≈ 0.22·U10²/g, within its rounding (0.21·1.026² = 0.221).
      expect(relative(hs, (0.22 * u10 ** 2) / G)).toBeLessThan(0.01);
    }
  });

  it('has m0 = 2.74e-3·U19.5⁴/g² (eq. 16.32) within 0.2 %, and = α·U19.5⁴/(4β·g²) to 1e-7', () => {
    for (const u10 of WIND_SPEEDS) {
      const u195 = 1.026 * u10;
      const m0 = integrate((w) => piersonMoskowitz(w, u10));
      expect(relative(m0, (2.74e-3 * u195 ** 4) / G ** 2)).toBeLessThan(0.002); // 2.74e-3 is rounded
      // Exact: ∫αg²ω⁻⁵exp(−β(g/(Uω))⁴)dω = αU⁴/(4βg²); the quadrature is good to ~1e-10.
      expect(relative(m0, (8.1e-3 * u195 ** 4) / (4 * 0.74 * G ** 2))).toBeLessThan(1e-7);
    }
  });

  it('peaks at ωp = 0.877·g/U19.5 (eq. 16.30) within 1 %, and exactly at (4β/5)^¼·g/U19.5', () => {
    for (const u10 of WIND_SPEEDS) {
      const u195 = 1.026 * u10;
      const peak = argmax((w) => piersonMoskowitz(w, u10), 0.1 / u195, 100 / u195);
      expect(relative(peak, (0.877 * G) / u195)).toBeLessThan(0.01);
      expect(relative(peak, ((0.8 * 0.74) ** 0.25 * G) / u195)).toBeLessThan(1e-8);
      expect(relative(piersonMoskowitzPeakFrequency(u10), ((0.8 * 0.74) ** 0.25 * G) / u195)).toBeLessThan(1e-14);
    }
  });

  it('matches the formula S = αg²/ω⁵·exp(−β(g/(U19.5·ω))⁴) written with Math functions (1e-13)', () => {
    for (const u10 of [5, 12, 25]) {
      const omega0 = G / (1.026 * u10);
      for (let w = 0.3 * omega0; w < 20 * omega0; w *= 1.07) {
        const want = ((8.1e-3 * G ** 2) / w ** 5) * Math.exp(-0.74 * (omega0 / w) ** 4);
        // detExp/detPow vs Math differ by a few ulp, magnified by the exponent (≤ ~100 here).
        expect(relative(piersonMoskowitz(w, u10), want)).toBeLessThan(1e-13);
      }
    }
  });
});

describe('JONSWAP fetch laws', () => {
  // (U10 m/s, F km), all short of full development (gF/U² < 1.7e4).
  const CASES: [number, number][] = [
    [10, 10],
    [20, 50],
    [5, 1],
    [30, 200],
  ];

  it('gives α = 0.076·(U10²/(F·g))^0.22 and ωp = 22·(g²/(U10·F))^⅓ (Stewart 2008, §16.3)', () => {
    for (const [u, fetchKm] of CASES) {
      const f = 1000 * fetchKm;
      const { alpha, peakFrequency } = jonswapParameters(u, fetchKm);
      // detPow vs Math.pow: ≤ ~1e-14 relative here (|y·ln x| ≤ 10).
      expect(relative(alpha, 0.076 * (u ** 2 / (f * G)) ** 0.22)).toBeLessThan(1e-13);
      expect(relative(peakFrequency, 22 * (G ** 2 / (u * f)) ** (1 / 3))).toBeLessThan(1e-13);
    }
  });

  it('has its peak where the fetch law puts it, and m0 = α·g²/ωp⁴·I(γ)', () => {
    for (const [u, fetchKm] of CASES) {
      const { alpha, peakFrequency } = jonswapParameters(u, fetchKm);
      const peak = argmax((w) => jonswap(w, u, fetchKm), 0.5 * peakFrequency, 2 * peakFrequency);
      // The γ^r factor peaks at ωp, the PM-shaped rest at ωp too: the maximum is at ωp.
      expect(relative(peak, peakFrequency)).toBeLessThan(1e-6);
      const m0 = integrate((w) => jonswap(w, u, fetchKm));
      expect(relative(m0, ((alpha * G ** 2) / peakFrequency ** 4) * jonswapShapeIntegral(3.3))).toBeLessThan(1e-6);
    }
  });

  it('reaches Pierson-Moskowitz’s peak at full development and stays there for longer fetch', () => {
    // gF/U² at full development: 22·1.026/0.877 cubed (see jonswapParameters), ≈ 1.70e4.
    expect(relative(FULLY_DEVELOPED_FETCH, ((22 * 1.026) / (0.8 * 0.74) ** 0.25) ** 3)).toBeLessThan(1e-13);
    for (const u of [5, 10, 20, 40]) {
      const fullKm = (FULLY_DEVELOPED_FETCH * u * u) / G / 1000;
      const pmPeak = piersonMoskowitzPeakFrequency(u);
      for (const factor of [1, 2, 10, 1e4]) {
        expect(jonswapParameters(u, fullKm * factor).peakFrequency).toBe(pmPeak);
        // α stops falling too: 0.076·(1.70e4)^−0.22 = 0.0089, near PM's 0.0081.
        expect(relative(jonswapParameters(u, fullKm * factor).alpha, 0.0089)).toBeLessThan(0.002);
      }
      // Just short of full development the fetch law still holds, and meets PM continuously.
      const short = jonswapParameters(u, fullKm * 0.999);
      expect(short.peakFrequency).toBeGreaterThan(pmPeak);
      expect(relative(short.peakFrequency, pmPeak)).toBeLessThan(0.001);
      // A long fetch approaches PM's peak from above.
      expect(jonswapParameters(u, fullKm * 0.5).peakFrequency).toBeGreaterThan(short.peakFrequency);
    }
  });

  it('is zero without wind, without NaN', () => {
    for (const w of [0, 1e-3, 1, 10]) expect(jonswap(w, 0, 100)).toBe(0);
  });
});

describe('JONSWAP peak enhancement', () => {
  it('I(1) = 1/5 exactly in closed form (γ = 1 is PM-shaped: ∫x⁻⁵e^{−(5/4)x⁻⁴}dx = 1/5)', () => {
    expect(Math.abs(jonswapShapeIntegral(1) - 0.2)).toBeLessThan(1e-9);
  });

  it('raises m0 by 1/(1 − 0.287·ln γ) (DNV-RP-C205 §3.5.5 normalising factor): ≈ 1.52 for γ = 3.3', () => {
    // DNV's A_γ is a fit to this ratio; it is within 0.3 % for 2 ≤ γ ≤ 5 and drifts to 2 % at γ = 7.
    for (const [gamma, tolerance] of [
      [2, 0.005],
      [3.3, 0.005],
      [5, 0.005],
      [7, 0.02],
    ]) {
      const ratio = jonswapShapeIntegral(gamma) / jonswapShapeIntegral(1);
      expect(relative(ratio, 1 / (1 - 0.287 * Math.log(gamma))), `γ = ${gamma}`).toBeLessThan(tolerance);
      // The same ratio by integrating the spectra themselves.
      const m0 = (g: number) => integrate((w) => jonswapShape(w, 0.01, 0.8, g));
      expect(relative(m0(gamma) / m0(1), ratio)).toBeLessThan(1e-6);
    }
    // The published value for the mean JONSWAP (γ = 3.3): 1/(1 − 0.287·ln 3.3) = 1.521.
    expect(relative(jonswapShapeIntegral(3.3) / 0.2, 1.521)).toBeLessThan(0.005);
  });
});

describe('tmaFactor', () => {
  it('is its piecewise definition in ω_h = ω·√(d/g) (Bouws et al. 1985)', () => {
    for (const depth of [0.1, 2, 5, 30, 400]) {
      const scale = Math.sqrt(depth / G);
      for (const [omegaH, want] of [
        [0, 0],
        [0.25, 0.03125],
        [0.5, 0.125],
        [1, 0.5],
        [1.5, 0.875],
        [1.75, 0.96875],
        [2, 1],
        [3, 1],
        [100, 1],
      ]) {
        // ω = ω_h/√(d/g) and back rounds twice: 1e-15 relative.
        expect(Math.abs(tmaFactor(omegaH / scale, depth) - want)).toBeLessThanOrEqual(2e-15);
      }
    }
  });

  it('is continuous and increasing, and 1 in deep water', () => {
    for (let omegaH = 0; omegaH < 3; omegaH += 0.001) {
      const here = tmaFactor(omegaH * Math.sqrt(10 / G), 10);
      const next = tmaFactor((omegaH + 0.001) * Math.sqrt(10 / G), 10);
      expect(next).toBeGreaterThanOrEqual(here);
      expect(next - here).toBeLessThan(0.0021); // slope ≤ 2 (Φ' = ω_h below 1, 2 − ω_h above)
    }
    for (const w of [1e-6, 0.1, 1, 100]) expect(tmaFactor(w, Infinity)).toBe(1);
  });

  it('is within 0.03 of Kitaigorodskii’s exact factor [k⁻³·dk/dω]_d / [k⁻³·dk/dω]_∞', () => {
    // Exact factor from ω² = gk·tanh(kd) (k by bisection) and c_g = (ω/2k)(1 + 2kd/sinh 2kd).
    const depth = 10;
    const waveNumber = (w: number) => {
      let [lo, hi] = [0, (w * w) / G + w / Math.sqrt(G * depth)];
      for (let i = 0; i < 200; i++) {
        const mid = (lo + hi) / 2;
        if (G * mid * Math.tanh(mid * depth) < w * w) lo = mid;
        else hi = mid;
      }
      return (lo + hi) / 2;
    };
    let largest = 0;
    for (let omegaH = 0.05; omegaH <= 4; omegaH += 0.05) {
      const w = omegaH / Math.sqrt(depth / G);
      const k = waveNumber(w);
      const groupVelocity = (w / (2 * k)) * (1 + (2 * k * depth) / Math.sinh(2 * k * depth));
      const kDeep = (w * w) / G;
      const exact = k ** -3 / groupVelocity / (kDeep ** -3 / (w / (2 * kDeep)));
      largest = Math.max(largest, Math.abs(exact - tmaFactor(w, depth)));
    }
    // The piecewise form is an approximation (Thompson & Vincent 1983): observed ≤ 0.023, at ω_h = 1.
    expect(largest).toBeLessThan(0.03);
  });

  it('lowers m0 at finite depth (TMA < JONSWAP) and leaves it in deep water', () => {
    const jonswapM0 = integrate((w) => jonswap(w, 12, 50));
    let previous = 0;
    for (const depth of [1, 3, 5, 10, 20]) {
      const tmaM0 = integrate((w) => jonswap(w, 12, 50) * tmaFactor(w, depth));
      expect(tmaM0).toBeLessThan(jonswapM0);
      expect(tmaM0).toBeGreaterThan(previous); // deeper water, more variance
      previous = tmaM0;
    }
    expect(integrate((w) => jonswap(w, 12, 50) * tmaFactor(w, Infinity))).toBe(jonswapM0);
  });
});

describe('swell', () => {
  it('has 4·√m0 = Hs (to 1e-6) and its peak at 2π/Tp', () => {
    for (const [hs, tp] of [
      [1, 8],
      [2.5, 14],
      [4, 20],
      [0.3, 5],
    ]) {
      const m0 = integrate((w) => swell(w, hs, tp));
      expect(relative(4 * Math.sqrt(m0), hs), `Hs ${hs}, Tp ${tp}`).toBeLessThan(1e-6);
      const peak = argmax((w) => swell(w, hs, tp), (0.5 * 2 * Math.PI) / tp, (2 * 2 * Math.PI) / tp);
      expect(relative(peak, (2 * Math.PI) / tp)).toBeLessThan(1e-6);
    }
  });

  it('is zero for Hs = 0 and scales with Hs²', () => {
    expect(swell(0.7, 0, 10)).toBe(0);
    expect(relative(swell(0.7, 3, 10), 9 * swell(0.7, 1, 10))).toBeLessThan(1e-15);
  });
});

describe('extreme inputs', () => {
  it('never give NaN, Infinity or a negative value', () => {
    const omegas = [0, 5e-324, 1e-300, 1e-10, 1e-3, 0.5, 3, 1e3, 1e10, 1e300, Infinity];
    for (const w of omegas) {
      const values = [
        ...[0, 0.1, 10, 60].map((u) => piersonMoskowitz(w, u)),
        ...[0, 0.1, 10, 60].flatMap((u) => [0.001, 1, 100, 10_000].map((f) => jonswap(w, u, f, 3.3))),
        jonswap(w, 20, 100, 1),
        jonswap(w, 20, 100, 20),
        ...[0.1, 5, Infinity].map((d) => tmaFactor(w, d)),
        ...[0, 0.5, 3].flatMap((hs) => [1, 10, 30].map((tp) => swell(w, hs, tp))),
      ];
      for (const v of values) expect(Number.isFinite(v) && v >= 0, `ω = ${w}: ${v}`).toBe(true);
    }
  });
});
