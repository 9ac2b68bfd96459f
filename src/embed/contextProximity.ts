/**
 * When an <fft-ocean> holds a WebGL context. Browsers keep only about 16 per page (beyond that they
 * drop the oldest for good), so an element holds its renderer, ocean and context only while it is
 * near the screen: it creates them when it comes within NEAR_MARGIN of the viewport, so they are
 * ready when it scrolls in, and frees them beyond FAR_MARGIN; the gap keeps scrolling back and
 * forth a little from rebuilding them. When MAX_CONTEXT_HOLDERS elements hold a context, one that
 * needs a context first frees the oldest held by an element beyond NEAR_MARGIN, else by one off
 * screen; one on screen keeps its context.
 */

/** Within this many px of the viewport an element creates its renderer and ocean. */
const NEAR_MARGIN = 200;
/** Beyond this many px from the viewport an element frees them. */
const FAR_MARGIN = 500;
/**
 * At most this many elements hold a WebGL context at once, unless more are on screen: below the
 * 16 per page that Chromium keeps, leaving some to the page's own canvases.
 */
const MAX_CONTEXT_HOLDERS = 12;

/** What a ContextProximity asks of its element. */
export interface ProximityHandlers {
  /** Whether the element holds a context now. */
  holds(): boolean;
  /** Whether it may start (it has not failed since it was put into the page). */
  mayStart(): boolean;
  /** Creates the renderer, ocean, … (and calls hold). */
  start(): void;
  /** Frees them (and calls release). */
  stop(): void;
  /** Being on screen changed. */
  onScreenChanged(): void;
}

/** Elements holding a renderer (and so a WebGL context), in the order they created it. */
const contextHolders = new Set<ContextProximity>();

/** How near the screen one element is, and the start and stop that follow from it. */
export class ContextProximity {
  /** Whether a part of the element is inside the viewport, as last reported. */
  onScreen = false;
  /** Whether a part of the element is within NEAR_MARGIN of the viewport, as last reported. */
  near = false;
  /** The observers of the viewport and of the NEAR_MARGIN and FAR_MARGIN bands while the element is on the page (else empty). */
  private observers: IntersectionObserver[] = [];

  constructor(
    private readonly element: Element,
    private readonly handlers: ProximityHandlers,
  ) {}

  get watching(): boolean {
    return this.observers.length > 0;
  }

  /**
   * Starts (creating the renderer, ocean, …) when the element comes within NEAR_MARGIN of the
   * viewport, or on screen (after makeRoomForContext stopped it while near), and stops (freeing
   * them) once it is beyond FAR_MARGIN. A failed start (its message shows) is not retried until
   * the element is put back into the page.
   */
  watch(): void {
    const intersecting = (entries: IntersectionObserverEntry[]) => entries[entries.length - 1].isIntersecting;
    const startIfNeeded = () => {
      if (this.near && !this.handlers.holds() && this.handlers.mayStart()) this.handlers.start();
    };
    const onScreen = new IntersectionObserver((entries) => {
      this.onScreen = intersecting(entries);
      startIfNeeded();
      this.handlers.onScreenChanged();
    });
    const near = new IntersectionObserver(
      (entries) => {
        this.near = intersecting(entries);
        startIfNeeded();
      },
      { rootMargin: `${NEAR_MARGIN}px` },
    );
    const far = new IntersectionObserver(
      (entries) => {
        if (!intersecting(entries) && this.handlers.holds()) this.handlers.stop();
      },
      { rootMargin: `${FAR_MARGIN}px` },
    );
    this.observers = [onScreen, near, far];
    for (const observer of this.observers) observer.observe(this.element);
  }

  /** Stops watching (the element left the page): neither on screen nor near. */
  unwatch(): void {
    for (const observer of this.observers) observer.disconnect();
    this.observers = [];
    this.onScreen = false;
    this.near = false;
  }

  /**
   * Stops other elements until one more context stays within MAX_CONTEXT_HOLDERS: the oldest
   * holders beyond NEAR_MARGIN first, then the oldest off screen; never one on screen.
   */
  makeRoomForContext(): void {
    for (const spare of [(holder: ContextProximity) => !holder.near, (holder: ContextProximity) => !holder.onScreen]) {
      for (const holder of contextHolders) {
        if (contextHolders.size < MAX_CONTEXT_HOLDERS) return;
        if (spare(holder)) holder.handlers.stop();
      }
    }
  }

  /** The element now holds a context. */
  hold(): void {
    contextHolders.add(this);
  }

  /** The element has given its context back. */
  release(): void {
    contextHolders.delete(this);
  }
}
