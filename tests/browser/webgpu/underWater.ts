/**
 * Test page for three-fft-ocean/webgpu under the water and after a lost device, driven by
 * tests/browser/webgpu/underWater.spec.ts. It loads webgpu.ts's page too (window.webgpuOcean.open
 * makes the WebGPURenderer these functions draw with).
 */
import { LinearSRGBColorSpace, NoToneMapping, PerspectiveCamera, RenderTarget, Scene, WebGLRenderer, WebGLRenderTarget } from 'three';
import type { WebGPURenderer } from 'three/webgpu';
import { Ocean } from '../../../src/webgpu/index';
import { Ocean as WebGLOcean } from '../../../src/ocean';
import { pictureTarget, renderer, SEA, SEA_PARAMETERS, topFirst } from './webgpu';
import { snellWindowEdges } from '../shared/snellWindowEdges';

/** An eye: where it is and the point it looks at, world metres. */
interface Pose {
  position: [number, number, number];
  target: [number, number, number];
}

/** An RGBA picture, rows from the top. */
interface Picture {
  width: number;
  height: number;
  data: number[];
}

function poseCamera({ position, target }: Pose, width: number, height: number, fov = 60): PerspectiveCamera {
  const camera = new PerspectiveCamera(fov, width / height, 0.5, 30_000);
  camera.position.set(...position);
  camera.lookAt(...target);
  camera.updateMatrixWorld();
  return camera;
}

function webgpuRenderer(): WebGPURenderer {
  if (!renderer) throw new Error('window.webgpuOcean.open(backend) first');
  return renderer;
}

/** Reads `target` back from `drawing`, rows from the top. */
async function readTarget(drawing: WebGPURenderer, target: RenderTarget, width: number, height: number): Promise<number[]> {
  const pixels = (await drawing.readRenderTargetPixelsAsync(target, 0, 0, width, height)) as Uint8Array;
  return topFirst(pixels, width, height, !(drawing.backend as { isWebGPUBackend?: boolean }).isWebGPUBackend);
}

/**
 * The WebGPU Ocean (default sea of webgpu.ts, time t) seen from each pose in turn, one Ocean
 * drawing them all in this order (as a camera moving through them), into 8-bit sRGB targets.
 */
async function drawPoses(poses: Pose[], t: number, width: number, height: number): Promise<Picture[]> {
  const drawing = webgpuRenderer();
  const scene = new Scene();
  const ocean = new Ocean(drawing, SEA);
  scene.add(ocean);
  ocean.update(t);
  const target = pictureTarget(RenderTarget, width, height);
  const pictures: Picture[] = [];
  for (const pose of poses) {
    drawing.setRenderTarget(target);
    drawing.render(scene, poseCamera(pose, width, height));
    drawing.setRenderTarget(null);
    pictures.push({ width, height, data: await readTarget(drawing, target, width, height) });
  }
  target.dispose();
  ocean.dispose();
  return pictures;
}

/**
 * The same sea drawn by the WebGL Ocean from each pose (its JS path, what the WebGPU Ocean does
 * not draw left out, no tone mapping), as webgpu.ts's drawWebGLView. Only while no WebGPU device
 * lives in the page (a WebGLRenderer beside one drops it, webgpu.spec.ts).
 */
function drawWebGLPoses(poses: Pose[], t: number, width: number, height: number): Picture[] {
  const gl = new WebGLRenderer({ antialias: false });
  gl.toneMapping = NoToneMapping;
  gl.setPixelRatio(1);
  gl.setSize(width, height);
  const ocean = new WebGLOcean(gl, { ...SEA_PARAMETERS, path: 'js', worker: false, localWaves: false, reflections: 'sky', refractions: 'sky' });
  const scene = new Scene();
  scene.add(ocean);
  const target = pictureTarget(WebGLRenderTarget, width, height);
  const pictures = poses.map((pose) => {
    const camera = poseCamera(pose, width, height);
    ocean.update(t, camera);
    gl.setRenderTarget(target);
    gl.render(scene, camera);
    gl.setRenderTarget(null);
    const pixels = new Uint8Array(4 * width * height);
    gl.readRenderTargetPixels(target, 0, 0, width, height, pixels);
    return { width, height, data: topFirst(pixels, width, height, true) };
  });
  target.dispose();
  ocean.dispose();
  gl.dispose();
  return pictures;
}

/**
 * Snell's window as ocean.spec.ts's snellWindow measures the WebGL Ocean's: a calm sea (no wind)
 * seen straight up from 1 m under it with a 120° lens, linear output without tone mapping, into a
 * 512×512 target. Where the sky's light ends (snellWindowEdges), degrees; the red at the centre.
 */
async function snellWindow(ior: number): Promise<{ edgeAngles: number[]; centreRed: number; picture: Picture }> {
  const drawing = webgpuRenderer();
  const size = 512;
  const fov = 120;
  const scene = new Scene();
  const ocean = new Ocean(drawing, { ...SEA, windSpeed: 0, ior });
  scene.add(ocean);
  ocean.update(3);
  const lens = new PerspectiveCamera(fov, 1, 0.1, 1e5);
  lens.position.set(0, -1, 0);
  lens.up.set(0, 0, -1);
  lens.lookAt(0, 10, 0);
  lens.updateMatrixWorld();
  const target = new RenderTarget(size, size);
  target.texture.colorSpace = LinearSRGBColorSpace;
  drawing.setRenderTarget(target);
  drawing.render(scene, lens);
  drawing.setRenderTarget(null);
  const data = await readTarget(drawing, target, size, size);
  target.dispose();
  ocean.dispose();
  const red = (x: number, y: number) => data[4 * (y * size + x)];
  return { edgeAngles: snellWindowEdges(red, size, fov), centreRed: red(size / 2, size / 2), picture: { width: size, height: size, data } };
}

/**
 * Loses the device of the renderer open now under a drawing Ocean (the WebGPU backend:
 * device.destroy(); the WebGL2 backend: WEBGL_lose_context), and reports what the Ocean did: its
 * devicelost event, ocean.deviceLost, and what update() throws then ([name, message]).
 */
async function loseDevice(): Promise<{ event: unknown; deviceLost: unknown; update: [string, string]; disposed: boolean }> {
  const drawing = webgpuRenderer();
  const scene = new Scene();
  const ocean = new Ocean(drawing, SEA);
  scene.add(ocean);
  ocean.update(1);
  const camera = poseCamera({ position: [0, 4, 0], target: [0, 1, -40] }, 64, 36);
  const target = new RenderTarget(64, 36);
  drawing.setRenderTarget(target);
  drawing.render(scene, camera);
  drawing.setRenderTarget(null);
  const event = new Promise((resolve) => ocean.addEventListener('devicelost', ({ loss }) => resolve(loss)));
  const backend = drawing.backend as { isWebGPUBackend?: boolean; device?: GPUDevice };
  if (backend.isWebGPUBackend) backend.device!.destroy();
  else (drawing.getContext() as WebGL2RenderingContext).getExtension('WEBGL_lose_context')!.loseContext();
  const loss = await event;
  let update: [string, string] = ['none', ''];
  try {
    ocean.update(2);
  } catch (error) {
    update = [(error as Error).name, (error as Error).message];
  }
  const deviceLost = ocean.deviceLost;
  target.dispose();
  ocean.dispose();
  return { event: loss, deviceLost, update, disposed: true };
}

const harness = { drawPoses, drawWebGLPoses, snellWindow, loseDevice };
declare global {
  interface Window {
    underWater: typeof harness;
  }
}
window.underWater = harness;
