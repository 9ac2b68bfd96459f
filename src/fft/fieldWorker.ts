/**
 * One Web Worker (waveFieldWorker.ts) that computes a cascade's JS fields at the times it is asked,
 * one request at a time, and what happens when it fails. Two owners use it: the JS path's textures
 * (cpuFieldTextures.ts), and on the GPU path the CPU copy the queries read (cascadeQueryFields.ts).
 *
 * The arrays travel: a request transfers a set to the worker, the reply transfers it back filled,
 * and the owner hands back the set it no longer needs for the next request. A frame allocates
 * nothing; the first requests, with no set to give, have the worker make one (allocating a 256²
 * set took 13 ms of the main thread here).
 *
 * The fields are asked for the time they will be used at: while the owner updates every frame with
 * a steady step, a request made at t asks for t + latency·step, where latency is the number of
 * updates the last round trip took (1 when the worker answers within a frame) and step the mean of
 * the recent frame steps: where frame times jitter, the last step alone, times a latency of several
 * updates, would miss by the jitter times the latency. The fields then arrive for about the time of
 * the frame that shows them, not a frame or more behind it.
 *
 * A worker can fail: an exception in it, a script that cannot load, one terminated from outside
 * (it then just never answers), or workers blocked altogether (a Content-Security-Policy without
 * worker-src). A failed worker is replaced by a new one; a worker that cannot be made, or that
 * fails before its first answer, or the WORKER_REPLACEMENTS-th failure, is given up: the owner is
 * told why (`giveUp`) and computes on the main thread from then on.
 */
import type { SpectrumForFields } from './cpuWaveFields';
import { buffersOf, type FieldArrays } from './fieldArrays';
import type { CascadeOrigin, WorkerReply, WorkerRequest } from './waveFieldWorker';

/** A worker that has not answered a request after this long (ms) counts as dead. */
const WORKER_TIMEOUT_MS = 4000;
/**
 * The same for a new worker's first request, which also waits for its script to load (and compile,
 * on a busy dev server), by default. An owner that answers from the main thread meanwhile may wait for ever.
 */
const FIRST_ANSWER_TIMEOUT_MS = 20_000;
/** Failed workers replaced before the owner is told to compute on the main thread. */
const WORKER_REPLACEMENTS = 3;
/** A step between updates longer than this (s) is a pause or a jump, not a frame: no time ahead. */
const LONGEST_FRAME_STEP = 0.5;
/** How much of each new frame step goes into the mean step (an exponential moving average). */
const STEP_AVERAGING = 0.25;

export class FieldWorker {
  private worker: Worker | null = null;
  /** When the request in flight was sent (performance.now()), or null when none is. */
  private sentAt: number | null = null;
  /** Whether the current worker has answered yet (one that never did is taken to be blocked). */
  private answered = false;
  private replacements = 0;
  /** Arrays for the next request (a dead worker keeps the ones it was sent: then new ones). */
  private spare: FieldArrays | null = null;
  private stopped = false;
  /** Requests refused while one was in flight (updates the round trip took, less one), and the last round trip's count. */
  private updatesWhileBusy = 0;
  private latency = 1;
  /** The mean of the recent frame steps (s), 0 until the first; a pause or a jump starts it again. */
  private meanStep = 0;

  /**
   * `source` is the spectrum (sent as a copy: its fields can come at once) or the cascade's origin
   * (the worker builds it: nothing large is copied here, and the first fields come later);
   * `role` names the worker in warnings; `receive` gets each finished set of fields and returns the
   * set it no longer needs (or null); `giveUp` is called once, with the reason, when the worker is
   * given up; `firstAnswerTimeout` (ms) is how long a new worker may take to answer its first request.
   */
  constructor(
    private readonly source: SpectrumForFields | CascadeOrigin,
    private readonly role: string,
    private readonly receive: (reply: WorkerReply) => FieldArrays | null,
    private readonly giveUp: (fault: string) => void,
    private readonly firstAnswerTimeout = FIRST_ANSWER_TIMEOUT_MS,
  ) {
    this.start();
  }

  /** Whether the worker has been given up (the owner computes on the main thread). */
  get givenUp(): boolean {
    return this.stopped;
  }

  /**
   * Asks for the fields for an update at time t (s) that came `step` s after the last one: at t, or
   * ahead of it by the latency (see the header); with their time derivative when `velocities`. Does
   * nothing while a request is in flight (a worker silent for too long is then replaced) or once
   * given up.
   */
  request(t: number, step: number, velocities: boolean): void {
    if (this.stopped) return;
    const frameStep = step > 0 && step <= LONGEST_FRAME_STEP;
    this.meanStep = !frameStep ? 0 : this.meanStep === 0 ? step : this.meanStep + STEP_AVERAGING * (step - this.meanStep);
    if (this.sentAt !== null) {
      this.updatesWhileBusy++;
      const timeout = this.answered ? WORKER_TIMEOUT_MS : this.firstAnswerTimeout;
      if (performance.now() - this.sentAt > timeout) this.failed(`it did not answer in ${timeout / 1000} s`);
      return;
    }
    const spare = this.spare;
    const ahead = this.latency * this.meanStep;
    const request: WorkerRequest = { type: 'update', t: t + ahead, velocities, spare };
    this.worker!.postMessage(request, spare ? buffersOf(spare) : []);
    this.spare = null;
    this.sentAt = performance.now();
  }

  dispose(): void {
    this.worker?.terminate();
    this.worker = null;
    this.stopped = true;
  }

  /** A new worker, given the spectrum or its origin. */
  private start(): void {
    this.sentAt = null;
    this.answered = false;
    let worker: Worker;
    try {
      worker = new Worker(new URL('./waveFieldWorker.ts', import.meta.url), { type: 'module' });
    } catch (error) {
      this.stop(`workers are blocked here (${error instanceof Error ? error.message : String(error)})`);
      return;
    }
    worker.onmessage = (event: MessageEvent<WorkerReply>) => {
      // A new worker's first answer also waited for its script to load: not a round trip to go by.
      this.latency = this.answered ? this.updatesWhileBusy + 1 : 1;
      this.updatesWhileBusy = 0;
      this.sentAt = null;
      this.answered = true;
      this.spare = this.receive(event.data);
    };
    worker.onerror = (event) => {
      event.preventDefault(); // handled here, not an uncaught error of the page
      this.failed(event.message || 'its script failed to load');
    };
    worker.onmessageerror = () => this.failed('a message could not be read');
    this.worker = worker;
    if ('params' in this.source) {
      const request: WorkerRequest = { type: 'cascade', origin: this.source };
      worker.postMessage(request);
      return;
    }
    // Copies, transferred: cloning the arrays in the message costs several times as much on the
    // main thread (25 ms against 8 for a 256² spectrum here).
    const { resolution, repeatPeriod, amplitudes, waveVectors } = this.source;
    const spectrum = { resolution, repeatPeriod, amplitudes: amplitudes.slice(), waveVectors: waveVectors.slice() };
    const request: WorkerRequest = { type: 'spectrum', spectrum };
    worker.postMessage(request, [spectrum.amplitudes.buffer, spectrum.waveVectors.buffer]);
  }

  private failed(why: string): void {
    this.worker?.terminate();
    this.worker = null;
    this.spare = null; // the dead worker kept them
    if (!this.answered) {
      this.stop(`the ${this.role} failed before its first answer: ${why}`);
    } else if (++this.replacements > WORKER_REPLACEMENTS) {
      this.stop(`the ${this.role} failed ${this.replacements} times, last: ${why}`);
    } else {
      console.warn(`three-fft-ocean: the ${this.role} failed (${why}); replaced by a new one.`);
      this.start();
    }
  }

  private stop(fault: string): void {
    this.stopped = true;
    this.sentAt = null;
    this.giveUp(fault);
  }
}
