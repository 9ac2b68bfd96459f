/**
 * What an <fft-ocean> holds while it is near the screen: its canvas, WebGLRenderer, scene, camera,
 * Ocean and output, the listeners on them (a click on the sea drops a stone; a lost context is
 * waited out) and the boat. Made and freed together, so that the context goes back to the browser
 * at once (browsers allow few at once).
 */
import { ACESFilmicToneMapping, PerspectiveCamera, Scene, WebGLRenderer } from 'three';
import { Ocean, type OceanOptions, type OceanPath } from '../ocean';
import { SceneOutput } from '../render/sceneOutput';
import { Boat } from '../objects/boat';
import { SunLight } from '../objects/sunLight';
import { CLICKED_STONE, seaPointUnder } from '../render/seaPointer';

/** What exists while the element is on the page, near the screen, and WebGL 2 works. */
export interface Live {
  kind: 'webgl';
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
  /** Removes every listener createLive added. */
  removeListeners: () => void;
  contextLost: boolean;
  /** The boat and the light it is lit by, while the boat attribute is on. */
  boat: { boat: Boat; light: SunLight } | null;
}

/** What the live parts tell their element. */
export interface LiveEvents {
  /** The context was lost or restored, or the tab hidden or shown. */
  activityChanged(): void;
  /** The element's box changed size. */
  resized(): void;
  /** The running path changed by itself (a worker failed, the main thread took over). */
  pathChanged(path: OceanPath): void;
}

/** Why createLive made nothing: the text for the page, and the error. */
export interface LiveFailure {
  failure: string;
  error: unknown;
}

/**
 * Makes the canvas (not yet in the page: the caller appends it), renderer, ocean (with the
 * `options` asked once the renderer exists), scene and camera, and listens to them; or says why it
 * could not (without WebGL 2, or when the options or the Ocean fail).
 */
export function createLive(options: () => OceanOptions, events: LiveEvents): Live | LiveFailure {
  const canvas = elementCanvas();
  let renderer: WebGLRenderer;
  try {
    // No antialiasing of the canvas's own, which could not be turned off: MSAA is the quality level's (SceneOutput).
    renderer = new WebGLRenderer({ canvas, antialias: false, powerPreference: 'high-performance' });
  } catch (error) {
    return { failure: 'This ocean needs WebGL 2, which this browser does not provide (or has switched off).', error };
  }
  let ocean: Ocean;
  try {
    ocean = new Ocean(renderer, options());
  } catch (error) {
    renderer.dispose();
    renderer.forceContextLoss();
    return { failure: 'The ocean could not start in this browser.', error };
  }
  renderer.toneMapping = ACESFilmicToneMapping;
  const scene = new Scene();
  scene.add(ocean);
  const camera = new PerspectiveCamera(50, 16 / 9, 0.5, 1e4);

  const onContextLost = () => {
    live.contextLost = true;
    events.activityChanged();
  };
  const onContextRestored = () => {
    // three.js has rebuilt its state and the sky has re-rendered its cube (their listeners
    // were added first); the fields are recomputed by the next update().
    live.contextLost = false;
    events.activityChanged();
  };
  const onVisibilityChange = () => events.activityChanged();
  // A click (or tap) on the sea drops a stone there, as in the app (local waves).
  const onClick = (event: MouseEvent) => {
    const hit = seaPointUnder(camera, canvas, event.clientX, event.clientY);
    if (hit) ocean.localWaves?.drop(hit.x, hit.z, CLICKED_STONE);
  };
  canvas.addEventListener('click', onClick);
  ocean.addEventListener('pathchange', ({ path }) => events.pathChanged(path));
  canvas.addEventListener('webglcontextlost', onContextLost);
  canvas.addEventListener('webglcontextrestored', onContextRestored);
  document.addEventListener('visibilitychange', onVisibilityChange);

  const live: Live = {
    kind: 'webgl',
    canvas,
    renderer,
    scene,
    camera,
    ocean,
    output: new SceneOutput(renderer),
    pixelRatio: Math.min(window.devicePixelRatio || 1, 2),
    resizeObserver: new ResizeObserver(() => events.resized()),
    contextLost: false,
    boat: null,
    removeListeners: () => {
      canvas.removeEventListener('click', onClick);
      canvas.removeEventListener('webglcontextlost', onContextLost);
      canvas.removeEventListener('webglcontextrestored', onContextRestored);
      document.removeEventListener('visibilitychange', onVisibilityChange);
    },
  };
  return live;
}

/** The element's canvas, for either renderer (the page's styles reach it as ::part(canvas)). */
export function elementCanvas(): HTMLCanvasElement {
  const canvas = document.createElement('canvas');
  canvas.setAttribute('part', 'canvas');
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label', 'An animated view of the open sea');
  return canvas;
}

/** Frees everything createLive made (and the boat), and gives the WebGL context back now. */
export function disposeLive(live: Live): void {
  live.resizeObserver.disconnect();
  live.removeListeners();
  showBoat(live, null);
  live.scene.remove(live.ocean);
  live.ocean.dispose();
  live.output.dispose();
  live.renderer.dispose();
  // Give the context back now rather than at garbage collection: browsers allow few at once.
  live.renderer.forceContextLoss();
  live.canvas.remove();
}

/**
 * Puts a boat circling `centre(t)` (and its light) in the scene, or, with null, takes it out and
 * frees it; an existing boat stays as it is.
 */
export function showBoat(live: Live, centre: ((t: number) => { x: number; z: number }) | null): void {
  if (centre && !live.boat) {
    const boat = new Boat(live.ocean, centre);
    live.boat = { boat, light: new SunLight(live.ocean) };
    live.scene.add(boat, live.boat.light);
  } else if (!centre && live.boat) {
    live.scene.remove(live.boat.boat, live.boat.light);
    live.boat.boat.dispose();
    live.boat = null;
  }
}
