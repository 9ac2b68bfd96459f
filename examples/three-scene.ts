/**
 * The Ocean in an ordinary three.js scene: your renderer, camera, lights and controls; the sea is
 * one Object3D that also draws its sky behind everything, and a crate floats on it: a FloatingBody
 * that heaves, pitches and rolls from the buoyancy at points of its bottom (ocean.heightAt), and
 * pushes on the local waves as it moves.
 *
 * Query parameters (for tests and screenshots): t=<seconds> freezes time, seed=<n>.
 */
import {
  ACESFilmicToneMapping,
  BoxGeometry,
  Color,
  DirectionalLight,
  HemisphereLight,
  Mesh,
  MeshStandardMaterial,
  PerspectiveCamera,
  Scene,
  WebGLRenderer,
} from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { FloatingBody, fitFarPlane, Ocean } from '../src/index';

const query = new URLSearchParams(location.search);
const fixedTime = query.has('t') ? Number(query.get('t')) : null;

const renderer = new WebGLRenderer({ antialias: true });
renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
renderer.toneMapping = ACESFilmicToneMapping;
document.body.appendChild(renderer.domElement);

const scene = new Scene();
const camera = new PerspectiveCamera(50, 1, 0.5, 1e4);
camera.position.set(-9, 4.5, 11);

// The sea: resolution 128 keeps heightAt's CPU copy of the fields cheap (it is computed once per
// frame, when first asked).
const sunElevation = 25;
const sunAzimuth = -60;
const ocean = new Ocean(renderer, {
  seed: Number(query.get('seed') ?? 3),
  windSpeed: 9,
  windDirection: 20,
  resolution: 128,
  sunElevation,
  sunAzimuth,
});
scene.add(ocean);

// Light from where the ocean's sky has its sun, plus sky and sea bounce.
const sun = new DirectionalLight(new Color(1, 0.95, 0.85), 2.5);
sun.position.copy(ocean.sky.sunDirection).multiplyScalar(100);
scene.add(sun, new HemisphereLight(0xc4daf0, 0x2a4a62, 2.4));

// A wooden crate, 2 × 1 × 2 m, of 1 t: it floats a quarter in. (A cube of half the water's density
// would roll over: upright, a floating cube is stable only below 0.21 or above 0.79 of it.)
const crate = new Mesh(new BoxGeometry(2, 1, 2), new MeshStandardMaterial({ color: 0xa0703c, roughness: 0.8 }));
scene.add(crate);
const crateBody = new FloatingBody({ mass: 1000, size: [2, 1, 2], samples: 3 });
crateBody.position.y = 0.5 - crateBody.restingDraft;
// As it heaves and rolls it pushes the water: rings spread from it on the local waves.
crateBody.pressOn(ocean.localWaves);
let lastTime: number | null = null;

/**
 * Moves the crate by the time since the last frame, so that it keeps up with the waves however slow
 * the frames (the body substeps by itself); at most 2 s, so a tab hidden for a minute does not make
 * one frame integrate the whole minute.
 */
function floatCrate(t: number): void {
  if (lastTime !== null && t > lastTime) crateBody.step(Math.min(t - lastTime, 2), ocean);
  lastTime = t;
  crate.position.copy(crateBody.position);
  crate.quaternion.copy(crateBody.orientation);
}

const controls = new OrbitControls(camera, renderer.domElement);
controls.target.set(0, 0, 0);
controls.maxPolarAngle = Math.PI * 0.495; // stay above the sea
controls.minDistance = 4;
controls.maxDistance = 300;
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
  floatCrate(t);
  controls.update();
  // The far plane must reach the surface's far edge (it moves with the camera's height).
  fitFarPlane(camera, ocean);
  renderer.render(scene, camera);
  frames++;
});

// For the console and the browser tests.
const example = { renderer, scene, camera, ocean, crate, crateBody, frames: () => frames };
Object.assign(window, { example });

declare global {
  interface Window {
    example: typeof example;
  }
}
