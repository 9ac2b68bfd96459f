/**
 * The app's state in the address bar (urlState.ts says how it is written): written at once, after
 * a pause in the changes (panel edits, camera moves), and now and then while time runs, so that a
 * reload comes back near now. history.replaceState: no new history entries.
 */
import { serializeState, type AppState } from './urlState';

export class UrlWriter {
  private timer: ReturnType<typeof setTimeout> | undefined;
  private lastWrite = 0;

  constructor(private readonly state: AppState) {}

  /** Writes the state into the address bar now. */
  write(): void {
    this.cancel();
    this.lastWrite = performance.now();
    const query = serializeState(this.state);
    if (location.search.slice(1) !== query) history.replaceState(history.state, '', `${location.pathname}?${query}${location.hash}`);
  }

  /** Writes the URL after `delayMs` without further changes. */
  schedule(delayMs: number): void {
    clearTimeout(this.timer);
    this.timer = setTimeout(() => this.write(), delayMs);
  }

  /** Drops a scheduled write (the app is closing). */
  cancel(): void {
    clearTimeout(this.timer);
    this.timer = undefined;
  }

  /** At a frame rendered at `now` (ms): while time runs, t in the URL is refreshed every second. */
  refresh(now: number): void {
    if (!this.state.paused && this.timer === undefined && now - this.lastWrite > 1000) this.write();
  }
}
