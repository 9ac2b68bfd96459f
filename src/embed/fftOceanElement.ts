/**
 * <fft-ocean>: the ocean as an HTML element, for pages that just want a sea.
 *
 *   <script type="module">import 'three-fft-ocean/register';</script>
 *   <fft-ocean wind-speed="14" sun-elevation="12" style="height: 400px"></fft-ocean>
 *
 * The element makes its own canvas (in its shadow root), WebGLRenderer, scene, camera and Ocean,
 * and renders a slowly drifting view out to the horizon. Attributes (all optional, all live):
 *
 *   every option of the tables in src/parameters/ in kebab case, written as parseOptionText reads
 *   them (an alias in kebab case too: scatter-colour is scatter-color):
 *     simulation (SIMULATION_OPTIONS): wind-speed, spectrum, fetch, patch-sizes="13.7,79.3,457",
 *       depth="deep", …                                                   → ocean.setParameters
 *     sun (SUN_OPTIONS): sun-elevation, sun-azimuth (degrees)             → ocean.setSun
 *     shading (SHADING_OPTIONS): ior, absorption="0.45,0.07,0.04", scatter-color and caustic-color
 *       ("#1a6b80", any CSS colour, or linear "r,g,b"), caustic-power, shading-mode (full,
 *       fresnel, reflection, refraction, caustics, height), reflections (scene, sky)
 *                                                                         → ocean.setShading
 *   path (auto, gpu, js)                      which simulation path runs
 *   time-scale (default 1)                    simulated seconds per real second, at most 1000 either way
 *   paused (boolean)                          freezes time; the view still redraws on changes
 *   camera-height (metres, default 8)         height of the viewpoint above the mean sea level
 *   boat (boolean)                            a boat circling ahead of the view, leaving a wake on
 *                                             the local waves (src/objects/boat.ts)
 *   quality (auto, high, medium, low, lowest) 'auto' lowers and raises the quality level (render
 *                                             scale, MSAA, grid, cascades: runtime/adaptiveQuality.ts)
 *                                             to hold target-fps; a level stays fixed
 *   target-fps (default 30)                   the frame rate 'auto' holds
 * A click or tap on the sea drops a stone there: rings spread on the local waves. When the quality
 * level changes the element dispatches fft-ocean-quality-change (detail: { level, medianFrameMs });
 * element.quality is the AdaptiveQuality in force.
 *
 * A bad value logs a console warning that names the attribute and quotes the value as written
 * (its first 40 characters), and the last good value stays.
 * Removing an attribute restores its default. The attributes are the element's settings: changes
 * made directly on element.ocean last only as long as that Ocean (see removal below).
 *
 * Sizing: display:block, as wide as its container and 16:9 (at least 150 px high) unless the page
 * gives it a height; the drawing buffer follows the box (ResizeObserver). It renders only while it is on screen
 * (IntersectionObserver) and its tab is visible; simulated time stands still while it does not
 * render, so nothing jumps when it comes back. While it renders, time follows the real time ×
 * time-scale however slow the frames (SimulationClock; a frame over a second late counts as an
 * ordinary one). A lost WebGL context is waited out and the same
 * scene is drawn again at the same time once the browser restores it. Without WebGL 2 the box
 * shows a short message instead of staying blank.
 *
 * Any number of elements can be on one page, although browsers keep only about 16 WebGL contexts
 * per page (beyond that they drop the oldest for good): an element holds its renderer, ocean and
 * WebGL context only while it is near the screen. It creates them when it comes within 200 px of
 * the viewport (NEAR_MARGIN), so they are ready when it scrolls in, and frees them, as on
 * removal, when it is more than 500 px away (FAR_MARGIN); the gap keeps scrolling back and forth
 * a little from rebuilding them. When 12 elements (MAX_CONTEXT_HOLDERS) hold a context, one that
 * needs a context first frees the oldest held by an element beyond 200 px, else by one off
 * screen; one on screen keeps its context. Coming back creates them again, at the same simulated
 * time with the same settings (its attributes). While an element holds none, its ocean,
 * renderer, scene, camera and canvas are null.
 *
 * Removing it from the page frees the renderer, the ocean, the WebGL context, the observers and
 * listeners (a synchronous move to another place in the document keeps them); putting it back
 * creates them again, once it is near the screen, and continues at the same simulated time.
 *
 * Define it with defineFftOceanElement() (or import src/embed/register.ts, which does).
 */
import { ACESFilmicToneMapping, PerspectiveCamera, Scene, Vector2, WebGLRenderer } from 'three';
import { Ocean } from '../ocean';
import { SceneOutput } from '../render/sceneOutput';
import { AdaptiveQuality, simulationAtQuality, type QualitySetting } from '../runtime/adaptiveQuality';
import { applyQualityStep } from '../runtime/applyQuality';
import { DEFAULT_QUALITY, QUALITY_OPTIONS } from '../parameters/qualityOptions';
import { Boat } from '../objects/boat';
import { SunLight } from '../objects/sunLight';
import { FrameLoop } from '../runtime/frameLoop';
import { describeValue, formatOptionText, kebabCase, optionRoutes, parseOptionText, quoteText, type OptionRule } from '../parameters/options';
import { DEFAULT_RUN, RUN_OPTIONS } from '../parameters/runOptions';
import { DEFAULT_SHADING, DEFAULT_SUN, SHADING_OPTIONS, SUN_OPTIONS, type ShadingOptions, type SunOptions } from '../parameters/sceneOptions';
import type { PathPreference } from '../layers/oceanSimulation';
import { CLICKED_STONE, seaPointUnder } from '../render/seaPointer';
import { DEFAULT_PARAMETERS, parseDecimal, SIMULATION_OPTIONS, validateParameters, type SimulationParameters } from '../parameters/parameters';

/** The parts of the settings that attributes set from an option table. */
type Group = 'simulation' | 'sun' | 'shading';
const TABLES: Readonly<Record<Group, Readonly<Record<string, OptionRule>>>> = {
  simulation: SIMULATION_OPTIONS,
  sun: SUN_OPTIONS,
  shading: SHADING_OPTIONS,
};
const GROUP_DEFAULTS: Readonly<Record<Group, Readonly<Record<string, unknown>>>> = {
  simulation: DEFAULT_PARAMETERS,
  sun: DEFAULT_SUN,
  shading: DEFAULT_SHADING,
};

/** Attributes that map onto options: each option's name, and each alias, in kebab case. */
const OPTION_ATTRIBUTES = optionRoutes(TABLES, kebabCase);

/**
 * The element's own settings that a table's rule reads, as the app's URL reads them: path and
 * time-scale (parameters/runOptions.ts), quality and target-fps (parameters/qualityOptions.ts).
 */
const OWN_TABLES = { run: RUN_OPTIONS, quality: QUALITY_OPTIONS } as const;
const OWN_ATTRIBUTES = optionRoutes<keyof typeof OWN_TABLES>(OWN_TABLES, kebabCase);
type OwnKey = 'path' | 'timeScale' | 'quality' | 'targetFps';

/** Every attribute the element reads. */
export const FFT_OCEAN_ATTRIBUTES = [...OPTION_ATTRIBUTES.keys(), ...OWN_ATTRIBUTES.keys(), 'paused', 'camera-height', 'boat'] as const;
export type FftOceanAttribute = (typeof FFT_OCEAN_ATTRIBUTES)[number];

/** The element's own attributes (beside the options), as its settings hold them. */
export interface ElementSettings {
  /** Which simulation path runs: 'auto', 'gpu' or 'js' (the Ocean's path option). @defaultValue 'auto' */
  path: PathPreference;
  /** Simulated seconds per real second, [-1000, 1000]. @defaultValue 1 */
  timeScale: number;
  /** A boolean attribute: time stands still; the view still redraws on changes. @defaultValue false */
  paused: boolean;
  /** Height of the viewpoint above the mean sea level, m, (0, 10000]. @defaultValue 8 */
  cameraHeight: number;
  /** A boolean attribute: a boat circling ahead of the view, leaving a wake on the local waves. @defaultValue false */
  boat: boolean;
  /** 'auto' lowers and raises the quality level (render scale, MSAA, grid, cascades) to hold target-fps; high, medium, low or lowest stays fixed. @defaultValue 'auto' */
  quality: QualitySetting;
  /** The frame rate 'auto' holds, frames per second, [5, 240]. @defaultValue 30 */
  targetFps: number;
}

/** The element's current (last good) settings: the options its attributes set, and its own. */
interface Settings extends ElementSettings {
  simulation: Partial<SimulationParameters>;
  sun: Partial<SunOptions>;
  shading: Partial<ShadingOptions>;
}

export const ELEMENT_DEFAULTS: Readonly<ElementSettings> = {
  path: DEFAULT_RUN.path,
  timeScale: DEFAULT_RUN.timeScale,
  paused: false,
  cameraHeight: 8,
  boat: false,
  ...DEFAULT_QUALITY,
};

/** Within this many px of the viewport an element creates its renderer and ocean. */
const NEAR_MARGIN = 200;
/** Beyond this many px from the viewport an element frees them. */
const FAR_MARGIN = 500;
/**
 * At most this many elements hold a WebGL context at once, unless more are on screen: below the
 * 16 per page that Chromium keeps, leaving some to the page's own canvases.
 */
const MAX_CONTEXT_HOLDERS = 12;

/** What exists while the element is on the page, near the screen, and WebGL 2 works. */
interface Live {
  canvas: HTMLCanvasElement;
  renderer: WebGLRenderer;
  scene: Scene;
  camera: PerspectiveCamera;
  ocean: Ocean;
  /** Draws the scene onto the canvas, multisampled at the quality levels with MSAA. */
  output: SceneOutput;
  /** The pixel ratio at render scale 1. */
  pixelRatio: number;
  resizeObserver: ResizeObserver;
  /** Removes every listener start() added. */
  removeListeners: () => void;
  contextLost: boolean;
  /** The boat and the light it is lit by, while the boat attribute is on. */
  boat: { boat: Boat; light: SunLight } | null;
}

// The background is a sky-and-sea placeholder until the first frame (or without WebGL 2).
// The sizer gives the box a height (16:9 of its width, at least 150 px) when the page sets none;
// a height from the page wins (the box clips the sizer). It adds no minimum width, so the element
// shrinks in grids and flex rows like any block (unlike aspect-ratio, which would also turn a
// page's height into a width).
const STYLE = `
  :host { display: block; position: relative; overflow: hidden;
          background: linear-gradient(#a9c0d3, #e3e8ea 49%, #2a4a66 50%, #0b1620); }
  :host([hidden]) { display: none; }
  .sizer { box-sizing: border-box; padding-top: 56.25%; min-height: 150px; }
  canvas { position: absolute; inset: 0; width: 100%; height: 100%; display: block; }
  .message { position: absolute; inset: 0; display: flex; align-items: center; justify-content: center;
             box-sizing: border-box; padding: 1em; text-align: center; color: #dde6ee;
             font: 15px/1.45 system-ui, sans-serif; background: linear-gradient(#5d86a8, #17324a 55%, #0b1620); }
`;

/** STYLE as a stylesheet, shared by every element of the page; made on first use (only browsers have it). */
let sharedSheet: CSSStyleSheet | null = null;

/**
 * Gives a shadow root STYLE. A constructed stylesheet (adoptedStyleSheets) is allowed by a strict
 * Content-Security-Policy (style-src 'self', no 'unsafe-inline'), which blocks a <style> element;
 * browsers without constructable stylesheets (Safari 15 to 16.3, which have WebGL 2) get the
 * <style> element instead.
 */
function adoptStyle(root: ShadowRoot): void {
  if ('adoptedStyleSheets' in root && 'replaceSync' in CSSStyleSheet.prototype) {
    if (!sharedSheet) {
      sharedSheet = new CSSStyleSheet();
      sharedSheet.replaceSync(STYLE);
    }
    root.adoptedStyleSheets = [sharedSheet];
  } else {
    const style = document.createElement('style');
    style.textContent = STYLE;
    root.append(style);
  }
}

// Defined also where there is no DOM (server-side rendering, Node tests), so importing the
// library there does not throw; the element only works in a browser.
const ElementBase: typeof HTMLElement =
  typeof HTMLElement === 'undefined' ? (class {} as unknown as typeof HTMLElement) : HTMLElement;

export class FftOceanElement extends ElementBase {
  static get observedAttributes(): readonly string[] {
    return FFT_OCEAN_ATTRIBUTES;
  }

  private readonly settings: Settings = { simulation: {}, sun: {}, shading: {}, ...ELEMENT_DEFAULTS };
  private readonly root: ShadowRoot;
  private live: Live | null = null;
  private message: HTMLElement | null = null;
  /**
   * The frame loop (runtime/frameLoop.ts): its clock, restarted whenever drawing stops or pauses,
   * its adaptive quality (the quality and target-fps attributes; kept while the element has no
   * context) and the simulated time shown.
   */
  private readonly loop = new FrameLoop(new AdaptiveQuality(ELEMENT_DEFAULTS.quality, ELEMENT_DEFAULTS.targetFps), { t: 0 });
  private frameRequest = 0;
  private needsDraw = true;
  private framesDrawn = 0;
  private readonly onVisibilityChange = () => this.activityChanged();
  /** The observers of the viewport and of the NEAR_MARGIN and FAR_MARGIN bands while the element is on the page (else empty). */
  private proximityObservers: IntersectionObserver[] = [];
  /** Whether a part of the element is inside the viewport, as last reported. */
  private onScreen = false;
  /** Whether a part of the element is within NEAR_MARGIN of the viewport, as last reported. */
  private near = false;
  /** Elements holding a renderer (and so a WebGL context), in the order they created it. */
  private static readonly contextHolders = new Set<FftOceanElement>();

  constructor() {
    super();
    this.root = this.attachShadow({ mode: 'open' });
    adoptStyle(this.root);
    const sizer = document.createElement('div');
    sizer.className = 'sizer';
    this.root.append(sizer);
  }

  /**
   * The Ocean while the element is on the page and near the screen (null before, while it is far
   * from the screen, after removal or without WebGL 2); so are renderer, camera, scene and canvas.
   */
  get ocean(): Ocean | null {
    return this.live?.ocean ?? null;
  }

  get renderer(): WebGLRenderer | null {
    return this.live?.renderer ?? null;
  }

  get camera(): PerspectiveCamera | null {
    return this.live?.camera ?? null;
  }

  get scene(): Scene | null {
    return this.live?.scene ?? null;
  }

  /** What draws the scene onto the canvas, multisampled or not as the quality level says; null with no context (see ocean). */
  get output(): SceneOutput | null {
    return this.live?.output ?? null;
  }

  /** The element's canvas (inside its shadow root), or null when it has none (see ocean). */
  get canvas(): HTMLCanvasElement | null {
    return this.live?.canvas ?? null;
  }

  /** Simulated seconds shown; settable (any finite number) to jump to a moment. */
  get time(): number {
    return this.loop.time.t;
  }

  set time(seconds: number) {
    if (typeof seconds !== 'number' || !Number.isFinite(seconds)) {
      console.warn(`<fft-ocean>: ignoring time = ${describeValue(seconds)}: it must be a finite number of seconds`);
      return;
    }
    this.loop.time.t = seconds;
    this.invalidate();
  }

  /**
   * The adaptive quality in force (runtime/adaptiveQuality.ts): its setting, its level and step,
   * and the median frame time that chose it.
   */
  get quality(): AdaptiveQuality {
    return this.loop.quality;
  }

  /** Frames drawn since the element was created (for diagnostics and tests). */
  get frameCount(): number {
    return this.framesDrawn;
  }

  /** Whether the element is drawing frames now (on the page, on screen, tab visible, context alive). */
  get active(): boolean {
    return this.isActive();
  }

  /**
   * Draws the current time now, synchronously (e.g. right before canvas.toDataURL() or
   * readPixels). Returns false when there is nothing to draw into (see ocean) or the context is lost.
   */
  renderFrame(): boolean {
    const live = this.live;
    if (!live || live.contextLost) return false;
    this.draw(live);
    return true;
  }

  connectedCallback(): void {
    if (this.proximityObservers.length === 0) this.watchProximity();
  }

  disconnectedCallback(): void {
    // A move (remove + insert in the same task) keeps everything; a real removal frees it all.
    queueMicrotask(() => {
      if (this.isConnected) return;
      for (const observer of this.proximityObservers) observer.disconnect();
      this.proximityObservers = [];
      this.onScreen = false;
      this.near = false;
      this.stop();
    });
  }

  attributeChangedCallback(name: string, _previous: string | null, value: string | null): void {
    this.applyAttribute(name as FftOceanAttribute, value);
  }

  // ---- attributes

  private applyAttribute(name: FftOceanAttribute, raw: string | null): void {
    const s = this.settings;
    const reject = (reason: string, kept: unknown): void => {
      console.warn(`<fft-ocean>: ignoring ${name}=${quoteText(raw ?? '')}: ${reason}; keeping ${formatOptionText(kept)}`);
    };
    const option = OPTION_ATTRIBUTES.get(name);
    const own = OWN_ATTRIBUTES.get(name);
    if (option) {
      const key = option.key;
      try {
        this.applyOption(option.group, key, option.name, raw);
      } catch (error) {
        reject(errorMessage(error), this.optionSetting(option.group, key));
        return;
      }
    } else if (own) {
      // The URL's rule and message, under the attribute's name.
      const key = own.key as OwnKey;
      try {
        const value = raw === null ? ELEMENT_DEFAULTS[key] : parseOptionText(OWN_TABLES[own.group] as Readonly<Record<string, OptionRule>>, own.name, raw);
        Object.assign(s, { [key]: value });
      } catch (error) {
        reject(errorMessage(error), s[key]);
        return;
      }
      const ocean = this.live?.ocean;
      if (key === 'path' && ocean && ocean.simulation.pathPreference !== s.path) ocean.simulation.pathPreference = s.path;
      if (key === 'quality' || key === 'targetFps') {
        this.loop.quality = new AdaptiveQuality(s.quality, s.targetFps);
        if (this.live) this.applyQuality(this.live);
      }
    } else if (name === 'camera-height') {
      const value = raw === null ? ELEMENT_DEFAULTS.cameraHeight : parseDecimal(raw);
      if (!Number.isFinite(value) || value <= 0 || value > 10000) {
        reject('it must be a number of metres above 0 and at most 10000', s.cameraHeight);
        return;
      }
      s.cameraHeight = value;
    } else if (name === 'paused') {
      const paused = booleanAttribute(raw);
      if (paused !== s.paused) {
        s.paused = paused;
        this.loop.restart();
      }
    } else if (name === 'boat') {
      s.boat = booleanAttribute(raw);
      if (this.live) this.showBoat(this.live);
    }
    this.invalidate();
  }

  /** The option's current value: its setting, or its default. */
  private optionSetting(group: Group, key: string, settings: object = this.settings[group]): unknown {
    return (settings as Record<string, unknown>)[key] ?? GROUP_DEFAULTS[group][key];
  }

  /**
   * Sets the option `key`, named `name` (the key or an alias), as written in `raw` (null: back to
   * its default) in the settings and on the ocean; throws a ParameterError and changes nothing
   * when it is bad.
   */
  private applyOption(group: Group, key: string, name: string, raw: string | null): void {
    const next: Record<string, unknown> = { ...this.settings[group] };
    if (raw === null) delete next[key];
    else next[key] = parseOptionText(TABLES[group], name, raw);
    const ocean = this.live?.ocean;
    if (group === 'simulation') {
      const asked = validateParameters(next); // throws a ParameterError naming the rule
      // The grid and the cascades run within the quality level's.
      if (key === 'resolution' || key === 'patchSizes') {
        if (this.live) applyQualityStep(this.live, asked, this.loop.quality.step);
      } else {
        ocean?.setParameters({ [key]: this.optionSetting(group, key, next) });
      }
    } else if (group === 'sun') {
      ocean?.setSun(this.optionSetting(group, 'sunElevation', next) as number, this.optionSetting(group, 'sunAzimuth', next) as number);
    } else {
      ocean?.setShading({ [key]: this.optionSetting(group, key, next) });
    }
    (this.settings as unknown as Record<Group, object>)[group] = next;
  }

  // ---- life cycle

  /**
   * Starts (creating the renderer, ocean, …) when the element comes within NEAR_MARGIN of the
   * viewport, or on screen (after makeRoomForContext stopped it while near), and stops (freeing
   * them) once it is beyond FAR_MARGIN. A failed start (its message shows) is not retried until
   * the element is put back into the page.
   */
  private watchProximity(): void {
    const intersecting = (entries: IntersectionObserverEntry[]) => entries[entries.length - 1].isIntersecting;
    const startIfNeeded = () => {
      if (this.near && !this.live && !this.message) this.start();
    };
    const onScreen = new IntersectionObserver((entries) => {
      this.onScreen = intersecting(entries);
      startIfNeeded();
      this.activityChanged();
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
        if (!intersecting(entries) && this.live) this.stop();
      },
      { rootMargin: `${FAR_MARGIN}px` },
    );
    this.proximityObservers = [onScreen, near, far];
    for (const observer of this.proximityObservers) observer.observe(this);
  }

  /**
   * Stops other elements until one more context stays within MAX_CONTEXT_HOLDERS: the oldest
   * holders beyond NEAR_MARGIN first, then the oldest off screen; never one on screen.
   */
  private makeRoomForContext(): void {
    const holders = FftOceanElement.contextHolders;
    for (const spare of [(holder: FftOceanElement) => !holder.near, (holder: FftOceanElement) => !holder.onScreen]) {
      for (const holder of holders) {
        if (holders.size < MAX_CONTEXT_HOLDERS) return;
        if (spare(holder)) holder.stop();
      }
    }
  }

  private start(): void {
    this.message?.remove();
    this.message = null;
    this.makeRoomForContext();
    const canvas = document.createElement('canvas');
    canvas.setAttribute('part', 'canvas');
    canvas.setAttribute('role', 'img');
    canvas.setAttribute('aria-label', 'An animated view of the open sea');
    let renderer: WebGLRenderer;
    try {
      // No antialiasing of the canvas's own, which could not be turned off: MSAA is the quality level's (SceneOutput).
      renderer = new WebGLRenderer({ canvas, antialias: false, powerPreference: 'high-performance' });
    } catch (error) {
      this.fail(
        'This ocean needs WebGL 2, which this browser does not provide (or has switched off).',
        error,
      );
      return;
    }
    let ocean: Ocean;
    const s = this.settings;
    try {
      ocean = new Ocean(renderer, {
        ...s.simulation,
        ...simulationAtQuality(validateParameters(s.simulation), this.loop.quality.step),
        ...s.sun,
        ...s.shading,
        path: s.path,
      });
    } catch (error) {
      renderer.dispose();
      renderer.forceContextLoss();
      this.fail('The ocean could not start in this browser.', error);
      return;
    }
    renderer.toneMapping = ACESFilmicToneMapping;
    const scene = new Scene();
    scene.add(ocean);
    const camera = new PerspectiveCamera(50, 16 / 9, 0.5, 1e4);
    this.root.append(canvas);

    const onContextLost = () => {
      live.contextLost = true;
      this.activityChanged();
    };
    const onContextRestored = () => {
      // three.js has rebuilt its state and the sky has re-rendered its cube (their listeners
      // were added first); the fields are recomputed by the next update().
      live.contextLost = false;
      this.activityChanged();
    };
    // A click (or tap) on the sea drops a stone there, as in the app (local waves).
    const onClick = (event: MouseEvent) => {
      const hit = seaPointUnder(camera, canvas, event.clientX, event.clientY);
      if (hit) ocean.localWaves?.drop(hit.x, hit.z, CLICKED_STONE);
    };
    canvas.addEventListener('click', onClick);
    // The path changed by itself (a worker failed, the main thread took over): tell the page.
    ocean.addEventListener('pathchange', ({ path }) => this.dispatchEvent(new CustomEvent('fft-ocean-path-change', { detail: path })));
    canvas.addEventListener('webglcontextlost', onContextLost);
    canvas.addEventListener('webglcontextrestored', onContextRestored);
    document.addEventListener('visibilitychange', this.onVisibilityChange);

    const resizeObserver = new ResizeObserver(() => this.resize());
    const live: Live = {
      canvas,
      renderer,
      scene,
      camera,
      ocean,
      output: new SceneOutput(renderer),
      pixelRatio: Math.min(window.devicePixelRatio || 1, 2),
      resizeObserver,
      contextLost: false,
      boat: null,
      removeListeners: () => {
        canvas.removeEventListener('click', onClick);
        canvas.removeEventListener('webglcontextlost', onContextLost);
        canvas.removeEventListener('webglcontextrestored', onContextRestored);
        document.removeEventListener('visibilitychange', this.onVisibilityChange);
      },
    };
    this.live = live;
    this.applyQuality(live);
    FftOceanElement.contextHolders.add(this);
    this.showBoat(live);
    this.loop.restart();
    this.resize();
    resizeObserver.observe(this);
  }

  private stop(): void {
    const live = this.live;
    if (live) {
      this.live = null;
      FftOceanElement.contextHolders.delete(this);
      if (this.frameRequest) cancelAnimationFrame(this.frameRequest);
      this.frameRequest = 0;
      live.resizeObserver.disconnect();
      live.removeListeners();
      this.showBoat(live, false);
      live.scene.remove(live.ocean);
      live.ocean.dispose();
      live.output.dispose();
      live.renderer.dispose();
      // Give the context back now rather than at garbage collection: browsers allow few at once.
      live.renderer.forceContextLoss();
      live.canvas.remove();
    }
    this.message?.remove();
    this.message = null;
    this.loop.restart();
    this.needsDraw = true;
  }

  /** Puts the quality level in force: pixel ratio, MSAA, grid and cascades (applyQuality.ts). */
  private applyQuality(live: Live): void {
    applyQualityStep(live, validateParameters(this.settings.simulation), this.loop.quality.step);
  }

  /** Puts the boat (and its light) in the scene, or takes it out and frees it, as `show` says. */
  private showBoat(live: Live, show = this.settings.boat): void {
    if (show && !live.boat) {
      const boat = new Boat(live.ocean, (t) => {
        const view = viewDrift(t, this.optionSetting('sun', 'sunAzimuth') as number);
        return { x: view.x + BOAT_AHEAD * Math.cos(view.heading), z: view.z + BOAT_AHEAD * Math.sin(view.heading) };
      });
      live.boat = { boat, light: new SunLight(live.ocean) };
      live.scene.add(boat, live.boat.light);
    } else if (!show && live.boat) {
      live.scene.remove(live.boat.boat, live.boat.light);
      live.boat.boat.dispose();
      live.boat = null;
    }
    this.invalidate();
  }

  private fail(text: string, error: unknown): void {
    console.error(`<fft-ocean>: ${text}`, error);
    const message = document.createElement('div');
    message.className = 'message';
    message.setAttribute('part', 'message');
    message.setAttribute('role', 'note');
    message.textContent = text;
    this.root.append(message);
    this.message = message;
    this.dispatchEvent(new CustomEvent('fft-ocean-error', { detail: { message: text, error } }));
  }

  // ---- frames

  private isActive(): boolean {
    const live = this.live;
    return !!live && this.onScreen && !live.contextLost && document.visibilityState !== 'hidden';
  }

  /** Something changed that affects whether frames are drawn. */
  private activityChanged(): void {
    this.loop.restart(); // the time that passed while inactive is not simulated
    this.invalidate();
  }

  /** The picture is out of date: draw on the next frame if active. */
  private invalidate(): void {
    this.needsDraw = true;
    this.schedule();
  }

  private schedule(): void {
    if (this.frameRequest === 0 && this.isActive()) this.frameRequest = requestAnimationFrame(this.tick);
  }

  private readonly tick = (now: number): void => {
    this.frameRequest = 0;
    const live = this.live;
    if (!live || !this.isActive()) {
      this.loop.restart();
      return;
    }
    const animating = !this.settings.paused;
    // Only frames drawn one after another tell how fast they come (paused, frames come on changes).
    if (animating && this.loop.advance(now, this.settings.timeScale)) {
      this.applyQuality(live);
      const { level, medianFrameMs } = this.loop.quality;
      this.dispatchEvent(new CustomEvent('fft-ocean-quality-change', { detail: { level, medianFrameMs } }));
    }
    if (animating || this.needsDraw) {
      try {
        this.draw(live);
      } catch (error) {
        // Nothing to recover with: say so in the box and to the page (fft-ocean-error), and stop.
        this.fail('Drawing the ocean failed; it has stopped.', error);
        return; // no further frames
      }
    }
    if (animating) this.schedule();
  };

  private resize(): void {
    const live = this.live;
    if (!live) return;
    const width = Math.max(1, this.clientWidth);
    const height = Math.max(1, this.clientHeight);
    live.camera.aspect = width / height;
    live.camera.updateProjectionMatrix();
    // The ResizeObserver's first report after start() is of the size start() set: keep the picture.
    const current = live.renderer.getSize(new Vector2());
    if (current.x === width && current.y === height) return;
    live.renderer.setSize(width, height, false);
    // Resizing clears the canvas: draw again right away so it never shows blank.
    if (this.isActive()) this.draw(live);
    else this.needsDraw = true;
  }

  private draw(live: Live): void {
    this.needsDraw = false;
    const sunAzimuth = this.optionSetting('sun', 'sunAzimuth') as number;
    // The time wrapped as a double resolves it, the sea updated for the drifting view, the far plane, the render.
    this.loop.draw(live, {
      placeCamera: (t) => placeCamera(live.camera, t, this.settings.cameraHeight, sunAzimuth),
      beforeRender: () => {
        live.boat?.boat.update();
        live.boat?.light.update();
      },
    });
    this.framesDrawn++;
    if (this.framesDrawn === 1) this.dispatchEvent(new CustomEvent('fft-ocean-ready'));
  }
}

/**
 * The default view: `height` metres up, a few degrees below the horizon, facing 30° to one side
 * of the sun's azimuth (so its glitter path crosses the view), drifting forward at 1.5 m/s and
 * turning slowly. A function of simulated time only, so it stands still when paused.
 */
export function placeCamera(camera: PerspectiveCamera, t: number, height: number, sunAzimuthDeg: number): void {
  const { x, z, heading } = viewDrift(t, sunAzimuthDeg);
  const yaw = heading + 0.12 * Math.sin((2 * Math.PI * t) / 120);
  const forwardX = Math.cos(yaw);
  const forwardZ = Math.sin(yaw);
  camera.position.set(x, height, z);
  const pitch = (-6 * Math.PI) / 180;
  const distance = 100;
  camera.lookAt(
    x + distance * Math.cos(pitch) * forwardX,
    height + distance * Math.sin(pitch),
    z + distance * Math.cos(pitch) * forwardZ,
  );
  camera.updateMatrixWorld();
}

/** Where the default view is on the sea at time t (s), and the heading (rad) it drifts along. */
function viewDrift(t: number, sunAzimuthDeg: number): { x: number; z: number; heading: number } {
  const heading = ((sunAzimuthDeg - 30) * Math.PI) / 180;
  const travelled = VIEW_DRIFT_SPEED * t;
  return { x: travelled * Math.cos(heading), z: travelled * Math.sin(heading), heading };
}

/** m/s */
const VIEW_DRIFT_SPEED = 1.5;
/** How far ahead of the drifting view the boat's circle is centred (m). */
const BOAT_AHEAD = 60;

/** A boolean attribute: present is true, except written "false", as people write it. */
function booleanAttribute(raw: string | null): boolean {
  return raw !== null && raw.trim().toLowerCase() !== 'false';
}

function errorMessage(error: unknown): string {
  return error instanceof Error ? error.message : String(error);
}

/**
 * Defines the element under `tagName` (default 'fft-ocean') unless that name is already taken;
 * safe to call any number of times. Returns the class now registered under the name.
 */
export function defineFftOceanElement(tagName = 'fft-ocean'): CustomElementConstructor | undefined {
  if (typeof customElements === 'undefined') return undefined;
  const existing = customElements.get(tagName);
  if (existing) {
    if (existing !== FftOceanElement) {
      console.warn(`<${tagName}> is already defined by another script (a second copy of three-fft-ocean?); keeping that one.`);
    }
    return existing;
  }
  customElements.define(tagName, FftOceanElement);
  return FftOceanElement;
}

declare global {
  interface HTMLElementTagNameMap {
    'fft-ocean': FftOceanElement;
  }
}
