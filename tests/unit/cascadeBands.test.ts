/**
 * How the spectrum is split between FFT cascades (src/spectrum/cascadeBands.ts) and what
 * createCascadeSpectra keeps of it, checked against the physics and the geometry of the grids:
 *
 *   (a) the bands are disjoint and together cover [0, ∞): every |k| belongs to exactly one
 *       cascade; a cascade keeps the modes whose cells (squares of side Δk around them) reach into
 *       its band, and its cells cover the band's area exactly once;
 *   (b) every kept mode moves at its true phase speed √(g·tanh(kd)/k) (the dispersion relation,
 *       Tessendorf 2001, eq. 15; e.g. Kinsman, "Wind Waves", 1965, §3) within 1 %, after its ω is
 *       quantized to a multiple of its cascade's 2π/T_c;
 *   (c) every T_c is the user's T times a power of two, so the whole sea repeats after max T_c;
 *   (d) each coarser cascade's band ends inside its grid's Nyquist radius πN/L;
 *   and the cascades together hold the spectrum's variance ∫Ψ d²k once (a sum over every kept
 *   mode against an independent polar quadrature).
 *
 * Wave vectors and |k| are computed here from the grid's definition (k = 2π·(n', m')/L), not read
 * back from the code under test; parameters are merged over the defaults without validation so
 * that these tests do not depend on parameters.ts (which has its own tests), except in the one
 * test that says so.
 */
import { describe, expect, it } from 'vitest';
import { DEFAULT_PARAMETERS, validateParameters, type SimulationParameters } from '../../src/parameters/parameters';
import { cascadeBands, maxPatchRatio, PHASE_SPEED_TOLERANCE } from '../../src/spectrum/cascadeBands';
import { createCascadeSpectra, type InitialSpectrum, type WaveNumberSpectrum } from '../../src/spectrum/initialSpectrum';
import { phillips } from '../../src/spectrum/phillips';
import { CpuWaveFields } from '../../src/fft/cpuWaveFields';

const G = 9.81;

function params(changes: Partial<SimulationParameters>): SimulationParameters {
  return { ...DEFAULT_PARAMETERS, patchSizes: [...DEFAULT_PARAMETERS.patchSizes], ...changes };
}

/** The signed frequency n' of texel index i (FFT order: 0 … N/2 − 1, then −N/2 … −1). */
function signed(i: number, n: number): number {
  return i < n / 2 ? i : i - n;
}

/** ω(k) of the dispersion relation, written out here (tanh(∞) = 1). */
function omegaTrue(k: number, depth: number): number {
  return Math.sqrt(G * k * Math.tanh(k * depth));
}

/** Calls f(i, j, texel, kx, kz, k) for every texel of a cascade's grid, k in double precision. */
function forEachMode(
  spectrum: InitialSpectrum,
  f: (i: number, j: number, texel: number, kx: number, kz: number, k: number) => void,
): void {
  const n = spectrum.resolution;
  const dk = (2 * Math.PI) / spectrum.patchSize;
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      const kx = dk * signed(i, n);
      const kz = dk * signed(j, n);
      f(i, j, j * n + i, kx, kz, Math.sqrt(kx * kx + kz * kz));
    }
  }
}

/** Ψ = 1 m⁴ at every k ≠ 0 (a spectrum has no mean level): cheap, and no mode hides behind a tiny Ψ. */
const CONSTANT: WaveNumberSpectrum = (kx, kz) => (kx === 0 && kz === 0 ? 0 : 1);

const CASES: [string, Partial<SimulationParameters>][] = [
  ['the defaults (3 cascades, N = 256, deep water)', {}],
  ['1 cascade, N = 64, deep water', { patchSizes: [100], resolution: 64 }],
  ['2 cascades, N = 1024, depth 10 m', { patchSizes: [20, 250], resolution: 1024, depth: 10 }],
  ['3 cascades, N = 64, depth 1 m', { patchSizes: [4, 20, 100], resolution: 64, depth: 1 }],
  ['4 cascades, N = 64, depth 0.1 m', { patchSizes: [2, 8, 32, 128], resolution: 64, depth: 0.1 }],
  ['4 cascades, N = 256, depth 1 m, T = 37 s', { patchSizes: [13.7, 79.3, 457, 2650], resolution: 256, depth: 1, repeatPeriod: 37 }],
  // Sizes in whole ratios put lattice points of two cascades exactly on their shared band edge.
  // The edge between L_c and L_{c+1} is √(2π/L_c · πN/L_{c+1}); sizes in whole ratios put lattice
  // points of both grids exactly on it (|k|² = 64·(2π/20)² for [10, 20] at N = 64).
  ['2 cascades whose lattices meet on the band edge, [10, 20] m, N = 64', { patchSizes: [10, 20], resolution: 64 }],
  ['2 cascades whose lattices meet on the band edge, [10, 40] m, N = 64', { patchSizes: [10, 40], resolution: 64, depth: 10 }],
  ['4 cascades in ratios of 2, N = 64, depth 10 m', { patchSizes: [10, 20, 40, 80], resolution: 64, depth: 10 }],
  // |k|² = 208·(2π/13)² = 8² + 12² (in units of 2π/13 m): coarse-grid points exactly on the edge.
  ['2 cascades with coarse lattice points on the band edge, [1, 13] m, N = 32', { patchSizes: [1, 13], resolution: 32 }],
  // At the largest ratio, N/2, the edge is both the finer grid's fundamental and the coarser
  // grid's Nyquist radius.
  ['2 cascades at the largest ratio N/2, [10, 80] m, N = 16', { patchSizes: [10, 80], resolution: 16 }],
  ['3 cascades at the largest ratio N/2, [1, 32, 1024] m, N = 64', { patchSizes: [1, 32, 1024], resolution: 64, depth: 5 }],
];

describe('the cases below are valid parameter sets (validateParameters)', () => {
  for (const [name, changes] of CASES) {
    it(name, () => {
      expect(() => validateParameters(changes)).not.toThrow();
    });
  }
});

for (const [name, changes] of CASES) {
  describe(`cascades: ${name}`, () => {
    const p = params(changes);
    const bands = cascadeBands(p.patchSizes, p.resolution);
    const spectra = createCascadeSpectra(p, CONSTANT);
    const n = p.resolution;

    it('returns one spectrum per patch size, finest first, each with its own band', () => {
      expect(bands.map((b) => b.patchSize)).toEqual(p.patchSizes);
      expect(spectra.map((s) => s.patchSize)).toEqual(p.patchSizes);
      spectra.forEach((s, c) => {
        expect(s.resolution).toBe(n);
        expect(s.band).toEqual(bands[c]);
      });
    });

    it('(a) has disjoint bands that together cover [0, ∞): each |k| lies in exactly one', () => {
      // Finest first: the finest reaches to infinity, the coarsest down to 0, and each band ends
      // exactly where the next finer one begins (the same number: no gap, no overlap).
      expect(bands[0].high).toBe(Infinity);
      expect(bands[bands.length - 1].low).toBe(0);
      for (let c = 0; c < bands.length; c++) {
        expect(bands[c].low).toBeLessThan(bands[c].high);
        if (c > 0) expect(bands[c].high).toBe(bands[c - 1].low);
      }
      // The boundary is the geometric mean of the finer grid's fundamental and the coarser grid's
      // Nyquist radius (cascadeBands.ts), so it lies inside both grids while L_c/L_{c−1} ≤ N/2.
      expect(maxPatchRatio(n)).toBe(n / 2);
      for (let c = 1; c < bands.length; c++) {
        const fundamental = (2 * Math.PI) / p.patchSizes[c - 1];
        const nyquist = (Math.PI * n) / p.patchSizes[c];
        expect(Math.abs(bands[c].high / Math.sqrt(fundamental * nyquist) - 1)).toBeLessThan(1e-15);
        expect(bands[c].high).toBeGreaterThanOrEqual(fundamental * (1 - 1e-15));
      }
      // And by probing: 0, log-spaced |k| from 1e-6 to 1e6 rad/m, every edge and its neighbours.
      const probes = [0, ...Array.from({ length: 241 }, (_, i) => 10 ** (-6 + i / 20))];
      for (const b of bands) {
        for (const edge of [b.low, b.high]) {
          if (edge > 0 && edge < Infinity) probes.push(edge, edge * (1 - 2 ** -52), edge * (1 + 2 ** -52));
        }
      }
      for (const k of probes) {
        const owners = bands.filter((b) => k >= b.low && k < b.high).length;
        expect(owners, `|k| = ${k}`).toBe(1);
      }
    });

    /**
     * Where a mode's cell (the square of side Δk = 2π/L centred on it) lies against band c, from
     * the grid's definition: its nearest and farthest |k| against the band's edges.
     */
    const cellOf = (c: number, i: number, j: number): 'whole' | 'part' | 'none' => {
      const dk = (2 * Math.PI) / p.patchSizes[c];
      const [a, b] = [Math.abs(signed(i, n)), Math.abs(signed(j, n))];
      const nearest = dk * Math.hypot(Math.max(0, a - 0.5), Math.max(0, b - 0.5));
      const farthest = dk * Math.hypot(a + 0.5, b + 0.5);
      if (farthest <= bands[c].low || nearest >= bands[c].high) return 'none';
      return nearest >= bands[c].low && farthest < bands[c].high ? 'whole' : 'part';
    };

    it('(a) keeps the modes whose cells lie in its band (Ψ there), some of those its edges cross, and no others', () => {
      spectra.forEach((s, c) => {
        let whole = 0;
        let part = 0;
        // Collected and asserted once: an expect per texel costs seconds at N = 1024.
        const wrong: string[] = [];
        forEachMode(s, (i, j, texel, _kx, _kz, k) => {
          const cell = cellOf(c, i, j);
          const m = s.waveVectors[4 * texel + 3];
          const amplitude = Math.hypot(s.amplitudes[4 * texel], s.amplitudes[4 * texel + 1]);
          const kept = m !== 0;
          // A whole cell holds Ψ = 1 throughout; a cell an edge crosses holds the share of it in
          // the band, so 0 < Ψ̄ ≤ 1 when kept (1 when the edge only grazes it, between the midpoints
          // of its 8 × 8 split); the mode k = 0 carries nothing (Ψ(0) = 0).
          const right =
            cell === 'whole'
              ? kept === k > 0 && (amplitude !== 0) === k > 0 && s.density[texel] === (k > 0 ? 1 : 0)
              : cell === 'none'
                ? !kept && amplitude === 0 && s.density[texel] === 0
                : kept === (amplitude !== 0) && kept === s.density[texel] > 0 && s.density[texel] <= 1;
          if (!right) wrong.push(`texel (${i}, ${j}), |k| = ${k}, cell ${cell}: m ${m}, |h̃0| ${amplitude}, Ψ̄ ${s.density[texel]}`);
          if (cell === 'whole' && k > 0) whole++;
          if (cell === 'part' && kept) part++;
        });
        expect(wrong.slice(0, 5), `cascade ${c}: ${wrong.length} texels wrong`).toEqual([]);
        // Each cascade carries a real share of the spectrum; where bands meet, edges cross cells.
        expect(whole, `cascade ${c}`).toBeGreaterThan(50);
        if (bands.length > 1) expect(part, `cascade ${c}`).toBeGreaterThan(0);
      });
    });

    it('(a) covers each band exactly with its cells: under Ψ = 1, Σ Ψ̄·Δk² is the band’s area', () => {
      // The cells of a grid tile the plane, so the shares of the band in them add up to the band's
      // area, π(high² − low²) (for the finest band, up to the grid's square of side N·Δk), less the
      // cell of k = 0, where Ψ = 0. The 8 × 8 midpoint split of a crossed cell misses at most a
      // sliver of it, of either sign from cell to cell: under 0.5 % in all. Crossed cells on the
      // Nyquist row or column are left out (initialSpectrum.ts), at most a cell each.
      spectra.forEach((s, c) => {
        const dk = (2 * Math.PI) / s.patchSize;
        let covered = 0;
        let leftOut = 0;
        forEachMode(s, (i, j, texel) => {
          covered += s.density[texel] * dk * dk;
          if ((i === n / 2 || j === n / 2) && cellOf(c, i, j) === 'part') leftOut += dk * dk;
        });
        const disc = (radius: number) => (radius === Infinity ? (n * dk) ** 2 : Math.PI * radius * radius);
        const area = disc(bands[c].high) - disc(bands[c].low) - (bands[c].low === 0 ? dk * dk : 0);
        expect(covered / area, `cascade ${c}`).toBeLessThan(1.005);
        expect((covered + leftOut) / area, `cascade ${c}`).toBeGreaterThan(0.995);
      });
    });

    it('(b) moves every kept mode at the true phase speed √(g·tanh(kd)/k) within 1 %', () => {
      expect(PHASE_SPEED_TOLERANCE).toBe(0.01);
      let worst = 0;
      let worstAt = '';
      let checked = 0;
      for (const s of spectra) {
        forEachMode(s, (i, j, texel, _kx, _kz, k) => {
          const m = s.waveVectors[4 * texel + 3];
          if (m === 0) return;
          const quantized = (m * 2 * Math.PI) / s.repeatPeriod / k;
          const exact = omegaTrue(k, p.depth) / k;
          const error = Math.abs(quantized / exact - 1);
          if (error > worst) [worst, worstAt] = [error, `cascade ${s.patchSize} m, texel (${i}, ${j}), |k| = ${k}`];
          checked++;
        });
      }
      // 1e-12 of slack for rounding in the comparison itself.
      expect(worst, worstAt).toBeLessThanOrEqual(0.01 + 1e-12);
      expect(checked).toBeGreaterThan(100);
      expect(worst).toBeGreaterThan(0); // quantization is real: the check is not vacuous
    });

    it('(c) has repeat periods T·2^j, so every mode turns a whole number of times in max T_c', () => {
      const periods = spectra.map((s) => s.repeatPeriod);
      const longest = Math.max(...periods);
      for (const s of spectra) {
        const doublings = Math.log2(s.repeatPeriod / p.repeatPeriod);
        // T·2^j is exact in floating point, so its ratio to T is exactly 2^j.
        expect(Number.isInteger(doublings) && doublings >= 0, `T_c = ${s.repeatPeriod}`).toBe(true);
        expect(Number.isInteger(Math.log2(longest / s.repeatPeriod))).toBe(true);
        // Not doubled further than needed: at T_c/2 the rounding error π/(T_c/2) would exceed 1 % of
        // ω at the band's slowest possible mode, max(low − Δk/√2, Δk): a mode is kept when its cell
        // reaches into the band (the bound cascadeBands.ts documents).
        if (doublings > 0) {
          const dk = (2 * Math.PI) / s.patchSize;
          const slowest = Math.max(s.band.low - dk / Math.SQRT2, dk);
          expect(Math.PI / (s.repeatPeriod / 2)).toBeGreaterThan(0.01 * omegaTrue(slowest, p.depth));
        }
        let fractional = 0;
        forEachMode(s, (_i, _j, texel) => {
          const m = s.waveVectors[4 * texel + 3];
          // ω·max T_c / 2π = m·(max T_c / T_c) turns: an integer.
          if (!(m >= 0 && Number.isInteger(m) && Number.isInteger((m * longest) / s.repeatPeriod))) fractional++;
        });
        expect(fractional, `cascade ${s.patchSize} m`).toBe(0);
      }
    });

    it('(d) ends each coarser cascade’s band inside its grid’s Nyquist radius πN/L', () => {
      for (let c = 1; c < bands.length; c++) {
        const nyquist = (Math.PI * n) / p.patchSizes[c];
        // (1 + 1e-15: at the largest ratio N/2 the edge is the Nyquist radius, up to rounding.)
        expect(bands[c].high, `cascade ${p.patchSizes[c]} m`).toBeLessThanOrEqual(nyquist * (1 + 1e-15));
        // So no kept mode of it sits on the Nyquist row or column (whose kx or kz is stored as 0).
        let onNyquist = 0;
        forEachMode(spectra[c], (i, j, texel) => {
          if ((i === n / 2 || j === n / 2) && spectra[c].waveVectors[4 * texel + 3] !== 0) onNyquist++;
        });
        expect(onNyquist).toBe(0);
      }
    });
  });
}

describe('(c) the whole sea repeats after the longest repeat period', () => {
  it('each cascade’s fields at t and t + max T_c agree (4 cascades, N = 16)', () => {
    const p = params({ patchSizes: [2, 8, 32, 128], resolution: 16, depth: 3, repeatPeriod: 30 });
    const spectra = createCascadeSpectra(p, (kx, kz) => 2 * phillips(kx, kz, p) * (128 / (2 * Math.PI)) ** 2);
    const longest = Math.max(...spectra.map((s) => s.repeatPeriod));
    expect(new Set(spectra.map((s) => s.repeatPeriod)).size).toBeGreaterThan(1); // the periods differ
    for (const s of spectra) {
      const a = new CpuWaveFields(s);
      const b = new CpuWaveFields(s);
      a.update(3.7);
      b.update(3.7 + longest);
      let scale = 0;
      let worst = 0;
      for (let q = 0; q < a.displacement.length; q++) {
        scale = Math.max(scale, Math.abs(a.displacement[q]));
        worst = Math.max(worst, Math.abs(a.displacement[q] - b.displacement[q]));
      }
      expect(scale).toBeGreaterThan(0);
      // Time is wrapped in double precision before float32 sees it: the two differ by rounding
      // (≤ ~1e-7 of the fields), against a change of order the fields' size within a period.
      expect(worst / scale, `cascade ${s.patchSize} m, T_c = ${s.repeatPeriod} s`).toBeLessThan(1e-6);
    }
  });
});

describe('the cascades hold the spectrum’s variance once: Σ Ψ(k)·Δk² over kept modes = ∫Ψ d²k', () => {
  /**
   * ∫∫ Ψ d²k over kMin ≤ |k| ≤ kMax by polar quadrature: composite Simpson in u = ln k (the
   * integrand Ψ·k² du is smooth there) and the trapezoid rule in θ (spectrally accurate for a
   * periodic integrand).
   */
  function polarIntegral(psi: WaveNumberSpectrum, kMin: number, kMax: number): number {
    // The test spectra vary in θ at most as cos²θ (Phillips), which the trapezoid rule integrates
    // exactly with ≥ 3 points; Simpson's error with 2000 steps over ln k is ~1e-12 here.
    const intervals = 2000;
    const angles = 64;
    const du = Math.log(kMax / kMin) / intervals;
    let total = 0;
    for (let s = 0; s <= intervals; s++) {
      const k = kMin * Math.exp(s * du);
      let ring = 0;
      for (let a = 0; a < angles; a++) {
        const theta = (2 * Math.PI * a) / angles;
        ring += psi(k * Math.cos(theta), k * Math.sin(theta));
      }
      ring *= (2 * Math.PI) / angles;
      const weight = s === 0 || s === intervals ? 1 : s % 2 === 1 ? 4 : 2;
      total += weight * ring * k * k;
    }
    return (total * du) / 3;
  }

  /** Σ over every cascade and every texel of Ψ·Δk_c² (density is Ψ where kept, 0 elsewhere). */
  function cascadeSum(spectra: InitialSpectrum[]): number {
    let sum = 0;
    for (const s of spectra) {
      const dk = (2 * Math.PI) / s.patchSize;
      // E|h̃0(k)|² = Ψ(−k)·Δk²/2 (initialSpectrum.ts), so 2·Σ E|h̃0|² is this same sum.
      for (let q = 0; q < s.density.length; q++) sum += s.density[q] * dk * dk;
    }
    return sum;
  }

  // A ring in log k: Ψ = exp(−ln²(k/k0)/2s²)/k², whose integral over the plane is 2π·s·√(2π).
  const k0 = 1.7;
  const width = 0.6;
  const ring: WaveNumberSpectrum = (kx, kz) => {
    const k2 = kx * kx + kz * kz;
    if (k2 === 0) return 0;
    return Math.exp(-(Math.log(Math.sqrt(k2) / k0) ** 2) / (2 * width * width)) / k2;
  };

  // [name, parameters, Ψ, tolerance]. 1 %, half the bound, on small grids too: there the band
  // edge lies only √(N·L_c/(2·L_{c+1})) fundamentals into the finer grid (2.5 and 4 here, against
  // 4.7 for the defaults), but each mode carries ∫Ψ over its cell's part in the band
  // (initialSpectrum.ts), so what remains is the midpoint rule's error inside whole cells,
  // Δk²·∇²Ψ/24 of Ψ (measured 0.03–0.45 %).
  const cases: [string, Partial<SimulationParameters>, WaveNumberSpectrum | 'phillips', number][] = [
    ['a ring in log k across the default cascades, N = 256', {}, ring, 0.01],
    ['a ring in log k across three cascades, N = 256', { patchSizes: [10, 50, 250], resolution: 256 }, ring, 0.01],
    ['a ring in log k across three cascades, N = 64', { patchSizes: [10, 50, 250], resolution: 64 }, ring, 0.01],
    ['a ring in log k across four cascades, N = 128', { patchSizes: [3, 12, 48, 192], resolution: 128, depth: 2 }, ring, 0.01],
    ['the report’s Phillips spectrum over the default cascades, N = 256', { spectrum: 'phillips', windSpeed: 10, smallWaveCutoff: 0.01 }, 'phillips', 0.01],
  ];
  for (const [name, changes, spectrum, tolerance] of cases) {
    it(name, () => {
      const p = params(changes);
      const largest = p.patchSizes[p.patchSizes.length - 1];
      const psi: WaveNumberSpectrum =
        spectrum === 'phillips' ? (kx, kz) => 2 * phillips(kx, kz, p) * (largest / (2 * Math.PI)) ** 2 : spectrum;
      const spectra = createCascadeSpectra(p, psi);
      // From the coarsest grid's fundamental to the finest grid's Nyquist radius.
      const kMin = (2 * Math.PI) / largest;
      const kMax = (Math.PI * p.resolution) / p.patchSizes[0];
      const integral = polarIntegral(psi, kMin, kMax);
      // Ψ must be negligible outside [kMin, kMax] (the grids also reach a little past both: the
      // finest grid's corners, the coarsest grid's k = 0 where Ψ = 0), and spread over several
      // cascades, or the comparison would prove little.
      const wider = polarIntegral(psi, kMin / 100, kMax * 10);
      expect(Math.abs(wider / integral - 1)).toBeLessThan(1e-3);
      if (spectrum === ring) expect(Math.abs(wider / (2 * Math.PI * width * Math.sqrt(2 * Math.PI)) - 1)).toBeLessThan(1e-6);
      const shares = spectra.map((s) => cascadeSum([s]) / integral);
      expect(shares.filter((share) => share > 0.02).length).toBeGreaterThanOrEqual(2);
      const sum = cascadeSum(spectra);
      // A cascade counted twice or left out shifts the sum by its share; modes weighed by Ψ at
      // their centres alone lose up to 3.5 % here, at the band edges.
      expect(Math.abs(sum / integral - 1), `shares ${shares.map((s) => s.toFixed(4))}`).toBeLessThan(tolerance);
    });
  }
});
