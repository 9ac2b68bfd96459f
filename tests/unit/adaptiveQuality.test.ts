import { describe, expect, it } from 'vitest';
import { MAX_CASCADES } from '../../src/parameters/parameters';
import {
  AdaptiveQuality,
  QUALITY_LEVELS,
  QUALITY_STEPS,
  simulationAtQuality,
  STAY_SECONDS,
  WINDOW_SECONDS,
  type QualityLevel,
} from '../../src/runtime/adaptiveQuality';

/**
 * Runs `seconds` of frames whose length is frameSeconds(level) (a device model), and returns the
 * levels in force after each frame.
 */
function run(quality: AdaptiveQuality, seconds: number, frameSeconds: (level: QualityLevel) => number): QualityLevel[] {
  const levels: QualityLevel[] = [];
  for (let elapsed = 0; elapsed < seconds; ) {
    const frame = frameSeconds(quality.level);
    quality.frame(frame);
    elapsed += frame;
    levels.push(quality.level);
  }
  return levels;
}

/** A software renderer: the frame's cost proportional to the pixels drawn, plus a fixed part. */
const fragmentBound = (atHigh: number, fixed = 0.005) => (level: QualityLevel) => fixed + (atHigh - fixed) * QUALITY_STEPS[level].renderScale ** 2;

describe('AdaptiveQuality', () => {
  it('a fixed level never changes, however slow or fast the frames', () => {
    for (const level of QUALITY_LEVELS) {
      const quality = new AdaptiveQuality(level);
      expect(new Set(run(quality, 60, () => 0.5))).toEqual(new Set([level]));
      expect(new Set(run(quality, 60, () => 0.001))).toEqual(new Set([level]));
    }
  });

  it('lowers one level per window while frames are too slow, down to the lowest', () => {
    const quality = new AdaptiveQuality('auto', 30);
    const levels = run(quality, 4 * WINDOW_SECONDS + 1, () => 0.25);
    expect([...new Set(levels)]).toEqual(['high', 'medium', 'low', 'lowest']);
    expect(quality.medianFrameMs).toBeCloseTo(250, 6);
  });

  it('settles on the level that holds the target and stays there (no switching back and forth)', () => {
    // 70 ms at high: 0.75² → 42 ms, 0.5² → 21 ms. At 30 fps (33 ms, lowered above 40 ms) medium is
    // still too slow and low holds it, not so fast that it would be raised (below 17 ms).
    const quality = new AdaptiveQuality('auto', 30);
    const levels = run(quality, 120, fragmentBound(0.07));
    const changes = levels.filter((level, i) => i > 0 && level !== levels[i - 1]).length;
    expect(levels[levels.length - 1]).toBe('low');
    expect(changes).toBe(2); // high → medium → low, then never again in two minutes
  });

  it('raises again when frames get fast, after staying at a level, one level at a time', () => {
    const quality = new AdaptiveQuality('auto', 30);
    while (quality.level !== 'lowest') quality.frame(0.2); // a slow spell: down to the lowest
    const levels = run(quality, 4 * (STAY_SECONDS + WINDOW_SECONDS), () => 0.01); // then 100 fps
    expect([...new Set(levels)]).toEqual(['lowest', 'low', 'medium', 'high']);
    // Not before it stayed STAY_SECONDS at the lowest level.
    const firstRaise = levels.findIndex((level) => level !== 'lowest');
    expect(firstRaise * 0.01).toBeGreaterThanOrEqual(STAY_SECONDS);
  });

  it('a few slow frames (a garbage collection) do not lower it: the window’s median decides', () => {
    const quality = new AdaptiveQuality('auto', 30);
    let frame = 0;
    run(quality, 30, () => (++frame % 10 === 0 ? 0.4 : 0.02));
    expect(quality.level).toBe('high');
  });

  it('a pause (a hidden tab) is not a slow frame', () => {
    const quality = new AdaptiveQuality('auto', 30);
    run(quality, 1.5, () => 0.02);
    quality.frame(30);
    run(quality, 1.5, () => 0.02);
    expect(quality.level).toBe('high');
  });
});

describe('the quality levels', () => {
  it('each level draws and simulates no more than the one above it, in every step', () => {
    for (let i = 1; i < QUALITY_LEVELS.length; i++) {
      const [better, worse] = [QUALITY_STEPS[QUALITY_LEVELS[i - 1]], QUALITY_STEPS[QUALITY_LEVELS[i]]];
      expect(worse.renderScale, QUALITY_LEVELS[i]).toBeLessThan(better.renderScale);
      expect(worse.maxResolution).toBeLessThanOrEqual(better.maxResolution);
      expect(worse.maxCascades).toBeLessThanOrEqual(better.maxCascades);
      expect(worse.fewestGridCells).toBeLessThanOrEqual(better.fewestGridCells);
      expect(!worse.msaa || better.msaa, `${QUALITY_LEVELS[i]}: MSAA only where the level above has it`).toBe(true);
    }
  });

  it('high keeps MSAA and every cascade; the levels below turn MSAA off; low and lowest draw fewer cascades, never none', () => {
    expect(QUALITY_STEPS.high).toMatchObject({ renderScale: 1, msaa: true, maxCascades: MAX_CASCADES });
    expect(QUALITY_STEPS.medium).toMatchObject({ msaa: false, maxCascades: MAX_CASCADES });
    for (const level of ['low', 'lowest'] as const) {
      expect(QUALITY_STEPS[level].msaa).toBe(false);
      expect(QUALITY_STEPS[level].maxCascades).toBeLessThan(3); // the default sea has 3
      expect(QUALITY_STEPS[level].maxCascades).toBeGreaterThanOrEqual(1);
    }
  });

  it('cuts the finest cascades and keeps the largest patches (the longest waves), and caps N', () => {
    const asked = { resolution: 256, patchSizes: [2.37, 13.7, 79.3, 457] };
    expect(simulationAtQuality(asked, QUALITY_STEPS.high)).toEqual(asked);
    expect(simulationAtQuality(asked, { ...QUALITY_STEPS.high, maxCascades: 2, maxResolution: 64 })).toEqual({ resolution: 64, patchSizes: [79.3, 457] });
    expect(simulationAtQuality(asked, { ...QUALITY_STEPS.high, maxCascades: 1 }).patchSizes).toEqual([457]);
    // Fewer cascades asked than a level allows: all of them; a finer grid than asked is never made.
    expect(simulationAtQuality({ resolution: 32, patchSizes: [457] }, QUALITY_STEPS.medium)).toEqual({ resolution: 32, patchSizes: [457] });
    expect(asked.patchSizes).toHaveLength(4); // the asked sizes are not changed
  });

  it('with MSAA and cascades in the cost, auto settles where the frames hold the target and stays', () => {
    // A software renderer: a fixed part, the pixels (twice over with MSAA: SwiftShader shades every
    // sample) and each cascade of the default three. 176 ms at high, 61 at medium, 32 at low.
    const model = (level: QualityLevel) => {
      const step = QUALITY_STEPS[level];
      return 0.004 + 0.08 * step.renderScale ** 2 * (step.msaa ? 2 : 1) + 0.004 * Math.min(3, step.maxCascades);
    };
    // At 30 fps: lowered above 40 ms, raised below 16.7 ms; low is neither.
    expect(model('medium')).toBeGreaterThan(0.04);
    expect(model('low')).toBeLessThan(0.04);
    expect(model('low')).toBeGreaterThan(0.0167);
    const quality = new AdaptiveQuality('auto', 30);
    const levels = run(quality, 120, model);
    const changes = levels.filter((level, i) => i > 0 && level !== levels[i - 1]).length;
    expect(levels[levels.length - 1]).toBe('low');
    expect(changes).toBe(2);
  });
});
