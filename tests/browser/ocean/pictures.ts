/**
 * What the ocean test page's sea looks like: pixel probes and picture statistics of the page's
 * surface (shading, gaps below the horizon, foam, Snell's window, fog), and of whole Oceans drawn
 * by renderers of their own (depth buffers, EffectComposer, night).
 */
import {
  ACESFilmicToneMapping,
  BoxGeometry,
  Color,
  Fog,
  FogExp2,
  LinearSRGBColorSpace,
  Mesh,
  MeshBasicMaterial,
  NoToneMapping,
  PerspectiveCamera,
  Scene,
  SRGBColorSpace,
  Vector3,
  WebGLRenderer,
} from 'three';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { OutputPass } from 'three/addons/postprocessing/OutputPass.js';
import { RenderPass } from 'three/addons/postprocessing/RenderPass.js';
import { Ocean } from '../../../src/ocean';
import { snellWindowEdges } from '../shared/snellWindowEdges';
import type { SimulationParameters } from '../../../src/parameters/parameters';
import { camera, current, height, pixel, render, renderer, scene, setup, view, width } from './oceanPage';

/**
 * For each pixel (x, y from the top): its rendered value (red, 0–1) and cos θi of the view ray
 * where it meets the flat sea plane y = 0.
 */
export function probe(pixels: [number, number][]): { value: number; cosIncident: number; hitsSea: boolean }[] {
  return pixels.map(([x, y]) => {
    const ndc = new Vector3(((x + 0.5) / width) * 2 - 1, 1 - ((y + 0.5) / height) * 2, 0.5);
    const direction = ndc.unproject(camera).sub(camera.position).normalize();
    return { value: pixel(x, y)[0] / 255, cosIncident: Math.abs(direction.y), hitsSea: direction.y < -0.01 };
  });
}

/**
 * Renders with a pure red background and counts red pixels below the horizon, where only sea
 * should be: a crack between rings or a gap before the horizon shows as red.
 */
export function holesBelowHorizon(t: number, marginPixels = 3): { holes: number; checked: number; firstHoles: number[][] } {
  const saved = scene.background;
  scene.background = new Color(1, 0, 0);
  render(t, true);
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
}

/**
 * The fraction of the canvas that whitecap foam brightens: the picture at time t with these
 * parameters against the same sea with foamAmount 0, pixels whose luminance rose by over 16/255 (under this page's uniform pale sky water and foam differ less than under a real sky).
 */
export function foamBrightened(parameters: Partial<SimulationParameters>, t: number): number {
  const gl = renderer.getContext();
  const pictures = [0, 1].map((foamAmount) => {
    setup({ ...parameters, foamAmount: foamAmount * (parameters.foamAmount ?? 1) });
    render(t);
    const pixels = new Uint8Array(4 * width * height);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    return pixels;
  });
  let brightened = 0;
  const luminance = (p: Uint8Array, i: number) => 0.2126 * p[i] + 0.7152 * p[i + 1] + 0.0722 * p[i + 2];
  for (let i = 0; i < pictures[0].length; i += 4) if (luminance(pictures[1], i) - luminance(pictures[0], i) > 16) brightened++;
  return brightened / (width * height);
}

/**
 * Snell's window: a calm sea seen straight up from 1 m under it with a 120° lens, under a
 * uniform sky, linear output. Returns where the sky's light ends (snellWindowEdges), in degrees.
 */
export function snellWindow(ior: number): { edgeAngles: number[]; centreRed: number } {
  current.surfaceBound = 0.5;
  setup({ resolution: 64, windSpeed: 0 }, { ior });
  const fov = 120;
  const lens = new PerspectiveCamera(fov, 1, 0.1, 1e5);
  lens.position.set(0, -1, 0);
  lens.up.set(0, 0, -1);
  lens.lookAt(0, 10, 0);
  lens.updateMatrixWorld();
  renderer.toneMapping = NoToneMapping;
  renderer.outputColorSpace = LinearSRGBColorSpace;
  current.simulation!.update(3);
  // Twice: the first draw after setup binds the layers (a new LAYER_COUNT recompiles) and shows no sea.
  renderer.render(scene, lens);
  renderer.render(scene, lens);
  const gl = renderer.getContext();
  const pixels = new Uint8Array(4 * width * height);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  current.surfaceBound = undefined;
  const red = (x: number, y: number) => pixels[4 * (y * width + x)];
  // The page is square here (ocean.spec.ts opens it 512×512).
  return { edgeAngles: snellWindowEdges(red, width, fov), centreRed: red(width / 2, height / 2) };
}

/**
 * scene.fog on the sea: the picture from 10 m up with no fog, with a Fog (40 m to 400 m) and with
 * a FogExp2 (density 0.01), all of magenta. Returns, for a pixel 20 m ahead on the sea and one
 * ~2 km ahead, each picture's colour (0–255).
 */
export function fogCheck(): { near: number[][]; far: number[][]; nearDistance: number; farDistance: number } {
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
    render(3);
    render(3);
    near.push(pixel(width / 2, rowAt(20)));
    far.push(pixel(width / 2, rowAt(2000)));
  }
  scene.fog = null;
  return { near, far, nearDistance: 20, farDistance: 2000 };
}

/**
 * A red box 2 m on a side, half under a calm sea, seen from 7 m away and 2 m up, with a renderer
 * of each depth buffer: plain, logarithmic and reversed (where EXT_clip_control allows it). For
 * each: whether this context and three.js release can give it (reversed: EXT_clip_control, and
 * a three.js with the option), whether it was in force (reversed: three's capability, and its
 * depth state reversed during the render), and the colour (0–255) at the middle of the box's
 * front face 0.6 m above and 0.6 m below the water line.
 */
export function depthBufferCheck(): { mode: string; supported: boolean; inForce: boolean; above: number[]; below: number[] }[] {
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
}

/**
 * The whole Ocean (its generated sky too) at the app's first view, drawn twice with the same
 * renderer, scene, camera and time: by renderer.render straight to the canvas, and through three's
 * EffectComposer (a RenderPass into its half-float target, then an OutputPass that applies the
 * renderer's tone mapping and output colour space). Returns the mean and largest per-channel
 * difference (0–255) between the two pictures, how many channel values differ by more than 4, and
 * the composer's mean colour of the sky (rows 5–35 % of the height) and of the sea (65–95 %).
 */
export function composerCheck(): { meanDifference: number; largestDifference: number; over4: number; channels: number; sky: number[]; sea: number[] } {
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
}

/**
 * The whole Ocean (its generated sky too), tone-mapped as the app draws it, seen level from 10 m
 * up towards the sun's azimuth, with the sun at each elevation (degrees). For each: the mean
 * linear luminance (Rec. 709 weights of the decoded sRGB pixels) of the sky (the rows 5–40 % of
 * the height) and of the sea (60–95 %), and the brightest 8-bit channel of each.
 */
export function nightCheck(elevations: number[]): { elevation: number; sky: number; sea: number; skyMax: number; seaMax: number }[] {
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
}
