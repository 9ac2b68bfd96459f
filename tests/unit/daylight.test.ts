import { describe, expect, it } from 'vitest';
import { cloudSunTransmittance, overcastLuminance, overcastZenithLuminance, skyDaylight, sunAboveHorizon } from '../../src/render/daylight';

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

describe('cloud cover', () => {
  it('the overcast sky is three times brighter at the zenith than at the horizon, the same in every azimuth (Moon & Spencer 1942, CIE sky type 16)', () => {
    expect(overcastLuminance(1) / overcastLuminance(0)).toBeCloseTo(3, 12);
    expect(overcastLuminance(1)).toBe(1);
    // L(θ)/L_z = (1 + 2 cos θ)/3: at 60° from the zenith (30° up), 2/3; below the horizon, the horizon's.
    expect(overcastLuminance(0.5)).toBeCloseTo(2 / 3, 12);
    expect(overcastLuminance(-0.3)).toBe(overcastLuminance(0));
  });

  it('the overcast zenith luminance is Krochmann & Seidl’s 123 + 8600·sin h cd/m² over 128 klx', () => {
    expect(overcastZenithLuminance(30)).toBeCloseTo((123 + 4300) / 128000, 12);
    expect(overcastZenithLuminance(90)).toBeCloseTo(8723 / 128000, 12);
    expect(overcastZenithLuminance(-5)).toBe(123 / 128000); // the twilight of skyDaylight dims it further
  });

  it('the direct sun under c = N/8 oktas is Kasten & Czeplak’s (1 − 0.75·c^3.4)·(1 − c²): all of it clear, none overcast', () => {
    expect(cloudSunTransmittance(0)).toBe(1);
    expect(cloudSunTransmittance(1)).toBe(0);
    // 4 oktas: G = 0.92895·G(0) (1 − 0.75·0.5^3.4), D/G = 0.475, so B = 0.9293·0.525·G(0) against the clear 0.7·G(0).
    expect(cloudSunTransmittance(0.5)).toBeCloseTo((0.92895 * 0.525) / 0.7, 4);
    const values = Array.from({ length: 101 }, (_, i) => cloudSunTransmittance(i / 100));
    values.slice(1).forEach((value, i) => expect(value).toBeLessThan(values[i]));
  });
});
