/**
 * The sun by direction: sunAnglesFromDirection is the inverse of sunDirectionFromAngles (elevation
 * above the horizon, azimuth from +x towards +z, y up), for any length of the vector; a zero,
 * non-finite or malformed direction is a ParameterError naming it.
 */
import { Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { ParameterError } from '../../src/parameters/options';
import { sunAnglesFromDirection, sunDirectionFromAngles, type SunDirection } from '../../src/render/skyEnvironment';

describe('sunAnglesFromDirection', () => {
  it('round-trips sunDirectionFromAngles over elevations and azimuths (azimuth in (-180, 180])', () => {
    for (let elevation = -89; elevation <= 89; elevation += 7.25) {
      for (let azimuth = -179; azimuth <= 180; azimuth += 11.5) {
        const direction = sunDirectionFromAngles(elevation, azimuth);
        const angles = sunAnglesFromDirection(direction);
        expect(angles.elevation).toBeCloseTo(elevation, 10);
        expect(angles.azimuth).toBeCloseTo(azimuth, 10);
        // And back: the same unit vector.
        expect(sunDirectionFromAngles(angles.elevation, angles.azimuth).distanceTo(direction)).toBeLessThan(1e-12);
      }
    }
  });

  it('follows the conventions: +x is azimuth 0, +z is 90, up is elevation 90', () => {
    expect(sunAnglesFromDirection([1, 0, 0])).toEqual({ elevation: 0, azimuth: 0 });
    expect(sunAnglesFromDirection([0, 0, 2])).toEqual({ elevation: 0, azimuth: 90 });
    expect(sunAnglesFromDirection([-3, 0, 0])).toEqual({ elevation: 0, azimuth: 180 });
    expect(sunAnglesFromDirection([0, 5, 0])).toEqual({ elevation: 90, azimuth: 0 });
    const { elevation, azimuth } = sunAnglesFromDirection(new Vector3(1, 1, 1));
    expect(elevation).toBeCloseTo((Math.atan(1 / Math.SQRT2) * 180) / Math.PI, 12);
    expect(azimuth).toBeCloseTo(45, 12);
  });

  it('takes a Vector3 or an array of any length, even one whose square would overflow', () => {
    const expected = sunAnglesFromDirection([0.3, 0.5, -0.8]);
    for (const direction of [new Vector3(0.3, 0.5, -0.8), [3e-300, 5e-300, -8e-300], [3e300, 5e300, -8e300]] as SunDirection[]) {
      const angles = sunAnglesFromDirection(direction);
      expect(angles.elevation).toBeCloseTo(expected.elevation, 12);
      expect(angles.azimuth).toBeCloseTo(expected.azimuth, 12);
    }
  });

  it('throws a ParameterError naming the direction for a zero, non-finite or malformed one', () => {
    const bad: unknown[] = [[0, 0, 0], new Vector3(), [NaN, 1, 0], [Infinity, 0, 0], [1, 2], [1, 2, 3, 4], ['1', 0, 0], { x: 1, y: 0 }, null, 5];
    for (const direction of bad) {
      let error: unknown;
      try {
        sunAnglesFromDirection(direction as SunDirection, 'direction');
      } catch (caught) {
        error = caught;
      }
      expect(error, String(direction)).toBeInstanceOf(ParameterError);
      expect((error as ParameterError).parameter).toBe('direction');
      expect((error as ParameterError).message).toMatch(/^direction must be a finite, non-zero direction towards the sun/);
    }
  });
});
