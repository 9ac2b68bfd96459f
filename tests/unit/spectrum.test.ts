/**
 * The Phillips spectrum and the initial amplitudes h̃0 on the FFT grid (Tessendorf 2001, eqs.
 * 23–25), checked against the formulas evaluated independently here with Math.exp / Math.cos.
 *
 * createCascadeSpectra takes a wave-number spectrum Ψ and draws h̃0(k) = (ξr + i·ξi)·√(Ψ(−k)·Δk²/4).
 * With Ψ = 2·P·(L/2π)² and one cascade of side L that is exactly the report's
 * h̃0 = (ξr + i·ξi)·√(P/2) (P symmetric), so the report's tests run on phillipsCascade() below.
 * Parameters are merged over the defaults without validation (parameters.test.ts checks that).
 */
import { describe, expect, it } from 'vitest';
import { angularFrequency, frequencyIndex } from '../../src/spectrum/dispersion';
import { DEFAULT_PARAMETERS, type SimulationParameters } from '../../src/parameters/parameters';
import { cascadeBands } from '../../src/spectrum/cascadeBands';
import { SeededRandom } from '../../src/spectrum/random';
import { createCascadeSpectra, createCascadeSpectrum, reducedSpectrum, signedFrequency, type InitialSpectrum, type WaveNumberSpectrum } from '../../src/spectrum/initialSpectrum';
import { phillips, windUnitVector } from '../../src/spectrum/phillips';

const G = 9.81;

/** The signed frequency n' of index i, straight from the definition in src/spectrum/initialSpectrum.ts. */
function signed(i: number, n: number): number {
  return i < n / 2 ? i : i - n;
}

/** Phillips spectrum, eq. 23 with the eq. 24 cutoff, written out with Math functions. */
function referencePhillips(kx: number, kz: number, p: SimulationParameters): number {
  const k = Math.hypot(kx, kz);
  if (k === 0 || p.windSpeed === 0) return 0;
  const angle = (p.windDirection * Math.PI) / 180;
  const cosine = (kx * Math.cos(angle) + kz * Math.sin(angle)) / k;
  const L = p.windSpeed ** 2 / G;
  const cutoff = Math.exp(-((k * p.smallWaveCutoff) ** 2));
  return ((p.amplitude * Math.exp(-1 / (k * L) ** 2)) / k ** 4) * cosine ** 2 * cutoff;
}

/**
 * The report's setting: the Phillips model on one 250 m patch, 12 m/s wind, ℓ = 0.1 m (the
 * defaults before cascades), with `changes` on top.
 */
function params(changes: Partial<SimulationParameters>): SimulationParameters {
  return {
    ...DEFAULT_PARAMETERS,
    spectrum: 'phillips',
    patchSizes: [250],
    windSpeed: 12,
    smallWaveCutoff: 0.1,
    ...changes,
  };
}

/** Side of the single cascade of these parameters. */
function patchOf(p: SimulationParameters): number {
  if (p.patchSizes.length !== 1) throw new Error(`one cascade expected, got ${p.patchSizes}`);
  return p.patchSizes[0];
}

/** Ψ = 2·P·(L/2π)² (m⁴), which makes one cascade of side L hold the report's h̃0. */
function phillipsDensity(p: SimulationParameters): WaveNumberSpectrum {
  const scale = 2 * (patchOf(p) / (2 * Math.PI)) ** 2;
  return (kx, kz) => scale * phillips(kx, kz, p);
}

/** The single cascade of the report's Phillips spectrum. */
function phillipsCascade(p: SimulationParameters): InitialSpectrum {
  const spectra = createCascadeSpectra(p, phillipsDensity(p));
  expect(spectra).toHaveLength(1);
  return spectra[0];
}

describe('phillips', () => {
  it('matches the formula written out independently (relative 1e-12)', () => {
    for (const p of [
      params({}),
      params({ windSpeed: 30, windDirection: -75, smallWaveCutoff: 0, amplitude: 1e-3 }),
      params({ windSpeed: 3, windDirection: 200, smallWaveCutoff: 0.5 }),
    ]) {
      let checked = 0;
      for (let a = -40; a <= 40; a++) {
        for (let b = -40; b <= 40; b++) {
          const kx = 0.05 * a;
          const kz = 0.037 * b;
          const want = referencePhillips(kx, kz, p);
          const angle = (p.windDirection * Math.PI) / 180;
          const cosine2 = ((kx * Math.cos(angle) + kz * Math.sin(angle)) / Math.hypot(kx, kz)) ** 2;
          // Skip where P underflows or the wind factor cos² is tiny (there the 1e-15 difference in
          // ŵ between detCosSinDegrees and Math.cos dominates the relative error).
          if (!(want > 1e-280) || cosine2 < 1e-2) continue;
          // detExp vs Math.exp differ by ≤ 2 ulp, and exp(x) magnifies the ~1 ulp rounding of its
          // argument x (|x| ≤ ~1000 here) to ≤ 2.2e-13 relative; cos² adds ≤ 2e-13. Observed: ≤ 6e-14.
          expect(Math.abs(phillips(kx, kz, p) / want - 1)).toBeLessThan(1e-12);
          checked++;
        }
      }
      expect(checked).toBeGreaterThan(1000);
    }
  });

  it('is 0 at k = 0', () => {
    for (const p of [params({}), params({ windSpeed: 60 }), params({ smallWaveCutoff: 0 })]) {
      expect(phillips(0, 0, p)).toBe(0);
    }
  });

  it('is 0 across the wind, positive and equal along and against it, for axis and oblique directions', () => {
    for (const direction of [0, 30, 45, 90, 137.5, 180, 270, -60, 400]) {
      const p = params({ windDirection: direction, smallWaveCutoff: 0 });
      const angle = (direction * Math.PI) / 180;
      // On the axes, exact unit vectors (Math.cos(π/2) is 6e-17, not 0).
      const onAxis = direction % 90 === 0;
      const wx = onAxis ? Math.round(Math.cos(angle)) : Math.cos(angle);
      const wz = onAxis ? Math.round(Math.sin(angle)) : Math.sin(angle);
      for (const k of [0.05, 0.5, 5]) {
        const along = phillips(k * wx, k * wz, p);
        const against = phillips(-k * wx, -k * wz, p);
        const across = phillips(-k * wz, k * wx, p);
        expect(along).toBeGreaterThan(0);
        expect(against).toBe(along);
        // Across the wind k̂·ŵ is 0 up to rounding (~1e-15), so P/P_along ≤ ~1e-30; a missing or
        // wrong angular factor gives a ratio of order 1.
        expect(across / along).toBeLessThan(1e-20);
        if (onAxis) expect(across === 0).toBe(true); // ŵ exact on the axes
        // Off the wind at 60°, |k̂·ŵ|² = 1/4.
        const c60 = Math.cos(angle + Math.PI / 3);
        const s60 = Math.sin(angle + Math.PI / 3);
        // 1e-12: the same argument as the formula test above.
        expect(Math.abs(phillips(k * c60, k * s60, p) / along - 0.25)).toBeLessThan(1e-12);
      }
    }
  });

  it('uses the wind direction from +x towards +z', () => {
    const [wx, wz] = windUnitVector(30);
    // detCosSinDegrees is within 1e-15 of cos/sin (deterministicMath.test.ts).
    expect(Math.abs(wx - Math.sqrt(3) / 2)).toBeLessThan(1e-15);
    expect(Math.abs(wz - 0.5)).toBeLessThan(1e-15);
    const p = params({ windDirection: 90 });
    expect(phillips(0, 0.3, p)).toBeGreaterThan(0);
    expect(phillips(0.3, 0, p) === 0).toBe(true);
  });

  it('is proportional to the amplitude A', () => {
    for (const [kx, kz] of [
      [0.1, 0.02],
      [-0.7, 0.4],
      [2, -3],
    ]) {
      const base = phillips(kx, kz, params({ amplitude: 2e-6 }));
      expect(phillips(kx, kz, params({ amplitude: 4e-6 }))).toBe(2 * base); // ×2 is exact
      // ×3 then rounding: a few ulp.
      expect(Math.abs(phillips(kx, kz, params({ amplitude: 6e-6 })) / base - 3)).toBeLessThan(1e-14);
      expect(phillips(kx, kz, params({ amplitude: 0 }))).toBe(0);
    }
  });

  it('is symmetric, P(k) = P(−k), exactly', () => {
    const p = params({ windDirection: 33.3, windSpeed: 17 });
    for (let a = -20; a <= 20; a++) {
      for (let b = -20; b <= 20; b++) {
        const [kx, kz] = [0.031 * a + 0.001, 0.027 * b];
        expect(phillips(-kx, -kz, p)).toBe(phillips(kx, kz, p));
      }
    }
  });

  it('is 0 everywhere, without NaN, when there is no wind', () => {
    const p = params({ windSpeed: 0 });
    for (const [kx, kz] of [
      [0, 0],
      [1e-6, 0],
      [0.3, 0.4],
      [-100, 7],
    ]) {
      expect(phillips(kx, kz, p)).toBe(0);
    }
  });
});

describe('signedFrequency', () => {
  it('orders frequencies as an FFT does: N = 8 gives 0 1 2 3 −4 −3 −2 −1', () => {
    // From the definition: n' = i for i < N/2, n' = i − N for i ≥ N/2.
    expect(Array.from({ length: 8 }, (_, i) => signedFrequency(i, 8))).toEqual([0, 1, 2, 3, -4, -3, -2, -1]);
  });

  it('is congruent to i mod N and lies in [−N/2, N/2) for every N', () => {
    for (let n = 2; n <= 1024; n *= 2) {
      for (let i = 0; i < n; i++) {
        const f = signedFrequency(i, n);
        expect((((f - i) % n) + n) % n).toBe(0);
        expect(f >= -n / 2 && f < n / 2).toBe(true);
      }
    }
  });
});

describe('createCascadeSpectra with one Phillips cascade (the report’s h̃0)', () => {
  const cases = [
    params({ resolution: 16, patchSizes: [50], windDirection: 30, depth: 5, smallWaveCutoff: 0 }),
    params({ resolution: 32, patchSizes: [80], windDirection: -110, windSpeed: 20, seed: 9 }),
  ];

  it('stores (kx, kz, 1/|k|, m) per texel, with the Nyquist components of kx and kz set to 0', () => {
    for (const p of cases) {
      const n = p.resolution;
      const L = patchOf(p);
      const spectrum = phillipsCascade(p);
      const { waveVectors, repeatPeriod } = spectrum;
      // One cascade keeps everything: band [0, ∞), period T·2^j (cascadeBands.test.ts checks j).
      expect(spectrum.band).toEqual({ patchSize: L, low: 0, high: Infinity });
      expect(spectrum.patchSize).toBe(L);
      expect(Number.isInteger(Math.log2(repeatPeriod / p.repeatPeriod))).toBe(true);
      const wrong: string[] = [];
      for (let j = 0; j < n; j++) {
        for (let i = 0; i < n; i++) {
          const t = 4 * (j * n + i);
          const kx = (2 * Math.PI * signed(i, n)) / L;
          const kz = (2 * Math.PI * signed(j, n)) / L;
          const k = Math.hypot(kx, kz);
          // Float32 storage: relative ≤ 2^−24 ≈ 6e-8; 1.2e-7 also allows a double rounding.
          const close = (got: number, want: number) => Math.abs(got - want) <= 1.2e-7 * Math.abs(want);
          const problems: string[] = [];
          if (i === n / 2 ? waveVectors[t] !== 0 : !close(waveVectors[t], kx)) problems.push('kx');
          if (j === n / 2 ? waveVectors[t + 1] !== 0 : !close(waveVectors[t + 1], kz)) problems.push('kz');
          // 1/|k| of the true k (Nyquist components included), 0 at k = 0.
          if (k === 0 ? waveVectors[t + 2] !== 0 : !close(waveVectors[t + 2], 1 / k)) problems.push('1/k');
          const m = waveVectors[t + 3];
          if (m !== frequencyIndex(k, { depth: p.depth, repeatPeriod })) problems.push('m');
          // and independently: m·2π/T_c is ω(k) rounded to the nearest multiple of 2π/T_c,
          // |m·2π/T_c − ω| ≤ π/T_c (1e-12: rounding slack, as in dispersion.test.ts)
          const omega = angularFrequency(k, p.depth);
          if (Math.abs((m * 2 * Math.PI) / repeatPeriod - omega) > (Math.PI / repeatPeriod) * (1 + 1e-12)) problems.push('ω');
          // The opposite texel holds −k (exactly: float32 negation) and the same m.
          const o = 4 * (((n - j) % n) * n + ((n - i) % n));
          if (waveVectors[o] !== -waveVectors[t] || waveVectors[o + 1] !== -waveVectors[t + 1]) problems.push('−k');
          if (waveVectors[o + 2] !== waveVectors[t + 2] || waveVectors[o + 3] !== m) problems.push('1/k or m at −k');
          if (problems.length > 0) wrong.push(`(${i}, ${j}): ${problems.join(', ')}`);
        }
      }
      expect(wrong).toEqual([]);
    }
  });

  it('stores Ψ = 2·P·(L/2π)² per texel (float32 of the independent formula)', () => {
    for (const p of cases) {
      const n = p.resolution;
      const L = patchOf(p);
      const scale = 2 * (L / (2 * Math.PI)) ** 2;
      const spectrum = phillipsCascade(p);
      for (let j = 0; j < n; j++) {
        for (let i = 0; i < n; i++) {
          const kx = (2 * Math.PI * signed(i, n)) / L;
          const kz = (2 * Math.PI * signed(j, n)) / L;
          const want = scale * referencePhillips(kx, kz, p);
          // Float32 rounding (≤ 6e-8 relative) plus the cos² term's ~2e-15 absolute (see above).
          const slack = 1.2e-7 * want + (scale * 2e-15 * p.amplitude) / Math.max(kx * kx + kz * kz, 1e-300) ** 2;
          expect(Math.abs(spectrum.density[j * n + i] - want)).toBeLessThanOrEqual(slack);
        }
      }
    }
  });

  it('holds h̃0 = (ξr + i·ξi)·√(P/2), the report’s amplitudes, with ξ the seed’s deviates in texel order', () => {
    for (const p of cases) {
      const n = p.resolution;
      const L = patchOf(p);
      const { amplitudes } = phillipsCascade(p);
      const random = new SeededRandom(p.seed);
      let worst = 0;
      for (let j = 0; j < n; j++) {
        for (let i = 0; i < n; i++) {
          const t = 4 * (j * n + i);
          const P = referencePhillips((2 * Math.PI * signed(i, n)) / L, (2 * Math.PI * signed(j, n)) / L, p);
          const scale = Math.sqrt(P / 2);
          const [xr, xi] = [random.nextNormal(), random.nextNormal()];
          // Float32 storage, relative 6e-8 of |h̃0|, plus P's own ~1e-13 (see the formula test).
          const slack = 1.2e-7 * scale * Math.max(Math.abs(xr), Math.abs(xi), 1) + 1e-300;
          worst = Math.max(worst, (Math.abs(amplitudes[t] - xr * scale) + Math.abs(amplitudes[t + 1] - xi * scale)) / slack);
        }
      }
      expect(worst).toBeLessThanOrEqual(1);
    }
  });

  it('pairs each texel k with the conjugate of h̃0 at −k, texel ((N−i) mod N, (N−j) mod N)', () => {
    for (const p of cases) {
      const n = p.resolution;
      const { amplitudes } = phillipsCascade(p);
      let nonzero = 0;
      for (let j = 0; j < n; j++) {
        for (let i = 0; i < n; i++) {
          const t = 4 * (j * n + i);
          const o = 4 * (((n - j) % n) * n + ((n - i) % n));
          // Exact: copying and negating a float32 does not round.
          expect(amplitudes[t + 2] === amplitudes[o] && amplitudes[t + 3] === -amplitudes[o + 1]).toBe(true);
          if (amplitudes[t] !== 0) nonzero++;
        }
      }
      // Everything but k = 0 has P > 0 here, so the pairing is not checked on zeros only.
      expect(nonzero).toBe(n * n - 1);
      const nyquist = 4 * ((n / 2) * n + n / 2);
      expect(amplitudes[nyquist]).not.toBe(0);
    }
  });

  it('is bit-identical for the same seed and different for another seed', () => {
    const p = params({ resolution: 64, seed: 12345 });
    const a = phillipsCascade(p);
    const b = phillipsCascade({ ...p });
    for (const key of ['amplitudes', 'waveVectors', 'density'] as const) {
      expect(new Uint32Array(a[key].buffer)).toEqual(new Uint32Array(b[key].buffer));
    }
    const other = phillipsCascade({ ...p, seed: 12346 });
    let differing = 0;
    for (let t = 0; t < 64 * 64; t++) if (other.amplitudes[4 * t] !== a.amplitudes[4 * t]) differing++;
    expect(differing).toBe(64 * 64 - 1); // all but k = 0, where h̃0 = 0 for any seed
    expect(new Uint32Array(other.waveVectors.buffer)).toEqual(new Uint32Array(a.waveVectors.buffer));
  });

  it('draws the same normal deviates whatever the spectrum, so a wind change keeps the sea’s phases', () => {
    const calm = params({ resolution: 32, windSpeed: 5, windDirection: 10, seed: 4 });
    const storm = params({ resolution: 32, windSpeed: 25, windDirection: 70, seed: 4 });
    const a = phillipsCascade(calm);
    const b = phillipsCascade(storm);
    let checked = 0;
    for (let t = 0; t < 32 * 32; t++) {
      const i = t % 32;
      const j = Math.floor(t / 32);
      const kx = (2 * Math.PI * signed(i, 32)) / patchOf(calm);
      const kz = (2 * Math.PI * signed(j, 32)) / patchOf(calm);
      const scaleA = Math.sqrt(phillips(kx, kz, calm) / 2);
      const scaleB = Math.sqrt(phillips(kx, kz, storm) / 2);
      if (!(scaleA > 1e-15 && scaleB > 1e-15)) continue;
      checked++;
      for (const c of [0, 1]) {
        // ξ = h̃0/√(P/2) from each spectrum; float32 storage makes each ≤ 6e-8 relative off.
        const xiA = a.amplitudes[4 * t + c] / scaleA;
        const xiB = b.amplitudes[4 * t + c] / scaleB;
        expect(Math.abs(xiA - xiB)).toBeLessThanOrEqual(2e-7 * Math.max(1, Math.abs(xiA)));
      }
    }
    expect(checked).toBeGreaterThan(900);
  });

  it('has ⟨|h̃0|²⟩ = P: mean of |h̃0|²/P over 65 000 texels is 1 within 5 standard errors', () => {
    const p = params({ resolution: 256, seed: 2024 });
    const n = p.resolution;
    const { amplitudes } = phillipsCascade(p);
    let count = 0;
    let sumBoth = 0;
    let sumReal = 0;
    let sumImag = 0;
    let sumCross = 0;
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const dk = (2 * Math.PI) / patchOf(p);
        const P = referencePhillips(dk * signed(i, n), dk * signed(j, n), p);
        if (!(P > 1e-50)) continue; // keep h̃0 well inside float32's normal range
        const t = 4 * (j * n + i);
        const re2 = amplitudes[t] ** 2 / (P / 2);
        const im2 = amplitudes[t + 1] ** 2 / (P / 2);
        sumReal += re2;
        sumImag += im2;
        sumBoth += (re2 + im2) / 2;
        sumCross += (amplitudes[t] * amplitudes[t + 1]) / (P / 2);
        count++;
      }
    }
    expect(count).toBeGreaterThan(60_000);
    // |h̃0|²/P = (ξr² + ξi²)/2 is exponential with mean 1 and variance 1: σ = 1/√count.
    expect(Math.abs(sumBoth / count - 1)).toBeLessThan(5 / Math.sqrt(count));
    // ξr² and ξi² alone are χ²₁: mean 1, variance 2.
    expect(Math.abs(sumReal / count - 1)).toBeLessThan(5 * Math.sqrt(2 / count));
    expect(Math.abs(sumImag / count - 1)).toBeLessThan(5 * Math.sqrt(2 / count));
    // ξr·ξi: mean 0, variance 1 (independent real and imaginary parts).
    expect(Math.abs(sumCross / count)).toBeLessThan(5 / Math.sqrt(count));
  });

  it('has no NaN or Infinity for no wind, a 60 m/s gale, and N = 1024 (built from at most 2·N² values of Ψ)', () => {
    for (const p of [params({ windSpeed: 0 }), params({ windSpeed: 60 }), params({ resolution: 1024 })]) {
      let evaluations = 0;
      const density = phillipsDensity(p);
      const spectra = createCascadeSpectra(p, (kx, kz) => {
        evaluations++;
        return density(kx, kz);
      });
      expect(spectra).toHaveLength(1);
      const [spectrum] = spectra;
      const n = p.resolution;
      // The build's work, whatever the machine (its time is the bench's): Ψ once per texel's cell,
      // and once more for the opposite cell where that is not the mirrored texel's (the rows and
      // columns 0 and N/2, and every texel of a calm sea, whose Ψ is 0). A cell integrated on
      // sub-cells (EDGE_CELL_SPLIT² each) where it need not be, or a search per texel, exceeds it.
      expect(evaluations).toBeGreaterThanOrEqual(n * n);
      expect(evaluations).toBeLessThanOrEqual(2 * n * n);
      expect(spectrum.resolution).toBe(n);
      expect(spectrum.patchSize).toBe(patchOf(p));
      expect(spectrum.amplitudes.length).toBe(4 * n * n);
      expect(spectrum.waveVectors.length).toBe(4 * n * n);
      expect(spectrum.density.length).toBe(n * n);
      for (const array of [spectrum.amplitudes, spectrum.waveVectors, spectrum.density]) {
        expect(array.every(Number.isFinite)).toBe(true);
      }
      if (p.windSpeed === 0) {
        expect(spectrum.amplitudes.every((x) => x === 0)).toBe(true);
        expect(spectrum.density.every((x) => x === 0)).toBe(true);
      } else {
        expect(spectrum.amplitudes.some((x) => x !== 0)).toBe(true);
      }
    }
  });
});

describe('createCascadeSpectrum (what a query worker builds its copy from)', () => {
  // The default sea state and a swell on a shallow bay: each cascade must be bit for bit the one
  // createCascadeSpectra makes, or the queries would answer for another sea than the one drawn.
  for (const changes of [{ resolution: 64 }, { resolution: 32, spectrum: 'tma', depth: 6, swellHeight: 1.5, seed: 9 }] as Partial<SimulationParameters>[]) {
    it(`equals createCascadeSpectra(params)[c] for every cascade c (${JSON.stringify(changes)})`, () => {
      const p = { ...DEFAULT_PARAMETERS, ...changes };
      const all = createCascadeSpectra(p);
      expect(all).toHaveLength(3);
      all.forEach((expected, c) => {
        const alone = createCascadeSpectrum(p, c);
        expect(alone.repeatPeriod).toBe(expected.repeatPeriod);
        expect(alone.band).toEqual(expected.band);
        expect(alone.amplitudes).toEqual(expected.amplitudes);
        expect(alone.waveVectors).toEqual(expected.waveVectors);
        expect(alone.density).toEqual(expected.density);
        // On a coarser grid: the reduced spectrum (the query copies of N > 256), computing only its modes.
        const size = p.resolution / 4;
        const reduced = reducedSpectrum(expected, size);
        const coarse = createCascadeSpectrum(p, c, size);
        expect(coarse.resolution).toBe(size);
        expect(coarse.repeatPeriod).toBe(reduced.repeatPeriod);
        expect(coarse.amplitudes).toEqual(reduced.amplitudes);
        expect(coarse.waveVectors).toEqual(reduced.waveVectors);
        expect(coarse.density).toEqual(reduced.density);
      });
    });
  }
});

describe('wind direction edge case found in review', () => {
  it('a tiny negative wind direction builds a spectrum', () => {
    expect(() => phillipsCascade(params({ resolution: 16, windDirection: -1e-20 }))).not.toThrow();
  });
});

describe('createCascadeSpectra with several cascades', () => {
  // A spectrum that is not symmetric, so Ψ(k) and Ψ(−k) differ: waves travel towards +x mostly.
  const lopsided: WaveNumberSpectrum = (kx, kz) => {
    const k2 = kx * kx + kz * kz;
    return k2 === 0 ? 0 : (Math.exp(-k2 / 400) * (1.5 + Math.tanh(kx))) / (1 + k2);
  };
  const p = params({ resolution: 32, patchSizes: [3, 15, 60], seed: 31, depth: 7 });

  it('draws h̃0(k) = (ξr + i·ξi)·√(Ψ̄(−k)·Δk²/4) in each band, Ψ̄ = Ψ inside, largest patch first, two deviates per texel', () => {
    const spectra = createCascadeSpectra(p, lopsided);
    const n = p.resolution;
    expect(spectra.map((s) => s.patchSize)).toEqual([3, 15, 60]);
    const bands = cascadeBands(p.patchSizes, p.resolution);
    const random = new SeededRandom(p.seed);
    // Largest first: cascade 2, then 1, then 0, each drawing 2·N² deviates in texel order.
    for (const c of [2, 1, 0]) {
      const s = spectra[c];
      expect(s.band).toEqual(bands[c]);
      const dk = (2 * Math.PI) / p.patchSizes[c];
      let worst = 0;
      let [inside, crossed] = [0, 0];
      let zeroOutside = true;
      for (let j = 0; j < n; j++) {
        for (let i = 0; i < n; i++) {
          const t = j * n + i;
          const [kx, kz] = [dk * signed(i, n), dk * signed(j, n)];
          const [xr, xi] = [random.nextNormal(), random.nextNormal()];
          // The mode's cell, the square of side Δk around it: its nearest and farthest |k|.
          const [a, b] = [Math.abs(signed(i, n)), Math.abs(signed(j, n))];
          const nearest = dk * Math.hypot(Math.max(0, a - 0.5), Math.max(0, b - 0.5));
          const farthest = dk * Math.hypot(a + 0.5, b + 0.5);
          if (farthest <= bands[c].low || nearest >= bands[c].high) {
            zeroOutside &&= s.amplitudes[4 * t] === 0 && s.amplitudes[4 * t + 1] === 0 && s.density[t] === 0;
            continue;
          }
          const whole = nearest >= bands[c].low && farthest < bands[c].high;
          if (whole) inside++;
          else if (s.density[t] > 0) crossed++;
          // Ψ̄(−k) is the opposite texel's (exactly −k off the Nyquist row and column, which no
          // crossed cell of these bands reaches); inside the band it is Ψ(−k) itself.
          const opposite = ((n - j) % n) * n + ((n - i) % n);
          const psi = whole ? lopsided(-kx, -kz) : s.density[opposite];
          const scale = Math.sqrt((psi * dk * dk) / 4);
          // Float32 storage: 6e-8 relative; the slack is relative to the larger of the two parts.
          const slack = 1.2e-7 * scale * Math.max(Math.abs(xr), Math.abs(xi), 1) + 1e-300;
          worst = Math.max(worst, (Math.abs(s.amplitudes[4 * t] - xr * scale) + Math.abs(s.amplitudes[4 * t + 1] - xi * scale)) / slack);
          // Ψ(k) itself, as float32, for inspection.
          if (whole) worst = Math.max(worst, Math.abs(s.density[t] - lopsided(kx, kz)) / (6e-8 * lopsided(kx, kz) + 1e-300));
        }
      }
      expect(inside, `cascade ${c}`).toBeGreaterThan(20);
      // Every band here but the finest's corner has an edge inside the grid, crossing cells.
      expect(crossed, `cascade ${c}`).toBeGreaterThan(0);
      expect(zeroOutside, `cascade ${c}`).toBe(true);
      expect(worst, `cascade ${c}`).toBeLessThanOrEqual(1);
    }
  });

  it('pairs each texel with the conjugate of h̃0 at −k in every cascade', () => {
    const n = p.resolution;
    for (const { amplitudes } of createCascadeSpectra(p, lopsided)) {
      let unpaired = 0;
      for (let j = 0; j < n; j++) {
        for (let i = 0; i < n; i++) {
          const t = 4 * (j * n + i);
          const o = 4 * (((n - j) % n) * n + ((n - i) % n));
          if (amplitudes[t + 2] !== amplitudes[o] || amplitudes[t + 3] !== -amplitudes[o + 1]) unpaired++;
        }
      }
      expect(unpaired).toBe(0);
    }
  });

  it('gives the largest cascade the deviates a single cascade of that size gets, so a seed keeps its swell', () => {
    const [, , coarsest] = createCascadeSpectra(p, lopsided);
    const [alone] = createCascadeSpectra({ ...p, patchSizes: [60] }, lopsided);
    const n = p.resolution;
    const dk = (2 * Math.PI) / 60;
    let compared = 0;
    for (let t = 0; t < n * n; t++) {
      // Modes whose cells lie wholly below the band's high edge: there the band holds all of the
      // cell, as the single cascade does (a cell the edge crosses holds only its share).
      const [a, b] = [Math.abs(signed(t % n, n)), Math.abs(signed(Math.floor(t / n), n))];
      if (coarsest.density[t] === 0 || dk * Math.hypot(a + 0.5, b + 0.5) >= coarsest.band.high) continue;
      // Same deviate, same Ψ, same Δk: bit-identical.
      expect(coarsest.amplitudes[4 * t]).toBe(alone.amplitudes[4 * t]);
      expect(coarsest.amplitudes[4 * t + 1]).toBe(alone.amplitudes[4 * t + 1]);
      compared++;
    }
    expect(compared).toBeGreaterThan(50);
  });
});
