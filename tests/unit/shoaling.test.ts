/**
 * Shores (src/spectrum/shoaling.ts, src/layers/seabed.ts, src/layers/shore.ts and the queries of
 * src/layers/surfaceQuery.ts over them), against linear wave theory and McCowan's limit:
 *
 *   (a) The shoaling coefficient of a deep-water wave, Ks = [tanh(kh)·(1 + 2kh/sinh 2kh)]^(−1/2) at
 *       the wave's own k in depth h (Dean & Dalrymple 1991, "Water Wave Mechanics for Engineers and
 *       Scientists", eq. 4.83; Coastal Engineering Manual II-3, eq. II-3-3), written out here with
 *       the dispersion relation solved by bisection: it falls to its minimum 0.913 near
 *       h/L0 = 0.15 (the CEM's Figure II-3-1 and Dean & Dalrymple's Table) and follows Green's law
 *       Ks → (4·k0·h)^(−1/4) in shallow water (k0 = ω²/g).
 *   (b) The cascade tables F_c(d) against the energy-weighted sum over every mode.
 *   (c) On a 1:50 plane beach under the default sea, the RMS of heightAt over time at depths of 40,
 *       15 and 8 m is √(Σ_k |h̃0(k)|²·Ks(k, d)²) (energy flux conserved mode by mode; (a)'s Ks)
 *       within 15 %; crest to trough never exceeds 0.78·d where d ≤ 3 m (McCowan 1894, "On the
 *       highest wave of permanent type", Phil. Mag. 38; CEM II-4-3 eq. II-4-4); with the seabed
 *       elsewhere every query is bit-identical to the one without a seabed.
 *   (d) Bad seabeds: a ParameterError naming what is wrong, nothing NaN kept.
 */
import { describe, expect, it } from 'vitest';
import { CpuWaveFields } from '../../src/fft/cpuWaveFields';
import { createSeabedMap, type Seabed } from '../../src/layers/seabed';
import { Shore } from '../../src/layers/shore';
import { heightAt, normalAt, velocityAt } from '../../src/layers/surfaceQuery';
import type { WaveLayer } from '../../src/layers/waveLayer';
import { ParameterError } from '../../src/parameters/options';
import { validateParameters } from '../../src/parameters/parameters';
import { createCascadeSpectra, type InitialSpectrum } from '../../src/spectrum/initialSpectrum';
import { spectralMoments } from '../../src/spectrum/seaState';
import { runup2, swashLength, swashScale } from '../../src/spectrum/swash';
import {
  breakingHeight,
  breakingSlope,
  cascadeShoalingRow,
  SHOALING_DEPTHS,
  shoalingCoefficient,
  shoalingDepths,
  shoalingFactor,
} from '../../src/spectrum/shoaling';

const G = 9.81;

/** k of frequency ω in depth h: ω² = g·k·tanh(kh), by bisection (independent of seaState.ts's Newton steps). */
function waveNumber(omega: number, h: number): number {
  let low = (omega * omega) / G; // deep water's k is the smallest
  let high = Math.max(low, omega / Math.sqrt(G * h)) * 2; // above the shallow-water k
  for (let i = 0; i < 200; i++) {
    const mid = 0.5 * (low + high);
    if (G * mid * Math.tanh(mid * h) < omega * omega) low = mid;
    else high = mid;
  }
  return 0.5 * (low + high);
}

/** Dean & Dalrymple 1991 eq. 4.83: Ks of a deep-water wave of wave number k0 in depth h. */
function deepWaterKs(k0: number, h: number): number {
  const kh = waveNumber(Math.sqrt(G * k0), h) * h;
  return 1 / Math.sqrt(Math.tanh(kh) * (1 + (2 * kh) / Math.sinh(2 * kh)));
}

describe('(a) the shoaling coefficient', () => {
  it('dips to 0.913 near h/L0 = 0.15 and follows Green’s law in shallow water', () => {
    const k0 = (2 * Math.PI) / 100; // L0 = 100 m
    let least = Infinity;
    let leastAt = 0;
    for (let ratio = 0.01; ratio < 0.6; ratio += 0.0005) {
      const ks = shoalingCoefficient(k0, ratio * 100, Infinity);
      expect(Math.abs(ks - deepWaterKs(k0, ratio * 100))).toBeLessThan(1e-9);
      if (ks < least) [least, leastAt] = [ks, ratio];
    }
    console.log(`Ks minimum ${least.toFixed(4)} at h/L0 = ${leastAt.toFixed(3)}`);
    expect(least).toBeCloseTo(0.913, 3);
    expect(Math.abs(leastAt - 0.15)).toBeLessThan(0.01);
    // Green's law, h/L0 = 0.0005: Ks = (4·k0·h)^(−1/4) within 1 %.
    expect(shoalingCoefficient(k0, 0.05, Infinity) / (4 * k0 * 0.05) ** -0.25).toBeCloseTo(1, 2);
    // Deep enough, no change; a finite reference depth is its own Ks = 1.
    expect(shoalingCoefficient(k0, 100, Infinity)).toBeCloseTo(1, 4);
    expect(shoalingCoefficient(k0, 20, 20)).toBe(1);
  });
});

const parameters = validateParameters({ resolution: 64 });
const spectra = createCascadeSpectra(parameters);
/** The sea's peak period Tp (s), from its spectrum's moments: the swash's scale L0 = g·Tp²/(2π). */
const peakPeriod = (2 * Math.PI) / spectralMoments(parameters, parameters.patchSizes[parameters.patchSizes.length - 1]).peakFrequency;

/** Σ over a cascade's modes of |h̃0|² (both halves of each texel) × g(|k|). */
function modeSum(s: InitialSpectrum, g: (k: number) => number): number {
  const n = s.resolution;
  const dk = (2 * Math.PI) / s.patchSize;
  let sum = 0;
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      const at = 4 * (j * n + i);
      const w = s.amplitudes[at] ** 2 + s.amplitudes[at + 1] ** 2 + s.amplitudes[at + 2] ** 2 + s.amplitudes[at + 3] ** 2;
      if (w === 0) continue;
      const k = dk * Math.hypot(i < n / 2 ? i : i - n, j < n / 2 ? j : j - n);
      sum += w * g(k);
    }
  }
  return sum;
}

describe('(b) the cascade tables', () => {
  it('give each cascade’s energy-weighted Ks within 0.3 % at every tabulated depth', () => {
    const depths = shoalingDepths(457, Infinity);
    const row = new Float32Array(SHOALING_DEPTHS);
    for (const s of spectra) {
      cascadeShoalingRow(s, depths, Infinity, row, 0);
      const total = modeSum(s, () => 1);
      for (const d of [0.05, 0.3, 1, 3, 8, 15, 40, 120]) {
        const exact = Math.sqrt(modeSum(s, (k) => deepWaterKs(k, d) ** 2) / total);
        expect(Math.abs(shoalingFactor(row, 0, depths, d) / exact - 1)).toBeLessThan(0.003);
      }
      expect(shoalingFactor(row, 0, depths, 457)).toBe(1);
    }
  });

  it('limit the height to ±0.39·d smoothly, and are the identity below the knee', () => {
    for (const d of [0.1, 1, 3]) {
      for (let h = -2; h <= 2; h += 0.001) {
        const limited = breakingHeight(h, d);
        expect(Math.abs(limited)).toBeLessThan(0.39 * d + 1e-12);
        const slope = (breakingHeight(h + 1e-6, d) - breakingHeight(h - 1e-6, d)) / 2e-6;
        expect(Math.abs(slope - breakingSlope(h, d))).toBeLessThan(1e-4);
        if (Math.abs(h) < 0.7 * 0.39 * d) expect(limited).toBe(h);
      }
    }
    expect(breakingHeight(1, -2)).toBe(-0.3); // over land, under the ground
  });
});

/** A cascade as a wave layer, its fields computed on the CPU at the time asked. */
function cascadeLayer(spectrum: InitialSpectrum): WaveLayer & { spectrum: InitialSpectrum } {
  const fields = new CpuWaveFields(spectrum);
  let time = NaN;
  const at = (t: number) => {
    if (t !== time) fields.update(t);
    time = t;
    return fields.forQueries(t);
  };
  return {
    spectrum,
    textures: { displacement: { value: null }, derivatives: { value: null } },
    frame: { size: spectrum.patchSize, origin: [0, 0], periodic: true, resolution: spectrum.resolution },
    movesSideways: true,
    update: () => {},
    queryFields: at,
    fieldsOnCpu: at,
    shownFieldsOnCpu: () => null,
    dispose: () => {},
  };
}

const SLOPE = 1 / 50;
const beach: Seabed = { depthAt: (x) => x * SLOPE, bounds: [-100, -1000, 2500, 1000] };

describe('(c) the queries over a 1:50 beach', () => {
  const layers = spectra.map(cascadeLayer);
  const shore = new Shore();
  shore.setMap(createSeabedMap(beach, null));
  const deepRms = Math.sqrt(spectra.reduce((sum, s) => sum + modeSum(s, () => 1), 0));
  shore.prepare(layers, layers, Infinity, 4 * deepRms, peakPeriod);

  it('follow linear shoaling of the spectrum: the RMS height at 40, 15 and 8 m within 15 %', () => {
    const depths = [40, 15, 8];
    const points = 12;
    const times = 160;
    const sums = depths.map(() => 0);
    for (let step = 0; step < times; step++) {
      const t = 1.7 * step;
      depths.forEach((d, i) => {
        for (let p = 0; p < points; p++) sums[i] += heightAt(layers, parameters.choppiness, t, d / SLOPE, -400 + 67 * p, shore) ** 2;
      });
    }
    depths.forEach((d, i) => {
      const measured = Math.sqrt(sums[i] / (points * times));
      const expected = Math.sqrt(spectra.reduce((sum, s) => sum + modeSum(s, (k) => deepWaterKs(k, d) ** 2), 0));
      console.log(`d = ${d} m: RMS ${measured.toFixed(3)} m, linear shoaling ${expected.toFixed(3)} m (deep ${deepRms.toFixed(3)} m), ratio ${(measured / expected).toFixed(3)}`);
      expect(Math.abs(measured / expected - 1)).toBeLessThan(0.15);
    });
  });

  // Shallower than SWASH_END·S (1.11 m for this sea) the swash level moves the water too (e).
  it('never let crest to trough exceed 0.78·d where 1.5·S < d ≤ 3 m', () => {
    expect(1.5 * swashScale(swashLength(4 * deepRms, peakPeriod), SLOPE).swash).toBeLessThan(1.5);
    for (const d of [1.5, 2, 3]) {
      let highest = -Infinity;
      let lowest = Infinity;
      for (let step = 0; step < 200; step++) {
        const h = heightAt(layers, parameters.choppiness, 0.9 * step, d / SLOPE, 35, shore);
        highest = Math.max(highest, h);
        lowest = Math.min(lowest, h);
      }
      console.log(`d = ${d} m: crest to trough ${(highest - lowest).toFixed(3)} m, McCowan 0.78·d = ${(0.78 * d).toFixed(3)} m`);
      // d as the depth map holds it (float32 depths: within 1e-6 m of the beach's).
      const mapped = shore.depthAt(d / SLOPE, 35);
      expect(Math.abs(mapped - d)).toBeLessThan(1e-6);
      expect(highest - lowest).toBeLessThanOrEqual(0.78 * mapped);
      expect(highest - lowest).toBeGreaterThan(0.3 * d); // the waves do reach the shallows
    }
  });

  // In the swash zone the waves ride on the swash level ζ (e), so McCowan's limit holds for the water
  // column d + ζ under them: about ζ, the crest and the trough each stay within 0.39·(d + ζ).
  it('never let the waves about the swash level exceed 0.78·(d + ζ) crest to trough where d ≤ 1 m', () => {
    let swash = 0;
    let depth = 0;
    const watched = {
      depthAt: (x: number, z: number) => (depth = shore.depthAt(x, z)),
      layerFactor: (layer: number, d: number) => shore.layerFactor(layer, d),
      swashLevel: (deepHeight: number, x: number, z: number, d: number) => (swash = shore.swashLevel(deepHeight, x, z, d)),
    };
    for (const d of [0.5, 1]) {
      let worst = 0;
      let wet = 0;
      for (let step = 0; step < 200; step++) {
        const h = heightAt(layers, parameters.choppiness, 0.9 * step, d / SLOPE, 35, watched);
        const column = depth + swash;
        if (column <= 0) continue; // the swash has left the point dry: no waves to limit
        wet++;
        worst = Math.max(worst, Math.abs(h - swash) / (0.39 * column));
      }
      console.log(`d = ${d} m: ${wet} of 200 instants wet, the waves about ζ at most ${worst.toFixed(3)} of 0.39·(d + ζ)`);
      expect(wet).toBeGreaterThan(100);
      expect(worst).toBeLessThanOrEqual(1 + 1e-9);
      expect(worst).toBeGreaterThan(0.5); // the waves do reach the limit's order here
    }
  });

  it('are bit-identical to those without a seabed where the seabed is not', () => {
    const elsewhere = new Shore();
    elsewhere.setMap(createSeabedMap({ depthAt: () => 2, bounds: [1e5, 1e5, 1e5 + 10, 1e5 + 10] }, null));
    elsewhere.prepare(layers, layers, Infinity, 4 * deepRms, peakPeriod);
    const a = { x: 0, y: 0, z: 0 };
    const b = { x: 0, y: 0, z: 0 };
    for (let p = 0; p < 20; p++) {
      const [x, z, t] = [37.1 * p - 300, 11.3 * p, 0.37 * p];
      expect(heightAt(layers, parameters.choppiness, t, x, z, elsewhere)).toBe(heightAt(layers, parameters.choppiness, t, x, z));
      expect(normalAt(layers, parameters.choppiness, t, x, z, a, elsewhere)).toEqual(normalAt(layers, parameters.choppiness, t, x, z, b));
      expect(velocityAt(layers, parameters.choppiness, t, x, z, a, elsewhere)).toEqual(velocityAt(layers, parameters.choppiness, t, x, z, b));
    }
    elsewhere.dispose();
  });

  it('put the water under the ground over land beyond the swash', () => {
    // 3 m above the sea, beyond any runup of this sea (R2 ≈ 0.5 m): the water LAND_DROP under its level.
    for (let step = 0; step < 50; step++) expect(heightAt(layers, parameters.choppiness, 1.3 * step, -150, 0, shore)).toBeLessThan(1.5);
    expect(shore.depthAt(-50, 0)).toBeCloseTo(-1, 5);
    expect(shore.depthAt(1e4, 0)).toBe(Infinity);
  });
});

describe('(e) swash on the 1:50 beach', () => {
  const layers = spectra.map(cascadeLayer);
  const shore = new Shore();
  shore.setMap(createSeabedMap(beach, null));
  const deepRms = Math.sqrt(spectra.reduce((sum, s) => sum + modeSum(s, () => 1), 0));
  shore.prepare(layers, layers, Infinity, 4 * deepRms, peakPeriod);

  it('Stockdon et al. 2006 eq. 19, written out: R2 = 1.1·(0.35·β·√(H0·L0) + ½·√(H0·L0·(0.563·β² + 0.004)))', () => {
    // H0 = 2 m, Tp = 10 s: L0 = g·T²/(2π) = 156.13 m (Dean & Dalrymple eq. 3.35), √(H0·L0) = 17.671 m.
    const root = Math.sqrt(2 * ((9.81 * 100) / (2 * Math.PI)));
    expect(swashLength(2, 10)).toBeCloseTo(root, 9);
    for (const beta of [0.01, 0.02, 0.1]) {
      expect(runup2(root, beta)).toBeCloseTo(1.1 * (0.35 * beta * root + 0.5 * Math.sqrt(root * root * (0.563 * beta * beta + 0.004))), 9);
    }
    expect(runup2(root, 0.02)).toBeCloseTo(0.768, 3); // by hand: 1.1·(0.1237 + 0.5743)
    expect(swashLength(0, 10)).toBe(0); // no waves, no swash
  });

  it('moves the queried waterline up and down the beach by the swash Stockdon et al. predict (within 20 %)', () => {
    // Where the water meets the ground along a line across the beach at time t: the first place,
    // going out to sea, where heightAt is above the ground (−depth), by 0.5 m steps and bisection.
    const wet = (x: number, z: number, t: number) => heightAt(layers, parameters.choppiness, t, x, z, shore) > -shore.depthAt(x, z);
    const waterline = (z: number, t: number) => {
      let x = -80;
      while (!wet(x, z, t)) x += 0.5;
      let [dry, water] = [x - 0.5, x];
      for (let i = 0; i < 12; i++) {
        const mid = 0.5 * (dry + water);
        if (wet(mid, z, t)) water = mid;
        else dry = mid;
      }
      return 0.5 * (dry + water);
    };
    const elevations: number[] = [];
    for (let line = 0; line < 4; line++) {
      for (let step = 0; step < 100; step++) elevations.push(-SLOPE * waterline(-500 + 283 * line, 3.7 * step));
    }
    const mean = elevations.reduce((a, b) => a + b, 0) / elevations.length;
    const swash = 4 * Math.sqrt(elevations.reduce((a, b) => a + (b - mean) ** 2, 0) / elevations.length);
    const sorted = [...elevations].sort((a, b) => a - b);
    const exceeded = sorted[Math.floor(0.98 * sorted.length)];
    const length = swashLength(4 * deepRms, peakPeriod);
    const expected = swashScale(length, SLOPE);
    const r2 = runup2(length, SLOPE);
    console.log(
      `waterline elevation over ${elevations.length} instants: mean ${mean.toFixed(3)} m (setup ${expected.setup.toFixed(3)}), 4σ ${swash.toFixed(3)} m (S ${expected.swash.toFixed(3)}), ` +
        `2 % exceeded ${exceeded.toFixed(3)} m (R2 ${r2.toFixed(3)}), range ${sorted[0].toFixed(3)} to ${sorted[sorted.length - 1].toFixed(3)} m: ${((sorted[sorted.length - 1] - sorted[0]) / SLOPE).toFixed(1)} m along the beach`,
    );
    expect(Math.abs(swash / expected.swash - 1)).toBeLessThan(0.2);
    expect(Math.abs(exceeded / r2 - 1)).toBeLessThan(0.2);
    expect(Math.abs(mean - expected.setup)).toBeLessThan(0.1 * expected.swash);
  });
});

describe('(d) bad seabeds', () => {
  const cases: [string, unknown, string][] = [
    ['a depthAt that returns NaN', { depthAt: () => NaN, bounds: [0, 0, 10, 10] }, 'seabed.depthAt'],
    ['a depthAt that throws', { depthAt: () => { throw new Error('no'); }, bounds: [0, 0, 10, 10] }, 'seabed.depthAt'],
    ['bounds with no area', { depthAt: () => 1, bounds: [0, 0, 0, 10] }, 'seabed.bounds'],
    ['a heightfield of the wrong size', { depths: new Float32Array(10), width: 4, height: 4, bounds: [0, 0, 10, 10] }, 'seabed.depths'],
    ['a heightfield with NaN in it', { depths: [1, 2, NaN, 4], width: 2, height: 2, bounds: [0, 0, 10, 10] }, 'seabed.depths'],
    ['no kind of seabed', { bounds: [0, 0, 10, 10] }, 'seabed'],
  ];
  for (const [what, seabed, name] of cases) {
    it(`refuses ${what}, naming ${name}`, () => {
      let error: unknown;
      try {
        createSeabedMap(seabed as Seabed, null);
      } catch (e) {
        error = e;
      }
      expect(error).toBeInstanceOf(ParameterError);
      expect((error as ParameterError).parameter).toBe(name);
    });
  }

  it('reads a heightfield back exactly at its nodes and bilinearly between', () => {
    const map = createSeabedMap({ depths: [1, 2, 3, 4, 5, 6], width: 3, height: 2, bounds: [0, 0, 20, 10] }, null);
    expect(map.depthAt(10, 0, 99)).toBe(2);
    expect(map.depthAt(20, 10, 99)).toBe(6);
    expect(map.depthAt(5, 5, 99)).toBe(3);
    expect(map.depthAt(-1, 5, 99)).toBe(99);
    map.dispose();
  });
});
