/**
 * The app (main.ts starts it once WebGL2 is known to work): the ocean in a full-window canvas with
 * fly controls (flyControls.ts), a panel for every parameter (panel.ts), the whole state in the
 * URL (urlState.ts), and the FFT path, frame rate, CPU timings and warnings on screen
 * (statusOverlay.ts). ?inspector=1 (or the panel) adds the
 * inspector's tiles along the bottom.
 *
 * Frames: the frame loop shared with <fft-ocean> (src/runtime/frameLoop.ts) advances the time by the
 * real frame time × time scale (SimulationClock), so the sea moves at its real speed however slow
 * the frames (a hidden tab or a stall longer than a second does not make it jump; paused keeps t
 * fixed), measures the frame for the adaptive quality, and updates, fits the far plane and renders.
 *
 * This module ties the app's parts together; each is a file of src/app/: what a change of state
 * does (applyChanges.ts), the extras the panel switches (appExtras.ts), the URL (urlWriter.ts), the
 * status line's figures (appStatus.ts), the copied link (copyLink.ts), the pixels for the tests
 * (pixelCapture.ts).
 */
import { Scene } from 'three';
import { ParameterError } from '../parameters/options';
import { CLICKED_STONE, seaPointUnder } from '../render/seaPointer';
import { FrameLoop } from '../runtime/frameLoop';
import { AdaptiveQuality } from '../runtime/adaptiveQuality';
import { SceneOutput } from '../render/sceneOutput';
import { applyQualityStep } from '../runtime/applyQuality';
import type { Boat } from '../objects/boat';
import type { Buoys } from '../objects/buoys';
import { applyChanges, hintCaustics } from './applyChanges';
import { AppExtras } from './appExtras';
import { AppStatus } from './appStatus';
import type { Island } from '../objects/island';
import { createAppCamera, createAppOcean, createAppRenderer, loadAppSkybox } from './appView';
import { copyToClipboard } from './copyLink';
import { CONTROLS_HELP, FlyControls } from './flyControls';
import { Inspector } from './inspector';
import { SunLight } from '../objects/sunLight';
import { Panel } from './panel';
import { PixelCapture } from './pixelCapture';
import { islandPose, SceneObjects, startingCam } from './sceneChoice';
import { describeSeaState, PATH_LABELS, StatusOverlay } from './statusOverlay';
import { UrlWriter } from './urlWriter';
import { parseState, roundTime, simulationParameters, type AppState } from './urlState';

/** Starts the app from the page's URL; window.oceanApp holds its live objects. */
export function startApp() {
  const container = document.querySelector<HTMLElement>('#app')!;
  // The page's listeners of this run of the app, removed when it is disposed.
  const listening = new AbortController();
  const { signal } = listening;
  let disposed = false;
  const overlay = new StatusOverlay(document.querySelector<HTMLElement>('#status')!, CONTROLS_HELP);

  const { state, warnings } = parseState(location.search);
  for (const { parameter, message } of warnings) overlay.warn(parameter, message);
  const urls = new UrlWriter(state);

  // The renderer, camera, ocean and per-frame steps are appView.ts's, which `npm run shot` shares.
  const renderer = createAppRenderer();
  const devicePixelRatio = Math.min(window.devicePixelRatio, 2);
  renderer.setPixelRatio(devicePixelRatio);
  container.appendChild(renderer.domElement);

  const scene = new Scene();
  const camera = createAppCamera();
  const ocean = createAppOcean(renderer, state);

  // Adaptive quality (adaptiveQuality.ts): the render scale, MSAA, grid and cascades that hold the
  // frame rate. The scene goes to the canvas through `output`, which multisamples when the level says.
  const output = new SceneOutput(renderer);
  // The frame loop (runtime/frameLoop.ts): the clock, the adaptive quality in force, and the time it
  // keeps in state.t.
  const loop = new FrameLoop(new AdaptiveQuality(state.quality, state.targetFps), state);
  /** Puts the quality level in force: the pixel ratio, MSAA, and the grid and cascades the ocean runs. */
  function applyQuality(asked = simulationParameters(state)): void {
    applyQualityStep({ renderer, output, ocean, pixelRatio: devicePixelRatio }, asked, loop.quality.step);
  }
  applyQuality();
  const sunLight = new SunLight(ocean);
  scene.add(ocean, sunLight);
  // The open sea or the island (sceneChoice.ts).
  const sceneObjects = new SceneObjects(scene, ocean);
  sceneObjects.show(state.scene);
  state.cam = startingCam(state);
  // A face set that fails to load (404, CORS, not an image, an untrusted origin) leaves the generated
  // sky in use, and leaves the URL: a copied link does not carry it on.
  loadAppSkybox(ocean, state.skybox)?.catch((error: Error) => {
    if (disposed) return;
    overlay.warn('skybox', error instanceof ParameterError && error.parameter === 'skybox' ? error.message : `skybox: ${error.message}`);
    state.skybox = 'generated';
    urls.write();
  });

  const [x, y, z, yaw, pitch] = state.cam;
  const controls = new FlyControls(camera, renderer.domElement, { position: [x, y, z], yaw, pitch });
  // A click on the sea drops a stone there.
  controls.onClick = (clientX, clientY) => {
    const hit = seaPointUnder(camera, renderer.domElement, clientX, clientY);
    if (hit) ocean.localWaves?.drop(hit.x, hit.z, CLICKED_STONE);
  };
  if (state.paused) state.t = roundTime(state.t);

  const extras = new AppExtras(ocean, scene, camera, container, () => fitPanel());
  // C shows the inspector's next cascade.
  window.addEventListener(
    'keydown',
    (event) => {
      if (event.code === 'KeyC' && !(event.target instanceof HTMLInputElement)) extras.inspector?.nextCascade();
    },
    { signal },
  );

  controls.onChange = () => {
    const { position, yaw, pitch } = controls.pose;
    state.cam = [...position, yaw, pitch];
    urls.schedule(300); // once the camera stops moving
  };

  // --- the panel -------------------------------------------------------------------------------

  hintCaustics(overlay, state.mode, state.sunElevation);

  /** Shows the open sea or the island; choosing the island takes the camera to its view. */
  function showScene(choice: AppState['scene']): void {
    if (sceneObjects.show(choice) && choice === 'island') controls.pose = islandPose();
  }

  async function copyLink(): Promise<void> {
    urls.write();
    const url = location.href;
    overlay.showLink(url, await copyToClipboard(url));
  }

  // On a narrow screen the panel starts closed (its title bar opens it).
  const panel = new Panel(state, window.innerWidth <= 700, {
    apply: (changes) => applyChanges({ ocean, state, loop, extras, overlay, applyQuality, showScene }, changes),
    changed: () => urls.schedule(150),
    warn: (parameter, message) => overlay.warn(parameter, message),
    clearWarning: (parameter) => overlay.clearWarning(parameter),
    copyLink: () => void copyLink(),
    runningPath: () => PATH_LABELS[ocean.simulation.path] ?? ocean.simulation.path,
    seaState: () => describeSeaState(ocean),
  });

  /** Keeps the panel above the inspector's tiles. */
  function fitPanel(): void {
    const tiles = extras.inspector ? Inspector.tileSize(window.innerWidth) : 0;
    panel.gui.domElement.style.maxHeight = `calc(100% - ${tiles}px)`;
    document.documentElement.style.setProperty('--inspector-height', `${tiles}px`);
  }

  extras.showInspector(state.inspector);
  extras.showBuoys(state.buoys, state.t);
  extras.showBoat(state.boat);

  // --- size and frames -------------------------------------------------------------------------

  function resize(): void {
    renderer.setSize(window.innerWidth, window.innerHeight);
    camera.aspect = window.innerWidth / window.innerHeight;
    camera.updateProjectionMatrix();
    fitPanel();
  }
  window.addEventListener('resize', resize, { signal });
  resize();

  const capture = new PixelCapture();
  const status = new AppStatus(overlay, { ocean, state, loop, output, controls });
  document.addEventListener('visibilitychange', () => loop.restart(), { signal }); // the first frame back advances nothing

  renderer.setAnimationLoop((now: number) => {
    if (loop.advance(now, state.paused ? 0 : state.timeScale)) applyQuality();
    controls.update(loop.clock.realStep);

    const start = performance.now();
    let simulated = start;
    // The sea at t (the eye may be on either side of the surface), the far plane, the render.
    loop.draw(
      { ocean, scene, camera, output },
      {
        beforeRender: (t) => {
          extras.buoys?.update(t);
          extras.boat?.update();
          sceneObjects.update();
          sunLight.update();
          simulated = performance.now();
        },
      },
    );
    extras.inspector?.render(renderer);
    const rendered = performance.now();
    capture.afterRender(renderer);
    status.frame(start, simulated, rendered);
    panel.update();
    // While time runs, t in the URL is refreshed now and then so a reload comes back near now.
    urls.refresh(rendered);
  });

  urls.write();

  /**
   * Stops this run of the app and frees what it made: the frame loop, the page's listeners, the
   * panel, the extras and the island, the ocean, the renderer and its WebGL context, the canvas.
   */
  function dispose(): void {
    if (disposed) return;
    disposed = true;
    renderer.setAnimationLoop(null);
    listening.abort();
    urls.cancel();
    controls.dispose();
    extras.showInspector(false);
    extras.showBuoys(false, state.t);
    extras.showBoat(false);
    panel.gui.destroy();
    sceneObjects.show('sea');
    output.dispose();
    ocean.dispose();
    renderer.dispose();
    renderer.forceContextLoss(); // a page has a few WebGL contexts only: this one is free at once
    renderer.domElement.remove();
  }

  // For the console and the browser tests: the live objects of this page.
  const oceanApp = {
    renderer,
    scene,
    camera,
    ocean,
    controls,
    state,
    panel,
    overlay,
    /** Draws the scene onto the canvas, multisampled at the levels with MSAA. */
    output,
    /** The adaptive quality in force (adaptiveQuality.ts). */
    get quality(): AdaptiveQuality {
      return loop.quality;
    },
    get inspector(): Inspector | null {
      return extras.inspector;
    },
    get buoys(): Buoys | null {
      return extras.buoys;
    },
    get boat(): Boat | null {
      return extras.boat;
    },
    /** The island, while the scene is the island (sceneChoice.ts). */
    get island(): Island | null {
      return sceneObjects.island;
    },
    /** Sets state values as the panel would (warnings included); false if the ocean rejected them. */
    set(changes: Partial<AppState>): boolean {
      let ok = true;
      for (const [key, value] of Object.entries(changes)) ok = panel.change(key as keyof AppState, value) && ok;
      return ok;
    },
    writeUrl: () => urls.write(),
    /** The canvas's pixels right after the next frame's render (bottom row first, RGBA). */
    capturePixels: () => capture.request(),
    /** Stops the app and frees what it made (its frame loop, listeners, panel, ocean, renderer, canvas); a second call does nothing. */
    dispose,
    /**
     * Opens the app again in place from `query` (a URL's query string, as after "?"): this run is
     * disposed (unless it is already), the address bar gets the query, and a new run reads it as a
     * page load would. The tests use it to share a page; window.oceanApp is the new run's.
     */
    reopen(query: string): void {
      dispose();
      history.replaceState(null, '', `${location.pathname}?${query}`);
      startApp();
    },
  };
  Object.assign(window, { oceanApp });
  return oceanApp;
}

export type OceanApp = ReturnType<typeof startApp>;
declare global {
  interface Window {
    oceanApp: OceanApp;
  }
}
