/**
 * The ocean test page's scene: its renderer and canvas (?width, ?height, ?antialias), camera, sun
 * and a uniform environment, and the sea it draws (the real simulation and surface, or a whole
 * Ocean), for the Playwright tests' hooks (ocean.ts).
 */
import {
  ACESFilmicToneMapping,
  Color,
  FloatType,
  LinearSRGBColorSpace,
  NoToneMapping,
  PerspectiveCamera,
  Scene,
  SRGBColorSpace,
  Vector3,
  WebGLCubeRenderTarget,
  WebGLRenderer,
} from 'three';
import { Ocean, type OceanOptions } from '../../../src/ocean';
import { shaderSource } from '../../../src/shaderSource';
import { OceanMaterial, type OceanShadingOptions } from '../../../src/render/oceanMaterial';
import { OceanSurface } from '../../../src/render/oceanSurface';
import { OceanSimulation } from '../../../src/layers/oceanSimulation';
import type { SimulationParameters } from '../../../src/parameters/parameters';

const query = new URLSearchParams(location.search);
export const width = Number(query.get('width') ?? 640);
export const height = Number(query.get('height') ?? 360);
export const renderer = new WebGLRenderer({ antialias: query.get('antialias') === '1', preserveDrawingBuffer: true });
renderer.setPixelRatio(1);
renderer.setSize(width, height);
document.body.appendChild(renderer.domElement);

export const scene = new Scene();
export const camera = new PerspectiveCamera(55, width / height, 0.5, 2e7);
/** The sun's direction as the page loads. */
const FIRST_SUN = new Vector3(0.3, 0.5, -0.8).normalize();
export const sunDirection = FIRST_SUN.clone();

// A uniform-colour environment (for shading probes), in the RGBM encoding the surface decodes
// (shaders/sky/rgbm.glsl): in a float cube, (colour / range, 1) decodes exactly to the colour.
const RGBM_RANGE = Number(/SKY_RGBM_RANGE = ([\d.]+)/.exec(shaderSource('sky/rgbm.glsl'))![1]);
const uniformCube = new WebGLCubeRenderTarget(16, { type: FloatType });
export function setUniformEnvironment(colour: [number, number, number]): void {
  // three.js converts a clear colour to the colour space of the target current when it is set:
  // set it with the (linear) cube current, not the (sRGB) canvas.
  renderer.setRenderTarget(uniformCube);
  renderer.setClearColor(new Color().fromArray(colour).multiplyScalar(1 / RGBM_RANGE));
  uniformCube.clear(renderer, true, true, true);
  renderer.setRenderTarget(null);
  renderer.setClearColor(0x000000);
  scene.background = new Color().fromArray(colour); // the same sky, for pixels the sea leaves
}
/** The sky's colour as the page loads. */
const FIRST_ENVIRONMENT: [number, number, number] = [0.5, 0.6, 0.7];
setUniformEnvironment(FIRST_ENVIRONMENT);
export const environment = { value: uniformCube.texture };

/**
 * The sea the page draws: setup's simulation and surface (or withOcean's Ocean's), and what the
 * surface is told bounds the waves (undefined: the eye is taken to be above them).
 */
export const current: { simulation: OceanSimulation | null; surface: OceanSurface | null; surfaceBound: number | undefined } = {
  simulation: null,
  surface: null,
  surfaceBound: undefined,
};

export function setup(parameters: Partial<SimulationParameters>, shading: OceanShadingOptions = {}): void {
  current.surface?.removeFromParent();
  current.surface?.dispose();
  current.simulation?.dispose();
  const sim = new OceanSimulation(renderer, parameters, { path: 'gpu', worker: false });
  current.simulation = sim;
  current.surface = new OceanSurface(new OceanMaterial({ environment, sunDirection: { value: sunDirection } }, shading), () => ({
    layers: sim.layers,
    choppiness: sim.parameters.choppiness,
    foam: sim.foam.texture,
    surfaceBound: current.surfaceBound,
  }));
  scene.add(current.surface);
}

export function view(position: [number, number, number], target: [number, number, number]): void {
  camera.position.fromArray(position);
  camera.lookAt(new Vector3().fromArray(target));
  camera.updateMatrixWorld();
}

/** Renders the page's sea at time t: tone-mapped as an app, or `linear` (no tone mapping, linear output). */
export function render(t: number, linear = false): void {
  renderer.toneMapping = linear ? NoToneMapping : ACESFilmicToneMapping;
  renderer.outputColorSpace = linear ? LinearSRGBColorSpace : SRGBColorSpace;
  current.simulation!.update(t);
  renderer.render(scene, camera);
}

/** Reads one pixel of the canvas (RGBA 0–255), y from the top. */
export function pixel(x: number, y: number): number[] {
  const gl = renderer.getContext();
  const out = new Uint8Array(4);
  gl.readPixels(x, height - 1 - y, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, out);
  return Array.from(out);
}

/**
 * Runs `use` with an Ocean (GPU path, no worker) made from `changes` in place of the page's own
 * simulation and surface (so geometryCheck reads its surface), and frees it after.
 */
export function withOcean<T>(changes: OceanOptions, use: (ocean: Ocean) => T): T {
  current.surface?.removeFromParent();
  current.surface?.dispose();
  current.simulation?.dispose();
  const ocean = new Ocean(renderer, { ...changes, path: 'gpu', worker: false });
  current.simulation = ocean.simulation;
  current.surface = ocean.surface;
  try {
    return use(ocean);
  } finally {
    current.simulation = null;
    current.surface = null;
    ocean.dispose();
  }
}

/**
 * Sets the page back as it loaded, for the next test on a page tests share: no sea (setup's is
 * freed), no fog, the first sky and sun, the camera at the origin looking along −z, and the
 * renderer's tone mapping and colour space three's defaults.
 */
export function resetPage(): void {
  current.surface?.removeFromParent();
  current.surface?.dispose();
  current.simulation?.dispose();
  current.simulation = null;
  current.surface = null;
  current.surfaceBound = undefined;
  scene.fog = null;
  sunDirection.copy(FIRST_SUN);
  setUniformEnvironment(FIRST_ENVIRONMENT);
  camera.position.set(0, 0, 0);
  camera.quaternion.identity();
  camera.updateMatrixWorld();
  renderer.setRenderTarget(null);
  renderer.toneMapping = NoToneMapping;
  renderer.outputColorSpace = SRGBColorSpace;
}
