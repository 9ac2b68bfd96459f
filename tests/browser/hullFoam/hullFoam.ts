/**
 * Test page for the foam of a hull under way (src/layers/hullFoam.ts): a light sea without
 * whitecaps (wind under Beaufort 3), a hull given to the local waves that runs along +x at a chosen
 * speed and stops at a chosen time, a dark box on it, and a camera straight down from above, the
 * sun low towards +z so its glint is out of the picture. Reads back the canvas and the foam field.
 */
import { BoxGeometry, Color, Mesh, MeshBasicMaterial, PerspectiveCamera, Scene, Vector3, WebGLRenderer } from 'three';
import { Ocean } from '../../../src/ocean';

export const HULL = { length: 8, beam: 2.6, draft: 0.6 };
/** Where the camera looks from (m). */
export const EYE: [number, number, number] = [-12, 50, 0];

let renderer: WebGLRenderer | null = null;
let ocean: Ocean | null = null;
let texturesBefore = 0;
/** The hull's x at time t (m). */
let hullX: (t: number) => number = () => 0;
const scene = new Scene();
const camera = new PerspectiveCamera(50, 16 / 9, 0.5, 1e4);
const box = new Mesh(new BoxGeometry(HULL.length, 1.4, HULL.beam), new MeshBasicMaterial({ color: new Color(0.15, 0.05, 0.05) }));
box.position.y = 0.7 - HULL.draft;

/**
 * A new renderer and Ocean; the hull runs along z = 0 at `speed` m/s, its centre at x = 0 at
 * `stopAt` s and there from then on.
 */
function setup(width: number, height: number, speed: number, stopAt: number): void {
  renderer = new WebGLRenderer({ preserveDrawingBuffer: true });
  renderer.setPixelRatio(1);
  renderer.setSize(width, height);
  document.body.append(renderer.domElement);
  texturesBefore = renderer.info.memory.textures;
  ocean = new Ocean(renderer, { windSpeed: 2, resolution: 64, worker: false, refractions: 'sky', reflections: 'sky', sunDirection: [0, Math.sin(0.17), Math.cos(0.17)] });
  scene.add(ocean, box);
  hullX = (t: number) => speed * (Math.min(t, stopAt) - stopAt);
  ocean.localWaves!.addPressure(HULL, { x: hullX(0), z: 0, heading: 0 }, (t) => ({ x: hullX(t), z: 0, heading: 0 }));
  ocean.localWaves!.follow(EYE[0], EYE[2]);
  camera.aspect = width / height;
  camera.position.set(...EYE);
  camera.up.set(0, 0, -1); // +x to the right of the picture, +z down it
  camera.lookAt(new Vector3(EYE[0], 0, EYE[2]));
  camera.updateProjectionMatrix();
  camera.updateMatrixWorld();
}

/**
 * Draws the sea at time t with the hull where its path is, and reads the canvas (RGBA bytes, from
 * the bottom row, in base64); with the bow's x (m).
 */
function draw(t: number): { pixels: string; bow: number } {
  ocean!.update(t, camera);
  box.position.x = hullX(t);
  renderer!.render(scene, camera);
  const { width, height } = renderer!.domElement;
  const gl = renderer!.getContext();
  const pixels = new Uint8Array(4 * width * height);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  // Base64: a string crosses to the test far faster than an array of numbers.
  let binary = '';
  for (let at = 0; at < pixels.length; at += 0x8000) binary += String.fromCharCode(...pixels.subarray(at, at + 0x8000));
  return { pixels: btoa(binary), bow: box.position.x + HULL.length / 2 };
}

/** Brings the sea to time t without drawing it. */
function advance(t: number): void {
  ocean!.update(t, camera);
}

/** The hull foam field: its coverage per texel, the grid's origin (m) and texel size. */
function field(): { coverage: number[]; origin: [number, number]; cellSize: number; resolution: number } {
  const waves = ocean!.localWaves!;
  return { coverage: Array.from(waves.foam.coverage), origin: [waves.frame.origin[0], waves.frame.origin[1]], cellSize: waves.grid.cellSize, resolution: waves.grid.resolution };
}

/** The world point (x, 0, z) on the rest plane under each pixel, [x, z] pairs row by row from the bottom. */
function ground(): number[] {
  const { width, height } = renderer!.domElement;
  const points: number[] = [];
  const ray = new Vector3();
  for (let row = 0; row < height; row++) {
    for (let column = 0; column < width; column++) {
      ray.set(((column + 0.5) / width) * 2 - 1, ((row + 0.5) / height) * 2 - 1, 0.5).unproject(camera).sub(camera.position);
      const t = -camera.position.y / ray.y;
      points.push(camera.position.x + t * ray.x, camera.position.z + t * ray.z);
    }
  }
  return points;
}

/** Disposes the Ocean and the renderer; the textures the renderer still holds against the count before the Ocean. */
function dispose(): { before: number; after: number } {
  scene.remove(ocean!, box);
  ocean!.dispose();
  ocean = null;
  const after = renderer!.info.memory.textures;
  renderer!.dispose();
  renderer!.domElement.remove();
  renderer = null;
  return { before: texturesBefore, after };
}

const harness = { setup, draw, advance, field, ground, dispose };
declare global {
  interface Window {
    hullFoamHarness: typeof harness;
  }
}
window.hullFoamHarness = harness;
document.title = 'ready';
