/**
 * Test page for the scene in the WebGPU Ocean's sea (reflections and refractions 'scene',
 * src/webgpu/sceneLightNodes.ts), driven by sceneLight.spec.ts: a red box above calm or rough
 * water and a plate under calm water, drawn at 960×540 by the WebGPU Ocean on a WebGPURenderer (its
 * WebGL2 or its WebGPU backend) into render targets and read back, and the same scenes drawn by the
 * WebGL Ocean on a WebGLRenderer (only before any WebGPU device lives in the page: see webgpu.spec.ts).
 */
import { BoxGeometry, FloatType, Mesh, MeshBasicMaterial, NoToneMapping, PerspectiveCamera, PlaneGeometry, RenderTarget, Scene, SRGBColorSpace, Vector3, WebGLRenderer, WebGLRenderTarget } from 'three';
import { WebGPURenderer } from 'three/webgpu';
import { Ocean } from '../../../src/webgpu/index';
import { Ocean as WebGLOcean } from '../../../src/ocean';

export const WIDTH = 960;
export const HEIGHT = 540;
export type Vec3 = [number, number, number];

/** A view: the sea's wind, what it shows of the scene, the box or the plate, the camera and the time. */
export interface View {
  windSpeed: number;
  reflections: 'scene' | 'sky';
  refractions: 'scene' | 'sky';
  /** The red box's centre and size (m), or none. */
  box?: { centre: Vec3; size: Vec3 };
  /** The plate's depth under the sea (m) and its grey (linear, 0..1), or none. */
  plate?: { depth: number; grey: number };
  eye: Vec3;
  target: Vec3;
  fov: number;
  t: number;
  hideSurface?: boolean;
}

const SEA = { resolution: 64, seed: 5, worker: false, causticColor: [0, 0, 0] as [number, number, number], sunElevation: 30, sunAzimuth: 90 };

let renderer: WebGPURenderer | null = null;
/** Whether the renderer got the WebGPU backend (whose read-back rows come top first). */
let webgpuBackend = false;
const scene = new Scene();
const camera = new PerspectiveCamera(40, WIDTH / HEIGHT, 0.5, 20000);
const box = new Mesh(new BoxGeometry(1, 1, 1), new MeshBasicMaterial({ color: 0xff0000, toneMapped: false }));
const plate = new Mesh(new PlaneGeometry(60, 60), new MeshBasicMaterial({ color: 0xffffff, toneMapped: false }));
plate.rotation.x = -Math.PI / 2;
scene.add(box, plate);
/** The WebGPU Oceans made so far, one for each wind and pair of options (each compiles its own material). */
const oceans = new Map<string, Ocean>();

function pose(view: View): void {
  box.visible = view.box !== undefined;
  if (view.box) {
    box.position.set(...view.box.centre);
    box.scale.set(...view.box.size);
  }
  plate.visible = view.plate !== undefined;
  if (view.plate) {
    plate.position.y = -view.plate.depth;
    plate.material.color.setScalar(view.plate.grey);
  }
  camera.fov = view.fov;
  camera.position.set(...view.eye);
  camera.lookAt(new Vector3(...view.target));
  camera.updateProjectionMatrix();
  camera.updateMatrixWorld();
}

/** The renderer on `backend`, initialized; whether it got the WebGPU backend. */
async function open(backend: 'webgl' | 'webgpu'): Promise<boolean> {
  for (const ocean of oceans.values()) ocean.dispose();
  oceans.clear();
  renderer?.dispose();
  renderer = new WebGPURenderer({ forceWebGL: backend === 'webgl', antialias: false });
  renderer.setPixelRatio(1);
  renderer.setSize(WIDTH, HEIGHT);
  renderer.toneMapping = NoToneMapping;
  await renderer.init();
  webgpuBackend = (renderer.backend as { isWebGPUBackend?: boolean }).isWebGPUBackend === true;
  return webgpuBackend;
}

/** The WebGPU Ocean of the view's wind and options, the only one in the scene. */
function oceanFor(view: View): Ocean {
  const key = `${view.windSpeed} ${view.reflections} ${view.refractions}`;
  let ocean = oceans.get(key);
  if (!ocean) {
    ocean = new Ocean(renderer!, { ...SEA, windSpeed: view.windSpeed, reflections: view.reflections, refractions: view.refractions });
    oceans.set(key, ocean);
  }
  for (const other of oceans.values()) if (other !== ocean) other.removeFromParent();
  scene.add(ocean);
  ocean.getObjectByName('OceanWebGPU surface')!.visible = view.hideSurface !== true;
  return ocean;
}

/** RGBA rows read back, reordered top first (WebGL's come bottom first, WebGPU's top first). */
function topFirst<T extends Uint8Array | Float32Array>(pixels: T, bottomFirst: boolean): T {
  if (!bottomFirst) return pixels;
  const rows = pixels.slice() as T;
  const row = 4 * WIDTH;
  for (let y = 0; y < HEIGHT; y++) rows.set(pixels.subarray(row * (HEIGHT - 1 - y), row * (HEIGHT - y)), row * y);
  return rows;
}

function base64(data: Uint8Array): string {
  let text = '';
  for (let i = 0; i < data.length; i += 0x8000) text += String.fromCharCode(...data.subarray(i, i + 0x8000));
  return btoa(text);
}

/** Draws `view` with the WebGPU Ocean into an sRGB 8-bit target; RGBA rows from the top, base64. */
async function render(view: View): Promise<string> {
  const ocean = oceanFor(view);
  pose(view);
  ocean.update(view.t);
  const target = new RenderTarget(WIDTH, HEIGHT);
  target.texture.colorSpace = SRGBColorSpace;
  renderer!.setRenderTarget(target);
  renderer!.render(scene, camera);
  renderer!.setRenderTarget(null);
  const pixels = (await renderer!.readRenderTargetPixelsAsync(target, 0, 0, WIDTH, HEIGHT)) as Uint8Array;
  target.dispose();
  return base64(topFirst(pixels, !webgpuBackend));
}

/** Draws `view` with the WebGPU Ocean into a linear float target (no tone mapping), twice, and returns the RGB of `pixels` ([x, y] from the top left). */
async function linearPixels(view: View, pixels: [number, number][]): Promise<Vec3[]> {
  const ocean = oceanFor(view);
  pose(view);
  ocean.update(view.t);
  const target = new RenderTarget(WIDTH, HEIGHT, { type: FloatType });
  renderer!.setRenderTarget(target);
  // Two frames: a material's colour changed since the last frame (the plate's grey) reached the
  // capture one frame late, where only the colour changed (seen: white to black at the same depth;
  // positions are never late). three r187's caching of material values across a nested render.
  renderer!.render(scene, camera);
  renderer!.render(scene, camera);
  renderer!.setRenderTarget(null);
  const data = topFirst((await renderer!.readRenderTargetPixelsAsync(target, 0, 0, WIDTH, HEIGHT)) as Float32Array, !webgpuBackend);
  target.dispose();
  return pixels.map(([x, y]) => {
    const i = 4 * (y * WIDTH + x);
    return [data[i], data[i + 1], data[i + 2]];
  });
}

/** The same view drawn by the WebGL Ocean on a WebGLRenderer (before any WebGPU device lives in the page); RGBA rows from the top, base64. */
function renderWebGL(view: View): string {
  const gl = new WebGLRenderer({ antialias: false });
  gl.toneMapping = NoToneMapping;
  gl.setPixelRatio(1);
  gl.setSize(WIDTH, HEIGHT);
  const ocean = new WebGLOcean(gl, { ...SEA, path: 'js', localWaves: false, windSpeed: view.windSpeed, reflections: view.reflections, refractions: view.refractions });
  const own = new Scene();
  own.add(ocean, box, plate);
  pose(view);
  const target = new WebGLRenderTarget(WIDTH, HEIGHT);
  target.texture.colorSpace = SRGBColorSpace;
  ocean.update(view.t, camera);
  gl.setRenderTarget(target);
  gl.render(own, camera);
  const pixels = new Uint8Array(4 * WIDTH * HEIGHT);
  gl.readRenderTargetPixels(target, 0, 0, WIDTH, HEIGHT, pixels);
  gl.setRenderTarget(null);
  target.dispose();
  ocean.dispose();
  gl.dispose();
  scene.add(box, plate);
  return base64(topFirst(pixels, true));
}

/** Where world points fall in the picture, in pixels from its top left. */
function project(view: View, points: Vec3[]): [number, number][] {
  pose(view);
  return points.map((p) => {
    const v = new Vector3(...p).project(camera);
    return [((v.x + 1) / 2) * WIDTH, ((1 - v.y) / 2) * HEIGHT];
  });
}

/** The unit ray from the eye through the centre of pixel (x, y) (from the top left). */
function pixelRay(view: View, x: number, y: number): Vec3 {
  pose(view);
  const d = new Vector3(((x + 0.5) / WIDTH) * 2 - 1, 1 - ((y + 0.5) / HEIGHT) * 2, 0.5).unproject(camera).sub(camera.position).normalize();
  return [d.x, d.y, d.z];
}

/** The sea's height over (x, z) at time t for the wind (for a box floating at the waterline). */
function heightAt(view: View, x: number, z: number): number {
  const ocean = oceanFor(view);
  ocean.update(view.t);
  return ocean.heightAt(x, z);
}

/**
 * Where the view ray of each pixel ([x, y] from the top left) meets the sea at the view's time, by
 * Ocean.heightAt along it (steps of 0.25 m, then halved 20 times where it passes under the
 * surface), and the sea's normal there (Ocean.normalAt); null where it meets none within 300 m.
 */
function surfacePoints(view: View, pixels: [number, number][]): ({ point: Vec3; normal: Vec3; ray: Vec3 } | null)[] {
  const ocean = oceanFor(view);
  ocean.update(view.t);
  const [ex, ey, ez] = view.eye;
  const below = (ray: Vec3, s: number) => ey + s * ray[1] < ocean.heightAt(ex + s * ray[0], ez + s * ray[2]);
  return pixels.map(([x, y]) => {
    const ray = pixelRay(view, x, y);
    let s = 0;
    while (s < 300 && !below(ray, s + 0.25)) s += 0.25;
    if (s >= 300) return null;
    let [above, under] = [s, s + 0.25];
    for (let i = 0; i < 20; i++) {
      const middle = (above + under) / 2;
      if (below(ray, middle)) under = middle;
      else above = middle;
    }
    const point: Vec3 = [ex + above * ray[0], ey + above * ray[1], ez + above * ray[2]];
    const n = ocean.normalAt(point[0], point[2]);
    return { point, normal: [n.x, n.y, n.z], ray };
  });
}

/** renderer.info.memory before the Oceans of `views` (each drawn twice), while they live, and after their dispose and a frame. */
async function memoryCycle(views: View[]): Promise<{ before: Record<string, number>; during: Record<string, number>; after: Record<string, number> }> {
  const disposeAll = () => {
    for (const ocean of oceans.values()) ocean.dispose();
    oceans.clear();
  };
  const memory = () => ({ geometries: renderer!.info.memory.geometries, textures: renderer!.info.memory.textures });
  // Into a target, as every draw here: a headless WebGPU canvas loses its device after its first frame.
  const emptyFrame = () => {
    box.visible = plate.visible = false;
    const target = new RenderTarget(4, 4);
    renderer!.setRenderTarget(target);
    renderer!.render(scene, camera);
    renderer!.setRenderTarget(null);
    target.dispose();
  };
  disposeAll();
  emptyFrame();
  const before = memory();
  for (const view of views) {
    await render(view);
    await render(view);
  }
  const during = memory();
  disposeAll();
  emptyFrame();
  return { before, during, after: memory() };
}

/** What the constructor throws for `options`: [name, message], or ['none', ''] . */
function construct(options: Record<string, unknown>): [string, string] {
  try {
    new Ocean(renderer!, { ...SEA, ...options }).dispose();
    return ['none', ''];
  } catch (error) {
    return [(error as Error).name, (error as Error).message];
  }
}

const harness = { WIDTH, HEIGHT, open, render, linearPixels, renderWebGL, project, pixelRay, heightAt, surfacePoints, memoryCycle, construct };
declare global {
  interface Window {
    sceneLight: typeof harness;
  }
}
window.sceneLight = harness;
document.title = 'ready';
