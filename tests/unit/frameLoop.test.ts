/**
 * The frame loop the app and <fft-ocean> share (src/runtime/frameLoop.ts): time by the clock, the
 * one wrap of a long time, and the order of a drawn frame (camera, update, far plane, render).
 */
import { PerspectiveCamera, Scene } from 'three';
import { describe, expect, it } from 'vitest';
import { AdaptiveQuality } from '../../src/runtime/adaptiveQuality';
import { FrameLoop, type FrameScene } from '../../src/runtime/frameLoop';
import { LONGEST_KEPT_TIME } from '../../src/runtime/simulationClock';
import type { Ocean } from '../../src/ocean';
import type { SceneOutput } from '../../src/render/sceneOutput';

/** A stand-in for the ocean and the output that records what a frame did. */
function fakeFrame(calls: string[]): FrameScene {
  const ocean = {
    repeatPeriod: 200,
    update: (t: number) => calls.push(`update ${t}`),
    horizonDistanceFor: (height: number) => 1e4 * height,
  } as unknown as Ocean;
  const output = { render: () => calls.push('render') } as unknown as SceneOutput;
  const camera = new PerspectiveCamera();
  camera.position.y = 2;
  return { ocean, output, scene: new Scene(), camera };
}

describe('FrameLoop', () => {
  it('advances the time it holds by real time × rate, from the second frame; 0 while paused', () => {
    const time = { t: 5 };
    const loop = new FrameLoop(new AdaptiveQuality('high', 30), time);
    loop.advance(1000, 1);
    expect(time.t).toBe(5);
    loop.advance(1100, 2);
    expect(time.t).toBeCloseTo(5.2, 12);
    loop.advance(1200, 0);
    expect(time.t).toBeCloseTo(5.2, 12);
    loop.restart();
    loop.advance(5000, 1); // the first frame after a restart advances nothing
    expect(time.t).toBeCloseTo(5.2, 12);
  });

  it('draws: the camera placed for t, the sea updated to t, the far plane out to the horizon, then the render', () => {
    const calls: string[] = [];
    const frame = fakeFrame(calls);
    const loop = new FrameLoop(new AdaptiveQuality('high', 30), { t: 12 });
    const drawn = loop.draw(frame, { placeCamera: (t) => calls.push(`camera ${t}`), beforeRender: (t) => calls.push(`before ${t}`) });
    expect(drawn).toBe(12);
    expect(calls).toEqual(['camera 12', 'update 12', 'before 12', 'render']);
    expect(frame.camera.far).toBe(1.5 * 2e4);
  });

  it('wraps a time beyond what a double resolves once, where it draws, and then moves on from there', () => {
    const time = { t: 1e16 };
    const loop = new FrameLoop(new AdaptiveQuality('high', 30), time);
    const calls: string[] = [];
    const drawn = loop.draw(fakeFrame(calls), {});
    expect(drawn).toBe(1e16 % 200);
    expect(time.t).toBe(drawn);
    expect(Math.abs(time.t)).toBeLessThan(LONGEST_KEPT_TIME);
    loop.advance(0, 1);
    loop.advance(500, 1);
    expect(time.t).toBeCloseTo(drawn + 0.5, 9);
  });
});
