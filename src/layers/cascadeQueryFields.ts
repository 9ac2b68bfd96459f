/**
 * The CPU copy of one cascade's fields that the queries read (surfaceQuery.ts), at most
 * QUERY_RESOLUTION² texels, which the main thread does not compute while a worker can: on the JS
 * path in a worker, the worker's fields the textures show (with their velocities); on the GPU
 * path, a second JS worker of its own (fieldWorker.ts), started QUERY_WORKER_DELAY_MS after the
 * first query (in a task of its own; it builds its copy from the parameters) and then asked at
 * each update that follows queries. Both ask for the time of the frame the fields arrive for
 * (fieldWorker.ts), and the queries carry them the rest of the way by their velocities
 * (surfaceQuery.ts). Only when there are none within LONGEST_CARRY of the time asked (the first
 * query, a jump in time, a frame step far from the last, a worker given up or one slower than the
 * frames) are the fields computed here (`fieldsComputedHere` counts them): while a worker is on its
 * way, a provisional copy (provisionalQuerySpectrum: the finest cascade on a coarser grid),
 * computed with the update of a frame that follows queries and carried like the workers' fields,
 * then set aside once a worker's fields are in (its arrays serve the next provisional copy, this
 * cascade's or the one of the cascade that replaces it); else the whole.
 *
 * Owned by its cascade (fftCascade.ts), which frees it in dispose(): its query worker, its timer
 * and its copies.
 */
import { CpuWaveFields } from '../fft/cpuWaveFields';
import type { CpuFieldsForQueries } from '../fft/fieldSource';
import { FieldWorker } from '../fft/fieldWorker';
import { largestFrequency, reducedSpectrum, type InitialSpectrum, type SpectrumOrigin } from '../spectrum/initialSpectrum';
import type { LayerFieldsOnCpu, LayerQueryFields } from './waveLayer';

/**
 * The longest time (s) the queries carry fields by their velocities. The error of that first-order
 * step is ½·Δt²·ω²·a per wave, and the short waves' ω is large: over a 12 m/s sea the worst height
 * error is 0.13 % of the RMS height at 16 ms, 0.55 % at 33 ms and 1.3 % at 50 ms (surfaceQuery.test.ts);
 * 40 ms keeps it under the 1 % heightAt holds against the drawn surface.
 */
export const LONGEST_CARRY = 0.04;

/**
 * The largest grid of the queries' CPU copy. A cascade on a larger grid is copied without its
 * shortest waves (reducedSpectrum): a worker then keeps up with the frames at any N, and a copy
 * computed here costs what N = 256 costs. Only the finest cascade has waves there (cascadeBands.ts),
 * ripples of millimetres.
 */
export const QUERY_RESOLUTION = 256;

/**
 * The grid of the finest cascade's copy computed here while a worker is on its way (the first
 * queries, a jump in time): it loses the ripples shorter than a 64th of the patch, and its waves
 * fall between the texels of a grid half as fine as the drawn one, and costs a fifth of the whole
 * (1.1 against 5.4 ms here). The other cascades' copies are on the queries' own grid
 * (provisionalQuerySpectrum). Together, over a 10 and a 14 m/s sea at N = 256, heightAt is then
 * about 0.5 cm at most (RMS 0.15 cm) from the exact answers, which follow from the worker.
 */
export const PROVISIONAL_QUERY_RESOLUTION = 128;

/**
 * How long (ms) after the first query the query worker is made. Building its copy of the spectrum
 * costs the worker ~0.1–0.2 s of CPU at N = 256, which a cascade replaced sooner (a slider being
 * dragged rebuilds the cascades at every step) would waste, on a machine whose cores the main
 * thread and the GPU's driver may be using. Meanwhile the provisional copy answers.
 */
export const QUERY_WORKER_DELAY_MS = 250;

/**
 * The spectrum of the copy computed here while a worker is on its way, from the queries' own one.
 * A cascade whose band ends inside the queries' grid (every one but the finest, cascadeBands.ts)
 * keeps that grid: its FFT skips the empty columns (fft.ts), and the queries then interpolate it
 * as the surface interpolates its texture. On a coarser grid its shortest waves would fall
 * between texels: 64² copies of every cascade were up to 32 cm off between texels over a 14 m/s
 * sea, though exact at them. The finest, whose band fills the grid, goes on
 * PROVISIONAL_QUERY_RESOLUTION².
 */
export function provisionalQuerySpectrum(querySpectrum: InitialSpectrum): InitialSpectrum {
  const { resolution } = querySpectrum;
  const finest = largestFrequency(querySpectrum) >= resolution / 2;
  return finest && resolution > PROVISIONAL_QUERY_RESOLUTION ? reducedSpectrum(querySpectrum, PROVISIONAL_QUERY_RESOLUTION) : querySpectrum;
}

export class CascadeQueryFields {
  /** The spectrum of the queries' CPU copy: the cascade's, or on a grid over QUERY_RESOLUTION a reduced one. */
  private readonly querySpectrum: InitialSpectrum;
  /** The JS path's fields, where they are also the queries' copy (the same spectrum), else null. */
  private readonly jsFieldsForQueries: CpuFieldsForQueries | null;
  /** The worker that computes the queries' CPU copy where the JS path's worker cannot (made after the first query). */
  private queryWorker: FieldWorker | null = null;
  /** The timer that makes the query worker once the first query came, until it fires; else null. */
  private queryWorkerTimer: ReturnType<typeof setTimeout> | null = null;
  private lastQueryTime = 0;
  /** Whether update() ran once. */
  private updated = false;
  /** Whether queryFields() was ever called. */
  private everQueried = false;
  /** Updates with a time step before the first query. */
  private unqueriedSteps = 0;
  /** The newest fields the query worker finished. */
  private newest: LayerQueryFields | null = null;
  /** Whether queries came since the last update (the query worker is then asked at the next). */
  private queried = false;
  /**
   * Fields computed here on demand: the cascade's (fieldsOnCpu, and the queries' copy when it has the
   * same spectrum), the queries' reduced copy, and the provisional one.
   */
  private computed: FieldsComputedHere | null = null;
  private computedReduced: FieldsComputedHere | null = null;
  /** The provisional copy (provisionalCopy) while it may be wanted, else null. */
  private provisional: FieldsComputedHere | null = null;
  /** A provisional copy no longer wanted, kept for its arrays (provisionalCopy), or null. */
  private spare: FieldsComputedHere | null = null;
  private computedHere = 0;

  constructor(
    private readonly spectrum: InitialSpectrum,
    /** What made `spectrum`: the query worker builds its copy from it. */
    private readonly origin: SpectrumOrigin,
    /** The backend's fields of the cascade on the CPU (the JS path's), or null (the GPU path). */
    jsFields: CpuFieldsForQueries | null,
    /** Whether the queries' fields may be computed in a worker (else here, once per time asked). */
    private readonly queryWorkerWanted: boolean,
    /** The copies of the cascade this one replaces, whose provisional copy's arrays it may take over (provisionalCopy). */
    private predecessor: CascadeQueryFields | null,
  ) {
    this.querySpectrum = spectrum.resolution > QUERY_RESOLUTION ? reducedSpectrum(spectrum, QUERY_RESOLUTION) : spectrum;
    this.jsFieldsForQueries = jsFields !== null && this.querySpectrum === spectrum ? jsFields : null;
  }

  /** After the cascade's update to time t (s), `step` (s) since the last: asks the workers, keeps or frees the provisional copy. */
  afterUpdate(t: number, step: number): void {
    if (this.queried) this.queryWorker?.request(t, step, true);
    // While a worker is on its way, the provisional fields for this frame's queries are computed
    // with the frame's update, not in its first query: at the first update (no worker has answered
    // yet, and a new cascade is usually queried as the one it replaces was) and after frames with
    // queries. (Not fromWorker at the first update: asking the JS path's fields for queries has its
    // worker compute velocities from then on.) Once the worker's fields are in, the copy is set
    // aside (`spare`) for its arrays; after two frames that moved on in time without any query
    // (counted by their steps: the foam's warm-up updates a new cascade many times before the
    // frame's queries, with no step) it is freed.
    if (step !== 0 && !this.everQueried) this.unqueriedSteps++;
    const fromWorker = this.updated && this.queried ? this.fromWorker(t) : null;
    if (fromWorker !== null || this.unqueriedSteps >= 2) {
      this.spare = this.everQueried ? (this.provisional ?? this.spare) : null;
      this.provisional = null;
    } else if ((!this.updated || this.queried) && this.workerComing) {
      const provisional = this.provisionalCopy();
      if (provisional.lastWithin(t, LONGEST_CARRY) === null) this.computeHere(provisional, t).velocities();
    }
    this.queried = false;
    this.updated = true;
    this.predecessor = null;
  }

  /** Whether queries came (queryFields) since the cascade was made, or since forgetQueries. */
  get queriedYet(): boolean {
    return this.everQueried;
  }

  /**
   * Forgets the queries so far, as if none had come: no query worker is made for them, the
   * provisional copy is freed as an unqueried cascade's is, and the JS path's worker is not asked
   * for velocities. For the Ocean's warm-up (Ocean.warmUpQueries), whose queries are not an app's;
   * before any query worker was made.
   */
  forgetQueries(): void {
    if (this.queryWorkerTimer !== null) clearTimeout(this.queryWorkerTimer);
    this.queryWorkerTimer = null;
    this.queried = this.everQueried = false;
    this.jsFieldsForQueries?.forgetQueries();
  }

  /** The fields at time t, computed here on the main thread (for the foam's warm-up and the tests). */
  fieldsOnCpu(t: number): LayerFieldsOnCpu {
    this.computed ??= new FieldsComputedHere(this.spectrum);
    return this.computed.at(t);
  }

  queryFields(t: number): LayerQueryFields {
    this.queried = this.everQueried = true;
    // A query worker only where the JS path's own fields are not the queries' copy.
    if (this.jsFieldsForQueries === null && this.queryWorkerWanted && this.queryWorker === null) this.startQueryWorkerSoon(t);
    const near = this.fromWorker(t);
    if (near !== null) return near;
    if (!this.workerComing) return this.computeHere(this.exactCopy(), t);
    // While a worker is on its way: the provisional copy, carried as the workers' fields are, so that
    // it is computed here at most once per LONGEST_CARRY rather than every frame.
    const provisional = this.provisionalCopy();
    return provisional.lastWithin(t, LONGEST_CARRY) ?? this.computeHere(provisional, t);
  }

  /** The fields of `copy` at time t, computed here unless they are already for t. */
  private computeHere(copy: FieldsComputedHere, t: number): LayerQueryFields {
    if (!copy.isAt(t)) this.computedHere++;
    return copy.at(t);
  }

  /** How many times the queries found no fields close enough to the time asked, and computed them here (once per time). */
  get fieldsComputedHere(): number {
    return this.computedHere;
  }

  /**
   * Whether a worker brings, or will bring once queried, the queries' fields (the JS path's, or the
   * query worker, not given up).
   */
  private get workerComing(): boolean {
    const jsFields = this.jsFieldsForQueries;
    return jsFields ? jsFields.inWorker : this.queryWorkerWanted && this.queryWorker?.givenUp !== true;
  }

  /**
   * A worker's newest fields if they are within LONGEST_CARRY of t, else null: the JS path's own
   * where they are the queries' copy, else the query worker's.
   */
  private fromWorker(t: number): LayerQueryFields | null {
    const jsFields = this.jsFieldsForQueries;
    const newest = jsFields ? jsFields.forQueries() : this.newest;
    return newest !== null && Math.abs(t - newest.time) <= LONGEST_CARRY ? newest : null;
  }

  /** The queries' copy computed here, for the time asked. */
  private exactCopy(): FieldsComputedHere {
    if (this.querySpectrum === this.spectrum) return (this.computed ??= new FieldsComputedHere(this.spectrum));
    return (this.computedReduced ??= new FieldsComputedHere(this.querySpectrum));
  }

  /**
   * The copy computed here while a worker is on its way (provisionalQuerySpectrum), in the arrays of
   * the one the cascade it replaces had (when they fit), or of its own earlier one.
   */
  private provisionalCopy(): FieldsComputedHere {
    if (this.provisional === null) {
      const reuse = this.spare ?? this.predecessor?.takeProvisionalCopy() ?? null;
      this.provisional = new FieldsComputedHere(provisionalQuerySpectrum(this.querySpectrum), reuse);
      this.spare = null;
    }
    return this.provisional;
  }

  /** Gives up the provisional copy (in use or kept aside), for a successor to compute its own in. */
  private takeProvisionalCopy(): FieldsComputedHere | null {
    const copy = this.provisional ?? this.spare;
    this.provisional = this.spare = null;
    return copy;
  }

  /**
   * Has the query worker made QUERY_WORKER_DELAY_MS from now (unless that is under way), then
   * asked for the time of the last query before: in a task of its own rather than in the query
   * (making a Worker takes milliseconds here), and only for a cascade that is kept a while.
   */
  private startQueryWorkerSoon(t: number): void {
    this.lastQueryTime = t;
    this.queryWorkerTimer ??= setTimeout(() => this.startQueryWorker(), QUERY_WORKER_DELAY_MS);
  }

  /** Makes the query worker and asks it for the time of the last query. */
  private startQueryWorker(): void {
    this.queryWorkerTimer = null;
    const { resolution } = this.querySpectrum;
    this.queryWorker = new FieldWorker(
      // The worker builds the copy itself: copying a 256² spectrum to it took ~12 ms here.
      { ...this.origin, resolution },
      'query worker',
      ({ t: time, displacement, derivatives, velocities }) => {
        const previous = this.newest;
        this.newest = { time, resolution, displacement, derivatives, velocities: () => velocities! };
        return previous && { displacement: previous.displacement, derivatives: previous.derivatives, velocities: previous.velocities() };
      },
      (fault) => console.warn(`three-fft-ocean: ${fault}; the queries compute their fields on the main thread.`),
      // A busy machine can hold up a new worker for long; the queries are answered here meanwhile.
      Infinity,
    );
    this.queryWorker.request(this.lastQueryTime, 0, true);
  }

  dispose(): void {
    if (this.queryWorkerTimer !== null) clearTimeout(this.queryWorkerTimer);
    this.queryWorkerTimer = null;
    this.queryWorker?.dispose();
    this.computed = this.computedReduced = this.provisional = this.spare = this.predecessor = null;
    this.newest = null;
  }
}


/** A spectrum's fields computed on the main thread when asked, once per time. */
class FieldsComputedHere {
  private readonly fields: CpuWaveFields;
  private last: LayerQueryFields | null = null;

  /** `reuse`: a copy no longer wanted, whose arrays these may take over (CpuWaveFields). */
  constructor(spectrum: InitialSpectrum, reuse: FieldsComputedHere | null = null) {
    this.fields = new CpuWaveFields(spectrum, reuse?.fields ?? null);
  }

  isAt(t: number): boolean {
    return this.last?.time === t;
  }

  /** The fields last computed, if they are for a time within `carry` seconds of t; else null. */
  lastWithin(t: number, carry: number): LayerQueryFields | null {
    return this.last !== null && Math.abs(t - this.last.time) <= carry ? this.last : null;
  }

  /** The fields at time t, as the queries read them. */
  at(t: number): LayerQueryFields {
    if (this.last?.time !== t) {
      this.fields.update(t);
      this.last = this.fields.forQueries(t);
    }
    return this.last;
  }
}
