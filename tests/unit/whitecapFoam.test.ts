/**
 * The whitecap foam model (src/layers/foamModel.ts) in JS, the path the GPU pass is compared with
 * in the browser (tests/browser/simulation/simulation.spec.ts): its coverage against Monahan &
 * O'Muircheartaigh's law, none in a calm, its decay, frame-rate independence and determinism.
 */
import { describe, expect, it } from 'vitest';
import { CpuWaveFields } from '../../src/fft/cpuWaveFields';
import { CpuFoamField, foamCreationRate, foamSchedule, foldingDegree, FOAM_J_FULL, FOAM_J_START, nearestTexels, WARM_UP_STEPS } from '../../src/layers/foamModel';
import { validateParameters, type SimulationParameters } from '../../src/parameters/parameters';
import { createCascadeSpectra } from '../../src/spectrum/initialSpectrum';
import { beaufortPreset } from '../../src/spectrum/presets';

/** The sea's cascades in JS and the foam over its largest patch, advanced as whitecapFoam.ts does. */
function seaWithFoam(parameters: Partial<SimulationParameters>) {
  const p = validateParameters(parameters);
  const spectra = createCascadeSpectra(p);
  const cascades = spectra.map((spectrum) => ({ fields: new CpuWaveFields(spectrum), size: spectrum.patchSize, resolution: spectrum.resolution }));
  const largest = spectra[spectra.length - 1];
  const foam = new CpuFoamField(largest.patchSize, largest.resolution);
  let lastTime = NaN;
  return {
    foam,
    advance(t: number): void {
      const { clear, steps } = foamSchedule(lastTime, t, p.foamPersistence);
      lastTime = t;
      if (clear) foam.clear();
      for (const { time, dt } of steps) {
        for (const cascade of cascades) cascade.fields.update(time);
        foam.step(cascades, p.choppiness, p.foamAmount * foamCreationRate(p.windSpeed), p.foamPersistence, dt);
      }
    },
  };
}

const mean = (values: Float32Array) => values.reduce((sum, v) => sum + v, 0) / values.length;

/** Monahan & O'Muircheartaigh (1980), "Optimal power-law description of oceanic whitecap coverage dependence on wind speed", J. Phys. Oceanogr. 10:2094–2099: whitecap fraction W(U10). */
const monahan = (windSpeed: number) => 3.84e-6 * windSpeed ** 3.41;

/** Mean coverage over 2 s after a warm-up to t = 20 s, sampled every 0.4 s with steps of 0.1 s. */
function measuredCoverage(parameters: Partial<SimulationParameters>): number {
  const sea = seaWithFoam(parameters);
  sea.advance(20);
  let sum = 0;
  for (let k = 1; k <= 20; k++) {
    sea.advance(20 + k * 0.1);
    if (k % 4 === 0) sum += mean(sea.foam.coverage);
  }
  return sum / 5;
}

describe('whitecap coverage against Monahan & O’Muircheartaigh (1980)', () => {
  it('is within a factor of 2 of W = 3.84e-6·U10^3.41 from 4 to 20 m/s, and grows with the wind', () => {
    const rows = [4, 6, 8, 10, 12, 15, 20].map((windSpeed) => {
      const coverage = measuredCoverage({ windSpeed });
      return { windSpeed, coverage, monahan: monahan(windSpeed), ratio: coverage / monahan(windSpeed) };
    });
    console.log(
      ['| U10 (m/s) | measured W (%) | Monahan W (%) | ratio |', '|---|---|---|---|']
        .concat(rows.map((r) => `| ${r.windSpeed} | ${(100 * r.coverage).toPrecision(3)} | ${(100 * r.monahan).toPrecision(3)} | ${r.ratio.toFixed(2)} |`))
        .join('\n'),
    );
    for (const row of rows) {
      expect(row.ratio, `U10 = ${row.windSpeed} m/s`).toBeGreaterThan(0.5);
      expect(row.ratio, `U10 = ${row.windSpeed} m/s`).toBeLessThan(2);
    }
    rows.slice(1).forEach((row, i) => expect(row.coverage).toBeGreaterThan(rows[i].coverage));
  }, 60_000);

  it('is none in a calm: Beaufort 0 to 2 make no foam at all (WMO: crests do not break below force 3)', () => {
    for (const force of [0, 1, 2]) {
      const sea = seaWithFoam({ ...beaufortPreset(force), resolution: 64 });
      sea.advance(20);
      sea.advance(20.5);
      expect(sea.foam.coverage.every((v) => v === 0), `force ${force}`).toBe(true);
    }
    expect(foamCreationRate(3.3)).toBe(0);
    expect(foamCreationRate(3.4)).toBeGreaterThan(0);
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
    expect(foldingDegree(FOAM_J_START)).toBe(0);
    expect(foldingDegree(1)).toBe(0);
    expect(foldingDegree(FOAM_J_FULL)).toBe(1);
    expect(foldingDegree(-3)).toBe(1);
    expect(foldingDegree((FOAM_J_START + FOAM_J_FULL) / 2)).toBeCloseTo(0.5, 12);
  });

  it('decays as e^(−t/τ) where no new foam is made', () => {
    const field = new CpuFoamField(100, 4);
    field.coverage.fill(0.8);
    const flat = { fields: { displacement: new Float32Array(64), derivatives: new Float32Array(64) }, size: 100, resolution: 4 };
    for (let k = 0; k < 30; k++) field.step([flat], 1, 60, 3, 0.1);
    // 3 s at τ = 3 s: e^{−1}.
    for (const v of field.coverage) expect(v).toBeCloseTo(0.8 * Math.exp(-1), 6);
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
