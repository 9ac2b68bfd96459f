/**
 * One deterministic frame of the whole Ocean (simulation, generated sky, surface) for screenshot
 * tests: everything comes from the URL — seed, t, width, height, view, mode, wireframe,
 * sunElevation — and the
 * title becomes 'rendered' once the frame is drawn.
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

const query = new URLSearchParams(location.search);
const width = Number(query.get('width') ?? 400);
const height = Number(query.get('height') ?? 225);
const renderer = new WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
renderer.setPixelRatio(1);
renderer.setSize(width, height);
renderer.toneMapping = ACESFilmicToneMapping;
document.body.appendChild(renderer.domElement);

const ocean = new Ocean(renderer, {
  seed: Number(query.get('seed') ?? 7),
  path: 'gpu',
  shadingMode: (query.get('mode') ?? 'full') as ShadingMode,
  sunElevation: Number(query.get('sunElevation') ?? 30),
});
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
document.title = 'rendered';
