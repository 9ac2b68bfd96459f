import { describe, expect, it } from 'vitest';
import { GAP_FACTOR, LONG_GAP, LONGEST_FRAME, LONGEST_KEPT_TIME, RATIO_INTERVAL, SimulationClock, wrapLongTime } from '../../src/runtime/simulationClock';
import { seaRepeatPeriod } from '../../src/spectrum/cascadeBands';
import { createCascadeSpectra } from '../../src/spectrum/initialSpectrum';
import { CpuWaveFields } from '../../src/fft/cpuWaveFields';
import { validateParameters } from '../../src/parameters/parameters';

/** Runs frames at these timestamps (ms) at `rate`; returns each frame's simulated step. */
function run(clock: SimulationClock, timestamps: number[], rate = 1): number[] {
  return timestamps.map((now) => clock.advance(now, rate));
}

/** Timestamps (ms) every `frameMs` from `startMs` for `seconds`, both ends included. */
function frames(startMs: number, frameMs: number, seconds: number): number[] {
  return Array.from({ length: Math.round((seconds * 1000) / frameMs) + 1 }, (_, i) => startMs + i * frameMs);
}

const sum = (values: number[]) => values.reduce((a, b) => a + b, 0);

describe('SimulationClock: simulated time follows real time', () => {
  it('the first frame adds nothing; each later one the real time since the previous × the rate', () => {
    const clock = new SimulationClock();
    run(clock, [5000, 5016, 5266, 6166], 2).forEach((step, i) => expect(step).toBeCloseTo([0, 0.032, 0.5, 1.8][i], 12));
    expect(clock.realStep).toBeCloseTo(0.9, 12);
  });

  it('at 60, 5 or 2 frames per second ten real seconds are ten × the rate simulated seconds', () => {
    for (const frameMs of [1000 / 60, 200, 500]) {
      const clock = new SimulationClock();
      expect(sum(run(clock, frames(1234, frameMs, 10), 1.5))).toBeCloseTo(15, 9);
      expect(clock.timeRatio, `${frameMs} ms frames`).toBeNull();
    }
  });

  it('a paused clock (rate 0) adds nothing, and a negative rate runs time backwards', () => {
    const clock = new SimulationClock();
    expect(sum(run(clock, frames(0, 100, 3), 0))).toBe(0);
    expect(sum(run(clock, [3100, 3200], -1))).toBeCloseTo(-0.2, 12);
  });

  it('a timestamp earlier than the previous one adds nothing', () => {
    const clock = new SimulationClock();
    expect(run(clock, [1000, 900, 1000])).toEqual([0, 0, 0.1]);
  });
});

describe('SimulationClock: long gaps', () => {
  it(`a gap longer than ${LONG_GAP} s counts as one ordinary frame, the last one that was not a gap`, () => {
    const clock = new SimulationClock();
    run(clock, [0, 16, 66]); // the last ordinary frame took 50 ms
    expect(clock.advance(66 + 30_000, 2)).toBeCloseTo(0.1, 12);
    expect(clock.realStep).toBe(30); // what moves in real time still sees the gap
    expect(clock.advance(66 + 60_000, 2)).toBeCloseTo(0.1, 12); // a gap does not become the ordinary frame
    expect(clock.advance(66 + 60_250, 2)).toBeCloseTo(0.5, 12); // and time follows real time again
  });

  it(`a frame of exactly ${LONG_GAP} s is simulated as it is; a longer one that follows short ones is not`, () => {
    const clock = new SimulationClock();
    expect(run(clock, [0, 20, 20 + LONG_GAP * 1000])).toEqual([0, 0.02, LONG_GAP]);
    const other = new SimulationClock();
    run(other, [0, 200]);
    expect(other.advance(200 + GAP_FACTOR * 200 + 1001, 1)).toBeCloseTo(0.2, 12); // over 1 s and over 4× the 200 ms frame
  });

  it('frames that are all slow are simulated as they are: at 0.8, 0.5 and 0.2 frames per second time follows real time', () => {
    for (const fps of [0.8, 0.5, 0.2]) {
      const clock = new SimulationClock();
      run(clock, [0, 16]);
      const added = run(clock, frames(16, 1000 / fps, 12).slice(1), 1);
      // The first slow frame after 60 Hz ones is a sudden stall (counted as 16 ms); then every frame is real.
      expect(added[0]).toBeCloseTo(0.016, 12);
      for (const step of added.slice(1)) expect(step).toBeCloseTo(1 / fps, 9);
    }
  });

  it(`a frame over ${LONGEST_FRAME} s is a gap whatever came before (a hidden tab)`, () => {
    const clock = new SimulationClock();
    run(clock, [0, 8000, 16_000]); // two 8 s frames: a very slow device, simulated as they are
    expect(clock.advance(16_000 + LONGEST_FRAME * 1000 + 1, 1)).toBeCloseTo(8, 12);
  });

  it('before any ordinary frame a gap counts as a 60 Hz frame; frames with one timestamp do not make the ordinary frame 0', () => {
    const clock = new SimulationClock();
    expect(run(clock, [0, 5000])).toEqual([0, 1 / 60]);
    expect(run(clock, [5100, 5100, 9000])).toEqual([0.1, 0, 0.1]);
  });

  it('restart(): the next frame adds nothing, however long ago the previous one was, and then time runs on', () => {
    const clock = new SimulationClock();
    run(clock, [0, 100, 200]);
    clock.restart();
    expect(clock.advance(700, 1)).toBe(0); // half a second later: not simulated
    expect(clock.realStep).toBe(0);
    expect(clock.advance(800, 1)).toBeCloseTo(0.1, 12);
  });
});

describe('SimulationClock: the time ratio', () => {
  it(`is null until ${RATIO_INTERVAL} s of frames were measured, and while time runs at the rate asked for`, () => {
    const clock = new SimulationClock();
    run(clock, frames(0, 100, RATIO_INTERVAL - 0.1), 2);
    expect(clock.timeRatio).toBeNull();
    run(clock, frames(RATIO_INTERVAL * 1000, 37, 30), 2);
    expect(clock.timeRatio).toBeNull();
  });

  it('reports the simulated seconds per real second over an interval with a gap cut short, then null again', () => {
    const clock = new SimulationClock();
    run(clock, frames(0, 100, 0.5), 2); // 0.5 s at 100 ms frames: 1 simulated second
    clock.advance(500 + 3000, 2); // a 3 s stall counts as 100 ms: 0.2 more
    expect(clock.timeRatio).toBeCloseTo(1.2 / 3.5, 12); // 1.2 simulated seconds in 3.5 real ones
    run(clock, frames(3600, 100, 1), 2); // a little over a second of ordinary frames
    expect(clock.timeRatio).toBeNull();
  });

  it('stays null while paused, and after restart() the pause is not part of the measurement', () => {
    const clock = new SimulationClock();
    run(clock, frames(0, 100, 3), 0);
    expect(clock.timeRatio).toBeNull();
    run(clock, frames(3100, 100, 0.5), 1);
    clock.restart(); // a hidden tab for a minute
    run(clock, frames(63_600, 100, 0.5), 1);
    expect(clock.timeRatio).toBeNull();
  });

  it('a clock at one frame every 2 s runs at the rate asked for: no ratio to report', () => {
    const clock = new SimulationClock();
    run(clock, [0, 100]); // one ordinary 100 ms frame
    run(clock, frames(100, 2000, 10)); // then 2 s frames: the first is a stall, the others are real
    expect(clock.timeRatio).toBeNull();
  });

  it('stalls now and then (each 4× the frame before and over 1 s) say how slow time ran', () => {
    const clock = new SimulationClock();
    const times = [0];
    for (let i = 0; i < 6; i++) times.push(times[times.length - 1] + 200, times[times.length - 1] + 200 + 1500); // 200 ms, then a 1.5 s stall
    run(clock, times);
    expect(clock.timeRatio).toBeCloseTo((0.2 + 0.2) / (0.2 + 1.5), 1);
  });
});

describe('wrapLongTime: a render loop’s time stays where a double resolves it', () => {
  const parameters = validateParameters({ resolution: 32 });
  const period = seaRepeatPeriod(parameters);

  it('the sea repeats after seaRepeatPeriod: every cascade’s period divides it by a power of two', () => {
    for (const spectrum of createCascadeSpectra(parameters)) {
      const ratio = period / spectrum.repeatPeriod;
      expect(Number.isInteger(Math.log2(ratio)), `${spectrum.patchSize} m`).toBe(true);
    }
  });

  it('leaves ordinary times alone, and wraps long ones into [0, period) where the sea is the same, exactly', () => {
    for (const t of [0, 12.5, -3, LONGEST_KEPT_TIME - 1]) expect(wrapLongTime(t, period)).toBe(t);
    for (const t of [6e8, 1e16, -1e16]) {
      const wrapped = wrapLongTime(t, period);
      expect(wrapped).toBeGreaterThanOrEqual(0);
      expect(wrapped).toBeLessThan(period);
      for (const spectrum of createCascadeSpectra(parameters)) {
        const [far, near] = [new CpuWaveFields(spectrum), new CpuWaveFields(spectrum)];
        far.update(t);
        near.update(wrapped);
        expect(near.displacement).toEqual(far.displacement);
      }
    }
  });

  it('keeps time moving at 10^16 s, where t += dt does not (doubles there are 2 s apart)', () => {
    let kept = 1e16;
    let naive = 1e16;
    for (let frame = 0; frame < 100; frame++) {
      kept = wrapLongTime(kept, period) + 1 / 60; // as the app and the element keep their time
      naive += 1 / 60;
    }
    expect(naive).toBe(1e16);
    expect(kept - wrapLongTime(1e16, period)).toBeCloseTo(100 / 60, 9);
  });
});
