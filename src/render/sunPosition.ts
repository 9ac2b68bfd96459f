/**
 * setSun's arguments, read by one rule for both Oceans (src/ocean.ts and the WebGPU one,
 * src/webgpu/ocean.ts): degrees, setSun(elevation, azimuth) or setSun({ elevation, azimuth }) (a
 * missing one stays), or the direction towards the sun, setSun({ direction }), and a cloud cover.
 * Everything is checked before anything moves, so a bad value leaves the sun where it was.
 */
import type { SunPosition } from '../ocean';
import { checkOption, checkOptionNames } from '../parameters/options';
import { SUN_OPTIONS } from '../parameters/sceneOptions';
import { sunAngles, type SunAngles } from './skyEnvironment';

const SUN_POSITION_KEYS: readonly string[] = ['elevation', 'azimuth', 'direction', 'cloudCover'];

/**
 * The sun setSun(sunOrElevation, azimuth) asks for, `current` where it gives no angle; `cloudCover`
 * only when it gives one. A ParameterError names the first bad value.
 */
export function readSunPosition(sunOrElevation: SunPosition | number, azimuth: number | undefined, current: SunAngles): SunAngles & { cloudCover?: number } {
  const sun = typeof sunOrElevation === 'number' ? { elevation: sunOrElevation, azimuth } : sunOrElevation;
  checkOptionNames(sun, SUN_POSITION_KEYS, 'setSun', { allowed: '{ elevation, azimuth } (degrees), { direction } or (elevation, azimuth)' });
  const angles = sunAngles(sun, current, 'direction');
  checkOption(SUN_OPTIONS, 'sunElevation', angles.elevation);
  checkOption(SUN_OPTIONS, 'sunAzimuth', angles.azimuth);
  if (sun.cloudCover === undefined) return angles;
  checkOption(SUN_OPTIONS, 'cloudCover', sun.cloudCover);
  return { ...angles, cloudCover: sun.cloudCover };
}
