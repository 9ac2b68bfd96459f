/**
 * The app with ?renderer=webgpu (main.ts starts it instead of app.ts): three's WebGPURenderer and
 * the Ocean of three-fft-ocean/webgpu (both loaded only now, src/runtime/webgpuStart.ts), on its
 * WebGL2 backend where the browser has no WebGPU adapter, with the fly controls, the URL's state
 * and the time (its clock, time scale and pause) of the WebGL app.
 *
 * The WebGPU Ocean is a first slice: what the URL asks for that it does not draw yet (the sun, the
 * analytic sky, caustics, local waves, …: its notDrawnYet) and the app's parts built on the
 * WebGL Ocean (the panel, the inspector, buoys, the boat, the island, wireframe, a skybox, the
 * stones) are turned off, each with a notice, rather than refused. The quality levels apply as in
 * the WebGL app (applyQuality.ts), but MSAA. The status line says which renderer and backend draw,
 * and why not WebGPU where it falls back, which FFT runs (ocean.path) and the quality level.
 */
import type { PerspectiveCamera } from 'three';
import { Scene } from 'three';
import { FrameLoop } from '../runtime/frameLoop';
import { AdaptiveQuality } from '../runtime/adaptiveQuality';
import { applyWebGPUQualityStep } from '../runtime/applyQuality';
import { fitFarPlane } from '../runtime/farPlane';
import { startWebGPUOcean, type WebGPUStart } from '../runtime/webgpuStart';
import { SIMULATION_OPTIONS } from '../parameters/parameters';
import { appOceanOptions, createAppCamera } from './appView';
import { CONTROLS_HELP, FlyControls } from './flyControls';
import { StatusOverlay } from './statusOverlay';
import { webgpuStatusLine } from './appStatus';
import { DEFAULT_STATE, parseState, simulationParameters, type AppState } from './urlState';

/** The app's parts built on the WebGL Ocean, by the state key that turns each on, and what it is. */
const WEBGL_ONLY: Partial<Record<keyof AppState, string>> = {
  inspector: 'the inspector',
  buoys: 'the buoys',
  boat: 'the boat',
  scene: 'the island',
  wireframe: 'wireframe',
  skybox: 'a skybox',
};

const container = document.querySelector<HTMLElement>('#app')!;
const overlay = new StatusOverlay(document.querySelector<HTMLElement>('#status')!, CONTROLS_HELP);
const { state, warnings } = parseState(location.search);
for (const { parameter, message } of warnings) overlay.warn(parameter, message);
for (const [key, part] of Object.entries(WEBGL_ONLY)) {
  if (state[key as keyof AppState] !== DEFAULT_STATE[key as keyof AppState]) overlay.warn(key, `${key}: not drawn with renderer=webgpu yet (${part}); turned off`);
}

// The simulation's options all go (the grid and cascades of the starting quality level); of the
// others only what the URL asks for beyond the defaults: the defaults of options the WebGPU Ocean
// does not draw yet (local waves, say) would otherwise each be named as left out.
const options = appOceanOptions(state) as Record<string, unknown>;
const defaults = appOceanOptions(DEFAULT_STATE) as Record<string, unknown>;
const asked = Object.fromEntries(Object.entries(options).filter(([name, value]) => Object.hasOwn(SIMULATION_OPTIONS, name) || JSON.stringify(value) !== JSON.stringify(defaults[name])));

/** Starts the renderer, the ocean, the controls and the frames; what the page and the tests see. */
async function start(): Promise<void> {
  const canvas = document.createElement('canvas');
  container.appendChild(canvas);
  const { renderer, ocean, backend, fallback, notDrawn } = await startWebGPUOcean(canvas, asked);
  for (const { name, missing } of notDrawn) overlay.warn(name, `${name}: not drawn with renderer=webgpu yet (${missing}); left out`);

  const scene = new Scene();
  scene.add(ocean);
  const camera = createAppCamera();
  const [x, y, z, yaw, pitch] = state.cam;
  const controls = new FlyControls(camera, canvas, { position: [x, y, z], yaw, pitch });
  const loop = new FrameLoop(new AdaptiveQuality(state.quality, state.targetFps), state);
  const showStatus = (): void => {
    overlay.status.textContent = webgpuStatusLine(backend, fallback, ocean.path, { level: loop.quality.level, auto: loop.quality.setting === 'auto' });
  };
  /** Puts the quality level in force (applyQuality.ts): the pixel ratio, the grid, and the grid and cascades the ocean runs. */
  const applyQuality = (): void => {
    applyWebGPUQualityStep({ renderer, ocean, pixelRatio: Math.min(window.devicePixelRatio, 2) }, simulationParameters(state), loop.quality.step);
    showStatus();
  };
  applyQuality();
  ocean.addEventListener('pathchange', showStatus);

  const resize = (): void => {
    renderer.setSize(window.innerWidth, window.innerHeight);
    camera.aspect = window.innerWidth / window.innerHeight;
    camera.updateProjectionMatrix();
  };
  window.addEventListener('resize', resize);
  resize();
  document.addEventListener('visibilitychange', () => loop.restart());

  let framesDrawn = 0;
  renderer.setAnimationLoop((now: number) => {
    if (loop.advance(now, state.paused ? 0 : state.timeScale)) applyQuality();
    controls.update(loop.clock.realStep);
    ocean.update(state.t);
    fitFarPlane(camera, ocean); // out to the grid's far edge (its sky is drawn at the far plane, whatever it is)
    renderer.render(scene, camera);
    framesDrawn++;
    overlay.time.textContent = `t = ${state.t.toFixed(2)} s${state.paused ? ' (paused)' : ''}`;
  });
  // A lost device never comes back (src/webgpu/deviceLoss.ts): stop drawing and say so, rather than throw each frame.
  ocean.addEventListener('devicelost', ({ loss }) => {
    renderer.setAnimationLoop(null);
    overlay.warn('renderer', `the ${loss.api === 'WebGPU' ? 'WebGPU device' : 'WebGL2 context'} was lost (${loss.reason}: ${loss.message}); reload the page to draw again`);
  });

  // For the console and the browser tests: the live objects of this page.
  window.oceanAppWebGPU = {
    renderer,
    scene,
    camera,
    ocean,
    state,
    /** 'WebGPU', or 'WebGL2' where there is no WebGPU adapter; fallback says why. */
    backend,
    fallback,
    notDrawn,
    get framesDrawn(): number {
      return framesDrawn;
    },
  };
}

start().catch((error: unknown) => {
  overlay.status.textContent = `The ocean could not start with WebGPURenderer in this browser: ${error instanceof Error ? error.message : String(error)}`;
  console.error(error);
});

export interface OceanAppWebGPU {
  renderer: WebGPUStart['renderer'];
  scene: Scene;
  camera: PerspectiveCamera;
  ocean: WebGPUStart['ocean'];
  state: AppState;
  backend: WebGPUStart['backend'];
  fallback: string | null;
  notDrawn: WebGPUStart['notDrawn'];
  readonly framesDrawn: number;
}

declare global {
  interface Window {
    oceanAppWebGPU: OceanAppWebGPU;
  }
}
