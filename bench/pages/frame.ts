/**
 * Full-frame benchmark page for `npm run bench`: the Ocean (simulation + sky + surface) rendered
 * at a fixed camera into a canvas of the requested size, timed per frame from an idle GPU through
 * ocean.update(t) and renderer.render() to a 1-pixel readPixels of the canvas (which cannot
 * return before the frame is drawn; gl.finish() does not block in Chromium).
 */
import { ACESFilmicToneMapping, PerspectiveCamera, Scene, WebGLRenderer } from 'three';
import { Ocean } from '../../src/ocean';

async function frames(options: { resolution: number; width: number; height: number; warmup: number; rounds: number }) {
  const renderer = new WebGLRenderer({ antialias: false });
  renderer.setPixelRatio(1);
  renderer.setSize(options.width, options.height);
  renderer.toneMapping = ACESFilmicToneMapping;
  document.body.appendChild(renderer.domElement);
  const gl = renderer.getContext();
  const scene = new Scene();
  const camera = new PerspectiveCamera(55, options.width / options.height, 0.5, 1e5);
  camera.position.set(0, 12, 0);
  camera.lookAt(60, 0, -80);
  const ocean = new Ocean(renderer, { resolution: options.resolution, seed: 7, path: 'gpu' });
  scene.add(ocean);
  const pixel = new Uint8Array(4);
  const sync = () => gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
  const samples: number[] = [];
  let t = 3;
  for (let round = 0; round < options.warmup + options.rounds; round++) {
    sync();
    const start = performance.now();
    ocean.update((t += 1 / 30));
    camera.far = Math.max(1e4, 1.5 * ocean.horizonDistance);
    camera.updateProjectionMatrix();
    renderer.render(scene, camera);
    sync();
    if (round >= options.warmup) samples.push(performance.now() - start);
    await new Promise((resolve) => setTimeout(resolve, 0));
  }
  const info = {
    samples,
    calls: renderer.info.render.calls,
    triangles: renderer.info.render.triangles,
    vertices: ocean.surface.geometry.getAttribute('position').count,
    simulationPasses: ocean.simulation.passCount,
    path: ocean.simulation.path,
  };
  ocean.dispose();
  renderer.dispose();
  renderer.domElement.remove();
  return info;
}

declare global {
  interface Window {
    frameBench: { frames: typeof frames };
  }
}
window.frameBench = { frames };
document.title = 'ready';
