/**
 * Statistics of the synthesized sea, measured on the fields the simulation produces (CpuWaveFields,
 * summed over every cascade), against published laws:
 *
 *   (a) Significant wave height. Hs = 4·√m0, m0 = ∫S dω the variance of the surface elevation
 *       (Holthuijsen 2007, "Waves in Oceanic and Coastal Waters", §4.2.2; DNV-RP-C205 (2021) §3.5.5;
 *       Longuet-Higgins 1952 for the Rayleigh wave heights behind it). The measured 4·RMS of the
 *       simulated height must match 4·√m0_band of the modes the cascades keep, and m0_band the full
 *       spectrum's m0 when the patches cover the peak.
 *   (b) Direction of travel. A directional spectrum S(ω)·D(ω, θ) puts the share
 *       ∫S(ω)·∫_{|θ|>90°} D dθ dω / m0 of the variance into waves travelling against the wind
 *       (Holthuijsen 2007, §3.5.6 for D; Longuet-Higgins, Cartwright & Smith 1963 for cos-2s;
 *       Donelan, Hamilton & Hui 1985 / Banner 1990 for the default). Measured from the field itself
 *       by separating every Fourier mode into its two travelling waves, from two instants.
 *   (c) Phase speed of every mode within 1 %: already checked by tests/unit/cascadeBands.test.ts
 *       ('(b) moves every kept mode at the true phase speed'), so not repeated here.
 *
 * Independent of the code under test: the forward FFT used to analyse the fields is written here,
 * and the band's expected variance and direction shares are computed here from Ψ, S and D.
 */
import { describe, expect, it } from 'vitest';
import { CpuWaveFields } from '../../src/fft/cpuWaveFields';
import { validateParameters, type SimulationParameters } from '../../src/parameters/parameters';
import { createCascadeSpectra, type InitialSpectrum } from '../../src/spectrum/initialSpectrum';
import {
  spectralMoments,
  waveNumberFromFrequency,
  waveNumberSpectrum,
  windSeaFrequencySpectrum,
  windSeaPeakFrequency,
} from '../../src/spectrum/seaState';
import { directionalSpreading } from '../../src/spectrum/spreading';
import { fft2d } from '../referenceFft';

const G = 9.81;

/** The signed frequency n' of texel index i (FFT order: 0 … N/2 − 1, then −N/2 … −1). */
function signed(i: number, n: number): number {
  return i < n / 2 ? i : i - n;
}

/** Mean over the patch of h² (the height is the displacement texture's G channel): Σ|h̃|² by Parseval. */
function meanSquareHeight(fields: CpuWaveFields): number {
  const d = fields.displacement;
  let sum = 0;
  for (let q = 1; q < d.length; q += 4) sum += d[q] * d[q];
  return sum / (d.length / 4);
}

/** Σ Ψ̄(k)·Δk² over the modes a cascade keeps (its density is Ψ̄, the mean of Ψ over the part of the mode’s cell in the band, and 0 elsewhere). */
function bandVariance(s: InitialSpectrum): number {
  const dk = (2 * Math.PI) / s.patchSize;
  let sum = 0;
  for (const psi of s.density) sum += psi * dk * dk;
  return sum;
}

/**
 * h̃(k) of a real field on an N×N patch, h(x) = Σ_k h̃(k)·e^{ik·x}: h̃ = (1/N²)·Σ_x h(x)·e^{−ik·x},
 * in the texel order of initialSpectrum.ts (row j ↔ kz, column i ↔ kx).
 */
function forwardSpectrum(heights: Float64Array, n: number): [Float64Array, Float64Array] {
  const re = Float64Array.from(heights, (h) => h / (n * n));
  const im = new Float64Array(n * n);
  fft2d(re, im, n, -1);
  return [re, im];
}

/** The height field (float64) of one cascade at time t. */
function heightField(fields: CpuWaveFields, t: number): Float64Array {
  fields.update(t);
  const d = fields.displacement;
  return Float64Array.from({ length: d.length / 4 }, (_, q) => d[4 * q + 1]);
}

describe('the forward FFT written here', () => {
  it('recovers the amplitudes of a sum of plane waves', () => {
    const n = 16;
    const h = new Float64Array(n * n);
    // 0.7·cos(2π(3x + 5z)/N) + 0.2·sin(2π(−2x + z)/N)
    for (let m = 0; m < n; m++) {
      for (let c = 0; c < n; c++) {
        h[m * n + c] = 0.7 * Math.cos((2 * Math.PI * (3 * c + 5 * m)) / n) + 0.2 * Math.sin((2 * Math.PI * (-2 * c + m)) / n);
      }
    }
    const [re, im] = forwardSpectrum(h, n);
    const at = (i: number, j: number) => [re[((j + n) % n) * n + ((i + n) % n)], im[((j + n) % n) * n + ((i + n) % n)]];
    expect(at(3, 5)[0]).toBeCloseTo(0.35, 12);
    expect(at(-3, -5)[0]).toBeCloseTo(0.35, 12);
    expect(at(-2, 1)[1]).toBeCloseTo(-0.1, 12); // sin = (e^{iθ} − e^{−iθ})/2i
    expect(at(2, -1)[1]).toBeCloseTo(0.1, 12);
    expect(at(1, 1)[0]).toBeCloseTo(0, 12);
  });
});

// ————— (a) Hs = 4·√m0 —————

interface SeaCase {
  name: string;
  changes: Partial<SimulationParameters>;
  /** Stated bound on |m0_band/m0 − 1|: how much of the spectrum the patches miss or mis-sample. */
  coverage: number;
}

const FOUR_CASCADES = [13.7, 79.3, 457, 2650];

const SEAS: SeaCase[] = [
  // The defaults: JONSWAP, U10 = 10 m/s, fetch 100 km (Tp ≈ 6 s, λp ≈ 57 m: 8 fundamentals of 457 m).
  { name: 'JONSWAP 10 m/s, 100 km (the defaults)', changes: {}, coverage: 0.02 },
  // Fully developed: Tp ≈ 11 s, λp ≈ 190 m, so a fourth, 2650 m cascade covers the peak.
  { name: 'Pierson–Moskowitz 15 m/s', changes: { spectrum: 'pierson-moskowitz', windSpeed: 15, patchSizes: FOUR_CASCADES }, coverage: 0.02 },
  // TMA: the JONSWAP sea of the defaults over 5 m of water (Bouws et al. 1985).
  { name: 'TMA 10 m/s, 100 km, depth 5 m', changes: { spectrum: 'tma', depth: 5 }, coverage: 0.02 },
  // Swell alone: Hs = 2 m by construction (frequencySpectra.ts scales it so), Tp = 12 s, λp ≈ 225 m.
  { name: 'swell 2 m, 12 s, no wind', changes: { windSpeed: 0, swellHeight: 2, swellPeriod: 12, patchSizes: FOUR_CASCADES }, coverage: 0.02 },
];

const SEEDS = Array.from({ length: 20 }, (_, i) => 101 + 37 * i);
const TIMES = [0, 55.1];
/**
 * N = 128, the 'medium' quality level's grid (N = 64, 'low''s, has its own test of m0 below, since
 * 20 seeds of the full fields there would prove little more).
 */
const RESOLUTION = 128;

describe('(a) the simulated sea has the significant wave height 4·√m0 (Holthuijsen 2007 §4.2.2; DNV-RP-C205 §3.5.5)', () => {
  for (const { name, changes, coverage } of SEAS) {
    it(name, () => {
      const params = validateParameters({ ...changes, resolution: RESOLUTION });
      const largest = params.patchSizes[params.patchSizes.length - 1];
      const { m0 } = spectralMoments(params, largest);
      let m0Band = 0;
      let sumMeasured = 0;
      let sumSquaredMeasured = 0;
      /** Σ over the half plane of μ_k² (μ_k = E|h̃(k)|²), for the statistical spread of one sample. */
      let spreadSquared = 0;
      for (const seed of SEEDS) {
        const spectra = createCascadeSpectra({ ...params, seed });
        if (seed === SEEDS[0]) {
          m0Band = spectra.reduce((sum, s) => sum + bandVariance(s), 0);
          for (const s of spectra) {
            const dk = (2 * Math.PI) / s.patchSize;
            // μ_k = (Ψ(k) + Ψ(−k))·Δk²/2 for the pair ±k; each pair once: Σ over all k of μ²/2.
            const n = s.resolution;
            for (let j = 0; j < n; j++) {
              for (let i = 0; i < n; i++) {
                const opposite = ((n - j) % n) * n + ((n - i) % n);
                const mu = ((s.density[j * n + i] + s.density[opposite]) * dk * dk) / 2;
                spreadSquared += (4 * mu * mu) / 2;
              }
            }
          }
        }
        const fields = spectra.map((s) => new CpuWaveFields(s));
        // The cascades' bands are disjoint, so their fields are uncorrelated (distinct wave vectors
        // with independent deviates: the cross terms have zero mean) and the variance of the sum is
        // the sum of the variances. Each cascade's mean of h² over its own patch is exact (Parseval).
        let seedMean = 0;
        for (const t of TIMES) {
          let variance = 0;
          for (const f of fields) {
            f.update(t);
            variance += meanSquareHeight(f);
          }
          seedMean += variance / TIMES.length;
        }
        sumMeasured += seedMean;
        sumSquaredMeasured += seedMean * seedMean;
      }
      const measured = sumMeasured / SEEDS.length;
      // One instant's Σ|h̃|² is a sum of independent exponential variables (one per pair ±k, mean
      // 2μ_k): relative standard deviation √(Σ(2μ)²)/Σ2μ. Averaged over the seeds (times of one seed
      // are correlated, so not counted), Hs = 4√m0 has half that relative spread.
      const sampleSpread = Math.sqrt(spreadSquared) / m0Band;
      const hsSpread = sampleSpread / Math.sqrt(SEEDS.length) / 2;
      const observedSpread = Math.sqrt(Math.max(0, sumSquaredMeasured / SEEDS.length - measured * measured)) / m0Band;
      const hsRatio = Math.sqrt(measured / m0Band);
      console.log(
        `${name}: Hs(measured) = ${(4 * Math.sqrt(measured)).toFixed(4)} m, 4√m0_band = ${(4 * Math.sqrt(m0Band)).toFixed(4)} m, ` +
          `ratio ${hsRatio.toFixed(4)} (σ of the mean ${(100 * hsSpread).toFixed(2)} %; one seed's σ(m0): predicted ${(100 * sampleSpread).toFixed(1)} %, ` +
          `observed ${(100 * observedSpread).toFixed(1)} %); 4√m0 = ${(4 * Math.sqrt(m0)).toFixed(4)} m, m0_band/m0 = ${(m0Band / m0).toFixed(4)}`,
      );
      // The statistical spread must leave room for a real check: 5 % is at least 2.5σ.
      expect(hsSpread).toBeLessThan(0.02);
      expect(Math.abs(hsRatio - 1)).toBeLessThan(0.05);
      // The patches cover the peak: the kept modes hold the spectrum's variance within `coverage`.
      expect(Math.abs(m0Band / m0 - 1)).toBeLessThan(coverage);
    });
  }

  it('at N = 64 too the cascades keep m0 within 2 %', () => {
    // Each band's lower edge lies only 2.35 fundamentals into the finer grid here (patches 5.8×
    // apart), where the lattice holds 21 points inside the disc of 17.4 cells and Ψ ∝ k⁻⁴ is steep:
    // weighed by Ψ at their centres, the modes kept 0.909–0.965 of m0 (swell 12 s … the defaults).
    // Each mode carries ∫Ψ over its cell's part in the band instead (initialSpectrum.ts), so the
    // bands' lattice sums are their integrals, as at N = 256.
    const worst = SEAS.map(({ changes }) => {
      const params = validateParameters({ ...changes, resolution: 64 });
      const { m0 } = spectralMoments(params, params.patchSizes[params.patchSizes.length - 1]);
      return Math.abs(createCascadeSpectra(params).reduce((sum, s) => sum + bandVariance(s), 0) / m0 - 1);
    });
    expect(Math.max(...worst)).toBeLessThan(0.02);
  });

  it('the cascades’ fields are uncorrelated on a common grid, so their variances add (default sea, N = 128)', () => {
    // The justification of adding variances above, checked: on the largest patch's grid, the sum
    // of the cascades (finer ones sampled bilinearly with REPEAT, as the surface shader does)
    // has a mean square equal to the sum of the sampled cascades' mean squares, up to the cross
    // terms, which are 2·Σ_{a<b} mean(h_a·h_b).
    const params = validateParameters({ resolution: RESOLUTION, seed: 5 });
    const spectra = createCascadeSpectra(params);
    const n = params.resolution;
    const largest = spectra[spectra.length - 1].patchSize;
    const sampled = spectra.map((s) => {
      const field = heightField(new CpuWaveFields(s), 4.2);
      const out = new Float64Array(n * n);
      for (let j = 0; j < n; j++) {
        for (let i = 0; i < n; i++) {
          const x = ((i * largest) / s.patchSize) % n;
          const z = ((j * largest) / s.patchSize) % n;
          const [i0, j0] = [Math.floor(x), Math.floor(z)];
          const [fx, fz] = [x - i0, z - j0];
          const at = (a: number, b: number) => field[((b + n) % n) * n + ((a + n) % n)];
          out[j * n + i] =
            (1 - fz) * ((1 - fx) * at(i0, j0) + fx * at(i0 + 1, j0)) + fz * ((1 - fx) * at(i0, j0 + 1) + fx * at(i0 + 1, j0 + 1));
        }
      }
      return out;
    });
    let total = 0;
    let separate = 0;
    for (let q = 0; q < n * n; q++) {
      let h = 0;
      for (const f of sampled) {
        h += f[q];
        separate += f[q] * f[q];
      }
      total += h * h;
    }
    console.log(`common grid: mean square of the sum / sum of mean squares = ${(total / separate).toFixed(4)}`);
    expect(Math.abs(total / separate - 1)).toBeLessThan(0.05);
  });
});

// ————— (b) Energy travelling against the wind —————

/**
 * From the simulated field of each cascade at times t0 + δ (several δ), the amplitudes of the two
 * waves in every Fourier mode: h̃(k, t) = a_k·e^{iωt} + b_k·e^{−iωt}, ω = m·2π/T_c. a_k·e^{i(k·x+ωt)}
 * travels towards −k̂, b_k·e^{i(k·x−ωt)} towards +k̂. Two instants t1, t2 give
 *   a = (h̃1·e^{−iωt2} − h̃2·e^{−iωt1}) / (e^{iω(t1−t2)} − e^{−iω(t1−t2)}),  b likewise;
 * of the pairs of instants, the one with the largest |sin ω(t1 − t2)| is used per mode.
 * Returns the variance travelling with and against the wind (mean direction ŵ), each wave's
 * variance |a|² or |b|² counted at its direction of travel.
 */
function directionalShares(
  spectra: InitialSpectrum[],
  wind: [number, number],
): { against: number; total: number; worstSine: number } {
  const times = [3.1, 3.1 + 0.77, 3.1 + 1.93, 3.1 + 4.41];
  let against = 0;
  let total = 0;
  let worstSine = 1;
  for (const s of spectra) {
    const n = s.resolution;
    const fields = new CpuWaveFields(s);
    const transforms = times.map((t) => forwardSpectrum(heightField(fields, t), n));
    const dk = (2 * Math.PI) / s.patchSize;
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const texel = j * n + i;
        const m = s.waveVectors[4 * texel + 3];
        if (m === 0) continue; // not kept, or k = 0
        const omega = (m * 2 * Math.PI) / s.repeatPeriod;
        // The pair of instants best conditioned for this ω.
        let best: [number, number] = [0, 1];
        let bestSine = 0;
        for (let p = 0; p < times.length; p++) {
          for (let q = p + 1; q < times.length; q++) {
            const sine = Math.abs(Math.sin(omega * (times[p] - times[q])));
            if (sine > bestSine) [best, bestSine] = [[p, q], sine];
          }
        }
        worstSine = Math.min(worstSine, bestSine);
        const [p, q] = best;
        const [t1, t2] = [times[p], times[q]];
        const h1 = [transforms[p][0][texel], transforms[p][1][texel]];
        const h2 = [transforms[q][0][texel], transforms[q][1][texel]];
        const mul = ([xr, xi]: number[], angle: number) => [xr * Math.cos(angle) - xi * Math.sin(angle), xr * Math.sin(angle) + xi * Math.cos(angle)];
        // Denominator D = e^{iω(t1−t2)} − e^{−iω(t1−t2)} = 2i·sin ω(t1−t2).
        const sine = Math.sin(omega * (t1 - t2));
        const divide = ([xr, xi]: number[]) => [xi / (2 * sine), -xr / (2 * sine)]; // x / (2i·sine)
        const numeratorA = mul(h1, -omega * t2).map((v, c) => v - mul(h2, -omega * t1)[c]);
        // b: h̃1·e^{iωt2} − h̃2·e^{iωt1} = b·(e^{−iω(t1−t2)} − e^{iω(t1−t2)}) = −b·D.
        const numeratorB = mul(h1, omega * t2).map((v, c) => v - mul(h2, omega * t1)[c]);
        const a = divide(numeratorA);
        const b = divide(numeratorB).map((v) => -v);
        const energyA = a[0] ** 2 + a[1] ** 2; // towards −k̂
        const energyB = b[0] ** 2 + b[1] ** 2; // towards +k̂
        const kx = dk * signed(i, n);
        const kz = dk * signed(j, n);
        const along = kx * wind[0] + kz * wind[1];
        if (along < 0) against += energyB;
        if (along > 0) against += energyA;
        if (along === 0) against += (energyA + energyB) / 2; // across the wind: half and half
        total += energyA + energyB;
      }
    }
  }
  return { against, total, worstSine };
}

/**
 * The share of the band's variance that S(ω)·D(ω, θ) puts at |θ| > 90° from the mean direction:
 * ∫S(ω)·∫_{|θ|>π/2} D(ω, θ) dθ dω / ∫S dω over the ω of the band (deep or finite depth), by the
 * midpoint rule in ln ω and in θ.
 */
function spreadingAllowance(params: SimulationParameters, kMin: number, kMax: number): number {
  const peak = windSeaPeakFrequency(params);
  const spreading = { model: params.spreading, peakFrequency: peak, windSpeed: params.windSpeed, exponent: params.spreadingExponent };
  const omegaOf = (k: number) => Math.sqrt(G * k * (params.depth === Infinity ? 1 : Math.tanh(k * params.depth)));
  const [lo, hi] = [Math.log(omegaOf(kMin)), Math.log(omegaOf(kMax))];
  const steps = 2000;
  const angles = 720;
  let against = 0;
  let total = 0;
  for (let s = 0; s < steps; s++) {
    const omega = Math.exp(lo + ((s + 0.5) * (hi - lo)) / steps);
    const k = waveNumberFromFrequency(omega, params.depth);
    const weight = windSeaFrequencySpectrum(omega, params) * Math.exp(-k * k * params.smallWaveCutoff ** 2) * omega;
    let share = 0;
    for (let a = 0; a < angles; a++) {
      const theta = -Math.PI + ((a + 0.5) * 2 * Math.PI) / angles;
      if (Math.abs(theta) > Math.PI / 2) share += (directionalSpreading(theta, omega, spreading) * 2 * Math.PI) / angles;
    }
    against += weight * share;
    total += weight;
  }
  return against / total;
}

describe('(b) waves travel with the wind: the variance travelling against it is what the spreading allots (Holthuijsen 2007 §3.5.6)', () => {
  const cases: [string, Partial<SimulationParameters>][] = [
    ['Donelan–Banner (the default sea)', {}],
    ['cos-2s, s = 20 (narrow): tiny', { spreading: 'cos-2s', spreadingExponent: 20 }],
    ['Mitsuyasu, JONSWAP 15 m/s, 300 km, depth 8 m (TMA)', { spectrum: 'tma', windSpeed: 15, fetch: 300, depth: 8, spreading: 'mitsuyasu', windDirection: -70 }],
  ];
  for (const [name, changes] of cases) {
    it(name, () => {
      const params = validateParameters({ ...changes, resolution: 64 });
      const wind: [number, number] = [Math.cos((params.windDirection * Math.PI) / 180), Math.sin((params.windDirection * Math.PI) / 180)];
      const n = params.resolution;
      // The band the cascades cover: from the largest patch's fundamental to the finest grid's corner.
      const allowance = spreadingAllowance(params, (2 * Math.PI) / params.patchSizes[params.patchSizes.length - 1], (Math.SQRT2 * Math.PI * n) / params.patchSizes[0]);
      // The same share from Ψ over the kept lattice modes (what the fields should hold on average).
      let latticeAgainst = 0;
      let latticeTotal = 0;
      /** Σ over against-wind waves of μ², μ = E|b_k|² = Ψ(k)·Δk²/2: the variance of their sum. */
      let againstSpreadSquared = 0;
      const fractions: number[] = [];
      const seeds = [3, 14, 15, 92, 65, 35, 89, 79];
      for (const seed of seeds) {
        const spectra = createCascadeSpectra({ ...params, seed });
        if (seed === 3) {
          for (const s of spectra) {
            const dk = (2 * Math.PI) / s.patchSize;
            for (let j = 0; j < n; j++) {
              for (let i = 0; i < n; i++) {
                const psi = s.density[j * n + i] * dk * dk;
                const along = dk * (signed(i, n) * wind[0] + signed(j, n) * wind[1]);
                latticeTotal += psi;
                if (along < 0) {
                  latticeAgainst += psi;
                  againstSpreadSquared += (psi / 2) ** 2;
                } else if (along === 0) latticeAgainst += psi / 2;
              }
            }
          }
        }
        const { against, total, worstSine } = directionalShares(spectra, wind);
        expect(worstSine).toBeGreaterThan(0.05); // every mode's two waves were separable
        fractions.push(against / total);
      }
      const measured = fractions.reduce((a, b) => a + b, 0) / fractions.length;
      const lattice = latticeAgainst / latticeTotal;
      // Each wave's |b_k|² is exponential (a circular Gaussian's square) with mean μ_k; the share's
      // standard deviation for one seed is about √(Σ_against μ²)/Σ_all μ (Σ_all μ = m0_band/2),
      // and the mean over the seeds has 1/√seeds of it. 1e-5 more for float32 fields.
      const sigma = Math.sqrt(againstSpreadSquared) / (latticeTotal / 2) / Math.sqrt(seeds.length);
      const margin = 3 * sigma + 1e-5;
      console.log(
        `${name}: against-wind share measured ${measured.toExponential(3)} (seeds: ${fractions.map((f) => f.toExponential(2)).join(', ')}), ` +
          `from Ψ on the lattice ${lattice.toExponential(3)}, spreading allowance ${allowance.toExponential(3)}, 3σ of the mean ${(3 * sigma).toExponential(2)}`,
      );
      // Below the allowance plus the statistical margin.
      expect(measured).toBeLessThan(allowance + margin);
      // And not vacuously: what the fields carry is what Ψ on the lattice says (a wrong travel
      // direction, e.g. h̃0(k) drawn from Ψ(k) instead of Ψ(−k), would make it 1 − allowance).
      expect(Math.abs(measured - lattice)).toBeLessThan(margin);
      if (params.spreading === 'cos-2s' && params.spreadingExponent === 20) {
        // cos^40(θ/2) ≤ 2^−20 beyond 90°: about 1e-7 of the variance (Longuet-Higgins et al. 1963).
        expect(allowance).toBeLessThan(1e-6);
        expect(measured).toBeLessThan(1e-5);
      }
    });
  }

  it("'phillips' (the report's spectrum): |k̂·ŵ|² is symmetric, so about half the variance travels against the wind — a known flaw", () => {
    // Tessendorf (2001, eq. 23) weights directions by |k̂·ŵ|², which is the same for k and −k, and
    // the report kept it: half the waves run upwind. Documented here, not fixed: the oceanographic
    // spectra with a spreading function (above) do not have this flaw.
    const params = validateParameters({ spectrum: 'phillips', resolution: 64 });
    // (Its ~0.5 is not a statistical accident: each seed's share is printed; the spread is a few %.)
    const wind: [number, number] = [Math.cos((params.windDirection * Math.PI) / 180), Math.sin((params.windDirection * Math.PI) / 180)];
    const fractions = [3, 14, 15, 92, 65, 35].map((seed) => {
      const { against, total } = directionalShares(createCascadeSpectra({ ...params, seed }), wind);
      return against / total;
    });
    const measured = fractions.reduce((a, b) => a + b, 0) / fractions.length;
    console.log(`phillips: against-wind share measured ${measured.toFixed(3)} (seeds: ${fractions.map((f) => f.toFixed(3)).join(', ')})`);
    expect(measured).toBeGreaterThan(0.4);
    expect(measured).toBeLessThan(0.6);
  });
});

/** Ψ itself, for reference: the default sea's against-wind share of ∫Ψ d²k on a fine polar grid. */
it('the spreading allowance agrees with Ψ integrated over the plane (a check of the reference itself)', () => {
  const params = validateParameters({});
  const kMin = (2 * Math.PI) / 457;
  const kMax = (Math.SQRT2 * Math.PI * 256) / 13.7;
  const wind = [Math.cos((params.windDirection * Math.PI) / 180), Math.sin((params.windDirection * Math.PI) / 180)];
  const steps = 600;
  const angles = 360;
  let against = 0;
  let total = 0;
  for (let s = 0; s < steps; s++) {
    const k = kMin * Math.exp(((s + 0.5) * Math.log(kMax / kMin)) / steps);
    for (let a = 0; a < angles; a++) {
      const theta = ((a + 0.5) * 2 * Math.PI) / angles;
      const [kx, kz] = [k * Math.cos(theta), k * Math.sin(theta)];
      const psi = waveNumberSpectrum(kx, kz, params, 457) * k * k; // d²k = k²·d(ln k)·dθ
      total += psi;
      if (kx * wind[0] + kz * wind[1] < 0) against += psi;
    }
  }
  const allowance = spreadingAllowance(params, kMin, kMax);
  console.log(`default sea: against-wind share of ∫Ψ ${(against / total).toExponential(3)}, spreading allowance ${allowance.toExponential(3)}`);
  expect(Math.abs(against / total / allowance - 1)).toBeLessThan(0.02);
});
