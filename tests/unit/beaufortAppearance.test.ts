/**
 * The streaks' and the spray's ramps (src/render/beaufortAppearance.ts) against the WMO Beaufort
 * scale's descriptions (WMO-No. 306; the Met Office's table): no streaks below force 7 ("foam …
 * begins to be blown in streaks"), all foam streaked from force 10 ("the surface of the sea takes
 * on a white appearance"), no spray below force 9 ("spray may affect visibility"), and the
 * visibility the meteorological optical range gives (WMO-No. 8: contrast 5 % at V, β = ln 20 / V).
 */
import { describe, expect, it } from 'vitest';
import { beaufortAppearance, sprayVisibility, SPRAY_VISIBILITY_AT_FORCE_12, STREAK_ELONGATION } from '../../src/render/beaufortAppearance';
import { BEAUFORT_WIND_RANGES, beaufortWindSpeed } from '../../src/spectrum/presets';

describe('Beaufort appearance', () => {
  it('streaks foam from the bottom of force 7, all of it from force 10, along the wind', () => {
    for (let force = 0; force <= 6; force++) {
      const look = beaufortAppearance(beaufortWindSpeed(force), 30);
      expect(look.streakShare).toBe(0);
      expect(look.streakElongation).toBe(1); // the pattern is the isotropic one
    }
    expect(beaufortAppearance(BEAUFORT_WIND_RANGES[6][1], 0).streakShare).toBe(0);
    expect(beaufortAppearance(beaufortWindSpeed(7), 0).streakShare).toBeGreaterThan(0);
    const shares = [7, 8, 9, 10].map((force) => beaufortAppearance(beaufortWindSpeed(force), 0).streakShare);
    for (let i = 1; i < shares.length; i++) expect(shares[i]).toBeGreaterThan(shares[i - 1]);
    expect(beaufortAppearance(BEAUFORT_WIND_RANGES[10][0], 0).streakShare).toBe(1);
    expect(beaufortAppearance(beaufortWindSpeed(12), 0).streakElongation).toBe(STREAK_ELONGATION);
    const [x, z] = beaufortAppearance(20, 90).windAlong; // towards +z
    expect(x).toBeCloseTo(0, 12);
    expect(z).toBeCloseTo(1, 12);
  });

  it('has spray from force 9 only, and its visibility falls through forces 9–12', () => {
    for (let force = 0; force <= 8; force++) {
      expect(beaufortAppearance(beaufortWindSpeed(force), 0).sprayExtinction).toBe(0);
      expect(sprayVisibility(beaufortWindSpeed(force))).toBe(Infinity);
    }
    const visibility = [9, 10, 11, 12].map((force) => sprayVisibility(beaufortWindSpeed(force)));
    console.log(`spray visibility, forces 9–12: ${visibility.map((v) => `${(v / 1000).toFixed(2)} km`).join(', ')}`);
    for (let i = 1; i < visibility.length; i++) expect(visibility[i]).toBeLessThan(visibility[i - 1]);
    expect(visibility[0]).toBeGreaterThan(10_000); // force 9: "may affect"
    expect(visibility[1]).toBeLessThan(10_000); // force 10: "visibility affected"
    expect(sprayVisibility(BEAUFORT_WIND_RANGES[12][0])).toBeCloseTo(SPRAY_VISIBILITY_AT_FORCE_12, 9);
    // MOR: at V the spray leaves 5 % of the contrast.
    const { sprayExtinction } = beaufortAppearance(beaufortWindSpeed(11), 0);
    expect(Math.exp(-sprayExtinction * visibility[2])).toBeCloseTo(0.05, 12);
  });
});
