import { describe, expect, it } from 'vitest';
import { AdaptiveQuality, QUALITY_LEVELS, QUALITY_STEPS, STAY_SECONDS, WINDOW_SECONDS, type QualityLevel } from '../../src/timing/adaptiveQuality';

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
