/**
 * Sea presets: the Beaufort forces against the WMO Beaufort table (WMO-No. 558: wind ranges in m/s
 * and the "probable wave height" in the open sea), and the named presets.
 */
import { describe, expect, it } from 'vitest';
import { BEAUFORT_WIND_RANGES, beaufortPreset, beaufortWindSpeed, presetCloudCover, SEA_PRESETS } from '../../src/spectrum/presets';
import { ParameterError, validateParameters } from '../../src/parameters/parameters';
import { seaState } from '../../src/spectrum/seaState';

/** WMO Beaufort table, probable wave height in m for forces 0–12 (force 0: flat calm). */
const WMO_PROBABLE_HEIGHT = [0, 0.1, 0.2, 0.6, 1, 2, 3, 4, 5.5, 7, 9, 11.5, 14];

const hs = (force: number) => seaState(beaufortPreset(force)).significantWaveHeight;

describe('Beaufort scale', () => {
  it('has the WMO ranges, contiguous to the 0.1 m/s they are given in, and their middles', () => {
    expect(BEAUFORT_WIND_RANGES[6]).toEqual([10.8, 13.8]);
    expect(BEAUFORT_WIND_RANGES[12][0]).toBe(32.7);
    for (let force = 1; force <= 12; force++) {
      const gap = BEAUFORT_WIND_RANGES[force][0] - BEAUFORT_WIND_RANGES[force - 1][1];
      expect(Math.abs(gap - 0.1)).toBeLessThan(1e-9);
    }
    expect(beaufortWindSpeed(0)).toBe(0.1);
    expect(beaufortWindSpeed(6)).toBeCloseTo(12.3, 12);
    expect(beaufortWindSpeed(12)).toBeCloseTo(34.75, 12);
    for (const bad of [-1, 13, 2.5, NaN]) expect(() => beaufortWindSpeed(bad)).toThrow(ParameterError); // the library's error type (docs/embedding.md, Errors)
    expect(() => beaufortPreset(13)).toThrow('Beaufort force must be an integer from 0 to 12; got 13');
  });

  it('grows Hs with every force, from ≈ 0 at force 0', () => {
    expect(hs(0)).toBeLessThan(0.001);
    for (let force = 1; force <= 12; force++) expect(hs(force)).toBeGreaterThan(hs(force - 1));
  });

  it('is within a factor 2 of the WMO probable wave height for forces 2–12', () => {
    for (let force = 2; force <= 12; force++) {
      const ratio = hs(force) / WMO_PROBABLE_HEIGHT[force];
      // Observed: 0.87 (force 2) to 1.75 (force 7).
      expect(ratio, `force ${force}: Hs ${hs(force)} m`).toBeGreaterThan(0.5);
      expect(ratio, `force ${force}: Hs ${hs(force)} m`).toBeLessThan(2);
    }
  });

  it('gives a few centimetres at force 1, below the table’s 0.1 m (its smallest unit: ripples)', () => {
    // A fully developed sea at 0.9 m/s has Hs = 0.21·(1.026·0.9)²/9.81 = 1.8 cm (Stewart 2008, eq.
    // 16.33); JONSWAP's larger α and γ make it 2.3 cm. The table rounds ripples up to 0.1 m.
    expect(hs(1)).toBeGreaterThan(0.01);
    expect(hs(1)).toBeLessThan(0.1);
  });
});

describe('named presets', () => {
  const result = (name: string) => seaState(SEA_PRESETS[name]);

  it('are valid sea states', () => {
    for (const [name, preset] of Object.entries(SEA_PRESETS)) {
      // Whole sea states with their patch sizes: valid simulation parameters.
      expect(() => validateParameters(preset), name).not.toThrow();
      const { significantWaveHeight, peakPeriod } = seaState(preset);
      expect(significantWaveHeight > 0 && Number.isFinite(significantWaveHeight), name).toBe(true);
      expect(peakPeriod > 0 && Number.isFinite(peakPeriod), name).toBe(true);
    }
  });

  it('order calm < breeze < storm in height and period', () => {
    expect(result('calm').significantWaveHeight).toBeLessThan(result('breeze').significantWaveHeight);
    expect(result('breeze').significantWaveHeight).toBeLessThan(result('storm').significantWaveHeight);
    expect(result('calm').peakPeriod).toBeLessThan(result('breeze').peakPeriod);
    expect(result('breeze').peakPeriod).toBeLessThan(result('storm').peakPeriod);
  });

  it('long swell: its 14 s swell sets the peak period, its Hs is about the swell’s 2.5 m', () => {
    const { significantWaveHeight, peakPeriod } = result('long swell');
    expect(Math.abs(peakPeriod - 14)).toBeLessThan(0.01);
    // Variances add: √(2.5² + wind sea²), the light wind sea adds a few percent.
    expect(significantWaveHeight).toBeGreaterThan(2.5);
    expect(significantWaveHeight).toBeLessThan(2.6);
  });

  it('shallow bay: TMA at 5 m gives less than the same wind and fetch in deep water', () => {
    const bay = SEA_PRESETS['shallow bay'];
    expect(bay.spectrum).toBe('tma');
    expect(result('shallow bay').significantWaveHeight).toBeLessThan(
      seaState({ ...bay, spectrum: 'jonswap', depth: Infinity }).significantWaveHeight,
    );
  });
});

describe('the sky a preset goes with (presetCloudCover)', () => {
  it('is overcast from Beaufort force 8 (a gale, 17.2 m/s and up) and on the storm preset, clear below', () => {
    const covers = Array.from({ length: 13 }, (_, force) => presetCloudCover(beaufortPreset(force)));
    expect(covers).toEqual([0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1]);
    expect(presetCloudCover(SEA_PRESETS.storm)).toBeGreaterThanOrEqual(0.8);
    for (const name of ['calm', 'breeze', 'long swell', 'shallow bay']) expect(presetCloudCover(SEA_PRESETS[name]), name).toBe(0);
    // At the edge: the lowest force-8 wind is overcast, the highest force-7 wind is not.
    expect(presetCloudCover({ windSpeed: 17.2 })).toBe(1);
    expect(presetCloudCover({ windSpeed: 17.1 })).toBe(0);
  });
});
