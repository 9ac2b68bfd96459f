/**
 * Test page for the rendered ocean: the real simulation, surface and environment in this page's
 * WebGL2 context, with hooks for the Playwright tests (geometry capture, shading probes).
 */
import {
  ACESFilmicToneMapping,
  BoxGeometry,
  Color,
  FloatType,
  Fog,
  FogExp2,
  LinearSRGBColorSpace,
  Mesh,
  MeshBasicMaterial,
  NoToneMapping,
  PerspectiveCamera,
  Points,
  RGBAFormat,
  Scene,
  SRGBColorSpace,
  Vector3,
  WebGLCubeRenderTarget,
  WebGLRenderer,
  WebGLRenderTarget,
} from 'three';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { OutputPass } from 'three/addons/postprocessing/OutputPass.js';
import { RenderPass } from 'three/addons/postprocessing/RenderPass.js';
import { DisposedError, Ocean, type OceanOptions } from '../../../src/ocean';
import { ParameterError } from '../../../src/parameters/options';
import { shaderSource } from '../../../src/shaderSource';
import { OceanMaterial, type OceanShadingOptions } from '../../../src/render/oceanMaterial';
import { OceanSurface } from '../../../src/render/oceanSurface';
import { finestTexel } from '../../../src/render/horizonGrid';
import { OceanSimulation } from '../../../src/layers/oceanSimulation';
import { blendAngle, COPY_OFFSET, patchBlendUniforms } from '../../../src/layers/patchBlend';
import { heightAt, normalAt } from '../../../src/layers/surfaceQuery';
import type { WaveLayer } from '../../../src/layers/waveLayer';
import { FftCascade } from '../../../src/layers/fftCascade';
import { QUERY_WORKER_DELAY_MS } from '../../../src/layers/cascadeQueryFields';
import type { SimulationParameters } from '../../../src/parameters/parameters';

const query = new URLSearchParams(location.search);
const width = Number(query.get('width') ?? 640);
const height = Number(query.get('height') ?? 360);
const renderer = new WebGLRenderer({ antialias: query.get('antialias') === '1', preserveDrawingBuffer: true });
renderer.setPixelRatio(1);
renderer.setSize(width, height);
document.body.appendChild(renderer.domElement);

const scene = new Scene();
const camera = new PerspectiveCamera(55, width / height, 0.5, 2e7);
const sunDirection = new Vector3(0.3, 0.5, -0.8).normalize();

// A uniform-colour environment (for shading probes), in the RGBM encoding the surface decodes
// (shaders/sky/rgbm.glsl): in a float cube, (colour / range, 1) decodes exactly to the colour.
const RGBM_RANGE = Number(/SKY_RGBM_RANGE = ([\d.]+)/.exec(shaderSource('sky/rgbm.glsl'))![1]);
const uniformCube = new WebGLCubeRenderTarget(16, { type: FloatType });
function setUniformEnvironment(colour: [number, number, number]): void {
  // three.js converts a clear colour to the colour space of the target current when it is set:
  // set it with the (linear) cube current, not the (sRGB) canvas.
  renderer.setRenderTarget(uniformCube);
  renderer.setClearColor(new Color().fromArray(colour).multiplyScalar(1 / RGBM_RANGE));
  uniformCube.clear(renderer, true, true, true);
  renderer.setRenderTarget(null);
  renderer.setClearColor(0x000000);
  scene.background = new Color().fromArray(colour); // the same sky, for pixels the sea leaves
}
setUniformEnvironment([0.5, 0.6, 0.7]);
const environment = { value: uniformCube.texture };

let simulation: OceanSimulation | null = null;
let surface: OceanSurface | null = null;
/** What setup's surface is told bounds the waves (undefined: the eye is taken to be above them). */
let surfaceBound: number | undefined;

function setup(parameters: Partial<SimulationParameters>, shading: OceanShadingOptions = {}): void {
  surface?.removeFromParent();
  surface?.dispose();
  simulation?.dispose();
  simulation = new OceanSimulation(renderer, parameters, { path: 'gpu', worker: false });
  const sim = simulation;
  surface = new OceanSurface(
    { environment, sunDirection: { value: sunDirection } },
    () => ({ layers: sim.layers, choppiness: sim.parameters.choppiness, foam: sim.foam.texture, surfaceBound }),
    shading,
  );
  scene.add(surface);
}

function view(position: [number, number, number], target: [number, number, number]): void {
  camera.position.fromArray(position);
  camera.lookAt(new Vector3().fromArray(target));
  camera.updateMatrixWorld();
}

const harness = {
  /** For tests of the Ocean's API. */
  renderer,
  Ocean,
  ParameterError,
  DisposedError,
  Color,
  Vector3,
  Scene,
  PerspectiveCamera,
  setup,
  view,
  setUniformEnvironment,
  render(t: number, linear = false): void {
    renderer.toneMapping = linear ? NoToneMapping : ACESFilmicToneMapping;
    renderer.outputColorSpace = linear ? LinearSRGBColorSpace : SRGBColorSpace;
    simulation!.update(t);
    renderer.render(scene, camera);
  },
  /** Reads one pixel of the canvas (RGBA 0–255), y from the top. */
  pixel(x: number, y: number): number[] {
    const gl = renderer.getContext();
    const out = new Uint8Array(4);
    gl.readPixels(x, height - 1 - y, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, out);
    return Array.from(out);
  },
  geometryCheck,
  /** Adds a layer to setup's simulation (the contract's way in, as Ocean.addLayer). */
  addLayer(layer: WaveLayer): void {
    simulation!.addLayer(layer);
  },
  /**
   * The fraction of the canvas that whitecap foam brightens: the picture at time t with these
   * parameters against the same sea with foamAmount 0, pixels whose luminance rose by over 16/255 (under this page's uniform pale sky water and foam differ less than under a real sky).
   */
  foamBrightened(parameters: Partial<SimulationParameters>, t: number): number {
    const gl = renderer.getContext();
    const pictures = [0, 1].map((foamAmount) => {
      setup({ ...parameters, foamAmount: foamAmount * (parameters.foamAmount ?? 1) });
      harness.render(t);
      const pixels = new Uint8Array(4 * width * height);
      gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
      return pixels;
    });
    let brightened = 0;
    const luminance = (p: Uint8Array, i: number) => 0.2126 * p[i] + 0.7152 * p[i + 1] + 0.0722 * p[i + 2];
    for (let i = 0; i < pictures[0].length; i += 4) if (luminance(pictures[1], i) - luminance(pictures[0], i) > 16) brightened++;
    return brightened / (width * height);
  },
  /**
   * heightAt against the rendered surface: an Ocean's own surface is read back from the vertex
   * shader (geometryCheck); a vertex displaced to (px, py, pz) is the surface point that lands on
   * (px, pz), so heightAt(px, pz) must be py.
   */
  heightAtCheck(
    changes: Partial<SimulationParameters>,
    t: number,
  ): { compared: number; folded: number; maxError: number; rms: number } {
    return withOcean(changes, (ocean) => {
      ocean.update(t);
      const { displacedAtMip0, rms } = geometryCheck(t);
      // Where the surface folds (J ≤ 0.2 at the rest point) more than one point lands on (x, z).
      const unfolded = displacedAtMip0.filter(([, , , jacobian]) => jacobian > 0.2);
      let maxError = 0;
      for (const [x, y, z] of unfolded) maxError = Math.max(maxError, Math.abs(ocean.heightAt(x, z) - y));
      return { compared: unfolded.length, folded: displacedAtMip0.length - unfolded.length, maxError, rms };
    });
  },
  /**
   * An Ocean's horizonDistanceFor(camera height) asked before its first render, its
   * horizonDistance then and after the render from the current view, and the farthest vertex from
   * the camera that the vertex shader placed (the skirt's corner).
   */
  /**
   * The queries over the local waves: after a stone, heightAt and normalAt of the Ocean against the
   * same queries over the cascades alone (surfaceQuery.ts), at points around the stone. Without
   * choppiness the rest point under (x, z) is (x, z) itself, so the difference in height must be the
   * local field there (bilinear), and the normals must differ where its slopes are. (With it, every
   * layer is sampled at the rest point the choppy map moves onto (x, z), as the surface does.)
   */
  queriesWithLocalWaves(): { largestLocal: number; worstHeight: number; normalsDiffer: boolean } {
    return withOcean({ resolution: 64, windSpeed: 6, seed: 4, choppiness: 0 }, (ocean) => {
      const waves = ocean.localWaves!;
      waves.follow(0, 0);
      ocean.update(10);
      waves.drop(3, -2, { radius: 1.2, depth: 0.8 });
      for (let t = 10.1; t < 13; t += 0.1) ocean.update(t);
      const { size, origin, resolution } = waves.frame;
      const local = waves.fieldsOnCpu(ocean.time).displacement;
      const localAt = (x: number, z: number) => {
        const [u, v] = [((x - origin[0]) / size) * resolution, ((z - origin[1]) / size) * resolution];
        const [i, j] = [Math.floor(u), Math.floor(v)];
        const [fu, fv] = [u - i, v - j];
        const h = (a: number, b: number) => local[4 * (b * resolution + a) + 1];
        return (1 - fv) * ((1 - fu) * h(i, j) + fu * h(i + 1, j)) + fv * ((1 - fu) * h(i, j + 1) + fu * h(i + 1, j + 1));
      };
      const cascades = ocean.simulation.cascades;
      const { choppiness } = ocean.parameters;
      let [largestLocal, worstHeight, normalsDiffer] = [0, 0, false];
      for (let x = -5; x <= 11; x += 0.7) {
        for (let z = -10; z <= 6; z += 0.7) {
          const expected = heightAt(cascades, choppiness, ocean.time, x, z);
          largestLocal = Math.max(largestLocal, Math.abs(localAt(x, z)));
          worstHeight = Math.max(worstHeight, Math.abs(ocean.heightAt(x, z) - expected - localAt(x, z)));
          const withLocal = ocean.normalAt(x, z);
          const without = normalAt(cascades, choppiness, ocean.time, x, z, new Vector3());
          normalsDiffer ||= withLocal.angleTo(without) > 0.02;
        }
      }
      return { largestLocal, worstHeight, normalsDiffer };
    });
  },
  /**
   * The batch queries on the GPU path against the JS path and against the single-point ones, and
   * their errors: the largest differences, and each bad call's message.
   */
  batchQueries(): { gpuVersusJs: number; batchVersusSingle: number; largestSpeed: number; messages: string[] } {
    const options = { resolution: 64, windSpeed: 11, seed: 8, worker: false } as const;
    const oceans = [new Ocean(renderer, { ...options, path: 'gpu' }), new Ocean(renderer, { ...options, path: 'js' })];
    const xz = new Float64Array(2 * 200);
    for (let p = 0; p < 200; p++) [xz[2 * p], xz[2 * p + 1]] = [-80 + (p % 20) * 8.3, -50 + Math.floor(p / 20) * 9.7];
    const results = oceans.map((ocean) => {
      ocean.update(0);
      ocean.localWaves!.drop(3, 4);
      for (let t = 0.1; t < 2; t += 0.1) ocean.update(21 + t);
      return { heights: ocean.heightsAt(xz, new Float32Array(200)), normals: ocean.normalsAt(xz, new Float32Array(600)), velocities: ocean.velocitiesAt(xz, new Float64Array(600)) };
    });
    let [gpuVersusJs, batchVersusSingle, largestSpeed] = [0, 0, 0];
    const [gpu, js] = results;
    for (const key of ['heights', 'normals', 'velocities'] as const) {
      for (let i = 0; i < js[key].length; i++) gpuVersusJs = Math.max(gpuVersusJs, Math.abs(gpu[key][i] - js[key][i]));
    }
    const vector = new Vector3();
    for (let p = 0; p < 200; p++) {
      const [x, z] = [xz[2 * p], xz[2 * p + 1]];
      const ocean = oceans[1];
      batchVersusSingle = Math.max(batchVersusSingle, Math.abs(ocean.heightAt(x, z) - js.heights[p]));
      ocean.velocityAt(x, z, vector);
      largestSpeed = Math.max(largestSpeed, vector.length());
      for (const [c, value] of [vector.x, vector.y, vector.z].entries()) batchVersusSingle = Math.max(batchVersusSingle, Math.abs(value - js.velocities[3 * p + c]));
      ocean.normalAt(x, z, vector);
      for (const [c, value] of [vector.x, vector.y, vector.z].entries()) batchVersusSingle = Math.max(batchVersusSingle, Math.abs(value - js.normals[3 * p + c]));
    }
    const messages: string[] = [];
    for (const attempt of [
      () => oceans[1].heightsAt([1, 2, 3], new Float32Array(2)),
      () => oceans[1].velocitiesAt([1, 2], new Float32Array(2)),
      () => oceans[1].normalsAt([1, NaN], new Float32Array(3)),
      () => oceans[1].velocityAt(Infinity, 0),
      () => oceans[1].heightAt(-1.6e308, 0),
    ]) {
      try {
        attempt();
        messages.push('(no error)');
      } catch (error) {
        messages.push((error as Error).message);
      }
    }
    for (const ocean of oceans) ocean.dispose();
    return { gpuVersusJs, batchVersusSingle, largestSpeed, messages };
  },
  /**
   * Snell's window: a calm sea seen straight up from 1 m under it with a 120° lens, under a
   * uniform sky, linear output. Returns, along the picture's middle row and column, the angles from
   * the zenith where the sky's light ends (scanning out from the centre, the first pixel that shows
   * only deep water: red 0, as scatterColor has none), in degrees.
   */
  snellWindow(ior: number): { edgeAngles: number[]; centreRed: number } {
    surfaceBound = 0.5;
    setup({ resolution: 64, windSpeed: 0 }, { ior });
    const fov = 120;
    const lens = new PerspectiveCamera(fov, 1, 0.1, 1e5);
    lens.position.set(0, -1, 0);
    lens.up.set(0, 0, -1);
    lens.lookAt(0, 10, 0);
    lens.updateMatrixWorld();
    renderer.toneMapping = NoToneMapping;
    renderer.outputColorSpace = LinearSRGBColorSpace;
    simulation!.update(3);
    // Twice: the first draw after setup binds the layers (a new LAYER_COUNT recompiles) and shows no sea.
    renderer.render(scene, lens);
    renderer.render(scene, lens);
    const gl = renderer.getContext();
    const pixels = new Uint8Array(4 * width * height);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    surfaceBound = undefined;
    const red = (x: number, y: number) => pixels[4 * (y * width + x)];
    const centre = width / 2;
    const toAngle = (pixelsFromCentre: number) => (Math.atan((pixelsFromCentre / (height / 2)) * Math.tan(((fov / 2) * Math.PI) / 180)) * 180) / Math.PI;
    const edgeAngles: number[] = [];
    for (const [dx, dy] of [[1, 0], [-1, 0], [0, 1], [0, -1]]) {
      for (let r = 0; r < centre; r++) {
        if (red(centre + dx * r, centre + dy * r) === 0) {
          edgeAngles.push(toAngle(r - 0.5)); // the edge lies between this pixel's centre and the last lit one's
          break;
        }
      }
    }
    return { edgeAngles, centreRed: red(centre, centre) };
  },
  /**
   * scene.fog on the sea: the picture from 10 m up with no fog, with a Fog (40 m to 400 m) and with
   * a FogExp2 (density 0.01), all of magenta. Returns, for a pixel 20 m ahead on the sea and one
   * ~2 km ahead, each picture's colour (0–255).
   */
  fogCheck(): { near: number[][]; far: number[][]; nearDistance: number; farDistance: number } {
    setup({ resolution: 64, windSpeed: 6 });
    view([0, 10, 0], [100, 5, 0]);
    const magenta = new Color(1, 0, 1);
    const fogs = [null, new Fog(magenta, 40, 400), new FogExp2(magenta, 0.01)];
    // Rows where the ray meets the sea ~20 m and ~2 km ahead (the camera looks 2.9° down).
    const rowAt = (distance: number) => {
      const down = Math.atan2(10, distance) - Math.atan2(5, 100);
      return Math.round(height / 2 + (Math.tan(down) / Math.tan((camera.fov * Math.PI) / 360)) * (height / 2));
    };
    const near: number[][] = [];
    const far: number[][] = [];
    for (const fog of fogs) {
      scene.fog = fog;
      harness.render(3);
      harness.render(3);
      near.push(harness.pixel(width / 2, rowAt(20)));
      far.push(harness.pixel(width / 2, rowAt(2000)));
    }
    scene.fog = null;
    return { near, far, nearDistance: 20, farDistance: 2000 };
  },
  /**
   * A red box 2 m on a side, half under a calm sea, seen from 7 m away and 2 m up, with a renderer
   * of each depth buffer: plain, logarithmic and reversed (where EXT_clip_control allows it). For
   * each: whether this context and three.js release can give it (reversed: EXT_clip_control, and
   * a three.js with the option), whether it was in force (reversed: three's capability, and its
   * depth state reversed during the render), and the colour (0–255) at the middle of the box's
   * front face 0.6 m above and 0.6 m below the water line.
   */
  depthBufferCheck(): { mode: string; supported: boolean; inForce: boolean; above: number[]; below: number[] }[] {
    const modes = [
      { mode: 'plain', options: {} },
      { mode: 'logarithmic', options: { logarithmicDepthBuffer: true } },
      { mode: 'reversed', options: { reversedDepthBuffer: true } },
    ];
    return modes.map(({ mode, options }) => {
      const own = new WebGLRenderer({ ...options, antialias: false });
      own.setSize(160, 120);
      const ownScene = new Scene();
      const ocean = new Ocean(own, { resolution: 32, windSpeed: 1, localWaves: false });
      const box = new Mesh(new BoxGeometry(2, 2, 2), new MeshBasicMaterial({ color: 0xff0000 }));
      ownScene.add(ocean, box);
      const ownCamera = new PerspectiveCamera(50, 160 / 120, 0.1, 1e5);
      ownCamera.position.set(0, 2, 7);
      ownCamera.lookAt(0, 0, 0);
      ocean.update(1);
      own.render(ownScene, ownCamera);
      own.render(ownScene, ownCamera); // the first draw after set-up builds the layers' programs
      const gl = own.getContext();
      const colourAt = (y: number) => {
        const at = new Vector3(0, y, 1).project(ownCamera);
        const pixel = new Uint8Array(4);
        gl.readPixels(Math.round(((at.x + 1) / 2) * 160), Math.round(((at.y + 1) / 2) * 120), 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
        return [...pixel.slice(0, 3)];
      };
      const capabilities = own.capabilities as { logarithmicDepthBuffer: boolean; reversedDepthBuffer?: boolean };
      const depthState = own.state.buffers.depth as { getReversed?: () => boolean };
      const supported = mode !== 'reversed' || (own.extensions.has('EXT_clip_control') && capabilities.reversedDepthBuffer !== undefined);
      const inForce =
        mode === 'plain' ||
        (mode === 'logarithmic' ? capabilities.logarithmicDepthBuffer : capabilities.reversedDepthBuffer === true && depthState.getReversed?.() === true);
      const result = { mode, supported, inForce, above: colourAt(0.6), below: colourAt(-0.6) };
      ocean.dispose();
      box.geometry.dispose();
      box.material.dispose();
      own.dispose();
      own.forceContextLoss();
      return result;
    });
  },
  /**
   * The whole Ocean (its generated sky too) at the app's first view, drawn twice with the same
   * renderer, scene, camera and time: by renderer.render straight to the canvas, and through three's
   * EffectComposer (a RenderPass into its half-float target, then an OutputPass that applies the
   * renderer's tone mapping and output colour space). Returns the mean and largest per-channel
   * difference (0–255) between the two pictures, how many channel values differ by more than 4, and
   * the composer's mean colour of the sky (rows 5–35 % of the height) and of the sea (65–95 %).
   */
  composerCheck(): { meanDifference: number; largestDifference: number; over4: number; channels: number; sky: number[]; sea: number[] } {
    const [w, h] = [320, 180];
    const own = new WebGLRenderer({ antialias: false });
    own.setSize(w, h);
    own.toneMapping = ACESFilmicToneMapping;
    own.outputColorSpace = SRGBColorSpace;
    const ownScene = new Scene();
    const ocean = new Ocean(own, { seed: 7, localWaves: false, worker: false });
    ownScene.add(ocean);
    const ownCamera = new PerspectiveCamera(55, w / h, 0.5, 1e4);
    ownCamera.position.set(0, 12, 0);
    ownCamera.lookAt(60, 0, -80);
    ownCamera.far = ocean.horizonDistanceFor(12);
    ownCamera.updateProjectionMatrix();
    const composer = new EffectComposer(own);
    composer.addPass(new RenderPass(ownScene, ownCamera));
    composer.addPass(new OutputPass());
    const gl = own.getContext();
    const read = (draw: () => void) => {
      draw();
      draw(); // the first draw after set-up builds the layers' programs
      const pixels = new Uint8Array(4 * w * h);
      gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
      return pixels;
    };
    ocean.update(6);
    const plain = read(() => own.render(ownScene, ownCamera));
    const composed = read(() => composer.render());
    let [sum, largestDifference, over4] = [0, 0, 0];
    for (let i = 0; i < plain.length; i++) {
      if (i % 4 === 3) continue; // alpha
      const difference = Math.abs(plain[i] - composed[i]);
      sum += difference;
      largestDifference = Math.max(largestDifference, difference);
      if (difference > 4) over4++;
    }
    const channels = (plain.length / 4) * 3;
    /** Mean RGB of the rows from `from` to `to` (fractions of the height from the top). */
    const band = (from: number, to: number) => {
      const total = [0, 0, 0];
      let count = 0;
      for (let y = Math.round((1 - to) * h); y < Math.round((1 - from) * h); y++) {
        for (let x = 0; x < w; x++, count++) for (let c = 0; c < 3; c++) total[c] += composed[4 * (y * w + x) + c];
      }
      return total.map((t) => t / count);
    };
    const result = { meanDifference: sum / channels, largestDifference, over4, channels, sky: band(0.05, 0.35), sea: band(0.65, 0.95) };
    composer.dispose();
    ocean.dispose();
    own.dispose();
    own.forceContextLoss();
    return result;
  },
  /**
   * The whole Ocean (its generated sky too), tone-mapped as the app draws it, seen level from 10 m
   * up towards the sun's azimuth, with the sun at each elevation (degrees). For each: the mean
   * linear luminance (Rec. 709 weights of the decoded sRGB pixels) of the sky (the rows 5–40 % of
   * the height) and of the sea (60–95 %), and the brightest 8-bit channel of each.
   */
  nightCheck(elevations: number[]): { elevation: number; sky: number; sea: number; skyMax: number; seaMax: number }[] {
    const [w, h] = [160, 90];
    const own = new WebGLRenderer({ antialias: false });
    own.setSize(w, h);
    own.toneMapping = ACESFilmicToneMapping;
    const ownScene = new Scene();
    const ocean = new Ocean(own, { resolution: 32, windSpeed: 8, localWaves: false, foamAmount: 0 });
    ownScene.add(ocean);
    const ownCamera = new PerspectiveCamera(60, w / h, 0.5, 1e5);
    ownCamera.position.set(0, 10, 0);
    ownCamera.lookAt(100, 10, 0); // the sun's azimuth 0: towards +x
    const gl = own.getContext();
    const pixels = new Uint8Array(w * h * 4);
    const decode = (v: number) => (v <= 10.31 ? v / 255 / 12.92 : ((v / 255 + 0.055) / 1.055) ** 2.4);
    const band = (from: number, to: number) => {
      let luminance = 0;
      let brightest = 0;
      let count = 0;
      // readPixels rows run from the bottom; `from` and `to` are fractions of the height from the top.
      for (let y = Math.round((1 - to) * h); y < Math.round((1 - from) * h); y++) {
        for (let x = 0; x < w; x++) {
          const i = 4 * (y * w + x);
          luminance += 0.2126 * decode(pixels[i]) + 0.7152 * decode(pixels[i + 1]) + 0.0722 * decode(pixels[i + 2]);
          brightest = Math.max(brightest, pixels[i], pixels[i + 1], pixels[i + 2]);
          count++;
        }
      }
      return { luminance: luminance / count, brightest };
    };
    const results = elevations.map((elevation) => {
      ocean.setSun(elevation, 0);
      ocean.update(2);
      own.render(ownScene, ownCamera);
      own.render(ownScene, ownCamera); // the first draw after set-up builds the layers' programs
      gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
      const sky = band(0.05, 0.4);
      const sea = band(0.6, 0.95);
      return { elevation, sky: sky.luminance, sea: sea.luminance, skyMax: sky.brightest, seaMax: sea.brightest };
    });
    ocean.dispose();
    own.dispose();
    own.forceContextLoss();
    return results;
  },
  /**
   * The page's first Ocean, whose first update runs the queries once and has its cascades forget
   * them (Ocean.warmUpQueries): frames without queries for QUERY_WORKER_DELAY_MS + 0.35 s, then a
   * query and as long again. Returns how many queries reached the cascades in the first update
   * (FftCascade.queryFields counted), whether any cascade counted as queried before the app's
   * query, the Workers made and the requests for fields with velocities sent to workers before and
   * after it (Worker counted), and the first answer against the height from fields computed for the
   * time asked.
   */
  async warmUpLeavesNoTrace(path: 'gpu' | 'js'): Promise<{
    warmUpQueries: number;
    cascades: number;
    queriedBefore: boolean;
    workersBefore: number;
    workersAfter: number;
    velocityRequestsBefore: number;
    velocityRequestsAfter: number;
    heightError: number;
    rms: number;
  }> {
    const RealWorker = window.Worker;
    let [workersMade, velocityRequests] = [0, 0];
    window.Worker = class extends RealWorker {
      constructor(url: string | URL, options?: WorkerOptions) {
        super(url, options);
        workersMade++;
      }
      override postMessage(message: unknown, transfer?: Transferable[] | StructuredSerializeOptions): void {
        if ((message as { type?: string; velocities?: boolean }).velocities === true) velocityRequests++;
        super.postMessage(message, transfer as Transferable[]);
      }
    };
    const queryFields = FftCascade.prototype.queryFields;
    let queries = 0;
    FftCascade.prototype.queryFields = function (this: FftCascade, t: number) {
      queries++;
      return queryFields.call(this, t);
    };
    const ocean = new Ocean(renderer, { path, worker: true, localWaves: false, seed: 3 });
    try {
      const cascades = ocean.simulation.cascades;
      let t = 10;
      const frames = async () => {
        for (const until = performance.now() + QUERY_WORKER_DELAY_MS + 350; performance.now() < until; ) {
          ocean.update((t += 1 / 60));
          await new Promise((resolve) => setTimeout(resolve, 30));
        }
      };
      ocean.update(t);
      const warmUpQueries = queries;
      await frames();
      const queriedBefore = cascades.some((cascade) => cascade.queriedYet);
      const [workersBefore, velocityRequestsBefore] = [workersMade, velocityRequests];
      const height = ocean.heightAt(3, -4);
      const heightError = Math.abs(height - heightAt(exactLayers(cascades), ocean.parameters.choppiness, t, 3, -4));
      await frames();
      return { warmUpQueries, cascades: cascades.length, queriedBefore, workersBefore, workersAfter: workersMade, velocityRequestsBefore, velocityRequestsAfter: velocityRequests, heightError, rms: ocean.heightRms };
    } finally {
      ocean.dispose();
      window.Worker = RealWorker;
      FftCascade.prototype.queryFields = queryFields;
    }
  },
  /**
   * The queries in a frame loop as an app makes them: update, heightAt and normalAt at 25 points,
   * then a pause for the workers (a frame of a slow renderer). On the GPU path the queries read the
   * query workers' fields, on the JS path the JS workers' (cascadeQueryFields.ts). The steps are 1/60 s,
   * or alternately 1/60 s ± `jitter`. Frames run until no cascade has computed fields here for
   * three frames in a row (the workers started: `warmUpFrames`, at most 40), then 20 more, over which
   * it returns how many times the cascades computed fields here, and the worst difference between
   * heightAt and the height from fields computed for the time asked. Then a new wind (14 m/s: new
   * cascades, which read provisional copies until their workers answer) and 3 frames, with the same
   * worst difference (`worstAfterChange`, RMS height `rmsAfterChange`). `computedByQueries` counts
   * the fields computed here inside the queries (not in the updates) over all frames.
   */
  async queriesFromWorkers(
    path: 'gpu' | 'js',
    jitter: number,
  ): Promise<{
    warmUpFrames: number;
    computedInWarmUp: number;
    computedByQueries: number;
    cascades: number;
    computedHere: number;
    worstError: number;
    rms: number;
    worstAfterChange: number;
    rmsAfterChange: number;
    path: string;
  }> {
    const ocean = new Ocean(renderer, { path, worker: true, localWaves: false, seed: 3 });
    const { choppiness } = ocean.parameters;
    let cascades = ocean.simulation.cascades;
    let exact = exactLayers(cascades);
    const points = Array.from({ length: 25 }, (_, p) => [(p % 5) * 23.1 - 40, Math.floor(p / 5) * 19.7 - 35]);
    const normal = new Vector3();
    const computedHere = () => cascades.reduce((sum, cascade) => sum + cascade.fieldsComputedHere, 0);
    let t = 20;
    let frame = 0;
    let computedByQueries = 0;
    /** One frame; with `compare`, heightAt's worst difference from the exact height, and the squared heights. */
    const step = async (compare: boolean) => {
      t += 1 / 60 + (frame++ % 2 === 0 ? jitter : -jitter);
      ocean.update(t);
      const beforeQueries = computedHere();
      let [worst, squares] = [0, 0];
      for (const [x, z] of points) {
        const height = ocean.heightAt(x, z);
        ocean.normalAt(x, z, normal);
        if (!compare) continue;
        const expected = heightAt(exact, choppiness, t, x, z);
        worst = Math.max(worst, Math.abs(height - expected));
        squares += expected ** 2;
      }
      computedByQueries += computedHere() - beforeQueries;
      await new Promise((resolve) => setTimeout(resolve, 80));
      return { worst, squares };
    };
    try {
      for (let quiet = 0; quiet < 3 && frame < 60; ) {
        const before = computedHere();
        await step(false);
        quiet = computedHere() === before ? quiet + 1 : 0;
      }
      const warmUpFrames = frame;
      const computedInWarmUp = computedHere();
      const before = computedHere();
      /** `frames` frames compared: the worst difference and the RMS height. */
      const compared = async (frames: number) => {
        let [worstError, squares] = [0, 0];
        for (let i = 0; i < frames; i++) {
          const { worst, squares: s } = await step(true);
          worstError = Math.max(worstError, worst);
          squares += s;
        }
        return [worstError, Math.sqrt(squares / (frames * points.length))];
      };
      const [worstError, rms] = await compared(20);
      const computedAfterWarmUp = computedHere() - before;
      ocean.setParameters({ windSpeed: 14 });
      cascades = ocean.simulation.cascades;
      exact = exactLayers(cascades);
      const [worstAfterChange, rmsAfterChange] = await compared(3);
      return {
        warmUpFrames,
        computedInWarmUp,
        computedByQueries,
        cascades: cascades.length,
        computedHere: computedAfterWarmUp,
        worstError,
        rms,
        worstAfterChange,
        rmsAfterChange,
        path: ocean.path.running,
      };
    } finally {
      ocean.dispose();
    }
  },
  /**
   * The local waves on the GPU and the queries: after a stone, frames of an update and heightAt at
   * points around it. Returns the read-backs that waited for the GPU (readRenderTargetPixels) after
   * the first query, those that did not (readRenderTargetPixelsAsync), and, after frames with no
   * update (the last read-back in), the largest difference between heightAt and the same query over
   * the fields read back at once (fieldsOnCpu), and how far the local field reaches there.
   */
  async localWavesQueriedOnGpu(): Promise<{ path: string; waited: number; notWaited: number; worstDifference: number; largestLocal: number }> {
    const ocean = new Ocean(renderer, { resolution: 64, choppiness: 0, seed: 4, localWaves: { path: 'gpu' } });
    const waves = ocean.localWaves!;
    const counts = { waited: 0, notWaited: 0, inFlight: 0 };
    const { readRenderTargetPixels, readRenderTargetPixelsAsync } = renderer;
    renderer.readRenderTargetPixels = (...args: Parameters<typeof readRenderTargetPixels>) => {
      counts.waited++;
      return readRenderTargetPixels.apply(renderer, args);
    };
    renderer.readRenderTargetPixelsAsync = (...args: Parameters<typeof readRenderTargetPixelsAsync>) => {
      counts.notWaited++;
      counts.inFlight++;
      return readRenderTargetPixelsAsync.apply(renderer, args).finally(() => counts.inFlight--);
    };
    const points = Array.from({ length: 36 }, (_, p) => [(p % 6) * 1.3 - 2, Math.floor(p / 6) * 1.3 - 5]);
    try {
      waves.follow(0, 0);
      ocean.update(10);
      waves.drop(1, -2, { radius: 1.2, depth: 0.8 });
      ocean.heightAt(0, 0); // the first query reads back at once
      const waitedAtFirst = counts.waited;
      for (let t = 10.05; t < 12; t += 0.05) {
        ocean.update(t);
        for (const [x, z] of points) ocean.heightAt(x, z);
        await new Promise((resolve) => setTimeout(resolve, 20));
      }
      // No more updates: queries until the read-backs in flight are in and none newer is started.
      for (let i = 0; i < 200; i++) {
        const started = counts.notWaited;
        ocean.heightAt(0, 0);
        if (counts.inFlight === 0 && counts.notWaited === started) break;
        await new Promise((resolve) => setTimeout(resolve, 50));
      }
      const waited = counts.waited - waitedAtFirst;
      const queried = points.map(([x, z]) => ocean.heightAt(x, z));
      const local = waves.fieldsOnCpu(ocean.time).displacement; // read back at once
      const cascadesOnly = points.map(([x, z]) => heightAt(ocean.simulation.cascades, 0, ocean.time, x, z));
      const { size, origin, resolution } = waves.frame;
      let [worstDifference, largestLocal] = [0, 0];
      points.forEach(([x, z], p) => {
        // choppiness 0: the local field at (x, z) itself, bilinear
        const [u, v] = [((x - origin[0]) / size) * resolution, ((z - origin[1]) / size) * resolution];
        const [i, j] = [Math.floor(u), Math.floor(v)];
        const [fu, fv] = [u - i, v - j];
        const h = (a: number, b: number) => local[4 * (b * resolution + a) + 1];
        const localHeight = (1 - fv) * ((1 - fu) * h(i, j) + fu * h(i + 1, j)) + fv * ((1 - fu) * h(i, j + 1) + fu * h(i + 1, j + 1));
        largestLocal = Math.max(largestLocal, Math.abs(localHeight));
        worstDifference = Math.max(worstDifference, Math.abs(queried[p] - cascadesOnly[p] - localHeight));
      });
      return { path: waves.path, waited, notWaited: counts.notWaited, worstDifference, largestLocal };
    } finally {
      renderer.readRenderTargetPixels = readRenderTargetPixels;
      renderer.readRenderTargetPixelsAsync = readRenderTargetPixelsAsync;
      ocean.dispose();
    }
  },
  /**
   * The JS path in workers, and what happens when a worker fails: `fault` is 'throws' (an
   * exception in the worker), 'terminated' (killed from outside: it never answers again),
   * 'unloadable' (its script cannot load: it fails before any answer) or 'blocked' (new Worker
   * throws, as under a CSP without worker-src). For each: the path before and after, the reason,
   * the pathchange events, and how far the shown fields of every cascade are, a few frames after
   * the fault, from the JS fields computed here at the time they show (0 when they are right).
   */
  async workerFault(fault: 'throws' | 'terminated' | 'unloadable' | 'blocked'): Promise<{
    before: string;
    after: string;
    reason: string;
    events: string[];
    largestError: number;
    largestHeight: number;
  }> {
    const RealWorker = window.Worker;
    if (fault === 'blocked') {
      window.Worker = class {
        constructor() {
          throw new DOMException('blocked by the test', 'SecurityError');
        }
      } as unknown as typeof Worker;
    } else if (fault === 'unloadable') {
      window.Worker = class extends RealWorker {
        constructor(_url: string | URL, options?: WorkerOptions) {
          super('/no-such-worker-script.js', options);
        }
      };
    }
    const ocean = new Ocean(renderer, { resolution: 32, path: 'js', worker: true, localWaves: false });
    window.Worker = RealWorker;
    const events: string[] = [];
    ocean.addEventListener('pathchange', ({ path }) => events.push(`${path.running}: ${path.reason}`));
    const pause = () => new Promise((resolve) => setTimeout(resolve, 30));
    const layers = ocean.simulation.cascades;
    /** Updates at t until every cascade shows the fields of t (at most `seconds` of frames). */
    const runUntilShown = async (t: number, seconds: number) => {
      const until = performance.now() + seconds * 1000;
      let error = Infinity;
      while (performance.now() < until) {
        ocean.update(t);
        await pause();
        error = Math.max(...layers.map((layer) => largestDifference(layer.shownFieldsOnCpu()!.displacement, layer.fieldsOnCpu(t).displacement)));
        if (error === 0) break;
      }
      return error;
    };
    await runUntilShown(1, 20);
    const before = ocean.path.running;
    const { worker } = (layers[0] as unknown as { backend: { worker: { worker: Worker } } }).backend;
    if (fault === 'throws') {
      // Arrays too short for the fields: filling them throws (a RangeError) in the worker.
      const spare = { displacement: new Float32Array(1), derivatives: new Float32Array(1), velocities: null };
      worker.worker.postMessage({ type: 'update', t: 2, velocities: false, spare });
    }
    if (fault === 'terminated') worker.worker.terminate();
    // Long enough for a silent worker to be given up (4 s) and its replacement to answer.
    const largestError = await runUntilShown(3, 20);
    const largestHeight = Math.max(...layers.map((layer) => Math.max(...layer.fieldsOnCpu(3).displacement.map(Math.abs))));
    const result = { before, after: ocean.path.running, reason: ocean.path.reason, events, largestError, largestHeight };
    ocean.dispose();
    return result;
  },
  horizonCheck(changes: Partial<SimulationParameters>): { before: number; beforeAtSeaLevel: number; seaLevel: number; after: number; farthest: number } {
    return withOcean(changes, (ocean) => {
      const before = ocean.horizonDistanceFor(camera.position.y);
      const beforeAtSeaLevel = ocean.horizonDistance;
      const seaLevel = ocean.horizonDistanceFor(0);
      const { farthest } = geometryCheck(0); // places the rings for the camera, as a render does
      return { before, beforeAtSeaLevel, seaLevel, after: ocean.horizonDistance, farthest };
    });
  },
  /**
   * For each pixel (x, y from the top): its rendered value (red, 0–1) and cos θi of the view ray
   * where it meets the flat sea plane y = 0.
   */
  probe(pixels: [number, number][]): { value: number; cosIncident: number; hitsSea: boolean }[] {
    return pixels.map(([x, y]) => {
      const ndc = new Vector3(((x + 0.5) / width) * 2 - 1, 1 - ((y + 0.5) / height) * 2, 0.5);
      const direction = ndc.unproject(camera).sub(camera.position).normalize();
      return { value: harness.pixel(x, y)[0] / 255, cosIncident: Math.abs(direction.y), hitsSea: direction.y < -0.01 };
    });
  },
  /**
   * Renders with a pure red background and counts red pixels below the horizon, where only sea
   * should be: a crack between rings or a gap before the horizon shows as red.
   */
  holesBelowHorizon(t: number, marginPixels = 3): { holes: number; checked: number; firstHoles: number[][] } {
    const saved = scene.background;
    scene.background = new Color(1, 0, 0);
    harness.render(t, true);
    scene.background = saved;
    const gl = renderer.getContext();
    const pixels = new Uint8Array(4 * width * height);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    let holes = 0;
    let checked = 0;
    const firstHoles: number[][] = [];
    const direction = new Vector3();
    for (let y = 0; y < height; y++) {
      for (let x = 0; x < width; x++) {
        // The ray through this pixel (y from the bottom in GL).
        direction.set(((x + 0.5) / width) * 2 - 1, ((y + 0.5) / height) * 2 - 1, 0.5).unproject(camera).sub(camera.position);
        // Below the horizon with a margin (the last few pixels may show the sky between far crests).
        const belowBy = -direction.normalize().y * (height / ((camera.fov * Math.PI) / 180));
        if (belowBy < marginPixels) continue;
        checked++;
        const i = 4 * (y * width + x);
        if (pixels[i] > 200 && pixels[i + 1] < 40 && pixels[i + 2] < 40) {
          holes++;
          if (firstHoles.length < 10) firstHoles.push([x, height - 1 - y]);
        }
      }
    }
    return { holes, checked, firstHoles };
  },
  setSun(direction: [number, number, number]): void {
    sunDirection.fromArray(direction).normalize();
  },
};

/**
 * Runs `use` with an Ocean (GPU path, no worker) made from `changes` in place of the page's own
 * simulation and surface (so geometryCheck reads its surface), and frees it after.
 */
/** The largest |a[i] − b[i]|. */
function largestDifference(a: ArrayLike<number>, b: ArrayLike<number>): number {
  let largest = 0;
  for (let i = 0; i < a.length; i++) largest = Math.max(largest, Math.abs(a[i] - b[i]));
  return largest;
}

function withOcean<T>(changes: OceanOptions, use: (ocean: Ocean) => T): T {
  surface?.removeFromParent();
  surface?.dispose();
  simulation?.dispose();
  const ocean = new Ocean(renderer, { ...changes, path: 'gpu', worker: false });
  simulation = ocean.simulation;
  surface = ocean.surface;
  try {
    return use(ocean);
  } finally {
    simulation = null;
    surface = null;
    ocean.dispose();
  }
}

/**
 * Draws the horizon grid as points with the real vertex shader (define CAPTURE_POSITIONS), one
 * float texel per vertex, reads back each vertex's displaced position and rest point, and checks
 * displaced − rest against the sum of the periodic layers' CPU fields (the contract's fieldsOnCpu:
 * the cascades' JS fields, and any layer added) sampled at the rest point (bilinear, REPEAT, at the
 * vertex's mip level in each layer, mips built by 2×2 averages as generateMipmap does), horizontal
 * parts scaled by the choppiness. The local waves are left out: no source has touched them here.
 */
function geometryCheck(t: number, withRestPoints = false) {
  const sim = simulation!;
  const mesh = surface!;
  sim.update(t);
  mesh.onBeforeRender(renderer, scene, camera); // the viewport's ring size, and the rings under the camera
  const count = mesh.geometry.getAttribute('position').count;
  const captureWidth = 1024;
  const captureHeight = Math.ceil(count / captureWidth);
  const material = new OceanMaterial({ environment, sunDirection: { value: sunDirection } }, {}, { CAPTURE_POSITIONS: 1 });
  const { choppiness } = sim.parameters;
  // Bound as the surface binds them (the local waves first: zero here, no source has touched them).
  material.bindLayers(sim.layers, choppiness, sim.foam.texture);
  for (const name of ['ringFrames', 'ringLayerUvOrigins', 'ringOffsets', 'halfRingCells', 'patchBlend']) {
    material.uniforms[name].value = mesh.material.uniforms[name].value;
  }
  material.uniforms.captureWidth.value = captureWidth;
  material.uniforms.captureHeight.value = captureHeight;
  const points = new Points(mesh.geometry, material);
  points.frustumCulled = false;
  const captureScene = new Scene().add(points);
  const target = new WebGLRenderTarget(captureWidth, captureHeight, { type: FloatType, format: RGBAFormat, depthBuffer: false });
  const read = (rest: boolean): Float32Array => {
    material.uniforms.captureRestPoint.value = rest;
    renderer.setRenderTarget(target);
    renderer.setClearColor(0x000000, 0);
    renderer.clear();
    renderer.render(captureScene, camera);
    const pixels = new Float32Array(4 * captureWidth * captureHeight);
    renderer.readRenderTargetPixels(target, 0, 0, captureWidth, captureHeight, pixels);
    renderer.setRenderTarget(null);
    return pixels;
  };
  const displaced = read(false);
  const rest = read(true);
  target.dispose();
  material.dispose();

  const layers = sim.layers
    .filter((layer) => layer.frame.periodic)
    .map((layer) => {
      const fields = layer.fieldsOnCpu(t);
      const n = layer.frame.resolution;
      const lodBias = material.uniforms.layerLodBias.value[sim.layers.indexOf(layer)] as number;
      return { size: layer.frame.size, n, fields, mips: mipChain(fields.displacement, n), lodBias };
    });
  // RMS of the summed height over the largest patch's grid (the sum does not repeat on a smaller one).
  const largest = layers[layers.length - 1];
  const n = largest.n;
  let sumSquares = 0;
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      const x = (i * largest.size) / n;
      const z = (j * largest.size) / n;
      let h = 0;
      for (const layer of layers) h += sampleBilinear(layer.fields.displacement, layer.n, x / layer.size + 0.5 / layer.n, z / layer.size + 0.5 / layer.n)[1];
      sumSquares += h * h;
    }
  }
  const rms = Math.sqrt(sumSquares / (n * n));
  const blend = patchBlendUniforms(largest.size, new Float64Array(12));
  /**
   * Σ over layers of the field sampled at rest point (x, z), each at its own mip level, the
   * largest as cos θ·P(x) + sin θ·P(x + o) (src/layers/patchBlend.ts).
   */
  const summed = (x: number, z: number, lod: number, pick: (layer: (typeof layers)[number], level: number) => Float32Array): number[] => {
    const total = [0, 0, 0, 0];
    const theta = blendAngle(blend, x, z);
    layers.forEach((layer, i) => {
      const level = Math.min(Math.max(0, Math.round(lod) + layer.lodBias), layer.mips.length - 1); // GL clamps
      const at = (u: number, v: number) => sampleBilinear(pick(layer, level), layer.n >> level, u + 0.5 / layer.n, v + 0.5 / layer.n);
      const [u, v] = [x / layer.size, z / layer.size];
      const copies: [number, number[]][] =
        i === layers.length - 1 ? [[Math.cos(theta), at(u, v)], [Math.sin(theta), at(u + COPY_OFFSET[0], v + COPY_OFFSET[1])]] : [[1, at(u, v)]];
      for (const [weight, value] of copies) for (let c = 0; c < 4; c++) total[c] += weight * value[c];
    });
    return total;
  };
  const byLevel: Record<string, { count: number; maxError: number }> = {};
  let skirt = 0;
  let maxOffGrid = 0;
  const heights: number[] = [];
  const restPoints: string[] = [];
  /** (x, y, z) displaced, and the Jacobian of the choppy map at the rest point. */
  const displacedAtMip0: [number, number, number, number][] = [];
  let farthest = 0;
  // The shader works in metres from the eye: back to world coordinates, in double precision.
  const eye = camera.getWorldPosition(new Vector3());
  for (let v = 0; v < count; v++) {
    const [restX, restZ, lod, ring] = rest.subarray(4 * v, 4 * v + 4);
    const [x, z] = [restX + eye.x, restZ + eye.z];
    const [px, py, pz] = [displaced[4 * v] + eye.x, displaced[4 * v + 1] + eye.y, displaced[4 * v + 2] + eye.z];
    farthest = Math.max(farthest, camera.position.distanceTo(new Vector3(px, py, pz)));
    if (lod > 500) { // SKIRT_LOD: the far edge, flat by design
      skirt++;
      continue;
    }
    const level = Math.min(Math.round(lod), layers[0].mips.length - 1); // of the finest layer
    const expected = summed(x, z, lod, (layer, mip) => layer.mips[mip]);
    const error = Math.max(
      Math.abs(px - x - choppiness * expected[0]),
      Math.abs(py - expected[1]),
      Math.abs(pz - z - choppiness * expected[2]),
    );
    const key = level === layers[0].mips.length - 1 ? 'coarsest' : String(level);
    byLevel[key] ??= { count: 0, maxError: 0 };
    byLevel[key].count++;
    byLevel[key].maxError = Math.max(byLevel[key].maxError, error / rms);
    // Rest points lie on the world grid of their ring: multiples of the ring's cell size (exact, in
    // double precision: the uniform's float32 cell is off by 6e-8 of itself, a whole cell at 10⁷ m).
    const cell = finestTexel(sim.layers) * 2 ** (mesh.material.uniforms.ringFrames.value[4 * ring + 3] as number);
    for (const c of [x, z]) maxOffGrid = Math.max(maxOffGrid, Math.abs(c / cell - Math.round(c / cell)));
    heights.push(py);
    if (level === 0 && layers.every((layer) => Math.round(lod) + layer.lodBias <= 0)) {
      const [, , dxx, dzz] = summed(x, z, 0, (layer) => layer.fields.derivatives);
      const dxz = choppiness * expected[3];
      displacedAtMip0.push([px, py, pz, (1 + choppiness * dxx) * (1 + choppiness * dzz) - dxz * dxz]);
    }
    // Keyed by the unclamped mip level: the coarser layers' levels go on growing past the finest's last.
    if (withRestPoints) restPoints.push(`${x},${z},${Math.round(lod)}`);
  }
  return { count, skirt, rms, byLevel, maxOffGrid, heights, restPoints, displacedAtMip0, farthest };
}

/** Mip levels of an RGBA N×N texture by 2×2 averaging, level 0 first. */
function mipChain(level0: Float32Array, n: number): Float32Array[] {
  const levels = [level0];
  for (let size = n / 2; size >= 1; size /= 2) {
    const previous = levels[levels.length - 1];
    const next = new Float32Array(4 * size * size);
    for (let j = 0; j < size; j++) {
      for (let i = 0; i < size; i++) {
        for (let c = 0; c < 4; c++) {
          const at = (jj: number, ii: number) => previous[4 * (jj * 2 * size + ii) + c];
          next[4 * (j * size + i) + c] = 0.25 * (at(2 * j, 2 * i) + at(2 * j, 2 * i + 1) + at(2 * j + 1, 2 * i) + at(2 * j + 1, 2 * i + 1));
        }
      }
    }
    levels.push(next);
  }
  return levels;
}

/** GL-style bilinear sample with REPEAT at (u, v) of an RGBA size×size texture. */
function sampleBilinear(data: Float32Array, size: number, u: number, v: number): number[] {
  const x = u * size - 0.5;
  const y = v * size - 0.5;
  const x0 = Math.floor(x);
  const y0 = Math.floor(y);
  const fx = x - x0;
  const fy = y - y0;
  const wrap = (i: number) => ((i % size) + size) % size;
  const texel = (i: number, j: number, c: number) => data[4 * (wrap(j) * size + wrap(i)) + c];
  return [0, 1, 2, 3].map(
    (c) =>
      (1 - fy) * ((1 - fx) * texel(x0, y0, c) + fx * texel(x0 + 1, y0, c)) +
      fy * ((1 - fx) * texel(x0, y0 + 1, c) + fx * texel(x0 + 1, y0 + 1, c)),
  );
}

declare global {
  interface Window {
    ocean: typeof harness;
  }
}
window.ocean = harness;
/** The same cascades, each answering the queries with its fields computed here for the time asked. */
function exactLayers(cascades: readonly FftCascade[]): WaveLayer[] {
  return cascades.map((cascade) => ({
    textures: cascade.textures,
    frame: cascade.frame,
    movesSideways: true,
    update: () => {},
    dispose: () => {},
    queryFields: (t: number) => ({ time: t, resolution: cascade.frame.resolution, ...cascade.fieldsOnCpu(t), velocities: () => new Float32Array(0) }),
    fieldsOnCpu: (t: number) => cascade.fieldsOnCpu(t),
    shownFieldsOnCpu: () => null,
  }));
}

document.title = 'ready';
