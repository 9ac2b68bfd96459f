/**
 * Directional spreading D(ω, θ): each model integrates to 1 over (−π, π], is symmetric and peaks at
 * θ = 0; the exponents and β follow the published laws (Mitsuyasu et al. 1975, Hasselmann et al.
 * 1980, Donelan et al. 1985 with Banner 1990); Horvath's (2015) swell elongation narrows cos-2s.
 */
import { describe, expect, it } from 'vitest';
import {
  cos2s,
  cos2sNormalization,
  directionalSpreading,
  donelanBanner,
  donelanBannerBeta,
  hasselmannExponent,
  horvathElongation,
  mitsuyasuExponent,
} from '../../src/spectrum/spreading';
import type { SpreadingModel } from '../../src/parameters/parameters';

const G = 9.81;
const MODELS: SpreadingModel[] = ['cos-2s', 'mitsuyasu', 'hasselmann', 'donelan-banner'];
const FREQUENCY_RATIOS = [0.05, 0.2, 0.56, 0.9, 0.95, 1, 1.05, 1.3, 1.6, 2, 4, 10];

/**
 * ∫ D dθ by the midpoint rule with 20 000 cells. Over the whole circle θ = π·v(3 − v²)/2, v in
 * (−1, 1), crowds the cells towards ±π, where cos-2s with a small s has a cusp (|π − θ|^{2s}): in v it
 * becomes (1 − v)^{4s+1}, smooth enough for 1e-9. The midpoint rule never samples θ = ±π itself.
 */
function integrateDirections(spreading: (theta: number) => number, from?: number, to?: number): number {
  const n = 20_000;
  let sum = 0;
  if (from === undefined || to === undefined) {
    for (let i = 0; i < n; i++) {
      const v = -1 + ((i + 0.5) * 2) / n;
      sum += spreading((Math.PI * v * (3 - v * v)) / 2) * ((3 * Math.PI) / 2) * (1 - v * v);
    }
    return (sum * 2) / n;
  }
  const h = (to - from) / n;
  for (let i = 0; i < n; i++) sum += spreading(from + (i + 0.5) * h);
  return sum * h;
}

/** Each model at ω = ratio·ωp, for a wind sea with ωp = 0.8 rad/s and U10 = 10 m/s. */
function model(name: SpreadingModel, ratio: number, exponent = 10) {
  const peakFrequency = 0.8;
  return (theta: number) =>
    directionalSpreading(theta, ratio * peakFrequency, { model: name, peakFrequency, windSpeed: 10, exponent });
}

describe('every spreading model', () => {
  it('integrates to 1 over (−π, π] within 1e-6, at every ω/ωp', () => {
    for (const name of MODELS) {
      for (const ratio of FREQUENCY_RATIOS) {
        expect(Math.abs(integrateDirections(model(name, ratio)) - 1), `${name} at ω/ωp = ${ratio}`).toBeLessThan(1e-6);
      }
    }
  });

  it('is symmetric (1e-14) and largest at θ = 0, falling monotonically to θ = ±π', () => {
    for (const name of MODELS) {
      for (const ratio of FREQUENCY_RATIOS) {
        const d = model(name, ratio);
        let previous = d(0);
        for (let theta = 0.01; theta <= Math.PI; theta += 0.01) {
          const here = d(theta);
          expect(Math.abs(d(-theta) - here)).toBeLessThanOrEqual(1e-14 * d(0));
          expect(here).toBeLessThanOrEqual(previous);
          previous = here;
        }
        expect(d(0)).toBeGreaterThan(d(Math.PI / 2));
      }
    }
  });
});

describe('cos-2s', () => {
  it('normalises with Γ(s+1)/(2√π·Γ(s+½)) = 2^{2s−1}Γ²(s+1)/(π·Γ(2s+1)) (Longuet-Higgins et al. 1963)', () => {
    // Integer s: 2^{2s−1}·(s!)²/(π·(2s)!), exact factorials.
    const factorial = (n: number): number => (n <= 1 ? 1 : n * factorial(n - 1));
    for (const s of [0, 1, 2, 5, 10, 20]) {
      const want = (2 ** (2 * s - 1) * factorial(s) ** 2) / (Math.PI * factorial(2 * s));
      expect(Math.abs(cos2sNormalization(s) / want - 1), `s = ${s}`).toBeLessThan(1e-13);
    }
    // ln Γ's ~2e-15 absolute error (deterministicMath.test.ts) passes through exp: 1e-14 relative.
    expect(Math.abs(cos2sNormalization(0) * 2 * Math.PI - 1)).toBeLessThan(1e-14); // isotropic
    expect(Math.abs(cos2sNormalization(1) * Math.PI - 1)).toBeLessThan(1e-14);
  });

  it('integrates to 1 for fractional and large s', () => {
    for (const s of [0, 0.25, 0.5, 1.5, 7.3, 33, 150, 400]) {
      expect(Math.abs(integrateDirections((t) => cos2s(t, s)) - 1), `s = ${s}`).toBeLessThan(1e-6);
    }
  });

  it('has |cos(θ/2)|^{2s} (Math.cos reference within 1e-14), 0 at θ = ±π for s > 0', () => {
    for (const s of [0.5, 3, 12]) {
      for (let theta = -Math.PI; theta <= Math.PI; theta += 0.05) {
        const want = cos2sNormalization(s) * Math.abs(Math.cos(theta / 2)) ** (2 * s);
        expect(Math.abs(cos2s(theta, s) - want)).toBeLessThan(1e-14);
      }
      expect(cos2s(Math.PI, s)).toBeLessThan(1e-15);
    }
  });
});

describe('Mitsuyasu et al. 1975', () => {
  it('has s_p = 11.5·(ωp·U10/g)^−2.5 at the peak, ×(ω/ωp)⁵ below and ×(ω/ωp)^−2.5 above', () => {
    for (const [peak, wind] of [
      [0.8, 10],
      [0.4, 20],
      [2, 5],
    ]) {
      const sp = 11.5 * ((peak * wind) / G) ** -2.5;
      expect(Math.abs(mitsuyasuExponent(peak, peak, wind) / sp - 1)).toBeLessThan(1e-13);
      expect(Math.abs(mitsuyasuExponent(0.5 * peak, peak, wind) / (sp * 0.5 ** 5) - 1)).toBeLessThan(1e-13);
      expect(Math.abs(mitsuyasuExponent(2 * peak, peak, wind) / (sp * 2 ** -2.5) - 1)).toBeLessThan(1e-13);
    }
    // A fully developed sea (ωp·U10/g = 0.877/1.026, Stewart eq. 16.30) has s_p = 11.5·0.8548^−2.5 ≈ 17.0.
    const fullyDevelopedPeak = (0.877 * G) / (1.026 * 10);
    expect(Math.abs(mitsuyasuExponent(fullyDevelopedPeak, fullyDevelopedPeak, 10) - 17.0)).toBeLessThan(0.05);
  });
});

describe('Hasselmann et al. 1980', () => {
  it('has 6.97·(ω/ωp)^4.06 below 1.05·ωp and 9.77·(ω/ωp)^μ above, μ = −2.33 − 1.45(U10/cp − 1.17)', () => {
    const peak = 0.8;
    for (const wind of [5, 10, 20]) {
      const mu = -2.33 - 1.45 * (wind / (G / peak) - 1.17);
      for (const ratio of [0.3, 0.8, 1, 1.04]) {
        expect(Math.abs(hasselmannExponent(ratio * peak, peak, wind) / (6.97 * ratio ** 4.06) - 1)).toBeLessThan(1e-13);
      }
      for (const ratio of [1.05, 1.5, 3]) {
        expect(Math.abs(hasselmannExponent(ratio * peak, peak, wind) / (9.77 * ratio ** mu) - 1)).toBeLessThan(1e-13);
      }
    }
  });
});

describe('Donelan-Banner', () => {
  it('has β = 2.61(ω/ωp)^1.3, 2.28(ω/ωp)^−1.3 and Banner’s 10^{−0.4+0.8393·exp(−0.567·ln(ω/ωp)²)}', () => {
    for (const x of [0.1, 0.56, 0.9]) expect(Math.abs(donelanBannerBeta(x) / (2.61 * x ** 1.3) - 1)).toBeLessThan(1e-13);
    for (const x of [0.95, 1, 1.3, 1.59]) expect(Math.abs(donelanBannerBeta(x) / (2.28 * x ** -1.3) - 1)).toBeLessThan(1e-13);
    for (const x of [1.6, 2, 5, 30]) {
      const want = 10 ** (-0.4 + 0.8393 * Math.exp(-0.567 * Math.log(x * x)));
      expect(Math.abs(donelanBannerBeta(x) / want - 1)).toBeLessThan(1e-13);
    }
  });

  it('is nearly continuous where the fitted laws meet (0.3 % at 0.95, 0.4 % at 1.6, as published)', () => {
    const jump = (x: number) => Math.abs(donelanBannerBeta(x * (1 + 1e-12)) / donelanBannerBeta(x * (1 - 1e-12)) - 1);
    expect(jump(0.95)).toBeLessThan(0.003);
    expect(jump(1.6)).toBeLessThan(0.005);
  });

  it('is β·sech²(βθ)/(2·tanh βπ), which corrects the truncation of sech²’s 2/β to (−π, π]', () => {
    for (const ratio of [0.3, 1, 3]) {
      const beta = donelanBannerBeta(ratio);
      for (const theta of [0, 0.4, 1.5, 3]) {
        const want = (beta / (2 * Math.tanh(beta * Math.PI))) / Math.cosh(beta * theta) ** 2;
        expect(Math.abs(donelanBanner(theta, ratio * 0.8, 0.8) / want - 1)).toBeLessThan(1e-14);
      }
    }
    // Far below the peak β → 0: isotropic, 1/(2π), without 0/0.
    expect(Math.abs(donelanBanner(1, 1e-300, 0.8) - 1 / (2 * Math.PI))).toBeLessThan(1e-15);
  });
});

describe('Horvath 2015 swell elongation', () => {
  it('adds 16·tanh(ωp/ω)·ξ² to s', () => {
    for (const xi of [0, 0.3, 1]) {
      for (const ratio of [0.5, 1, 2]) {
        const want = 10 + 16 * Math.tanh(1 / ratio) * xi * xi;
        expect(Math.abs(horvathElongation(10, ratio * 0.6, 0.6, xi) - want)).toBeLessThan(1e-13);
      }
    }
    expect(horvathElongation(7, 0.3, 0.6, 0)).toBe(7);
  });

  it('narrows the spreading: more of it within ±30°, higher at θ = 0, still normalised', () => {
    for (const base of [1, 10]) {
      for (const ratio of [0.7, 1, 2]) {
        let previousCore = 0;
        let previousPeak = 0;
        for (const xi of [0, 0.25, 0.5, 0.75, 1]) {
          const s = horvathElongation(base, ratio, 1, xi);
          const d = (theta: number) => cos2s(theta, s);
          expect(Math.abs(integrateDirections(d) - 1)).toBeLessThan(1e-6);
          const core = integrateDirections(d, -Math.PI / 6, Math.PI / 6);
          if (xi > 0) {
            expect(core).toBeGreaterThan(previousCore);
            expect(d(0)).toBeGreaterThan(previousPeak);
          }
          previousCore = core;
          previousPeak = d(0);
        }
      }
    }
  });
});
