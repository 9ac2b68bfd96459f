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
 *     sun (SUN_OPTIONS): sun-elevation, sun-azimuth (degrees), cloud-cover → ocean.setSun
 *     shading (SHADING_OPTIONS): ior, absorption="0.45,0.07,0.04", scatter-color and caustic-color
 *       ("#1a6b80", any CSS colour, or linear "r,g,b"), caustic-power, shading-mode (full,
 *       fresnel, reflection, refraction, caustics, height), refractions and reflections (scene, sky)
 *                                                                        → ocean.setShading
 *   renderer (webgl, webgpu)                  three's WebGLRenderer (default) or WebGPURenderer with
 *                                             the Ocean of three-fft-ocean/webgpu (loaded only then;
 *                                             its WebGL2 backend where there is no WebGPU adapter, said
 *                                             in rendererStatus, the fft-ocean-renderer event and one
 *                                             console note); what that Ocean does not draw yet is
 *                                             left out with a console warning (docs/embedding.md)
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
 * scene is drawn again at the same time once the browser restores it; with renderer="webgpu", whose
 * lost device three.js never restores, the element dispatches fft-ocean-device-lost and makes a new
 * renderer and ocean at the same time (recoverDevice). Without WebGL 2 the box
 * shows a short message instead of staying blank.
 *
 * Any number of elements can be on one page, although browsers keep only about 16 WebGL contexts
 * per page (beyond that they drop the oldest for good): an element holds its renderer, ocean and
 * WebGL context only while it is near the screen. It creates them when it comes within 200 px of
 * the viewport (NEAR_MARGIN), so they are ready when it scrolls in, and frees them, as on
 * removal, when it is more than 500 px away (FAR_MARGIN); the gap keeps scrolling back and forth
 * a little from rebuilding them (src/embed/contextProximity.ts). When 12 elements (MAX_CONTEXT_HOLDERS) hold a context, one that
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
 *
 * The element's parts, one file each in src/embed/: its attributes and settings
 * (elementAttributes.ts), what it holds while near the screen (elementScene.ts), when it holds it
 * (contextProximity.ts), its frames (elementFrames.ts), the drifting view (defaultView.ts) and its
 * style and message (elementStyle.ts). This class ties them together.
 */
import type { PerspectiveCamera, Scene, WebGLRenderer } from 'three';
import type { WebGPURenderer } from 'three/webgpu';
import type { Ocean } from '../ocean';
import type { Ocean as WebGPUOcean } from '../webgpu/ocean';
import type { SceneOutput } from '../render/sceneOutput';
import type { AdaptiveQuality } from '../runtime/adaptiveQuality';
import { describeValue } from '../parameters/options';
import { applyAttribute, defaultSettings, oceanOptionsOf, setsOceanOption, sunAzimuthOf, type AttributeTarget, type FftOceanAttribute, FFT_OCEAN_ATTRIBUTES } from './elementAttributes';
import { ContextProximity } from './contextProximity';
import { boatCentre } from './defaultView';
import { ElementFrames } from './elementFrames';
import { createLive, disposeLive, showBoat, type Live } from './elementScene';
import { createWebGPULive, disposeWebGPULive, type WebGPULive } from './elementWebGPU';
import { showMessage, styleShadowRoot } from './elementStyle';
import type { DeviceLoss } from '../webgpu/deviceLoss';

export { FFT_OCEAN_ATTRIBUTES, type FftOceanAttribute } from './elementAttributes';

/**
 * With renderer="webgpu", a lost device is replaced by a new renderer and Ocean this many times in
 * a row (a loss within RECOVERED_FRAMES frames of the last recovery counts as one more in a row);
 * the next loss ends in the element's message, rather than replacing devices that keep failing.
 */
const DEVICE_RECOVERIES = 3;
/** Frames drawn after a recovery from which a device counts as working again. */
const RECOVERED_FRAMES = 60;

// Defined also where there is no DOM (server-side rendering, Node tests), so importing the
// library there does not throw; the element only works in a browser.
const ElementBase: typeof HTMLElement =
  typeof HTMLElement === 'undefined' ? (class {} as unknown as typeof HTMLElement) : HTMLElement;

export class FftOceanElement extends ElementBase {
  static get observedAttributes(): readonly string[] {
    return FFT_OCEAN_ATTRIBUTES;
  }

  private readonly settings = defaultSettings();
  private readonly root: ShadowRoot;
  private live: Live | WebGPULive | null = null;
  /** Counts starts and stops: a WebGPU start that resolves after a later one is freed unused. */
  private generation = 0;
  /** Whether a WebGPU start is under way (the renderer initializes asynchronously). */
  private starting = false;
  /** Lost WebGPU devices replaced in a row, and frameCount at the last replacement (recoverDevice). */
  private deviceRecoveries = { inARow: 0, atFrame: 0 };
  private message: HTMLElement | null = null;
  private readonly proximity = new ContextProximity(this, {
    holds: () => this.live !== null || this.starting,
    mayStart: () => this.message === null,
    start: () => this.start(),
    stop: () => this.stop(),
    onScreenChanged: () => this.frames.activityChanged(),
  });
  private readonly frames = new ElementFrames({
    element: this,
    settings: this.settings,
    live: () => this.live,
    onScreen: () => this.proximity.onScreen,
    fail: (text, error) => this.fail(text, error),
  });
  /** What attribute changes act on. */
  private readonly attributeTarget: AttributeTarget = {
    settings: this.settings,
    loop: this.frames.loop,
    // The WebGPU Ocean is made again instead (attributeChangedCallback).
    ocean: () => this.ocean,
    applyQuality: (asked) => {
      if (this.live) this.frames.applyQuality(this.live, asked);
    },
    showBoat: () => {
      if (this.live?.kind === 'webgl') this.showBoat(this.live);
    },
    invalidate: () => this.frames.invalidate(),
  };

  constructor() {
    super();
    this.root = this.attachShadow({ mode: 'open' });
    styleShadowRoot(this.root);
  }

  /**
   * The Ocean while the element is on the page and near the screen (null before, while it is far
   * from the screen, after removal or without WebGL 2); so are renderer, camera, scene and canvas.
   * With renderer="webgpu", ocean and renderer are null: see webgpuOcean and webgpuRenderer.
   */
  get ocean(): Ocean | null {
    return this.live?.kind === 'webgl' ? this.live.ocean : null;
  }

  get renderer(): WebGLRenderer | null {
    return this.live?.kind === 'webgl' ? this.live.renderer : null;
  }

  /** With renderer="webgpu": the Ocean of three-fft-ocean/webgpu while the element holds one (see ocean), else null. */
  get webgpuOcean(): WebGPUOcean | null {
    return this.live?.kind === 'webgpu' ? this.live.ocean : null;
  }

  /** With renderer="webgpu": its WebGPURenderer while the element holds one (see ocean), else null. */
  get webgpuRenderer(): WebGPURenderer | null {
    return this.live?.kind === 'webgpu' ? this.live.renderer : null;
  }

  /**
   * What draws, while the element holds its renderer (else null): which renderer, its backend
   * ('WebGL2' or 'WebGPU'), why a WebGPU renderer is on its WebGL2 backend (null when it is not),
   * and the options and settings the WebGPU Ocean does not draw yet, left out (see
   * docs/embedding.md). Also the detail of the fft-ocean-renderer event, sent when it starts.
   */
  get rendererStatus(): RendererStatus | null {
    const live = this.live;
    if (!live) return null;
    if (live.kind === 'webgl') return { renderer: 'webgl', backend: 'WebGL2', fallback: null, notDrawn: [] };
    return { renderer: 'webgpu', ...live.status };
  }

  get camera(): PerspectiveCamera | null {
    return this.live?.camera ?? null;
  }

  get scene(): Scene | null {
    return this.live?.scene ?? null;
  }

  /** What draws the scene onto the canvas, multisampled or not as the quality level says; null with no context (see ocean) or with renderer="webgpu". */
  get output(): SceneOutput | null {
    return this.live?.kind === 'webgl' ? this.live.output : null;
  }

  /** The element's canvas (inside its shadow root), or null when it has none (see ocean). */
  get canvas(): HTMLCanvasElement | null {
    return this.live?.canvas ?? null;
  }

  /** Simulated seconds shown; settable (any finite number) to jump to a moment. */
  get time(): number {
    return this.frames.loop.time.t;
  }

  set time(seconds: number) {
    if (typeof seconds !== 'number' || !Number.isFinite(seconds)) {
      console.warn(`<fft-ocean>: ignoring time = ${describeValue(seconds)}: it must be a finite number of seconds`);
      return;
    }
    this.frames.loop.time.t = seconds;
    this.frames.invalidate();
  }

  /**
   * The adaptive quality in force (runtime/adaptiveQuality.ts): its setting, its level and step,
   * and the median frame time that chose it.
   */
  get quality(): AdaptiveQuality {
    return this.frames.loop.quality;
  }

  /** Frames drawn since the element was created (for diagnostics and tests). */
  get frameCount(): number {
    return this.frames.framesDrawn;
  }

  /** Whether the element is drawing frames now (on the page, on screen, tab visible, context alive). */
  get active(): boolean {
    return this.frames.isActive();
  }

  /**
   * Draws the current time now, synchronously (e.g. right before canvas.toDataURL() or
   * readPixels). Returns false when there is nothing to draw into (see ocean) or the context is lost.
   */
  renderFrame(): boolean {
    const live = this.live;
    if (!live || live.contextLost) return false;
    this.frames.draw(live);
    return true;
  }

  connectedCallback(): void {
    if (!this.proximity.watching) this.proximity.watch();
  }

  disconnectedCallback(): void {
    // A move (remove + insert in the same task) keeps everything; a real removal frees it all.
    queueMicrotask(() => {
      if (this.isConnected) return;
      this.proximity.unwatch();
      this.stop();
    });
  }

  attributeChangedCallback(name: string, _previous: string | null, value: string | null): void {
    const renderer = this.settings.renderer;
    applyAttribute(this.attributeTarget, name as FftOceanAttribute, value);
    // Another renderer, or an option of the WebGPU Ocean (which has no setters for them all yet): made again, at the same time.
    const remake = this.settings.renderer !== renderer || (this.settings.renderer === 'webgpu' && setsOceanOption(name));
    if (remake && (this.live !== null || this.starting)) this.restart();
  }

  // ---- life cycle

  /** Frees the live parts and makes them again with the settings now, at the same simulated time. */
  private restart(): void {
    this.stop();
    this.start();
  }

  /**
   * The WebGPU renderer's device was lost (elementWebGPU.ts), which three.js never restores: tells
   * the page (fft-ocean-device-lost, detail: the DeviceLoss) and draws on with a new renderer and
   * Ocean on the same settings and time, as a lost WebGL context is waited out; after
   * DEVICE_RECOVERIES in a row, shows the message instead.
   */
  private recoverDevice(loss: DeviceLoss): void {
    this.dispatchEvent(new CustomEvent('fft-ocean-device-lost', { detail: loss }));
    const recoveries = this.deviceRecoveries;
    if (this.frames.framesDrawn - recoveries.atFrame >= RECOVERED_FRAMES) recoveries.inARow = 0;
    const device = loss.api === 'WebGPU' ? 'WebGPU device' : 'WebGL2 context';
    if (recoveries.inARow >= DEVICE_RECOVERIES) {
      this.stop();
      this.fail(`The ${device} was lost ${DEVICE_RECOVERIES + 1} times in a row; the ocean has stopped.`, loss);
      return;
    }
    recoveries.inARow++;
    recoveries.atFrame = this.frames.framesDrawn;
    console.warn(`<fft-ocean renderer="webgpu">: the ${device} was lost (${loss.reason}: ${loss.message}); starting a new renderer and ocean`);
    this.restart();
  }

  private start(): void {
    this.message?.remove();
    this.message = null;
    this.proximity.makeRoomForContext();
    if (this.settings.renderer === 'webgpu') {
      void this.startWebGPU(++this.generation);
      return;
    }
    const created = createLive(() => oceanOptionsOf(this.settings, this.frames.loop.quality.step), {
      activityChanged: () => this.frames.activityChanged(),
      resized: () => this.frames.resize(),
      // The path changed by itself (a worker failed, the main thread took over): tell the page.
      pathChanged: (path) => this.dispatchEvent(new CustomEvent('fft-ocean-path-change', { detail: path })),
    });
    if ('failure' in created) {
      this.fail(created.failure, created.error);
      return;
    }
    this.begin(created);
  }

  /**
   * Starts the WebGPURenderer and its Ocean (loading three/webgpu now), unless a stop or another
   * start came first (`generation` is no longer the element's), in which case they are freed.
   */
  private async startWebGPU(generation: number): Promise<void> {
    this.starting = true;
    let live: WebGPULive;
    try {
      live = await createWebGPULive(oceanOptionsOf(this.settings, this.frames.loop.quality.step), this.settings.boat, {
        activityChanged: () => this.frames.activityChanged(),
        resized: () => this.frames.resize(),
        deviceLost: (loss) => this.recoverDevice(loss),
      });
    } catch (error) {
      if (generation !== this.generation) return;
      this.starting = false;
      this.fail('The ocean could not start with WebGPURenderer in this browser.', error);
      return;
    }
    if (generation !== this.generation) {
      disposeWebGPULive(live);
      return;
    }
    this.starting = false;
    this.begin(live);
    const { notDrawn } = live.status;
    if (notDrawn.length > 0) console.warn(`<fft-ocean renderer="webgpu">: left out, not drawn by the WebGPU Ocean yet: ${notDrawn.map(({ name, missing }) => `${name} (${missing})`).join('; ')}`);
    this.dispatchEvent(new CustomEvent('fft-ocean-renderer', { detail: this.rendererStatus }));
  }

  /** Puts the new live parts in the page (the boat too, before the first frame) and starts drawing them. */
  private begin(live: Live | WebGPULive): void {
    this.root.append(live.canvas);
    this.live = live;
    this.frames.applyQuality(live);
    this.proximity.hold();
    if (live.kind === 'webgl') this.showBoat(live);
    else this.frames.invalidate();
    this.frames.loop.restart();
    this.frames.resize();
    live.resizeObserver.observe(this);
  }

  private stop(): void {
    this.generation++;
    this.starting = false;
    const live = this.live;
    if (live) {
      this.live = null;
      this.proximity.release();
      if (live.kind === 'webgl') disposeLive(live);
      else disposeWebGPULive(live);
    }
    this.message?.remove();
    this.message = null;
    this.frames.stop();
  }

  /** Puts the boat (and its light) in the scene, or takes it out and frees it, as `show` says. */
  private showBoat(live: Live, show = this.settings.boat): void {
    showBoat(live, show ? (t) => boatCentre(t, sunAzimuthOf(this.settings)) : null);
    this.frames.invalidate();
  }

  private fail(text: string, error: unknown): void {
    console.error(`<fft-ocean>: ${text}`, error);
    this.message = showMessage(this.root, text);
    this.dispatchEvent(new CustomEvent('fft-ocean-error', { detail: { message: text, error } }));
  }
}

/** What draws an element (FftOceanElement.rendererStatus, the fft-ocean-renderer event's detail). */
export interface RendererStatus {
  renderer: 'webgl' | 'webgpu';
  backend: 'WebGL2' | 'WebGPU';
  /** Why renderer 'webgpu' draws with WebGPURenderer's WebGL2 backend; null when it does not. */
  fallback: string | null;
  /** Options and settings left out: what the WebGPU Ocean does not draw yet. */
  notDrawn: { name: string; missing: string }[];
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
