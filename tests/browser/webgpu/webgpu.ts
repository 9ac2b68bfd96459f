/**
 * Test page for three-fft-ocean/webgpu: the WebGPU Ocean on a real WebGPURenderer, on its WebGL2
 * backend (forceWebGL) or its WebGPU backend, driven by tests/browser/webgpu/webgpu.spec.ts.
 */
import { Fog, FloatType, NoToneMapping, Vector2, OrthographicCamera, PerspectiveCamera, RenderTarget, Scene, SRGBColorSpace, type Mesh } from 'three';
import { MeshBasicNodeMaterial, WebGPURenderer } from 'three/webgpu';
import { positionWorld, vec4 } from 'three/tsl';
import { Ocean, type WebGPUOceanOptions } from '../../../src/webgpu/index';
import { Ocean as WebGLOcean, type OceanPath } from '../../../src/ocean';
import { finestTexel } from '../../../src/render/horizonGrid';
import { WebGLRenderer, WebGLRenderTarget } from 'three';
import { FloatingBody } from '../../../src/layers/floatingBody';
import { QUALITY_STEPS, type QualityLevel } from '../../../src/runtime/adaptiveQuality';
import { applyQualityStep, applyWebGPUQualityStep } from '../../../src/runtime/applyQuality';
import { SceneOutput } from '../../../src/render/sceneOutput';

/** A small sea for quick tests: N = 64, the JS FFT on this thread (the fields are there at once), whitecaps on (the default). */
export const SEA_PARAMETERS = { resolution: 64, windSpeed: 10, seed: 3 };
export const SEA: WebGPUOceanOptions = { ...SEA_PARAMETERS, worker: false };

/** A compared view: where the sun is, the wind, the foam and the seabed (the default's where left out), and the camera's (x, z) (the origin's) and altitude (4 m). */
type ViewOptions = Pick<WebGPUOceanOptions, 'sunElevation' | 'sunAzimuth' | 'cloudCover' | 'windSpeed' | 'foamAmount' | 'resolution' | 'seabed'> & {
  at?: [number, number];
  altitude?: number;
  /** A quality level put in force on the renderer and the ocean (applyQuality.ts): the picture is then the drawing buffer's size. */
  quality?: QualityLevel;
  /** three's scene.fog: a linear Fog of this colour (hex), near and far (m). */
  fog?: [number, number, number];
};

/**
 * Puts `quality` in force by `apply` (applyQualityStep or applyWebGPUQualityStep at pixel ratio 1)
 * on a renderer of width × height: the size of its drawing buffer then, which the picture takes.
 */
function sizeAtQuality(target: { setSize(w: number, h: number, style?: boolean): void; getDrawingBufferSize(v: Vector2): Vector2 }, width: number, height: number, apply: () => void): [number, number] {
  target.setSize(width, height, false);
  apply();
  const size = target.getDrawingBufferSize(new Vector2());
  return [size.x, size.y];
}

export let renderer: WebGPURenderer | null = null;

/** The renderer open() made, for the pages that build on this one (shore.ts). */
export function openedRenderer(): WebGPURenderer {
  if (!renderer) throw new Error('open a renderer first (window.webgpuOcean.open)');
  return renderer;
}

/**
 * A WebGPURenderer of 320×180 on `backend`, initialized; which backend it got. Asked for WebGPU
 * where there is no adapter, three falls back to its WebGL2 backend: `reason` says why.
 */
async function open(backend: 'webgl' | 'webgpu'): Promise<{ isWebGPUBackend: boolean; reason: string }> {
  renderer?.dispose();
  renderer?.domElement.remove();
  renderer = new WebGPURenderer({ forceWebGL: backend === 'webgl', antialias: false });
  renderer.setSize(320, 180);
  renderer.setPixelRatio(1);
  renderer.toneMapping = NoToneMapping;
  document.body.append(renderer.domElement);
  await renderer.init();
  const isWebGPUBackend = (renderer.backend as { isWebGPUBackend?: boolean }).isWebGPUBackend === true;
  const reason = backend === 'webgl' ? 'forceWebGL' : isWebGPUBackend ? 'WebGPU adapter' : navigator.gpu ? 'navigator.gpu has no adapter' : 'navigator.gpu is undefined (no --enable-unsafe-webgpu, or not a secure context)';
  return { isWebGPUBackend, reason };
}

/** The default view's camera: 4 m (or `altitude`) over the sea at (x, z) looking towards a point 40 m ahead (−z), 1 m up. */
function viewCamera(x = 0, z = 0, altitude = 4): PerspectiveCamera {
  const camera = new PerspectiveCamera(60, 16 / 9, 0.5, 30_000);
  camera.position.set(x, altitude, z);
  camera.lookAt(x, 1, z - 40);
  camera.updateMatrixWorld();
  return camera;
}

/** RGBA rows read back from a target, reordered top first (WebGL's come bottom first, WebGPU's top first). */
export function topFirst(pixels: Uint8Array, width: number, height: number, bottomFirst: boolean): number[] {
  const data: number[] = [];
  for (let row = 0; row < height; row++) {
    const from = bottomFirst ? height - 1 - row : row;
    data.push(...pixels.subarray(4 * width * from, 4 * width * (from + 1)));
  }
  return data;
}

/** An sRGB 8-bit picture of `width` × `height` pixels: what both Oceans are read back from. */
export function pictureTarget<T extends RenderTarget | WebGLRenderTarget>(Target: new (w: number, h: number) => T, width: number, height: number): T {
  const target = new Target(width, height);
  target.texture.colorSpace = SRGBColorSpace;
  return target;
}

/**
 * The default view of the WebGPU Ocean at time t, drawn into an sRGB 8-bit target of width ×
 * height and read back, rows from the top. (Into a target, not the canvas: headless Chromium's
 * SwiftShader WebGPU lost its device after presenting one frame to a canvas, even of an empty
 * scene, "A valid external Instance reference no longer exists".)
 */
async function drawView(t: number, pictureWidth = 320, pictureHeight = 180, { at = [0, 0], altitude, quality, fog, ...view }: ViewOptions = {}): Promise<{ width: number; height: number; data: number[] }> {
  const scene = new Scene();
  const ocean = new Ocean(renderer!, { ...SEA, ...view });
  scene.add(ocean);
  if (fog) scene.fog = new Fog(...fog);
  const [width, height] = quality
    ? sizeAtQuality(renderer!, pictureWidth, pictureHeight, () => applyWebGPUQualityStep({ renderer: renderer!, ocean, pixelRatio: 1 }, ocean.parameters, QUALITY_STEPS[quality]))
    : [pictureWidth, pictureHeight];
  const target = pictureTarget(RenderTarget, width, height);
  ocean.update(t);
  renderer!.setRenderTarget(target);
  renderer!.render(scene, viewCamera(...at, altitude));
  renderer!.setRenderTarget(null);
  const pixels = (await renderer!.readRenderTargetPixelsAsync(target, 0, 0, width, height)) as Uint8Array;
  target.dispose();
  ocean.dispose();
  renderer!.setPixelRatio(1);
  renderer!.setSize(320, 180, false);
  const bottomFirst = !(renderer!.backend as { isWebGPUBackend?: boolean }).isWebGPUBackend;
  return { width, height, data: topFirst(pixels, width, height, bottomFirst) };
}

/**
 * The same view of the same sea under the same sun drawn by the WebGL Ocean on a WebGLRenderer, its
 * foam from its JS path as the WebGPU Ocean's, without what the WebGPU Ocean does not draw yet
 * (local waves; scene reflections and refractions show the sky here, with no object), no tone
 * mapping as in open(). Only while no WebGPU device lives in the page (see the spec).
 */
function drawWebGLView(t: number, pictureWidth: number, pictureHeight: number, { at = [0, 0], altitude, quality, fog, ...view }: ViewOptions = {}): { width: number; height: number; data: number[] } {
  const gl = new WebGLRenderer({ antialias: false });
  gl.toneMapping = NoToneMapping;
  gl.setPixelRatio(1);
  gl.setSize(pictureWidth, pictureHeight);
  const ocean = new WebGLOcean(gl, { ...SEA_PARAMETERS, path: 'js', worker: false, localWaves: false, reflections: 'sky', refractions: 'sky', ...view });
  const scene = new Scene();
  scene.add(ocean);
  if (fog) scene.fog = new Fog(...fog);
  // The level's MSAA is the output's, which this picture does not go through (nor the WebGPU Ocean's: see applyWebGPUQualityStep).
  const output = new SceneOutput(gl);
  const [width, height] = quality
    ? sizeAtQuality(gl, pictureWidth, pictureHeight, () => applyQualityStep({ renderer: gl, output, ocean, pixelRatio: 1 }, ocean.parameters, QUALITY_STEPS[quality]))
    : [pictureWidth, pictureHeight];
  const camera = viewCamera(...at, altitude);
  const target = pictureTarget(WebGLRenderTarget, width, height);
  ocean.update(t, camera);
  gl.setRenderTarget(target);
  gl.render(scene, camera);
  const pixels = new Uint8Array(4 * width * height);
  gl.readRenderTargetPixels(target, 0, 0, width, height, pixels);
  gl.setRenderTarget(null);
  target.dispose();
  ocean.dispose();
  output.dispose();
  gl.dispose();
  return { width, height, data: topFirst(pixels, width, height, true) };
}

/**
 * The displaced surface read back from the real vertex node: the surface's positionNode with the
 * world position as its colour, drawn straight down by an orthographic camera over a `side` m square
 * centred on (cx, cz) into an RGBA32F target; for every pixel the sea covers, the drawn (x, y, z)
 * and ocean.heightAt(x, z) (`xs` the pixels' drawn x). Also the same at another time, for a control.
 */
async function heightAgreement(cx: number, cz: number, side: number, t: number, options: WebGPUOceanOptions): Promise<{ drawn: number[]; queried: number[]; bound: number[]; xs: number[]; heightRms: number }> {
  const scene = new Scene();
  const ocean = new Ocean(renderer!, { ...SEA, ...options });
  scene.add(ocean);
  ocean.update(t);
  const surface = ocean.getObjectByName('OceanWebGPU surface') as Mesh<never, MeshBasicNodeMaterial>;
  const positions = new MeshBasicNodeMaterial();
  positions.positionNode = surface.material.positionNode;
  // The whole fragment output: no colour-space conversion or tone mapping on the way.
  positions.fragmentNode = vec4(positionWorld, 1);
  const shaded = surface.material;
  surface.material = positions;
  ocean.getObjectByName('OceanWebGPU sky')!.visible = false;
  const size = 64;
  const target = new RenderTarget(size, size, { type: FloatType });
  // 2.5 m up: the rings' finest cells are then the finest texel (finestRingLevel in horizonGrid.ts,
  // 32 cells a ring), and ring 0 covers ±10 m around the camera, the whole square.
  const camera = new OrthographicCamera(-side / 2, side / 2, side / 2, -side / 2, 0.01, 10);
  camera.position.set(cx, 2.5, cz);
  camera.up.set(0, 0, -1);
  camera.lookAt(cx, 0, cz);
  renderer!.setRenderTarget(target);
  renderer!.setClearColor(0x000000, 0);
  renderer!.render(scene, camera);
  renderer!.setRenderTarget(null);
  const pixels = (await renderer!.readRenderTargetPixelsAsync(target, 0, 0, size, size)) as Float32Array;
  const drawn: number[] = [];
  const queried: number[] = [];
  const bound: number[] = [];
  const xs: number[] = [];
  let sumSquares = 0;
  for (let p = 0; p < size * size; p++) {
    if (pixels[4 * p + 3] !== 1) continue; // not the sea
    const [x, y, z] = [pixels[4 * p], pixels[4 * p + 1], pixels[4 * p + 2]];
    drawn.push(y);
    xs.push(x);
    const h = ocean.heightAt(x, z);
    queried.push(h);
    bound.push(interpolationBound(ocean, x, z, finestTexel(ocean.waveLayers)));
    sumSquares += y * y;
  }
  surface.material = shaded;
  positions.dispose();
  target.dispose();
  ocean.dispose();
  return { drawn, queried, bound, xs, heightRms: Math.sqrt(sumSquares / Math.max(drawn.length, 1)) };
}

/**
 * How far the drawn triangles may lie from the surface at (x, z): the mesh is linear between
 * vertices, and linear interpolation over an edge of length L misses a function by at most
 * L²/8·max|f''| along it (the remainder of linear interpolation, e.g. Burden & Faires, Numerical
 * Analysis, Theorem 3.3). L is the diagonal of a cell `cell` m wide, stretched by up to 1.5 where
 * the choppy displacement pulls vertices apart; max|f''| is taken over the triangle's reach, at
 * (x, z) and half an edge away along x and z: heightAt's second difference over half a metre along
 * x, z and both diagonals, the largest of them all.
 */
function interpolationBound(ocean: Ocean, x: number, z: number, cell: number): number {
  const step = 0.5;
  const edge = 1.5 * Math.SQRT2 * cell;
  let curvature = 0;
  for (const [cx, cz] of [[0, 0], [1, 0], [-1, 0], [0, 1], [0, -1]]) {
    const [px, pz] = [x + (cx * edge) / 2, z + (cz * edge) / 2];
    const h = ocean.heightAt(px, pz);
    for (const [dx, dz] of [[1, 0], [0, 1], [Math.SQRT1_2, Math.SQRT1_2], [Math.SQRT1_2, -Math.SQRT1_2]]) {
      const second = (ocean.heightAt(px + step * dx, pz + step * dz) - 2 * h + ocean.heightAt(px - step * dx, pz - step * dz)) / (step * step);
      curvature = Math.max(curvature, Math.abs(second));
    }
  }
  return (edge * edge * curvature) / 8;
}

/**
 * heightAt and normalAt (x, y, z) of this Ocean and of the WebGL Ocean (JS path, no local waves)
 * for the same options, at the same points and time, then again after both were given windSpeed 14
 * by setParameters.
 */
function sameQueriesAsWebGL(points: [number, number][], t: number): { webgpu: number[]; webgl: number[] } {
  const ocean = new Ocean(renderer!, SEA);
  const gl = new WebGLRenderer();
  const reference = new WebGLOcean(gl, { ...SEA_PARAMETERS, path: 'js', localWaves: false, worker: false });
  const answers = (sea: Ocean | WebGLOcean) => points.flatMap(([x, z]) => [sea.heightAt(x, z), ...sea.normalAt(x, z).toArray()]);
  const result = { webgpu: [] as number[], webgl: [] as number[] };
  for (const windSpeed of [SEA_PARAMETERS.windSpeed, 14]) {
    ocean.setParameters({ windSpeed });
    reference.setParameters({ windSpeed });
    ocean.update(t);
    reference.update(t);
    result.webgpu.push(...answers(ocean));
    result.webgl.push(...answers(reference));
  }
  ocean.dispose();
  reference.dispose();
  gl.dispose();
  return result;
}

/**
 * The WebGL Ocean's API asked of both Oceans for the same options and time (the JS path, no local
 * waves, the sky reflected and refracted), each answer as numbers or words: the parameters, the statistics, the horizon, the
 * queries one point and many at once, the shading after setShading, the sun after setSun (its
 * direction in the TSL uniform), what bad calls throw, and the heights of a FloatingBody stepped
 * on each sea for 4 s from the same start.
 */
function sameApiAsWebGL(t: number): { webgpu: Record<string, unknown>; webgl: Record<string, unknown>; events: string[] } {
  // Reflections and refractions of the sky on both (no scene to capture here): the shading then reads the same.
  const ocean = new Ocean(renderer!, { ...SEA, reflections: 'sky', refractions: 'sky' });
  const gl = new WebGLRenderer();
  gl.setSize(320, 180);
  const reference = new WebGLOcean(gl, { ...SEA_PARAMETERS, path: 'js', localWaves: false, worker: false, reflections: 'sky', refractions: 'sky' });
  const events: string[] = [];
  ocean.addEventListener('pathchange', ({ path }) => events.push(path.running));
  const xz = [0, 0, 3.3, -7.1, -120, 45.5];
  const thrown = (call: () => unknown): string => {
    try {
      call();
      return 'none';
    } catch (error) {
      return `${(error as Error).name}: ${(error as Error).message}`;
    }
  };
  const answers = (sea: Ocean | WebGLOcean, sunDirection: () => number[]) => {
    sea.update(t);
    const body = new FloatingBody({ mass: 800, size: [2, 1, 1.5] });
    body.position.set(4, 0, -3);
    body.settle(sea);
    const heave: number[] = [];
    for (let step = 1; step <= 240; step++) {
      sea.update(t + step / 60);
      body.step(1 / 60, sea);
      if (step % 30 === 0) heave.push(body.position.y);
    }
    sea.update(t);
    const result = {
      parameters: sea.parameters,
      heightRms: sea.heightRms,
      seaState: sea.seaState,
      repeatPeriod: sea.repeatPeriod,
      horizon: [sea.horizonDistanceFor(10), sea.horizonDistanceFor(300), sea.horizonDistance],
      velocityAt: sea.velocityAt(3.3, -7.1).toArray(),
      heightsAt: sea.heightsAt(xz, new Float64Array(3)),
      normalsAt: sea.normalsAt(xz, new Float64Array(9)),
      velocitiesAt: sea.velocitiesAt(xz, new Float64Array(9)),
      heave,
      badCalls: [
        thrown(() => sea.setShading({ ior: 5 })),
        thrown(() => sea.setSun({ elevation: 95 })),
        thrown(() => sea.setSun({ direction: [0, 0, 0] })),
        thrown(() => sea.setSun({ cloudCover: 2 })),
        thrown(() => sea.setSun({ elevation: 10, azimuth: 20, direction: [1, 1, 0] })),
        thrown(() => sea.velocityAt(NaN, 0)),
        thrown(() => sea.horizonDistanceFor(Infinity)),
      ],
      shadingKept: sea.shading,
    };
    sea.setShading({ scatterColour: '#0a3040', ior: 1.34, causticPower: 20 });
    sea.setSun({ elevation: 15 });
    const afterElevation = sunDirection();
    sea.setSun(25, -60);
    sea.setSun({ direction: [1, 2, 3], cloudCover: 0.4 });
    return { ...result, shading: sea.shading, sun: [...afterElevation, ...sunDirection()] };
  };
  const webgpuSky = (ocean as unknown as { uniforms: { sky: { sunDirection: { value: { toArray(): number[] } } } } }).uniforms.sky;
  const webgpu = answers(ocean, () => webgpuSky.sunDirection.value.toArray());
  const webgl = answers(reference, () => reference.sky.skyUniforms.skySunDirection.value.toArray());
  ocean.dispose();
  reference.dispose();
  gl.dispose();
  return { webgpu: JSON.parse(JSON.stringify(webgpu)), webgl: JSON.parse(JSON.stringify(webgl)), events };
}

/** renderer.info.memory before an Ocean, while it draws, and after its dispose (and a frame after). */
async function memoryCycle(): Promise<{ before: Record<string, number>; during: Record<string, number>; after: Record<string, number> }> {
  const scene = new Scene();
  const camera = new PerspectiveCamera(60, 16 / 9, 0.5, 30_000);
  camera.position.set(0, 4, 0);
  renderer!.render(scene, camera);
  const memory = () => ({ geometries: renderer!.info.memory.geometries, textures: renderer!.info.memory.textures });
  const before = memory();
  const ocean = new Ocean(renderer!, SEA);
  scene.add(ocean);
  ocean.update(1);
  renderer!.render(scene, camera);
  ocean.update(1.1);
  renderer!.render(scene, camera);
  const during = memory();
  ocean.dispose();
  renderer!.render(scene, camera);
  return { before, during, after: memory() };
}

/**
 * ocean.path for each `path` option the backend takes ('gpu' on the WebGPU backend only), at
 * N = 64; then at N = 1024, beyond the compute FFT's 512: 'auto' made so, and 'auto' and 'gpu'
 * after setParameters asks for it (with what 'gpu' threw, and its resolution after).
 */
function paths(): { at64: Record<string, OceanPath>; at1024: OceanPath; autoTo1024: OceanPath; gpuTo1024: { thrown: string; resolution: number; path: OceanPath } | null } {
  const isWebGPUBackend = (renderer!.backend as { isWebGPUBackend?: boolean }).isWebGPUBackend === true;
  const asked = isWebGPUBackend ? (['auto', 'js', 'gpu'] as const) : (['auto', 'js'] as const);
  const pathOf = (options: WebGPUOceanOptions, change?: Partial<WebGPUOceanOptions>): OceanPath => {
    const ocean = new Ocean(renderer!, { ...SEA, ...options });
    if (change) ocean.setParameters(change);
    const { path } = ocean;
    ocean.dispose();
    return path;
  };
  let gpuTo1024 = null;
  if (isWebGPUBackend) {
    const ocean = new Ocean(renderer!, { ...SEA, path: 'gpu' });
    let thrown = '';
    try {
      ocean.setParameters({ resolution: 1024 });
    } catch (error) {
      thrown = `${(error as Error).name}: ${(error as Error).message}`;
    }
    gpuTo1024 = { thrown, resolution: ocean.waveLayers[0].frame.resolution, path: ocean.path };
    ocean.dispose();
  }
  return {
    at64: Object.fromEntries(asked.map((path) => [path, pathOf({ path })])),
    at1024: pathOf({ resolution: 1024 }),
    autoTo1024: pathOf({}, { resolution: 1024 }),
    gpuTo1024,
  };
}

/** What each bad input throws: [name, message]. */
function badInputs(): [string, string][] {
  const gl = new WebGLRenderer();
  const attempts: (() => unknown)[] = [
    () => new Ocean(gl as never),
    () => new Ocean(renderer!, { reflections: 'mirror' as never }),
    () => new Ocean(renderer!, { path: 'gpu' }),
    () => new Ocean(renderer!, { windSpeed: -1 }),
    () => new Ocean(renderer!, { sunElevation: 100 }),
    () => new Ocean(renderer!, { sunDirection: [0, 1, 0], sunAzimuth: 10 }),
    () => new Ocean(renderer!, { cloudCover: 2 }),
    () => new Ocean(renderer!, { causticPower: 0 }),
  ];
  const thrown = attempts.map((attempt): [string, string] => {
    try {
      (attempt() as Ocean).dispose();
      return ['none', ''];
    } catch (error) {
      return [(error as Error).name, (error as Error).message];
    }
  });
  gl.dispose();
  return thrown;
}

const harness = { open, drawView, drawWebGLView, heightAgreement, sameQueriesAsWebGL, sameApiAsWebGL, memoryCycle, paths, badInputs };
declare global {
  interface Window {
    webgpuOcean: typeof harness;
  }
}
window.webgpuOcean = harness;
document.title = 'ready';
