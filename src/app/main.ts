/**
 * The app. For now: the live height field of the simulation (like the course report's Figure 3,
 * normalized height as grey) with the FFT path and timings on screen.
 */
import { WebGLRenderer } from 'three';
import { OceanSimulation } from '../sim/oceanSimulation';
import { FieldView } from './fieldView';

const canvas = document.querySelector<HTMLCanvasElement>('#ocean')!;
const status = document.querySelector<HTMLElement>('#status')!;
const renderer = new WebGLRenderer({ canvas, antialias: false });
renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));

const query = new URLSearchParams(location.search);
const path = (query.get('path') ?? 'auto') as 'auto' | 'gpu' | 'js';
const simulation = new OceanSimulation(renderer, {}, { path });
const heightView = new FieldView(simulation.uniforms.tDisplacement, 1, 4, false);

function resize(): void {
  const size = Math.min(window.innerWidth, window.innerHeight);
  renderer.setSize(size, size);
}
window.addEventListener('resize', resize);
resize();

const start = performance.now();
let lastStatus = 0;
renderer.setAnimationLoop(() => {
  const t = (performance.now() - start) / 1000;
  const before = performance.now();
  simulation.update(t);
  heightView.render(renderer);
  const ms = performance.now() - before;
  if (before - lastStatus > 250) {
    const { resolution, patchSize, windSpeed } = simulation.parameters;
    status.textContent =
      `FFT path: ${simulation.path}  ·  N = ${resolution}  ·  ${patchSize} m patch  ·  wind ${windSpeed} m/s  ·  ` +
      `t = ${t.toFixed(1)} s  ·  CPU time per frame ${ms.toFixed(1)} ms`;
    lastStatus = before;
  }
});
