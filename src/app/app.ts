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
 */
import { Scene } from 'three';
import { ParameterError } from '../parameters/options';
import { CLICKED_STONE, seaPointUnder } from '../render/seaPointer';
import { FrameLoop } from '../runtime/frameLoop';
import { AdaptiveQuality } from '../runtime/adaptiveQuality';
import { validateParameters } from '../parameters/parameters';
import { SceneOutput } from '../render/sceneOutput';
import { applyQualityStep } from '../runtime/applyQuality';
import { Boat, centreAhead } from '../objects/boat';
import { Buoys } from '../objects/buoys';
import { createAppCamera, createAppOcean, createAppRenderer, loadAppSkybox } from './appView';
import { CONTROLS_HELP, FlyControls } from './flyControls';
import { Inspector } from './inspector';
import { SunLight } from '../objects/sunLight';
import { Panel } from './panel';
import { describeSeaState, PATH_LABELS, StatusOverlay, TimingAverager } from './statusOverlay';
import { parseState, roundTime, serializeState, simulationParameters, type AppState } from './urlState';

const container = document.querySelector<HTMLElement>('#app')!;
const overlay = new StatusOverlay(document.querySelector<HTMLElement>('#status')!, CONTROLS_HELP);

const { state, warnings } = parseState(location.search);
for (const { parameter, message } of warnings) overlay.warn(parameter, message);

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
// A face set that fails to load (404, CORS, not an image, an untrusted origin) leaves the generated
// sky in use, and leaves the URL: a copied link does not carry it on.
loadAppSkybox(ocean, state.skybox)?.catch((error: Error) => {
  overlay.warn('skybox', error instanceof ParameterError && error.parameter === 'skybox' ? error.message : `skybox: ${error.message}`);
  state.skybox = 'generated';
  writeUrl();
});

const [x, y, z, yaw, pitch] = state.cam;
const controls = new FlyControls(camera, renderer.domElement, { position: [x, y, z], yaw, pitch });
// A click on the sea drops a stone there.
controls.onClick = (clientX, clientY) => {
  const hit = seaPointUnder(camera, renderer.domElement, clientX, clientY);
  if (hit) ocean.localWaves?.drop(hit.x, hit.z, CLICKED_STONE);
};
if (state.paused) state.t = roundTime(state.t);

let inspector: Inspector | null = null;
// C shows the inspector's next cascade.
window.addEventListener('keydown', (event) => {
  if (event.code === 'KeyC' && !(event.target instanceof HTMLInputElement)) inspector?.nextCascade();
});
function showInspector(show: boolean): void {
  if (show && !inspector) inspector = new Inspector(ocean, container);
  if (!show && inspector) {
    inspector.dispose();
    inspector = null;
  }
  fitPanel();
}

let boat: Boat | null = null;
/** Puts the boat on its course ahead of the camera, or takes it away. */
function showBoat(show: boolean): void {
  if (show && !boat) {
    boat = new Boat(ocean, centreAhead(camera));
    scene.add(boat);
  }
  if (!show && boat) {
    boat.removeFromParent();
    boat.dispose();
    boat = null;
  }
}

let buoys: Buoys | null = null;
/** Drops buoys ahead of the camera, or takes them away. */
function showBuoys(show: boolean): void {
  if (show && !buoys) {
    buoys = new Buoys(ocean);
    ocean.update(state.t, camera); // the water they are set down on
    buoys.dropAhead(camera);
    scene.add(buoys);
  }
  if (!show && buoys) {
    buoys.removeFromParent();
    buoys.dispose();
    buoys = null;
  }
}

// --- the URL ---------------------------------------------------------------------------------

let urlTimer: ReturnType<typeof setTimeout> | undefined;
let lastUrlWrite = 0;
/** Writes the state into the address bar now (history.replaceState: no new history entries). */
function writeUrl(): void {
  clearTimeout(urlTimer);
  urlTimer = undefined;
  lastUrlWrite = performance.now();
  const query = serializeState(state);
  if (location.search.slice(1) !== query) history.replaceState(history.state, '', `${location.pathname}?${query}${location.hash}`);
}
/** Writes the URL after `delayMs` without further changes (panel edits, camera moves). */
function scheduleUrl(delayMs: number): void {
  clearTimeout(urlTimer);
  urlTimer = setTimeout(writeUrl, delayMs);
}

controls.onChange = () => {
  const { position, yaw, pitch } = controls.pose;
  state.cam = [...position, yaw, pitch];
  scheduleUrl(300); // once the camera stops moving
};

// --- the panel -------------------------------------------------------------------------------

/** Applies changes to the scene; throws (and changes nothing) when the ocean rejects a value. */
function apply(changes: Partial<AppState>): void {
  const has = (key: keyof AppState) => Object.hasOwn(changes, key);
  const simulation: Record<string, unknown> = Object.fromEntries(Object.entries(changes).filter(([key]) => key in ocean.parameters));
  // What is asked for must hold at every level (the grid and cascades may rise again later); the
  // ocean runs its grid and cascades within the level's (applyQualityStep), the rest as asked.
  const asked = validateParameters({ ...simulationParameters(state), ...simulation });
  const { resolution, patchSizes, ...rest } = simulation;
  if (Object.keys(rest).length > 0) ocean.setParameters(rest);
  const newQuality = changes.quality !== undefined || changes.targetFps !== undefined;
  if (newQuality) loop.quality = new AdaptiveQuality(changes.quality ?? state.quality, changes.targetFps ?? state.targetFps);
  if (newQuality || resolution !== undefined || patchSizes !== undefined) applyQuality(asked);
  const shading = {
    ior: changes.ior,
    absorption: changes.absorption,
    scatterColor: changes.scatterColor,
    causticPower: changes.causticPower,
    causticColor: changes.causticColor,
    shadingMode: changes.mode,
    reflections: changes.reflections,
  };
  if (Object.values(shading).some((value) => value !== undefined)) ocean.setShading(shading);
  if (has('sunElevation') || has('sunAzimuth')) {
    ocean.setSun(changes.sunElevation ?? state.sunElevation, changes.sunAzimuth ?? state.sunAzimuth);
  }
  if (changes.path !== undefined) ocean.simulation.pathPreference = changes.path;
  if (changes.wireframe !== undefined) ocean.surface.material.wireframe = changes.wireframe;
  if (changes.inspector !== undefined) showInspector(changes.inspector);
  if (changes.buoys !== undefined) showBuoys(changes.buoys);
  if (changes.boat !== undefined) showBoat(changes.boat);
  if (changes.paused) changes.t = roundTime(state.t); // a paused t is exactly what the URL holds
  hintCaustics(changes.mode ?? state.mode, changes.sunElevation ?? state.sunElevation);
}

/**
 * The caustics mode (the report's Figure 9) is black under a low sun, which looks broken: say why.
 * Guardado's term (shaders/surface/caustics.glsl) lights the surface where a vertical ray leaving
 * the water points at the sun, which a sun lower than about 60° needs slopes steeper than waves have.
 */
function hintCaustics(mode: AppState['mode'], sunElevation: number): void {
  if (mode === 'caustics' && sunElevation < 60) {
    overlay.warn('caustics', `caustics: a sun ${sunElevation.toFixed(0)}° high lights almost none of the sea in this term; raise the sun above 60° (Sun & shading) to see the pattern`);
  } else {
    overlay.clearWarning('caustics');
  }
}
hintCaustics(state.mode, state.sunElevation);

async function copyLink(): Promise<void> {
  writeUrl();
  const url = location.href;
  let copied = false;
  try {
    if (!navigator.clipboard) throw new Error('no clipboard');
    // Headless or unfocused pages may never settle the promise: give up after a second.
    await Promise.race([
      navigator.clipboard.writeText(url),
      new Promise((_resolve, reject) => setTimeout(() => reject(new Error('clipboard timeout')), 1000)),
    ]);
    copied = true;
  } catch {
    copied = false;
  }
  overlay.showLink(url, copied);
}

// On a narrow screen the panel starts closed (its title bar opens it).
const panel = new Panel(state, window.innerWidth <= 700, {
  apply,
  changed: () => scheduleUrl(150),
  warn: (parameter, message) => overlay.warn(parameter, message),
  clearWarning: (parameter) => overlay.clearWarning(parameter),
  copyLink: () => void copyLink(),
  runningPath: () => PATH_LABELS[ocean.simulation.path] ?? ocean.simulation.path,
  seaState: () => describeSeaState(ocean),
});

/** Keeps the panel above the inspector's tiles. */
function fitPanel(): void {
  const tiles = inspector ? Inspector.tileSize(window.innerWidth) : 0;
  panel.gui.domElement.style.maxHeight = `calc(100% - ${tiles}px)`;
  document.documentElement.style.setProperty('--inspector-height', `${tiles}px`);
}

showInspector(state.inspector);
showBuoys(state.buoys);
showBoat(state.boat);

// --- size and frames -------------------------------------------------------------------------

function resize(): void {
  renderer.setSize(window.innerWidth, window.innerHeight);
  camera.aspect = window.innerWidth / window.innerHeight;
  camera.updateProjectionMatrix();
  fitPanel();
}
window.addEventListener('resize', resize);
resize();

let pendingCaptures: ((pixels: { width: number; height: number; data: Uint8Array }) => void)[] = [];
/** The canvas's pixels right after the next frame's render (bottom row first, RGBA). */
function capturePixels(): Promise<{ width: number; height: number; data: Uint8Array }> {
  return new Promise((resolve) => pendingCaptures.push(resolve));
}
function readCanvas(): { width: number; height: number; data: Uint8Array } {
  const gl = renderer.getContext();
  renderer.setRenderTarget(null);
  const width = gl.drawingBufferWidth;
  const height = gl.drawingBufferHeight;
  const data = new Uint8Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, data);
  return { width, height, data };
}

const averager = new TimingAverager(500);
let lastStatus = 0;
document.addEventListener('visibilitychange', () => loop.restart()); // the first frame back advances nothing

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
        buoys?.update(t);
        boat?.update();
        sunLight.update();
        simulated = performance.now();
      },
    },
  );
  inspector?.render(renderer);
  const rendered = performance.now();
  if (pendingCaptures.length > 0) {
    const pixels = readCanvas();
    for (const resolve of pendingCaptures) resolve(pixels);
    pendingCaptures = [];
  }

  averager.add(rendered, simulated - start, rendered - simulated);
  if (rendered - lastStatus > 250) {
    const time = { t: state.t, paused: state.paused, timeScale: state.timeScale, ratio: loop.clock.timeRatio };
    const { pathReason, pathPreference } = ocean.simulation;
    const { quality } = loop;
    const qualityStatus = {
      level: quality.level,
      auto: quality.setting === 'auto',
      targetFps: quality.targetFps,
      frameMs: quality.medianFrameMs,
      renderScale: quality.step.renderScale,
      msaa: output.msaa,
      resolution: ocean.parameters.resolution,
      cascades: ocean.parameters.patchSizes.length,
    };
    overlay.show(describeSeaState(ocean), ocean.simulation.path, averager.latest, time, controls.speed, pathPreference === 'js' ? '' : pathReason, qualityStatus);
    lastStatus = rendered;
  }
  panel.update();
  // While time runs, t in the URL is refreshed now and then so a reload comes back near now.
  if (!state.paused && urlTimer === undefined && rendered - lastUrlWrite > 1000) writeUrl();
});

writeUrl();

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
    return inspector;
  },
  get buoys(): Buoys | null {
    return buoys;
  },
  get boat(): Boat | null {
    return boat;
  },
  /** Sets state values as the panel would (warnings included); false if the ocean rejected them. */
  set(changes: Partial<AppState>): boolean {
    let ok = true;
    for (const [key, value] of Object.entries(changes)) ok = panel.change(key as keyof AppState, value) && ok;
    return ok;
  },
  writeUrl,
  capturePixels,
};
Object.assign(window, { oceanApp });

export type OceanApp = typeof oceanApp;
declare global {
  interface Window {
    oceanApp: OceanApp;
  }
}
