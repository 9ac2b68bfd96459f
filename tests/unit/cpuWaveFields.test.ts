/**
 * CpuWaveFields against an independent reference, and against the physics it must reproduce.
 *
 * The reference evolves h̃(k, t) = h̃0(k)·e^{iωt} + h̃0*(−k)·e^{−iωt} (Tessendorf 2001, eq. 26) per
 * texel in double precision with Math.cos/Math.sin of ω·t, ω = m·2π/T, builds each of the eight
 * field spectra of waveFieldLayout.ts on its own (not packed in pairs) and inverse-transforms each
 * one alone with the term-by-term DFT of naiveDft.ts. Nothing of CpuWaveFields, fft.ts or the phase
 * table is used. Physical checks (phase speed, finite differences, the Jacobian of the choppy map)
 * need no reference at all.
 *
 * CpuWaveFields computes the fields for a choppiness λ = 1, over its spectrum's own repeat period
 * T_c; the surface and the queries scale Dx, Dz and their derivatives by λ (Tessendorf 2001,
 * eq. 29: D = λ·Σ −i·k̂·h̃·e^{ik·x} is linear in λ). The reference here is built for λ = 1, and the
 * choppy-surface checks scale the λ = 1 fields by λ the way the surface does.
 */
import { describe, expect, it } from 'vitest';
import { CpuWaveFields } from '../../src/fft/cpuWaveFields';
import { DEFAULT_PARAMETERS, validateParameters, type SimulationParameters } from '../../src/parameters/parameters';
import { SeededRandom } from '../../src/spectrum/random';
import { createCascadeSpectra, reducedSpectrum, type InitialSpectrum } from '../../src/spectrum/initialSpectrum';
import { phillips } from '../../src/spectrum/phillips';
import { naiveInverseDft2D } from './naiveDft';

const G = 9.81;

const FIELD_NAMES = ['h', 'dhdx', 'dhdz', 'Dx', 'Dz', 'dDxdx', 'dDzdz', 'dDxdz'] as const;
type FieldName = (typeof FIELD_NAMES)[number];
/** Each field on the N×N grid, row-major (index j·N + i for the sample at (x, z) = (i, j)·Δ). */
type Fields = Record<FieldName, Float64Array>;
type ComplexGrid = [Float64Array, Float64Array];

/** h̃(k, t) per texel, double precision, with Math.cos/sin of ω·t. */
function evolvedSpectrum(spectrum: InitialSpectrum, repeatPeriod: number, t: number): ComplexGrid {
  const count = spectrum.resolution ** 2;
  const re = new Float64Array(count);
  const im = new Float64Array(count);
  const a = spectrum.amplitudes;
  for (let p = 0; p < count; p++) {
    const omega = (spectrum.waveVectors[4 * p + 3] * 2 * Math.PI) / repeatPeriod;
    const c = Math.cos(omega * t);
    const s = Math.sin(omega * t);
    // h̃0(k)·(c + i s) + h̃0*(−k)·(c − i s), with amplitudes[2..3] = h̃0*(−k)
    re[p] = a[4 * p] * c - a[4 * p + 1] * s + a[4 * p + 2] * c + a[4 * p + 3] * s;
    im[p] = a[4 * p] * s + a[4 * p + 1] * c - a[4 * p + 2] * s + a[4 * p + 3] * c;
  }
  return [re, im];
}

/** The eight field spectra of waveFieldLayout.ts for a choppiness λ = 1, each separately. */
function fieldSpectra(spectrum: InitialSpectrum, h: ComplexGrid): Record<FieldName, ComplexGrid> {
  const count = spectrum.resolution ** 2;
  const out = Object.fromEntries(
    FIELD_NAMES.map((name) => [name, [new Float64Array(count), new Float64Array(count)]]),
  ) as Record<FieldName, ComplexGrid>;
  const set = (name: FieldName, p: number, factorRe: number, factorIm: number) => {
    // (factorRe + i·factorIm)·h̃
    out[name][0][p] = factorRe * h[0][p] - factorIm * h[1][p];
    out[name][1][p] = factorRe * h[1][p] + factorIm * h[0][p];
  };
  for (let p = 0; p < count; p++) {
    const kx = spectrum.waveVectors[4 * p];
    const kz = spectrum.waveVectors[4 * p + 1];
    const kInverse = spectrum.waveVectors[4 * p + 2];
    set('h', p, 1, 0);
    set('dhdx', p, 0, kx); // i·kx·h̃
    set('dhdz', p, 0, kz); // i·kz·h̃
    set('Dx', p, 0, kx * kInverse); // i·kx/k·h̃
    set('Dz', p, 0, kz * kInverse); // i·kz/k·h̃
    set('dDxdx', p, -kx * kx * kInverse, 0); // −kx²/k·h̃
    set('dDzdz', p, -kz * kz * kInverse, 0); // −kz²/k·h̃
    set('dDxdz', p, -kx * kz * kInverse, 0); // −kx·kz/k·h̃
  }
  return out;
}

interface Reference {
  spectra: Record<FieldName, ComplexGrid>;
  real: Fields;
  imag: Fields;
}

function reference(spectrum: InitialSpectrum, t: number): Reference {
  const spectra = fieldSpectra(spectrum, evolvedSpectrum(spectrum, spectrum.repeatPeriod, t));
  const real = {} as Fields;
  const imag = {} as Fields;
  for (const name of FIELD_NAMES) {
    [real[name], imag[name]] = naiveInverseDft2D(spectra[name][0], spectra[name][1], spectrum.resolution);
  }
  return { spectra, real, imag };
}

/** The fields CpuWaveFields computed, unpacked from its two RGBA layouts. */
function readFields(waves: CpuWaveFields, n: number): Fields {
  const f = Object.fromEntries(FIELD_NAMES.map((name) => [name, new Float64Array(n * n)])) as Fields;
  const { displacement: d, derivatives: g } = waves;
  for (let p = 0; p < n * n; p++) {
    f.Dx[p] = d[4 * p];
    f.h[p] = d[4 * p + 1];
    f.Dz[p] = d[4 * p + 2];
    f.dDxdz[p] = d[4 * p + 3];
    f.dhdx[p] = g[4 * p];
    f.dhdz[p] = g[4 * p + 1];
    f.dDxdx[p] = g[4 * p + 2];
    f.dDzdz[p] = g[4 * p + 3];
  }
  return f;
}

function fieldsAt(spectrum: InitialSpectrum, t: number): Fields {
  const waves = new CpuWaveFields(spectrum);
  waves.update(t);
  return readFields(waves, spectrum.resolution);
}

/** The horizontal fields (Dx, Dz and their derivatives) scaled by λ, as the surface and queries do. */
function withChoppiness(f: Fields, lambda: number): Fields {
  const out = { ...f };
  for (const name of ['Dx', 'Dz', 'dDxdx', 'dDzdz', 'dDxdz'] as const) out[name] = f[name].map((v) => lambda * v);
  return out;
}

/** The same scaling of the reference field spectra. */
function spectraWithChoppiness(spectra: Record<FieldName, ComplexGrid>, lambda: number): Record<FieldName, ComplexGrid> {
  const out = { ...spectra };
  for (const name of ['Dx', 'Dz', 'dDxdx', 'dDzdz', 'dDxdz'] as const) {
    out[name] = [spectra[name][0].map((v) => lambda * v), spectra[name][1].map((v) => lambda * v)];
  }
  return out;
}

const rms = (a: ArrayLike<number>) => {
  let sum = 0;
  for (let i = 0; i < a.length; i++) sum += a[i] * a[i];
  return Math.sqrt(sum / a.length);
};
const maxAbsDifference = (a: ArrayLike<number>, b: ArrayLike<number>) => {
  let worst = 0;
  for (let i = 0; i < a.length; i++) worst = Math.max(worst, Math.abs(a[i] - b[i]));
  return worst;
};
const sumSquares = ([re, im]: ComplexGrid) => re.reduce((s, x, p) => s + x * x + im[p] * im[p], 0);

/**
 * The simulation grid's spectrum with every amplitude replaced by unit normals, paired as
 * documented; with `band`, only on the texels whose signed frequencies i and j are both within it
 * (0 elsewhere), as a coarse cascade keeps only its disc of modes.
 */
function whiteSpectrum(base: InitialSpectrum, seed: number, band = base.resolution / 2): InitialSpectrum {
  const n = base.resolution;
  const random = new SeededRandom(seed);
  const h0 = Float64Array.from({ length: 2 * n * n }, () => random.nextNormal());
  const amplitudes = new Float32Array(4 * n * n);
  const inBand = (index: number) => Math.min(index, n - index) <= band;
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      if (!inBand(i) || !inBand(j)) continue;
      const t = j * n + i;
      const o = ((n - j) % n) * n + ((n - i) % n);
      amplitudes.set([h0[2 * t], h0[2 * t + 1], h0[2 * o], -h0[2 * o + 1]], 4 * t);
    }
  }
  return { ...base, amplitudes };
}

/**
 * One travelling wave: h̃0(q) = a at texel (i, j) of wave vector q, everything else 0 (the conjugate
 * entry h̃0*(−k) at texel −q is set to match, as createCascadeSpectra does). The sea is then
 * h(x, t) = 2|a|·cos(q·x + ωt + arg a).
 */
function singleMode(base: InitialSpectrum, i: number, j: number, a: [number, number]): InitialSpectrum {
  const n = base.resolution;
  const amplitudes = new Float32Array(4 * n * n);
  const t = j * n + i;
  const o = ((n - j) % n) * n + ((n - i) % n);
  amplitudes[4 * t] = a[0];
  amplitudes[4 * t + 1] = a[1];
  amplitudes[4 * o + 2] = a[0];
  amplitudes[4 * o + 3] = -a[1];
  return { ...base, amplitudes };
}

/** The Phillips model on one patch, merged over the defaults (parameters.test.ts checks validity). */
function params(changes: Partial<SimulationParameters>): SimulationParameters {
  return { ...DEFAULT_PARAMETERS, spectrum: 'phillips', patchSizes: [250], windSpeed: 12, smallWaveCutoff: 0.1, ...changes };
}

/**
 * The single cascade of the report's Phillips spectrum: Ψ = 2·P·(L/2π)² gives h̃0 = (ξr + i·ξi)·√(P/2)
 * (spectrum.test.ts).
 */
function phillipsCascade(p: SimulationParameters): InitialSpectrum {
  const [size] = p.patchSizes;
  const spectra = createCascadeSpectra(p, (kx, kz) => 2 * phillips(kx, kz, p) * (size / (2 * Math.PI)) ** 2);
  expect(spectra).toHaveLength(1);
  return spectra[0];
}

// Small grids for the O(N⁴) reference. Wind at 30° so no row or column of the spectrum is empty,
// no small-wave cutoff so the Nyquist row and column carry real weight.
const SMALL_CASES = [
  {
    name: 'Phillips N=16',
    p: params({ resolution: 16, patchSizes: [40], windSpeed: 8, windDirection: 30, smallWaveCutoff: 0, repeatPeriod: 90 }),
  },
  {
    name: 'Phillips N=32, depth 4 m',
    p: params({
      resolution: 32,
      patchSizes: [60],
      windSpeed: 10,
      windDirection: -50,
      smallWaveCutoff: 0,
      repeatPeriod: 100,
      seed: 8,
      depth: 4,
    }),
  },
].map(({ name, p }) => ({ name, p, spectrum: phillipsCascade(p) }));
// Unit amplitudes on every texel, Nyquist and k = 0 included, so no mode hides behind a small P.
const WHITE = { name: 'white N=16', p: SMALL_CASES[0].p, spectrum: whiteSpectrum(SMALL_CASES[0].spectrum, 77) };
// Modes only up to frequency 3 of 16 (N = 32): the FFT's pass 1 then transforms every 8th column
// and the one before it (BatchedInverseFft2D's inputBand), as for the default coarse cascades.
const WHITE_BAND = { name: 'white N=32 within frequency 3', p: SMALL_CASES[1].p, spectrum: whiteSpectrum(SMALL_CASES[1].spectrum, 78, 3) };
const ALL_SMALL = [...SMALL_CASES, WHITE, WHITE_BAND];
// t = 1e7 s (four months) checks that long runs keep full precision (time is wrapped before float32).
const TIMES = [0, 3.7, 1e7 + 0.37];

describe('the field spectra (the reference built from spectrum.ts)', () => {
  for (const { name, p, spectrum } of [...SMALL_CASES, WHITE]) {
    it(`are Hermitian, so every field is real, incl. the Nyquist row and column (${name})`, () => {
      const n = p.resolution;
      // The Nyquist row and column must carry weight, or this test would prove nothing about them.
      let nyquist = 0;
      let total = 0;
      for (let j = 0; j < n; j++) {
        for (let i = 0; i < n; i++) {
          const power = spectrum.amplitudes[4 * (j * n + i)] ** 2 + spectrum.amplitudes[4 * (j * n + i) + 1] ** 2;
          total += power;
          if (i === n / 2 || j === n / 2) nyquist += power;
        }
      }
      expect(nyquist / total).toBeGreaterThan(1e-6);
      for (const t of TIMES) {
        const { real, imag } = reference(spectrum, t);
        for (const field of FIELD_NAMES) {
          const scale = rms(real[field]);
          expect(scale).toBeGreaterThan(0);
          // Double-precision DFT of N² terms: the imaginary part of a real field is rounding,
          // ~1e-16·√(N²)·RMS ≲ 1e-14·RMS (observed ≤ 2.4e-15); 1e-12 leaves margin. A non-Hermitian
          // texel pair of relative weight w ≥ 1e-6 gives an imaginary part ~√w·RMS ≥ 1e-3·RMS.
          expect(Math.max(...imag[field].map(Math.abs)) / scale, `${field} at t = ${t}`).toBeLessThan(1e-12);
        }
      }
    });
  }
});

describe('CpuWaveFields.update', () => {
  for (const { name, p, spectrum } of ALL_SMALL) {
    it(`equals the separately transformed reference fields (${name})`, () => {
      const waves = new CpuWaveFields(spectrum);
      for (const t of TIMES) {
        waves.update(t);
        const got = readFields(waves, p.resolution);
        const { real } = reference(spectrum, t);
        for (const field of FIELD_NAMES) {
          // float32 phase table, FFT input and 2·log2(N) float32 FFT stages: ~1e-7 of the packed
          // pair's RMS per sample, the max over the grid a few times that (observed ≤ 1.4e-6);
          // 1e-5·RMS leaves margin for pairs of unequal size, while a wrong sign, factor, index
          // or channel gives errors of order RMS.
          const error = maxAbsDifference(got[field], real[field]) / rms(real[field]);
          expect(error, `${field} at t = ${t}`).toBeLessThan(1e-5);
        }
      }
    });

    it(`satisfies Parseval: mean of f² over the grid = Σ|F̃(k, t)|² for every field (${name})`, () => {
      for (const t of TIMES) {
        const got = fieldsAt(spectrum, t);
        const spectra = fieldSpectra(spectrum, evolvedSpectrum(spectrum, spectrum.repeatPeriod, t));
        for (const field of FIELD_NAMES) {
          const meanSquare = rms(got[field]) ** 2;
          // The fields are within ~1e-6 of exact pointwise (above), so their mean square is within
          // ~2e-6 relative; 1e-5 is the bound.
          expect(Math.abs(meanSquare / sumSquares(spectra[field]) - 1), `${field} at t = ${t}`).toBeLessThan(1e-5);
        }
      }
    });

    it(`repeats exactly after the cascade's repeat period T_c (${name})`, () => {
      const t = 3.7;
      const T = spectrum.repeatPeriod;
      // T_c is the user's T doubled as often as the 1 % phase-speed bound needs (cascadeBands.ts).
      expect(Number.isInteger(Math.log2(T / p.repeatPeriod))).toBe(true);
      const first = fieldsAt(spectrum, t);
      for (const later of [t + T, t + 1000 * T, t - 7 * T]) {
        const again = fieldsAt(spectrum, later);
        for (const field of FIELD_NAMES) {
          // t + 1000·T is rounded by ≤ 1.5e-11 s in double, a phase change of ≤ 1e-9 rad, far
          // below float32 resolution: the phase table differs by at most one float32 ulp (6e-8),
          // the fields by ~1e-7·RMS. 1e-6 is the bound; an unquantized ω would move them ~RMS.
          const difference = maxAbsDifference(again[field], first[field]) / rms(first[field]);
          expect(difference, `${field} at t = ${later}`).toBeLessThan(1e-6);
        }
      }
      // And it does change within a period.
      const between = fieldsAt(spectrum, t + T / 3);
      expect(maxAbsDifference(between.h, first.h) / rms(first.h)).toBeGreaterThan(0.1);
    });
  }

  it('carries no state between updates: any order of times gives bit-identical fields', () => {
    const { spectrum } = SMALL_CASES[1];
    const fresh = new CpuWaveFields(spectrum);
    fresh.update(12.5);
    const reused = new CpuWaveFields(spectrum);
    reused.update(80);
    reused.update(1e6);
    reused.update(12.5);
    expect(new Uint32Array(reused.displacement.buffer)).toEqual(new Uint32Array(fresh.displacement.buffer));
    expect(new Uint32Array(reused.derivatives.buffer)).toEqual(new Uint32Array(fresh.derivatives.buffer));
  });

  it('evolves with the spectrum’s own repeat period: fields(T) at t equal fields(2T) at 2t', () => {
    const { spectrum } = SMALL_CASES[0];
    const doubled = { ...spectrum, repeatPeriod: 2 * spectrum.repeatPeriod };
    for (const t of [3.7, 41.25]) {
      const a = fieldsAt(spectrum, t);
      const b = fieldsAt(doubled, 2 * t);
      // ω = m·2π/T: the same phases m·2π·t/T; only float32 rounding of the phase table differs.
      for (const field of FIELD_NAMES) expect(maxAbsDifference(a[field], b[field]) / rms(a[field]), field).toBeLessThan(1e-6);
    }
    // And the period does matter: at the same t the two differ.
    expect(maxAbsDifference(fieldsAt(spectrum, 3.7).h, fieldsAt(doubled, 3.7).h) / rms(fieldsAt(spectrum, 3.7).h)).toBeGreaterThan(0.1);
  });
});

describe('CpuWaveFields physics: one travelling wave', () => {
  // N = 64 over 100 m; T = 2000 s makes ω0 = 2π/T = 0.0031 rad/s, so rounding ω to the nearest
  // multiple of ω0 changes the phase speed by < (ω0/2)/ω ≈ 0.1% for these modes.
  const deep = params({ resolution: 64, patchSizes: [100], repeatPeriod: 2000 });
  const shallow = params({ resolution: 64, patchSizes: [100], repeatPeriod: 2000, depth: 3 });
  const n = 64;
  const dx = 100 / n;

  /** Phase of the sea's Fourier projection Σ h(x)·e^{−iq·x}: the crest is where q·x = −phase. */
  function projectionPhase(h: Float64Array, qx: number, qz: number): number {
    let re = 0;
    let im = 0;
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const angle = qx * i * dx + qz * j * dx;
        re += h[j * n + i] * Math.cos(angle);
        im -= h[j * n + i] * Math.sin(angle);
      }
    }
    return Math.atan2(im, re);
  }

  // Texel (i, j) of the amplitude, and the wave vector q it holds.
  const modes: [number, number][] = [
    [4, 0], // q along +x, |q| = 0.251 rad/m, wavelength 25 m
    [0, 4], // along +z
    [60, 0], // q along −x (signed frequency −4)
    [3, 60], // oblique, q = (3, −4)·2π/100, wavelength 20 m
  ];

  for (const p of [deep, shallow]) {
    for (const [i, j] of modes) {
      it(`moves at the phase speed √(g·tanh(kd)/k), against q: mode (${i}, ${j}), depth ${p.depth}`, () => {
        const spectrum = singleMode(phillipsCascade(p), i, j, [0.3, -0.2]);
        const T = spectrum.repeatPeriod;
        expect(T).toBe(p.repeatPeriod); // 2000 s already keeps every mode within 1 %: not doubled
        const qx = (2 * Math.PI * (i < n / 2 ? i : i - n)) / 100;
        const qz = (2 * Math.PI * (j < n / 2 ? j : j - n)) / 100;
        const k = Math.hypot(qx, qz);
        const omegaTrue = Math.sqrt(G * k * Math.tanh(k * p.depth)); // tanh(∞) = 1
        const t1 = 0.3;
        const t2 = 1.5; // the crest moves ~7 m, under half a wavelength: the phase difference is unambiguous
        const phase1 = projectionPhase(fieldsAt(spectrum, t1).h, qx, qz);
        const phase2 = projectionPhase(fieldsAt(spectrum, t2).h, qx, qz);
        let dPhase = phase2 - phase1;
        dPhase -= 2 * Math.PI * Math.round(dPhase / (2 * Math.PI)); // into (−π, π]
        // Crest at q·x = −phase, so along q̂ it moves by −ΔΦ/|q|.
        const velocityAlongQ = -dPhase / k / (t2 - t1);
        // Direction: with Tessendorf's e^{+iωt} on h̃0(k), h = 2|a|·cos(q·x + ωt + arg a), so the
        // part of the sea held in h̃0(q) travels towards −q̂; the conjugate term h̃0*(−k)·e^{−iωt}
        // makes the part held in h̃0(−q) travel towards +q̂. (With the symmetric Phillips spectrum,
        // waves therefore run both with and against the wind.)
        expect(velocityAlongQ).toBeLessThan(0);
        // Speed: ω/k within 1% (quantization of ω costs < 0.1%, the phase measurement ~1e-7).
        const speed = -velocityAlongQ;
        expect(Math.abs(speed / (omegaTrue / k) - 1)).toBeLessThan(0.01);
        if (p.depth === Infinity) expect(Math.abs(speed / Math.sqrt(G / k) - 1)).toBeLessThan(0.01);
        // And ω is exactly a multiple of 2π/T, the nearest one (1e-3 of a step: phase noise ~1e-7·T/Δt).
        const stepsPerPeriod = (-velocityAlongQ * k * T) / (2 * Math.PI);
        expect(Math.abs(stepsPerPeriod - Math.round(stepsPerPeriod))).toBeLessThan(1e-3);
        expect(Math.round(stepsPerPeriod)).toBe(Math.round((omegaTrue * T) / (2 * Math.PI)));
      });
    }
  }

  it('is a cosine of amplitude 2|a|, moving nothing sideways once scaled by λ = 0', () => {
    const spectrum = singleMode(phillipsCascade(deep), 4, 0, [0.5, 0]);
    const f = withChoppiness(fieldsAt(spectrum, 0), 0);
    const k = (2 * Math.PI * 4) / 100;
    let worst = 0;
    for (let p = 0; p < n * n; p++) {
      worst = Math.max(worst, Math.abs(f.h[p] - Math.cos(k * (p % n) * dx)), Math.abs(f.Dx[p]), Math.abs(f.Dz[p]));
    }
    expect(worst).toBeLessThan(1e-6); // float32 fields of amplitude 1: rounding ~1e-7
  });

  for (const lambda of [0.5, 1, 1.5]) {
    it(`scaled by λ = ${lambda} sharpens crests like a Gerstner wave: Dx = −λ·sin(kx) for h = cos(kx)`, () => {
      const spectrum = singleMode(phillipsCascade(deep), 4, 0, [0.5, 0]); // h = cos(kx) at t = 0
      const f = withChoppiness(fieldsAt(spectrum, 0), lambda);
      const k = (2 * Math.PI * 4) / 100;
      const crest = 0; // texel 0: x = 0, h = 1
      const trough = n / 8; // half a wavelength (16 texels) later: h = −1
      // Tolerances 1e-6: float32 fields of amplitude ≤ 1.5 (rounding ≤ ~1e-7).
      expect(Math.abs(f.h[crest] - 1)).toBeLessThan(1e-6);
      expect(Math.abs(f.h[trough] + 1)).toBeLessThan(1e-6);
      // The crest itself does not move sideways; its neighbours move towards it.
      expect(Math.abs(f.Dx[crest])).toBeLessThan(1e-6);
      expect(f.Dx[crest + 1]).toBeLessThan(0);
      expect(f.Dx[n - 1]).toBeGreaterThan(0);
      // Compressed at the crest, stretched at the trough.
      expect(1 + f.dDxdx[crest]).toBeLessThan(1);
      expect(1 + f.dDxdx[trough]).toBeGreaterThan(1);
      expect(Math.abs(f.dDxdx[crest] + lambda * k)).toBeLessThan(1e-6);
      expect(Math.abs(f.dDxdx[trough] - lambda * k)).toBeLessThan(1e-6);
      // The same, from the displaced points themselves: spacing < Δx at the crest, > Δx at the trough.
      expect(dx + f.Dx[crest + 1] - f.Dx[crest]).toBeLessThan(dx);
      expect(dx + f.Dx[trough + 1] - f.Dx[trough]).toBeGreaterThan(dx);
      // The Gerstner wave x' = x − λ·sin(kx), y = cos(kx), everywhere; no motion along z.
      let worst = 0;
      for (let p = 0; p < n * n; p++) {
        const x = (p % n) * dx;
        worst = Math.max(
          worst,
          Math.abs(f.Dx[p] + lambda * Math.sin(k * x)),
          Math.abs(f.dDxdx[p] + lambda * k * Math.cos(k * x)),
          Math.abs(f.Dz[p]),
          Math.abs(f.dDzdz[p]),
          Math.abs(f.dDxdz[p]),
        );
      }
      expect(worst).toBeLessThan(1e-6);
    });
  }
});

describe('CpuWaveFields physics: derivatives against finite differences on a smooth sea', () => {
  // N = 128 over 100 m, Δx = 0.78 m, small-wave cutoff ℓ = 4·Δx: modes with k·Δx ≳ 1 are damped by
  // exp(−k²ℓ²/2) ≤ e^{−8}, so central differences resolve the sea.
  const p = params({ resolution: 128, patchSizes: [100], smallWaveCutoff: 400 / 128, windSpeed: 12, windDirection: 30 });
  const n = p.resolution;
  const dx = 100 / n;
  const spectrum = phillipsCascade(p);
  const t = 2.5;
  const hTilde = evolvedSpectrum(spectrum, spectrum.repeatPeriod, t);

  /** Central difference of f along x or z on the periodic grid. */
  function centralDifference(f: Float64Array, along: 'x' | 'z'): Float64Array {
    const out = new Float64Array(n * n);
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const [a, b] =
          along === 'x'
            ? [j * n + ((i + 1) % n), j * n + ((i + n - 1) % n)]
            : [((j + 1) % n) * n + i, ((j + n - 1) % n) * n + i];
        out[j * n + i] = (f[a] - f[b]) / (2 * dx);
      }
    }
    return out;
  }

  /**
   * Truncation error of the central difference, mode by mode: (f(x+Δ) − f(x−Δ))/2Δ = f′·sin(kΔ)/(kΔ),
   * and 1 − sin(u)/u ≤ u²/6. So the RMS error is at most √(Σ|F̃′|²·(k_along·Δx)⁴/36) (Parseval),
   * the k²Δx²/6 rule weighted by the derivative's own spectrum. Returns [RMS bound, L∞ bound].
   */
  function truncationBound(derivative: ComplexGrid, along: 'x' | 'z'): [number, number] {
    let squares = 0;
    let sum = 0;
    for (let q = 0; q < n * n; q++) {
      const kAlong = spectrum.waveVectors[4 * q + (along === 'x' ? 0 : 1)];
      const factor = (kAlong * dx) ** 2 / 6;
      const magnitude = Math.hypot(derivative[0][q], derivative[1][q]);
      squares += (magnitude * factor) ** 2;
      sum += magnitude * factor;
    }
    return [Math.sqrt(squares), sum];
  }

  it('∂h/∂x and ∂h/∂z equal central differences of h within the k²Δx²/6 truncation bound', () => {
    const f = fieldsAt(spectrum, t);
    const spectra = fieldSpectra(spectrum, hTilde);
    for (const [field, along] of [
      ['dhdx', 'x'],
      ['dhdz', 'z'],
    ] as const) {
      const scale = rms(f[field]);
      const [bound] = truncationBound(spectra[field], along);
      // The bound must be small, or the test would not test anything (it is ~0.7% here).
      expect(bound / scale).toBeLessThan(0.02);
      const difference = centralDifference(f.h, along);
      let squares = 0;
      for (let q = 0; q < n * n; q++) squares += (difference[q] - f[field][q]) ** 2;
      const error = Math.sqrt(squares / (n * n));
      // 5% above the rigorous bound for its own rounding, plus 1e-5·RMS for float32 h, whose
      // ~1e-7 rounding is amplified by 1/(2Δx·k_rms) ≈ 10 in the difference quotient.
      expect(error, `${field}: bound ${bound / scale} of RMS`).toBeLessThan(1.05 * bound + 1e-5 * scale);
    }
  });

  it('the Jacobian (1 + λ∂Dx/∂x)(1 + λ∂Dz/∂z) − (λ∂Dx/∂z)² is that of the displaced grid x + λD', () => {
    const lambda = 2.5; // makes J range over about [0.66, 1.49] for this sea
    // The λ = 1 fields scaled by λ, as the surface scales them.
    const f = withChoppiness(fieldsAt(spectrum, t), lambda);
    const spectra = spectraWithChoppiness(fieldSpectra(spectrum, hTilde), lambda);
    const analytic = new Float64Array(n * n);
    for (let q = 0; q < n * n; q++) analytic[q] = (1 + f.dDxdx[q]) * (1 + f.dDzdz[q]) - f.dDxdz[q] ** 2;
    // Finite-difference Jacobian of (x, z) → (x + Dx, z + Dz); ∂Dz/∂x comes from Dz itself, which
    // also checks the symmetry ∂Dz/∂x = ∂Dx/∂z that the layout relies on.
    const xx = centralDifference(f.Dx, 'x');
    const xz = centralDifference(f.Dx, 'z');
    const zx = centralDifference(f.Dz, 'x');
    const zz = centralDifference(f.Dz, 'z');
    const numeric = new Float64Array(n * n);
    for (let q = 0; q < n * n; q++) numeric[q] = (1 + xx[q]) * (1 + zz[q]) - xz[q] * zx[q];

    // Error budget: with e1…e4 the truncation errors of the four differences (bounds as above),
    // J_num − J = e1(1 + ∂Dz/∂z) + e2(1 + ∂Dx/∂x) + e1·e2 − (e3 + e4)·∂Dx/∂z − e3·e4, so its
    // RMS is at most the sum of max|factor|·RMS bound, plus the products' L∞·RMS bounds.
    const maxAbs = (a: Float64Array, offset: number) => Math.max(...a.map((v) => Math.abs(offset + v)));
    const [e1, e1max] = truncationBound(spectra.dDxdx, 'x');
    const [e2] = truncationBound(spectra.dDzdz, 'z');
    const [e3, e3max] = truncationBound(spectra.dDxdz, 'z');
    const [e4] = truncationBound(spectra.dDxdz, 'x');
    const bound =
      maxAbs(f.dDzdz, 1) * e1 + maxAbs(f.dDxdx, 1) * e2 + maxAbs(f.dDxdz, 0) * (e3 + e4) + e1max * e2 + e3max * e4;
    const spread = rms(analytic.map((v) => v - 1));
    // The sea must actually be choppy and the bound small against it.
    expect(Math.min(...analytic)).toBeLessThan(0.8);
    expect(bound / spread).toBeLessThan(0.05);
    let squares = 0;
    for (let q = 0; q < n * n; q++) squares += (numeric[q] - analytic[q]) ** 2;
    const error = Math.sqrt(squares / (n * n));
    // 5% above the bound plus float32 rounding of D amplified by 1/(2Δx) (≤ 1e-5 of the spread).
    expect(error, `bound ${bound}, spread ${spread}`).toBeLessThan(1.05 * bound + 1e-5 * spread);
  });
});

describe('CpuWaveFields robustness', () => {
  for (const [name, changes] of [
    ['no wind', { windSpeed: 0 }],
    ['a 60 m/s gale', { windSpeed: 60 }],
    ['N = 1024', { resolution: 1024 }],
  ] as const) {
    it(`gives finite fields for ${name}`, () => {
      const p = params(changes);
      const waves = new CpuWaveFields(phillipsCascade(p));
      waves.update(5.3);
      expect(waves.displacement.every(Number.isFinite)).toBe(true);
      expect(waves.derivatives.every(Number.isFinite)).toBe(true);
      if (p.windSpeed === 0) {
        expect(waves.displacement.every((v) => v === 0)).toBe(true);
        expect(waves.derivatives.every((v) => v === 0)).toBe(true);
      } else {
        expect(rms(waves.displacement)).toBeGreaterThan(0);
      }
    });
  }

  it('gives finite, nonzero fields for every cascade of the default sea (Phillips Ψ over the default patches)', () => {
    const p = { ...DEFAULT_PARAMETERS, spectrum: 'phillips' as const };
    const largest = p.patchSizes[p.patchSizes.length - 1];
    const spectra = createCascadeSpectra(p, (kx, kz) => 2 * phillips(kx, kz, p) * (largest / (2 * Math.PI)) ** 2);
    expect(spectra).toHaveLength(3);
    for (const spectrum of spectra) {
      const waves = new CpuWaveFields(spectrum);
      waves.update(1e7 + 5.3);
      expect(waves.displacement.every(Number.isFinite), `${spectrum.patchSize} m`).toBe(true);
      expect(waves.derivatives.every(Number.isFinite), `${spectrum.patchSize} m`).toBe(true);
      expect(rms(waves.displacement), `${spectrum.patchSize} m`).toBeGreaterThan(0);
    }
  });
});

describe('CpuWaveFields memory', () => {
  it("makes its fields' texels on first use only: spectraAt (the compute FFT's input) leaves them unmade, 8 MB at N = 512", () => {
    const waves = new CpuWaveFields(phillipsCascade(params({ resolution: 512 })));
    const texelBytes = 2 * 4 * 512 * 512 * Float32Array.BYTES_PER_ELEMENT;
    const before = process.memoryUsage().arrayBuffers;
    waves.spectraAt(1.5);
    const afterSpectra = process.memoryUsage().arrayBuffers;
    waves.update(1.5);
    const afterUpdate = process.memoryUsage().arrayBuffers;
    console.log(`N = 512: spectraAt allocated ${((afterSpectra - before) / 2 ** 20).toFixed(2)} MB, the first update ${((afterUpdate - afterSpectra) / 2 ** 20).toFixed(2)} MB`);
    expect(afterSpectra - before).toBeLessThan(texelBytes / 8);
    expect(afterUpdate - afterSpectra).toBeGreaterThanOrEqual(texelBytes);
    // The same arrays from then on, which the update writes.
    const displacement = waves.displacement;
    waves.update(2.5);
    expect(waves.displacement).toBe(displacement);
    expect(rms(displacement)).toBeGreaterThan(0);
  }, 30_000);
});

/**
 * Each cascade of `parameters` at time t on its grid and on a reduced grid of `resolution`, compared
 * at the reduced grid's texels: the largest difference of any channel relative to the largest
 * value, the RMS height and the RMS height difference.
 */
function reducedAgainstFull(parameters: SimulationParameters, resolution: number, t: number) {
  const step = parameters.resolution / resolution;
  return createCascadeSpectra(parameters).map((spectrum) => {
    const full = new CpuWaveFields(spectrum);
    full.update(t);
    const reduced = new CpuWaveFields(reducedSpectrum(spectrum, resolution));
    reduced.update(t);
    let [worst, largest, heightSquares, heightErrorSquares] = [0, 0, 0, 0];
    for (let j = 0; j < resolution; j++) {
      for (let i = 0; i < resolution; i++) {
        const [at, from] = [4 * (j * resolution + i), 4 * (step * j * parameters.resolution + step * i)];
        for (const name of ['displacement', 'derivatives'] as const) {
          for (let c = 0; c < 4; c++) {
            worst = Math.max(worst, Math.abs(reduced[name][at + c] - full[name][from + c]));
            largest = Math.max(largest, Math.abs(full[name][from + c]));
          }
        }
        heightSquares += full.displacement[from + 1] ** 2;
        heightErrorSquares += (reduced.displacement[at + 1] - full.displacement[from + 1]) ** 2;
      }
    }
    const texels = resolution * resolution;
    return { patch: spectrum.patchSize, worstRelative: worst / largest, heightRms: Math.sqrt(heightSquares / texels), heightErrorRms: Math.sqrt(heightErrorSquares / texels) };
  });
}

describe('CpuWaveFields taking over the arrays of fields no longer wanted (cascadeQueryFields.ts: a new cascade\'s provisional copy)', () => {
  it('gives bit for bit the fields, velocities included, of fields made afresh; in the old arrays only where grid and band match', () => {
    const [before, after] = [10, 15].map((windSpeed) => createCascadeSpectra(validateParameters({ resolution: 64, windSpeed, seed: 4 })));
    for (let cascade = 0; cascade < before.length; cascade++) {
      const old = new CpuWaveFields(before[cascade]);
      old.update(3);
      const oldVelocities = old.updateVelocities(3);
      const fresh = new CpuWaveFields(after[cascade]);
      const taken = new CpuWaveFields(after[cascade], old);
      for (const fields of [fresh, taken]) fields.update(7.5);
      expect(taken.displacement).toBe(old.displacement); // the same array
      expect(taken.displacement).toEqual(fresh.displacement);
      expect(taken.derivatives).toEqual(fresh.derivatives);
      expect(taken.updateVelocities(7.5)).toBe(oldVelocities);
      expect(taken.updateVelocities(7.5)).toEqual(fresh.updateVelocities(7.5));
    }
    // Another band (the finest cascade's against a coarse one's): fresh arrays.
    const finest = new CpuWaveFields(before[0]);
    expect(new CpuWaveFields(after[2], finest).displacement).not.toBe(finest.displacement);
  });
});

describe('reducedSpectrum (the queries\' copies of a cascade on coarser grids, cascadeQueryFields.ts)', () => {
  it('a 64² copy of the default N = 256 sea: every cascade but the finest exact at its texels; the finest within 1 % of the sea\'s RMS height there', () => {
    // Between the texels the coarse cascades' copies are not exact: surfaceQuery.test.ts.
    const results = reducedAgainstFull(validateParameters({ resolution: 256, windSpeed: 12, seed: 8 }), 64, 17.25);
    console.log(`reduced 256² → 64²: ${JSON.stringify(results)}`);
    for (const coarse of results.slice(1)) expect(coarse.worstRelative).toBeLessThan(1e-5);
    const seaRms = Math.hypot(...results.map((r) => r.heightRms));
    expect(results[0].heightErrorRms).toBeGreaterThan(0);
    expect(results[0].heightErrorRms).toBeLessThan(0.01 * seaRms); // heightAt's tolerance against the drawn surface
  });

  it('gives every cascade but the finest exactly, at every 4th texel of N = 1024; the finest loses only its shortest ripples', () => {
    // The same modes on a coarser grid: an inverse DFT of the same coefficients evaluated at the
    // coarse grid's points, which are every (N/256)-th point of the fine grid. A coarse cascade's
    // band ends far inside the 256² grid (cascadeBands.ts), so nothing is dropped there.
    const results = reducedAgainstFull(validateParameters({ resolution: 1024, windSpeed: 12, seed: 8 }), 256, 17.25);
    console.log(`reduced 1024² → 256²: ${JSON.stringify(results)}`);
    for (const coarse of results.slice(1)) expect(coarse.worstRelative).toBeLessThan(1e-5); // (measured: identical)
    // The finest cascade's lost ripples: under a millimetre RMS (measured 0.5 mm of its 12 mm), far
    // under 1 % of the sea's RMS height, heightAt's tolerance against the drawn surface.
    expect(results[0].heightErrorRms).toBeLessThan(1e-3);
    expect(results[0].heightErrorRms).toBeLessThan(0.01 * results[2].heightRms);
    expect(results[0].heightErrorRms).toBeGreaterThan(0); // it does drop waves
  });
});
