/**
 * Adaptive quality: holds a frame rate by drawing fewer pixels, without multisampling, and
 * simulating coarser grids and fewer cascades when frames are slow, and more again when they are
 * fast, for a render loop (the app, <fft-ocean>).
 *
 * Each level sets a render scale (a factor on the pixel ratio: under a software renderer the
 * frame's cost is about proportional to the pixels drawn), whether the picture is multisampled
 * (MSAA: under SwiftShader it shades every sample, so it costs about as much as the pixels
 * themselves), a largest simulation grid N (the FFT's cost is about N² log N per cascade) and a
 * largest number of cascades (each one is an FFT per frame and a texture fetch per vertex and
 * pixel; the finest go first, so the sea keeps its longest waves). The loop reports every
 * frame's real length; over a window of WINDOW_SECONDS the median decides:
 *   - slower than the target by more than LOWER_ABOVE: one level down;
 *   - faster than RAISE_BELOW of the target, after STAY_SECONDS at the level: one level up.
 * The gap between the two (hysteresis), the median (one slow frame, a garbage collection, does not
 * count) and the time a level is kept keep it from switching back and forth. A window starts
 * afresh after every change (the frames just after one are not representative) and after a pause
 * in the frames (a hidden tab).
 */

import { MAX_CASCADES } from '../parameters/parameters';
import { FEWEST_CELLS_PER_RING } from '../render/horizonGrid';

/** The levels, best first. */
export const QUALITY_LEVELS = ['high', 'medium', 'low', 'lowest'] as const;
export type QualityLevel = (typeof QUALITY_LEVELS)[number];
/** 'auto' adapts; a level stays fixed (the shot CLI and the screenshot tests: deterministic pictures). */
export type QualitySetting = 'auto' | QualityLevel;
export const QUALITY_SETTINGS: readonly QualitySetting[] = ['auto', ...QUALITY_LEVELS];

export interface QualityStep {
  /** Factor on the renderer's pixel ratio. */
  renderScale: number;
  /** The largest simulation grid N (the sea's resolution is the smaller of this and the one asked for). */
  maxResolution: number;
  /** Whether the picture is drawn multisampled (4× MSAA; render/sceneOutput.ts). */
  msaa: boolean;
  /** The most cascades simulated and drawn: the largest patch sizes asked for, up to this many. */
  maxCascades: number;
  /**
   * The fewest cells a side of each ring of the sea's grid (OceanSurface.fewestCellsPerRing): the
   * grid follows the scaled-down picture's height down to this many.
   */
  fewestGridCells: number;
  /**
   * The size of the scene's capture for the refraction (SceneRefraction.scale) as a fraction of
   * the picture's; 0 draws none, and the sea shows only the sky through the water.
   */
  refractionScale: number;
  /**
   * The scene's reflection's size as a fraction of the drawing buffer's (OceanSurface.reflectionScale;
   * 0: the sea reflects only its sky). Its render costs about the scene's own draw at that size.
   */
  reflectionScale: number;
}

export const QUALITY_STEPS: Readonly<Record<QualityLevel, QualityStep>> = {
  high: { renderScale: 1, maxResolution: 1024, msaa: true, maxCascades: MAX_CASCADES, fewestGridCells: FEWEST_CELLS_PER_RING, refractionScale: 1, reflectionScale: 0.5 },
  medium: { renderScale: 0.75, maxResolution: 128, msaa: false, maxCascades: MAX_CASCADES, fewestGridCells: FEWEST_CELLS_PER_RING, refractionScale: 0.5, reflectionScale: 0.5 },
  low: { renderScale: 0.5, maxResolution: 64, msaa: false, maxCascades: 2, fewestGridCells: FEWEST_CELLS_PER_RING, refractionScale: 0.5, reflectionScale: 0.5 },
  lowest: { renderScale: 0.3, maxResolution: 32, msaa: false, maxCascades: 2, fewestGridCells: 16, refractionScale: 0, reflectionScale: 0 },
};

/**
 * The grid and the cascades a sea asked for with `resolution` and `patchSizes` runs at under
 * `step`: N at most the level's, and the largest patch sizes (the longest waves, which shape the
 * sea; the finest cascades add ripples that a coarse picture cannot show anyway).
 */
export function simulationAtQuality(
  asked: { readonly resolution: number; readonly patchSizes: readonly number[] },
  step: QualityStep,
): { resolution: number; patchSizes: number[] } {
  return {
    resolution: Math.min(asked.resolution, step.maxResolution),
    patchSizes: asked.patchSizes.slice(Math.max(0, asked.patchSizes.length - step.maxCascades)),
  };
}

/** The frame rate 'auto' holds unless told otherwise, frames per second. */
export const DEFAULT_TARGET_FPS = 30;
/** Real seconds of frames whose median frame time decides a change. */
export const WINDOW_SECONDS = 2;
/** Frames a window needs at least, however slow. */
const WINDOW_FRAMES = 5;
/** Lower when the median frame is this much longer than the target's. */
export const LOWER_ABOVE = 1.2;
/** Raise when the median frame takes less than this fraction of the target's. */
export const RAISE_BELOW = 0.5;
/** Seconds at a level before it may be raised again. */
export const STAY_SECONDS = 6;
/** A frame longer than this (s) is a pause (a hidden tab, a breakpoint): the window starts again. */
const PAUSE_SECONDS = 1.5;

export class AdaptiveQuality {
  private levelIndex = 0;
  private readonly window: number[] = [];
  private windowSeconds = 0;
  private secondsAtLevel = 0;
  private lastMedian: number | null = null;

  /**
   * @param setting 'auto', or a fixed level
   * @param targetFps the frame rate 'auto' holds
   */
  constructor(
    readonly setting: QualitySetting,
    readonly targetFps = DEFAULT_TARGET_FPS,
  ) {
    if (setting !== 'auto') this.levelIndex = QUALITY_LEVELS.indexOf(setting);
  }

  /** The level in force. */
  get level(): QualityLevel {
    return QUALITY_LEVELS[this.levelIndex];
  }

  get step(): QualityStep {
    return QUALITY_STEPS[this.level];
  }

  /** The median frame time of the last full window, ms (null before the first). */
  get medianFrameMs(): number | null {
    return this.lastMedian === null ? null : 1000 * this.lastMedian;
  }

  /**
   * One frame of `seconds` real time. Returns true when the level changed (the caller then applies
   * `step`).
   */
  frame(seconds: number): boolean {
    if (!(seconds > 0)) return false;
    if (seconds > PAUSE_SECONDS) {
      this.restartWindow();
      return false;
    }
    this.window.push(seconds);
    this.windowSeconds += seconds;
    this.secondsAtLevel += seconds;
    if (this.windowSeconds < WINDOW_SECONDS || this.window.length < WINDOW_FRAMES) return false;
    const median = medianOf(this.window);
    this.lastMedian = median;
    this.restartWindow();
    if (this.setting !== 'auto') return false;
    const target = 1 / this.targetFps;
    if (median > LOWER_ABOVE * target && this.levelIndex < QUALITY_LEVELS.length - 1) return this.moveTo(this.levelIndex + 1);
    if (median < RAISE_BELOW * target && this.levelIndex > 0 && this.secondsAtLevel >= STAY_SECONDS) return this.moveTo(this.levelIndex - 1);
    return false;
  }

  private moveTo(index: number): boolean {
    this.levelIndex = index;
    this.secondsAtLevel = 0;
    return true;
  }

  private restartWindow(): void {
    this.window.length = 0;
    this.windowSeconds = 0;
  }
}

function medianOf(values: number[]): number {
  const sorted = [...values].sort((a, b) => a - b);
  const middle = sorted.length >> 1;
  return sorted.length % 2 === 1 ? sorted[middle] : 0.5 * (sorted[middle - 1] + sorted[middle]);
}
