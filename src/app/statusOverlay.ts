/**
 * What the app shows on top of the canvas, top left: the sea state (Hs, Tp), the FFT path, frame rate and CPU timings
 * (ocean.update and renderer.render as measured on the main thread — GPU work is not included),
 * the time (and how fast it runs, when slower than asked: frames over a second apart), a help line for the keys, and below them notices — warnings about bad values (each names its
 * parameter and stays until dismissed or fixed) and the "copy link" field. Last in the box, a link to the examples gallery.
 */
import type { SimulationPath } from '../layers/oceanSimulation';
import type { Ocean } from '../ocean';

export const PATH_LABELS: Record<SimulationPath, string> = {
  'gpu-rgba32f': 'GPU RGBA32F',
  'gpu-rgba16f': 'GPU RGBA16F',
  'js-worker': 'JS in a worker',
  js: 'JS',
};

/**
 * The sea state as the status line and the panel say it: the spectrum's significant wave height
 * and peak period, and the Hs of what the cascades simulate (4·RMS of the summed height).
 */
export function describeSeaState(ocean: Ocean): string {
  const { significantWaveHeight, peakPeriod } = ocean.seaState;
  const simulated = 4 * ocean.heightRms;
  return `Hs ${significantWaveHeight.toFixed(2)} m, Tp ${peakPeriod.toFixed(1)} s (simulated Hs ${simulated.toFixed(2)} m)`;
}

export interface FrameTimings {
  /** Frames per second over the last interval. */
  fps: number;
  /** Mean CPU milliseconds per frame in ocean.update. */
  simulationMs: number;
  /** Mean CPU milliseconds per frame in renderer.render (and the inspector's tiles). */
  renderMs: number;
}

/** Averages frame timings over intervals of `intervalMs` (pure, for the status line). */
export class TimingAverager {
  private frames = 0;
  private simulation = 0;
  private render = 0;
  private start: number | null = null;
  latest: FrameTimings | null = null;

  constructor(private readonly intervalMs = 500) {}

  /** Adds one frame; returns fresh averages when an interval has passed, else null. */
  add(now: number, simulationMs: number, renderMs: number): FrameTimings | null {
    if (this.start === null) {
      this.start = now;
      return null;
    }
    this.frames++;
    this.simulation += simulationMs;
    this.render += renderMs;
    const elapsed = now - this.start;
    if (elapsed < this.intervalMs) return null;
    this.latest = {
      fps: (1000 * this.frames) / elapsed,
      simulationMs: this.simulation / this.frames,
      renderMs: this.render / this.frames,
    };
    this.start = now;
    this.frames = 0;
    this.simulation = 0;
    this.render = 0;
    return this.latest;
  }
}

/** The simulated time as the status line shows it. */
export interface TimeStatus {
  t: number;
  paused: boolean;
  timeScale: number;
  /** Simulated seconds per real second when not what the time scale asks for (SimulationClock.timeRatio), else null. */
  ratio: number | null;
}

/** The quality level as the status line shows it (AdaptiveQuality). */
export interface QualityStatus {
  level: string;
  auto: boolean;
  targetFps: number;
  /** The median frame time of the last window, ms, or null before the first. */
  frameMs: number | null;
  /** What the level draws: its render scale (of the device's pixel ratio), MSAA, and the ocean's grid and cascades. */
  renderScale: number;
  msaa: boolean;
  resolution: number;
  cascades: number;
}

export class StatusOverlay {
  readonly root: HTMLElement;
  readonly status: HTMLElement;
  readonly time: HTMLElement;
  readonly help: HTMLElement;
  readonly notices: HTMLElement;
  private readonly warnings = new Map<string, HTMLElement>();
  private linkNotice: HTMLElement | null = null;

  constructor(root: HTMLElement, helpText: string) {
    this.root = root;
    root.replaceChildren();
    this.status = element('div', 'status-line');
    this.status.textContent = 'starting…';
    this.time = element('div', 'status-time');
    this.help = element('div', 'status-help');
    this.help.textContent = helpText;
    // The examples gallery (examples/index.html), relative to the app's page so that it is found
    // wherever the built app is served from.
    const links = element('div', 'status-links');
    const examples = document.createElement('a');
    examples.href = 'examples/index.html';
    examples.textContent = 'Examples';
    examples.title = 'Example pages: the ocean as an element, in a three.js scene, in React';
    links.append(examples);
    const box = element('div', 'status-box');
    box.append(this.status, this.time, this.help, links);
    this.notices = element('div', 'notices');
    this.notices.setAttribute('role', 'status');
    this.notices.setAttribute('aria-live', 'polite');
    root.append(box, this.notices);
  }

  /**
   * The status: FFT path, frame rate, the quality level with the median frame time it was chosen
   * by and what it draws, and CPU timings on one line; time and camera speed on the next. `reason`: why the path is
   * not the best asked for (SimulationPath's pathReason), shown after it.
   */
  show(seaState: string, path: SimulationPath, timings: FrameTimings | null, time: TimeStatus, speed: number, reason = '', quality?: QualityStatus): void {
    const parts = [seaState, `FFT: ${PATH_LABELS[path] ?? path}${reason ? ` (${reason})` : ''}`];
    if (timings) parts.push(`${timings.fps.toFixed(0)} fps`);
    if (quality) {
      const frame = quality.frameMs === null ? '' : `, frame ${quality.frameMs.toFixed(0)} ms`;
      const drawn = `render scale ${quality.renderScale}, ${quality.msaa ? '4× MSAA' : 'no MSAA'}, ${quality.cascades} cascade${quality.cascades === 1 ? '' : 's'} of ${quality.resolution}²`;
      parts.push(`quality ${quality.level}${quality.auto ? ` (auto, for ${quality.targetFps} fps${frame})` : frame}: ${drawn}`);
    }
    if (timings) parts.push(`CPU time: sim ${timings.simulationMs.toFixed(1)} ms, render ${timings.renderMs.toFixed(1)} ms`);
    this.status.textContent = parts.join(' · ');
    const clock = [`t = ${time.t.toFixed(2)} s${time.paused ? ' (paused)' : ''}`];
    if (time.ratio !== null) clock.push(`time ×${time.ratio.toPrecision(2)}${time.timeScale === 1 ? '' : ` (time scale ${time.timeScale})`}`);
    this.time.textContent = [...clock, `camera speed ${formatSpeed(speed)} m/s`].join(' · ');
  }

  /** Shows (or replaces) the warning for `parameter`. */
  warn(parameter: string, message: string): void {
    let item = this.warnings.get(parameter);
    if (!item) {
      item = element('div', 'notice warning');
      item.dataset.parameter = parameter;
      const text = element('span', 'notice-text');
      const close = dismissButton(() => this.clearWarning(parameter));
      item.append(text, close);
      this.notices.append(item);
      this.warnings.set(parameter, item);
    }
    item.querySelector('.notice-text')!.textContent = `⚠ ${message}`;
  }

  clearWarning(parameter: string): void {
    this.warnings.get(parameter)?.remove();
    this.warnings.delete(parameter);
  }

  /** Parameters with a warning on screen. */
  get warningParameters(): string[] {
    return [...this.warnings.keys()];
  }

  /** Shows the link in a selectable read-only field with a note whether it is in the clipboard. */
  showLink(url: string, copied: boolean): HTMLInputElement {
    this.linkNotice?.remove();
    const item = element('div', 'notice link');
    const label = element('div', 'notice-text');
    label.textContent = copied ? 'Link copied to the clipboard:' : 'Copy this link (the clipboard is unavailable here):';
    const field = document.createElement('input');
    field.type = 'text';
    field.readOnly = true;
    field.value = url;
    field.className = 'link-field';
    field.addEventListener('focus', () => field.select());
    item.append(label, dismissButton(() => this.hideLink()), field);
    this.notices.prepend(item);
    this.linkNotice = item;
    if (!copied) {
      field.focus();
      field.select();
    }
    return field;
  }

  hideLink(): void {
    this.linkNotice?.remove();
    this.linkNotice = null;
  }
}

function formatSpeed(speed: number): string {
  return speed >= 10 ? speed.toFixed(0) : speed.toFixed(1);
}

function element(tag: string, className: string): HTMLElement {
  const el = document.createElement(tag);
  el.className = className;
  return el;
}

function dismissButton(onClick: () => void): HTMLButtonElement {
  const button = document.createElement('button');
  button.type = 'button';
  button.className = 'notice-close';
  button.title = 'Dismiss';
  button.setAttribute('aria-label', 'Dismiss');
  button.textContent = '×';
  button.addEventListener('click', onClick);
  return button;
}
