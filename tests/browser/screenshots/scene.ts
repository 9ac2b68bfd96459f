/**
 * One deterministic frame of the whole Ocean (simulation, generated sky, surface) for screenshot
 * tests: the canvas's width and height come from the page's URL, the scene from a query — seed,
 * t, view, mode, wireframe, sunElevation — first the URL's, then any given to
 * window.screenshotScene.draw (a page per canvas size serves every scene of that size: a page
 * load costs more than a frame). Each scene is drawn by a new Ocean, the one before disposed, so
 * that it is the frame a fresh page draws; the title becomes 'rendered' once the first is drawn.
 */
import { ACESFilmicToneMapping, PerspectiveCamera, Scene, Vector3, WebGLRenderer } from 'three';
import { Ocean } from '../../../src/ocean';
import type { ShadingMode } from '../../../src/parameters/sceneOptions';

/** Camera position and target of each named view. */
export const VIEWS: Record<string, [[number, number, number], [number, number, number]]> = {
  default: [[0, 9, 0], [80, -2, 70]],
  horizon: [[0, 2, 0], [-100, 1.5, -30]],
  high: [[0, 2000, 0], [2000, 700, 1500]],
  // 4 m under the surface, looking up 50°: Snell's window over the surface seen from below.
  underwater: [[0, -4, 0], [-8, 6, -3]],
};

const pageQuery = new URLSearchParams(location.search);
const width = Number(pageQuery.get('width') ?? 400);
const height = Number(pageQuery.get('height') ?? 225);
const renderer = new WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
renderer.setPixelRatio(1);
renderer.setSize(width, height);
renderer.toneMapping = ACESFilmicToneMapping;
document.body.appendChild(renderer.domElement);

let shown: Ocean | null = null;

/** Draws the scene `query` describes onto the canvas, with a new Ocean (the one before is disposed). */
function draw(query: URLSearchParams): void {
  shown?.dispose();
  const ocean = new Ocean(renderer, {
    seed: Number(query.get('seed') ?? 7),
    path: 'gpu',
    shadingMode: (query.get('mode') ?? 'full') as ShadingMode,
    sunElevation: Number(query.get('sunElevation') ?? 30),
  });
  shown = ocean;
  ocean.surface.material.wireframe = query.get('wireframe') === '1';
  const scene = new Scene().add(ocean);
  const [position, target] = VIEWS[query.get('view') ?? 'default'];
  const camera = new PerspectiveCamera(55, width / height, 0.5, 1e5);
  camera.position.fromArray(position);
  camera.lookAt(new Vector3().fromArray(target));

  ocean.update(Number(query.get('t') ?? 12.5));
  renderer.render(scene, camera); // places the rings, so horizonDistance is known
  camera.far = 1.5 * ocean.horizonDistance;
  camera.updateProjectionMatrix();
  renderer.render(scene, camera);
  // A one-pixel readback waits for the GPU to finish the frame (gl.finish does not, in Chromium):
  // the screenshot after a draw then waits for nothing (it has 30 s to become stable).
  const gl = renderer.getContext();
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
}

draw(pageQuery);
const screenshotScene = { draw: (query: string) => draw(new URLSearchParams(query)) };
declare global {
  interface Window {
    screenshotScene: typeof screenshotScene;
  }
}
window.screenshotScene = screenshotScene;
document.title = 'rendered';
