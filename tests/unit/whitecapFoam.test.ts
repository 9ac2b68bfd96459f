/**
 * The whitecap foam model (src/layers/foamModel.ts) in JS, the path the GPU pass is compared with
 * in the browser (tests/browser/simulation/simulation.spec.ts): its coverage against Monahan &
 * O'Muircheartaigh's law, none in a calm, its decay, frame-rate independence and determinism.
 */
import { describe, expect, it } from 'vitest';
import {
  calibrateFoam,
  CpuFoamField,
  erfc,
  foamSchedule,
  foldingDegree,
  jacobianCovariance,
  nearestTexels,
  NO_FOAM,
  WARM_UP_STEPS,
  whitecapFraction,
} from '../../src/layers/foamModel';
import { validateParameters } from '../../src/parameters/parameters';
import { createCascadeSpectra } from '../../src/spectrum/initialSpectrum';
import type { WebGLRenderer } from 'three';
import { OceanSimulation } from '../../src/layers/oceanSimulation';
import { beaufortPreset } from '../../src/spectrum/presets';
import { mean, seaWithFoam } from './seaWithFoam';


/**
 * Monahan & O'Muircheartaigh (1980), J. Phys. Oceanogr. 10:2094–2099, eq. 5: whitecap fraction
 * W(U10) (the law checks are in whitecapCoverage.test.ts).
 */
const monahan = (windSpeed: number) => 3.84e-6 * windSpeed ** 3.41;

describe('whitecap foam in a calm and without folds', () => {
  it('is none in a calm: Beaufort 0 to 2 make no foam at all (WMO: crests do not break below force 3)', () => {
    for (const force of [0, 1, 2]) {
      const sea = seaWithFoam({ ...beaufortPreset(force), resolution: 64 });
      sea.advance(20);
      sea.advance(20.5);
      expect(sea.foam.coverage.every((v) => v === 0), `force ${force}`).toBe(true);
    }
    // The onset rule: W = 0 up to 3.3 m/s (the top of force 2), Monahan's law above.
    expect(whitecapFraction(3.3)).toBe(0);
    expect(whitecapFraction(3.4)).toBeCloseTo(monahan(3.4), 12);
    const covariance = jacobianCovariance(createCascadeSpectra(validateParameters({ windSpeed: 3.3, resolution: 64 })));
    expect(calibrateFoam(covariance, 1, 3.3)).toEqual(NO_FOAM);
    expect(calibrateFoam(covariance, 1, 3.4).foamPerFolding).toBeGreaterThan(0);
  });

  it('is none with foamAmount 0 or choppiness 0 (no fold without horizontal displacement)', () => {
    for (const changes of [{ foamAmount: 0 }, { choppiness: 0 }]) {
      const sea = seaWithFoam({ windSpeed: 20, resolution: 64, ...changes });
      sea.advance(10);
      expect(Math.max(...sea.foam.coverage), JSON.stringify(changes)).toBe(0);
    }
  });
});

describe('the foam model', () => {
  it('makes foam only below J_START and at the full rate from J_FULL down', () => {
    const [start, full] = [0.6, 0.1];
    expect(foldingDegree(start, start, full)).toBe(0);
    expect(foldingDegree(1, start, full)).toBe(0);
    expect(foldingDegree(full, start, full)).toBe(1);
    expect(foldingDegree(-3, start, full)).toBe(1);
    expect(foldingDegree((start + full) / 2, start, full)).toBeCloseTo(0.5, 12);
  });

  it('decays as e^(−t/τ) where no new foam is made', () => {
    const field = new CpuFoamField(100, 4);
    field.coverage.fill(0.8);
    const flat = { fields: { displacement: new Float32Array(64), derivatives: new Float32Array(64) }, size: 100, resolution: 4 };
    for (let k = 0; k < 30; k++) field.step([flat], 1, { jacobianStart: 0.5, jacobianFull: 0, foamPerFolding: 180 }, 60, 3, 0.1);
    // 3 s at τ = 3 s: e^{−1}.
    for (const v of field.coverage) expect(v).toBeCloseTo(0.8 * Math.exp(-1), 6);
  });

  it('computes erfc to 1.2e-7 (Abramowitz & Stegun 1964, Table 7.1: erf 0.5, 1, 2)', () => {
    expect(erfc(0)).toBeCloseTo(1, 7);
    expect(erfc(0.5)).toBeCloseTo(1 - 0.5204998778, 7);
    expect(erfc(1)).toBeCloseTo(1 - 0.8427007929, 7);
    expect(erfc(2)).toBeCloseTo(1 - 0.9953222650, 7);
    expect(erfc(-1)).toBeCloseTo(1 + 0.8427007929, 7);
  });

  it('makes no foam without choppiness or without slopes, and calibrates J_START, J_FULL and R·τ by the wind', () => {
    const zero = { aa: 0, bb: 0, cc: 0, ab: 0, ac: 0, bc: 0 };
    expect(calibrateFoam(zero, 1, 20)).toEqual(NO_FOAM);
    const covariance = jacobianCovariance(createCascadeSpectra(validateParameters({ windSpeed: 12, resolution: 64 })));
    expect(calibrateFoam(covariance, 0, 20)).toEqual(NO_FOAM);
    const [gentle, strong] = [calibrateFoam(covariance, 1, 6), calibrateFoam(covariance, 1, 20)];
    // More whitecaps on the same slopes: a threshold nearer 1 (more of the surface makes foam).
    expect(strong.jacobianStart).toBeGreaterThan(gentle.jacobianStart);
    for (const c of [gentle, strong]) {
      expect(c.jacobianFull).toBeLessThan(c.jacobianStart);
      expect(c.jacobianStart).toBeLessThan(1);
      expect(c.foamPerFolding).toBeGreaterThan(0);
    }
  });

  it('is calibrated once per sea, choppiness and wind by OceanSimulation (JS path), not per frame', () => {
    // A stand-in renderer: the JS path without workers or local waves asks it only for extensions
    // (and createGpuDevice checks three's flag for a WebGLRenderer).
    const renderer = { isWebGLRenderer: true, extensions: { has: () => false } } as unknown as WebGLRenderer;
    const simulation = new OceanSimulation(renderer, { windSpeed: 12, resolution: 64 }, { path: 'js', worker: false, localWaves: false });
    const first = simulation.foamCalibration;
    expect(first).toEqual(calibrateFoam(jacobianCovariance(simulation.spectra), 1, 12));
    simulation.update(20);
    simulation.update(20.1);
    expect(simulation.foamCalibration).toBe(first);
    expect(mean(simulation.foam.coverageOnCpu())).toBeGreaterThan(0);
    simulation.setParameters({ choppiness: 1.2 });
    const steeper = simulation.foamCalibration;
    expect(steeper).not.toBe(first);
    simulation.pathPreference = 'js'; // a rebuild with the same spectra
    expect(simulation.foamCalibration).toBe(steeper);
    simulation.setParameters({ windSpeed: 3 });
    expect(simulation.foamCalibration).toEqual(NO_FOAM);
    simulation.dispose();
  });

  it('picks each cascade’s nearest texel in float32 arithmetic, wrapping at the patch', () => {
    // Foam texels of 457/256 m over a cascade of 79.3 m at N = 256: texel i is at i·457/256 m.
    const texels = nearestTexels(457, 256, 79.3, 256);
    for (let i = 0; i < 256; i++) {
      const exact = ((i * 457) / 256 / 79.3) * 256;
      const nearest = Math.round(exact) % 256;
      // The same as exact rounding except within float32 rounding of a half.
      if (Math.abs((exact % 1) - 0.5) > 1e-4) expect(texels[i]).toBe(nearest);
    }
    expect(nearestTexels(457, 256, 457, 256)).toEqual(Int32Array.from({ length: 256 }, (_, i) => i));
  });

  it('goes on from its state for a step up to 3τ, and warms up afresh otherwise', () => {
    expect(foamSchedule(10, 10.1, 3)).toEqual({ clear: false, steps: [{ time: 10.1, dt: expect.closeTo(0.1, 12) }] });
    expect(foamSchedule(10, 10, 3)).toEqual({ clear: false, steps: [] });
    for (const [last, t] of [[NaN, 5], [10, 9.9], [10, 19.1]]) {
      const { clear, steps } = foamSchedule(last, t, 3);
      expect(clear).toBe(true);
      expect(steps).toHaveLength(WARM_UP_STEPS);
      expect(steps[steps.length - 1].time).toBe(t);
      expect(t - steps[0].time + steps[0].dt).toBeCloseTo(9, 12);
    }
  });

  it('is deterministic: the foam at t after any jump is the same, whatever came before', () => {
    const first = seaWithFoam({ windSpeed: 15, resolution: 64 });
    first.advance(40);
    const second = seaWithFoam({ windSpeed: 15, resolution: 64 });
    second.advance(3);
    second.advance(4);
    second.advance(40);
    expect(mean(first.foam.coverage)).toBeGreaterThan(0);
    expect(second.foam.coverage).toEqual(first.foam.coverage);
  });

  it('does not depend on the frame rate: 1 s at 30 fps and at 60 fps agree', () => {
    const at = (fps: number) => {
      const sea = seaWithFoam({ windSpeed: 15, resolution: 128 });
      sea.advance(30);
      for (let k = 1; k <= fps; k++) sea.advance(30 + k / fps);
      return sea.foam.coverage;
    };
    const [slow, fast] = [at(30), at(60)];
    const coverage = [mean(slow), mean(fast)];
    const difference = mean(slow.map((v, i) => Math.abs(v - fast[i])));
    console.log(`foam after 1 s at 30 and 60 fps: mean coverage ${coverage.map((c) => (100 * c).toFixed(3)).join(' % and ')} %, mean |difference| ${(100 * difference).toFixed(3)} %`);
    // Tolerance: mean coverage within 5 %, the texel-wise difference under 10 % of the coverage.
    expect(Math.abs(coverage[0] / coverage[1] - 1)).toBeLessThan(0.05);
    expect(difference / coverage[1]).toBeLessThan(0.1);
  });
});
