/**
 * The Ocean in an ordinary three.js scene: your renderer, camera, lights and controls; the sea is
 * one Object3D that also draws its sky behind everything, and a crate floats on ocean.heightAt(x, z), tilted
 * to the local slope.
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
  Quaternion,
  Scene,
  Vector3,
  WebGLRenderer,
} from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { Ocean } from '../src/index';

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

// A wooden crate, 2 m on a side, floating with its centre at the water line.
const crate = new Mesh(new BoxGeometry(2, 2, 2), new MeshStandardMaterial({ color: 0xa0703c, roughness: 0.8 }));
scene.add(crate);
const cratePosition = new Vector3(0, 0, 0);
const up = new Vector3(0, 1, 0);
const normal = new Vector3();
const tilt = new Quaternion();

/** Floats the crate: height from the surface at its centre, tilt from the slope across it. */
function floatCrate(): void {
  const { x, z } = cratePosition;
  const d = 1; // half the crate: the slope over its footprint, not the ripple under its centre
  const h = ocean.heightAt(x, z);
  const slopeX = (ocean.heightAt(x + d, z) - ocean.heightAt(x - d, z)) / (2 * d);
  const slopeZ = (ocean.heightAt(x, z + d) - ocean.heightAt(x, z - d)) / (2 * d);
  normal.set(-slopeX, 1, -slopeZ).normalize();
  crate.position.set(x, h, z);
  crate.quaternion.copy(tilt.setFromUnitVectors(up, normal));
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
  ocean.update(t);
  floatCrate();
  controls.update();
  // The far plane must reach the surface's far edge (it moves with the camera's height).
  camera.far = Math.max(1e4, 1.5 * ocean.horizonDistanceFor(camera.position.y));
  camera.updateProjectionMatrix();
  renderer.render(scene, camera);
  frames++;
});

// For the console and the browser tests.
Object.assign(window, { example: { renderer, scene, camera, ocean, crate, frames: () => frames } });
