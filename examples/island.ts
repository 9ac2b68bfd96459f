/**
 * An island in the sea, seen from a boat offshore of its beach: the terrain, the reef under the
 * surface, the pier and the moored boat of src/objects/island.ts, lit by three.js's lights where the
 * ocean's sky has its sun (a low afternoon sun, so the sea mirrors the land), with OrbitControls.
 * The island's seabed (island.seabed: the depth below mean sea level under every point, the
 * function the terrain is built from) is what shapes the waves near its shores.
 *
 * Query parameters (for tests and screenshots): t=<seconds> freezes time, seed=<n>.
 */
import { ACESFilmicToneMapping, PerspectiveCamera, Scene, WebGLRenderer } from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { fitFarPlane, Ocean } from '../src/index';
import { Island, ISLAND_VIEW } from '../src/objects/island';
import { SunLight } from '../src/objects/sunLight';

const query = new URLSearchParams(location.search);
const fixedTime = query.has('t') ? Number(query.get('t')) : null;

const renderer = new WebGLRenderer({ antialias: true });
renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
renderer.toneMapping = ACESFilmicToneMapping;
document.body.appendChild(renderer.domElement);

const scene = new Scene();
const camera = new PerspectiveCamera(50, 1, 0.5, 1e4);
camera.position.fromArray(ISLAND_VIEW.position);

// A moderate breeze from the open sea onto the beach (which faces +z: the wind blows towards −z),
// and a low sun behind the viewer's right shoulder, lighting the beach and the cliff's face.
const ocean = new Ocean(renderer, {
  seed: Number(query.get('seed') ?? 5),
  windSpeed: 7,
  windDirection: -75,
  resolution: 128,
  sunElevation: 14,
  sunAzimuth: 60,
});
const island = new Island();
// The island's sea floor (docs/shores.md): the waves shoal and break on the beach and the reef.
ocean.setSeabed(island.seabed);
scene.add(ocean, island);

// The land is lit by the ocean's sun and sky (src/objects/sunLight.ts).
const light = new SunLight(ocean);
light.update();
scene.add(light);

const controls = new OrbitControls(camera, renderer.domElement);
controls.target.fromArray(ISLAND_VIEW.target);
controls.maxPolarAngle = Math.PI * 0.495; // stay above the sea
controls.minDistance = 10;
controls.maxDistance = 1500;
controls.enableDamping = true;
controls.update();

function resize(): void {
  renderer.setSize(window.innerWidth, window.innerHeight);
  camera.aspect = window.innerWidth / window.innerHeight;
  camera.updateProjectionMatrix();
}
window.addEventListener('resize', resize);
resize();

const start = performance.now();
let frames = 0;
renderer.setAnimationLoop(() => {
  const t = fixedTime ?? (performance.now() - start) / 1000;
  ocean.update(t, camera);
  island.update(ocean);
  controls.update();
  fitFarPlane(camera, ocean);
  renderer.render(scene, camera);
  frames++;
});

// For the console and the browser tests.
const islandExample = { renderer, scene, camera, ocean, island, frames: () => frames };
Object.assign(window, { islandExample });

declare global {
  interface Window {
    islandExample: typeof islandExample;
  }
}
