/**
 * Still frames for `npm run shot` (scripts/shot.mjs): the ocean at exactly the times asked for,
 * one frame at a time (not in real time), so the same arguments give the same picture.
 *
 * Query parameters (all optional):
 *   seed, wind (m/s), wind-direction (deg), choppiness, resolution, sun-elevation, sun-azimuth (deg)
 *   width, height        drawing-buffer size in pixels (default 1280×720), pixel ratio 1
 *   camera=x,y,z,tx,ty,tz  position and look-at point (default: <fft-ocean>'s view at 8 m)
 *   fov                  vertical field of view in degrees (default 50)
 *   t                    the time drawn on load (default 0)
 *
 * Exposes window.renderFrame(t): draws time t and resolves once the GPU has finished the frame;
 * then canvas.toDataURL('image/png') is that frame. document.title becomes 'ready' after the first
 * frame, or 'error: …' (with window.shotError) when the parameters are bad or WebGL 2 is missing.
 */
import { ACESFilmicToneMapping, PerspectiveCamera, Scene, WebGLRenderer } from 'three';
import { placeCamera } from '../src/embed/fftOceanElement';
import { Ocean, type OceanOptions } from '../src/index';

declare global {
  interface Window {
    renderFrame: (t: number) => Promise<void>;
    shotError?: string;
  }
}

function numberParameter(query: URLSearchParams, name: string): number | undefined {
  const raw = query.get(name);
  if (raw === null) return undefined;
  const value = raw.trim() === '' ? NaN : Number(raw);
  if (!Number.isFinite(value)) throw new Error(`${name}=${raw} is not a number`);
  return value;
}

function start(): void {
  const query = new URLSearchParams(location.search);
  const width = numberParameter(query, 'width') ?? 1280;
  const height = numberParameter(query, 'height') ?? 720;
  for (const [name, value] of [['width', width], ['height', height]] as const) {
    if (!Number.isInteger(value) || value < 1 || value > 8192) throw new Error(`${name} must be an integer from 1 to 8192, got ${value}`);
  }
  const options: OceanOptions = { path: 'auto', worker: false }; // the JS fallback runs synchronously
  const set = <K extends keyof OceanOptions>(key: K, value: OceanOptions[K] | undefined) => {
    if (value !== undefined) options[key] = value;
  };
  set('seed', numberParameter(query, 'seed'));
  set('windSpeed', numberParameter(query, 'wind'));
  set('windDirection', numberParameter(query, 'wind-direction'));
  set('choppiness', numberParameter(query, 'choppiness'));
  set('resolution', numberParameter(query, 'resolution'));
  const sunElevation = numberParameter(query, 'sun-elevation') ?? 22;
  const sunAzimuth = numberParameter(query, 'sun-azimuth') ?? 40;
  options.sunElevation = sunElevation;
  options.sunAzimuth = sunAzimuth;

  const renderer = new WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(1);
  renderer.setSize(width, height);
  renderer.toneMapping = ACESFilmicToneMapping;
  document.body.appendChild(renderer.domElement);

  const ocean = new Ocean(renderer, options);
  const scene = new Scene();
  scene.add(ocean);
  const camera = new PerspectiveCamera(numberParameter(query, 'fov') ?? 50, width / height, 0.5, 1e4);
  const cameraText = query.get('camera');
  if (cameraText === null) {
    placeCamera(camera, 0, 8, sunAzimuth);
  } else {
    const c = cameraText.split(',').map(Number);
    if (c.length !== 6 || !c.every(Number.isFinite)) throw new Error(`camera must be x,y,z,targetX,targetY,targetZ; got ${cameraText}`);
    camera.position.set(c[0], c[1], c[2]);
    camera.lookAt(c[3], c[4], c[5]);
  }
  camera.updateMatrixWorld();

  const gl = renderer.getContext();
  const pixel = new Uint8Array(4);
  window.renderFrame = async (t: number) => {
    if (typeof t !== 'number' || !Number.isFinite(t)) throw new Error(`renderFrame: t must be a finite number, got ${t}`);
    ocean.update(t);
    // The far plane must reach the horizon, known after a render: render until it does (twice
    // at most, and only on the first frame).
    for (let attempt = 0; attempt < 2; attempt++) {
      renderer.render(scene, camera);
      const far = Math.max(1e4, 1.5 * ocean.horizonDistance);
      if (far <= camera.far) break;
      camera.far = far;
      camera.updateProjectionMatrix();
    }
    // A one-pixel readback waits for the GPU to finish the frame (gl.finish does not, in Chromium).
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
  };
  void window.renderFrame(numberParameter(query, 't') ?? 0).then(() => {
    document.title = 'ready';
  });
}

try {
  start();
} catch (error) {
  window.shotError = error instanceof Error ? error.message : String(error);
  document.title = `error: ${window.shotError}`;
}
