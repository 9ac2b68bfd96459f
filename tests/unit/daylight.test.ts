import { describe, expect, it } from 'vitest';
import { skyDaylight, sunAboveHorizon } from '../../src/render/daylight';

describe('daylight as the sun sets', () => {
  it('follows the clear-sky twilight illuminance: ~400 lx at sunset, 3.4 lx at −6° (AMS Glossary of Meteorology, "civil twilight")', () => {
    expect(skyDaylight(30)).toBe(1);
    expect(skyDaylight(0)).toBe(1);
    expect(skyDaylight(-6)).toBeCloseTo(3.4 / 400, 6);
    expect(skyDaylight(-3)).toBeCloseTo(Math.sqrt(3.4 / 400), 6); // log-linear through twilight
  });

  it('never goes below the clear moonless night: 0.002 lx of airglow and starlight (Schlyter)', () => {
    expect(skyDaylight(-15)).toBeGreaterThan(0.002 / 400);
    expect(skyDaylight(-20)).toBe(0.002 / 400);
    expect(skyDaylight(-90)).toBe(0.002 / 400);
  });

  it('falls monotonically', () => {
    const elevations = Array.from({ length: 181 }, (_, i) => 90 - i);
    const values = elevations.map(skyDaylight);
    for (let i = 1; i < values.length; i++) expect(values[i]).toBeLessThanOrEqual(values[i - 1]);
  });

  it('counts the part of the sun disk (0.4° radius) above the horizon as its direct light', () => {
    expect(sunAboveHorizon(0.4)).toBe(1);
    expect(sunAboveHorizon(0)).toBe(0.5);
    expect(sunAboveHorizon(-0.4)).toBe(0);
    expect(sunAboveHorizon(-10)).toBe(0);
  });
});
