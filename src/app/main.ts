/**
 * The app: the ocean in a full-window canvas, with the FFT path and timings on screen and the
 * inspector's tiles along the bottom.
 */
import { ACESFilmicToneMapping, PerspectiveCamera, Scene, WebGLRenderer } from 'three';
import { Ocean } from '../ocean';
import { Inspector } from './inspector';

const container = document.querySelector<HTMLElement>('#app')!;
const status = document.querySelector<HTMLElement>('#status')!;
const renderer = new WebGLRenderer({ antialias: true });
renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
renderer.toneMapping = ACESFilmicToneMapping;
container.appendChild(renderer.domElement);

const query = new URLSearchParams(location.search);
const scene = new Scene();
const camera = new PerspectiveCamera(55, 1, 0.5, 1e5);
camera.position.set(0, 12, 0);
camera.lookAt(60, 0, -80);
const ocean = new Ocean(renderer, { seed: Number(query.get('seed') ?? 1), path: (query.get('path') ?? 'auto') as 'auto' | 'gpu' | 'js' });
scene.add(ocean);
scene.background = ocean.background;
const inspector = query.get('inspector') === '1' ? new Inspector(ocean, container) : null;

function resize(): void {
  renderer.setSize(window.innerWidth, window.innerHeight);
  camera.aspect = window.innerWidth / window.innerHeight;
  camera.updateProjectionMatrix();
}
window.addEventListener('resize', resize);
resize();

const fixedTime = query.get('t');
const start = performance.now();
let lastStatus = 0;
renderer.setAnimationLoop(() => {
  const t = fixedTime !== null ? Number(fixedTime) : (performance.now() - start) / 1000;
  const before = performance.now();
  ocean.update(t);
  camera.far = Math.max(1e4, 1.5 * ocean.horizonDistance);
  camera.updateProjectionMatrix();
  renderer.render(scene, camera);
  inspector?.render(renderer);
  const ms = performance.now() - before;
  if (before - lastStatus > 250) {
    const { resolution, windSpeed } = ocean.parameters;
    status.textContent = `FFT path: ${ocean.simulation.path} · N = ${resolution} · wind ${windSpeed} m/s · t = ${t.toFixed(1)} s · ${ms.toFixed(1)} ms`;
    lastStatus = before;
  }
});

// For the console and the browser tests: the live objects of this page.
Object.assign(window, { oceanApp: { renderer, scene, camera, ocean, inspector } });
