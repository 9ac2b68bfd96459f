/**
 * How far simulated time moves per drawn frame, for a render loop: <fft-ocean>
 * (src/embed/fftOceanElement.ts) and the app (src/app/app.ts) both step their time with it. It
 * lives apart from both because the element is part of the library and the app is the demo,
 * which the library never imports.
 *
 * A frame advances simulated time by the real time since the previous frame × the rate asked for
 * (the time scale; 0 while paused), so the sea moves at the same speed at 60 frames per second and
 * at 3, and at one frame every few seconds (a slow device): frames that are all slow are simulated
 * as they are. Only a gap is not, or the sea would jump: a frame longer than LONG_GAP that also
 * takes over GAP_FACTOR times the frame before it (a breakpoint, a main thread stalled by something
 * else, a frame loop that stopped without restart()), or any frame over LONGEST_FRAME (a hidden
 * tab). It counts as one ordinary frame, the last frame time that was not a gap.
 *
 * It also measures the time ratio actually achieved (simulated seconds per real second, over
 * about RATIO_INTERVAL of frames), which differs from the rate asked for only when gaps were cut
 * short; timeRatio reports it then, for a status line to show.
 */

/**
 * Simulated time beyond which (either sign) a render loop's time is wrapped, s (2^24: 194 days, where
 * a double still resolves 4 ns). Time kept as t += dt stops advancing once dt is below half the
 * spacing of doubles near t (at 10^16 s they are 2 s apart), so it is kept small: see wrapLongTime.
 */
export const LONGEST_KEPT_TIME = 2 ** 24;

/**
 * t, or beyond ±LONGEST_KEPT_TIME the time in [0, period) at which the sea is the same (period:
 * Ocean.repeatPeriod, after which every wave is where it was). For a render loop's clock: a view
 * at t = 10^16 s then moves as one at t mod period does. The local waves and the foam, which are
 * not periodic, start again at the wrap (once every 194 days of simulated time).
 */
export function wrapLongTime(t: number, period: number): number {
  if (Math.abs(t) < LONGEST_KEPT_TIME) return t;
  const wrapped = t % period;
  return wrapped < 0 ? wrapped + period : wrapped;
}

/** Frames up to this long are always simulated as they are, seconds. */
export const LONG_GAP = 1;
/** A longer frame is a gap when it also takes more than this many times the frame before it. */
export const GAP_FACTOR = 4;
/** Frames longer than this are always gaps, seconds. */
export const LONGEST_FRAME = 10;
/** Real seconds of frames that one measurement of the time ratio spans (at least). */
export const RATIO_INTERVAL = 1;
/** timeRatio reports a ratio that differs from the rate asked for by more than this fraction. */
export const RATIO_TOLERANCE = 0.05;
/** What a gap counts as before any ordinary frame was seen, seconds (a frame at 60 Hz). */
const FIRST_ORDINARY_STEP = 1 / 60;

export class SimulationClock {
  /** The previous frame's timestamp (ms), or null when the next frame starts anew. */
  private last: number | null = null;
  private ordinaryStep = FIRST_ORDINARY_STEP;
  private lastRealStep = 0;
  /** The real length of the last frame that had one (a repeated timestamp has none), seconds. */
  private previousReal = 0;
  /** The measurement under way: real seconds, simulated seconds and the simulated seconds asked for. */
  private real = 0;
  private simulated = 0;
  private requested = 0;
  private ratio: number | null = null;

  /**
   * The frame at `nowMs` (a requestAnimationFrame or performance.now() timestamp, milliseconds):
   * returns the simulated seconds to add, at `rate` simulated seconds per real second (0 while
   * paused). The first frame, and the first after restart(), adds nothing.
   */
  advance(nowMs: number, rate: number): number {
    const last = this.last;
    this.last = nowMs;
    if (last === null) {
      this.lastRealStep = 0;
      return 0;
    }
    const real = Math.max(0, (nowMs - last) / 1000);
    this.lastRealStep = real;
    const gap = real > LONGEST_FRAME || (real > LONG_GAP && real > GAP_FACTOR * this.previousReal);
    // A frame with the same timestamp as the previous one says nothing about the frame rate.
    if (real > 0) this.previousReal = real;
    if (!gap && real > 0) this.ordinaryStep = real;
    const simulated = (gap ? this.ordinaryStep : real) * rate;
    this.measure(real, simulated, real * rate);
    return simulated;
  }

  /**
   * The next frame starts anew and advances nothing: call it when frames stop on purpose (a
   * hidden tab, an element off screen, a lost context), so the pause is not simulated.
   */
  restart(): void {
    this.last = null;
  }

  /** Real seconds between the last two frames (0 on a first frame), for what moves in real time (the camera). */
  get realStep(): number {
    return this.lastRealStep;
  }

  /**
   * Simulated seconds per real second over the last measured interval (about RATIO_INTERVAL), when
   * it differs from the rate asked for by more than RATIO_TOLERANCE; otherwise null.
   */
  get timeRatio(): number | null {
    return this.ratio;
  }

  private measure(real: number, simulated: number, requested: number): void {
    this.real += real;
    this.simulated += simulated;
    this.requested += requested;
    if (this.real < RATIO_INTERVAL) return;
    const off = Math.abs(this.simulated - this.requested) > RATIO_TOLERANCE * Math.abs(this.requested);
    this.ratio = off ? this.simulated / this.real : null;
    this.real = 0;
    this.simulated = 0;
    this.requested = 0;
  }
}
