/**
 * The adaptive quality's settings (runtime/adaptiveQuality.ts): their defaults, ranges and checks,
 * for the app's URL and panel and <fft-ocean>'s attributes, which so read them by one rule and
 * say the same of a bad value.
 */
import { between, oneOf, type OptionTable } from './options';
import { DEFAULT_TARGET_FPS, QUALITY_SETTINGS, type QualitySetting } from '../runtime/adaptiveQuality';

export interface QualityOptions {
  /** 'auto' adapts the quality level to hold targetFps; a level (high, medium, low, lowest) stays fixed. @defaultValue 'auto' */
  quality: QualitySetting;
  /** The frame rate 'auto' holds, frames per second, [5, 240]. @defaultValue 30 */
  targetFps: number;
}

export const MIN_TARGET_FPS = 5;
export const MAX_TARGET_FPS = 240;

export const QUALITY_OPTIONS: OptionTable<QualityOptions> = {
  quality: { type: 'choice', unit: '', allowed: `one of ${QUALITY_SETTINGS.join(', ')}`, check: oneOf(QUALITY_SETTINGS), choices: QUALITY_SETTINGS },
  targetFps: {
    type: 'number',
    unit: 'fps',
    allowed: `a number of frames per second from ${MIN_TARGET_FPS} to ${MAX_TARGET_FPS}`,
    check: between(MIN_TARGET_FPS, MAX_TARGET_FPS),
  },
};

export const DEFAULT_QUALITY: Readonly<QualityOptions> = Object.freeze({ quality: 'auto', targetFps: DEFAULT_TARGET_FPS });
