/**
 * The WebGPU Ocean's benchmark page for `npm run bench` (bench/groups/webgpu.mjs): one page holds
 * either the WebGL subjects (`?backend=webgl`: the WebGL Ocean on a WebGLRenderer and the WebGPU
 * Ocean on WebGPURenderer's WebGL2 backend, forceWebGL) or the WebGPU backend's (`?backend=webgpu`),
 * never both: a WebGLRenderer made in a page whose WebGPU device lives drops that device
 * (tests/browser/webgpu/webgpu.spec.ts). The group alternates blocks of rounds between the two
 * pages; within a page the subjects are interleaved round by round (timedRounds.ts).
 *
 * When a subject's work is done (timeRounds' `finish`): on WebGL a 1-pixel readPixels of its
 * canvas (onePixelRead); on WebGPU `device.queue.onSubmittedWorkDone()`, which resolves once the
 * GPU has run everything submitted (three submits a frame's render and a compute's dispatches
 * as it records them).
 */
import { ACESFilmicToneMapping, PerspectiveCamera, RenderTarget, SRGBColorSpace, Scene, WebGLRenderer } from 'three';
import { WebGPURenderer } from 'three/webgpu';
import { Ocean as WebGLOcean, type OceanOptions } from '../../src/ocean';
import { Ocean as WebGPUOcean, type WebGPUOceanOptions } from '../../src/webgpu/index';
import { onePixelRead, timeRounds } from './timedRounds';

/** What a session times: `frame`, a whole frame at width × height; `fft`, ocean.update(t) alone at N = `resolution`. */
export interface SessionOptions {
  what: 'frame' | 'fft';
  width: number;
  height: number;
  resolution?: number;
}

interface Subject {
  label: string;
  /** Draws (frame) or updates (fft) at time t. */
  step: (t: number) => void;
  finish: () => void | Promise<void>;
  samples: number[];
}

const backend = new URLSearchParams(location.search).get('backend') === 'webgpu' ? 'webgpu' : 'webgl';
let subjects: Subject[] = [];
/** What the session made, freed by stop(). */
let disposers: (() => void)[] = [];

/** The frame pages' camera (frame.ts): 12 m up, the app's first view. */
function viewCamera({ width, height }: SessionOptions): PerspectiveCamera {
  const camera = new PerspectiveCamera(55, width / height, 0.5, 3e4);
  camera.position.set(0, 12, 0);
  camera.lookAt(60, 0, -80);
  camera.updateMatrixWorld();
  return camera;
}

/** A WebGPURenderer of width × height, initialized; `forceWebGL` for its WebGL2 backend. */
async function webgpuRenderer({ width, height }: SessionOptions, forceWebGL: boolean): Promise<WebGPURenderer> {
  const renderer = new WebGPURenderer({ antialias: false, forceWebGL });
  renderer.setPixelRatio(1);
  renderer.setSize(width, height);
  renderer.toneMapping = ACESFilmicToneMapping;
  renderer.outputColorSpace = SRGBColorSpace;
  await renderer.init();
  const isWebGPU = (renderer.backend as { isWebGPUBackend?: boolean }).isWebGPUBackend === true;
  if (isWebGPU === forceWebGL) throw new Error(`asked for the ${forceWebGL ? 'WebGL2' : 'WebGPU'} backend, got the other (no adapter without --enable-unsafe-webgpu?)`);
  disposers.push(() => renderer.dispose());
  return renderer;
}

/** A subject that draws `ocean`'s scene with `renderer` (into `target`, else its canvas) each frame. */
function frameSubject(label: string, ocean: WebGLOcean | WebGPUOcean, renderer: WebGLRenderer | WebGPURenderer, camera: PerspectiveCamera, finish: () => void | Promise<void>, target: RenderTarget | null = null): Subject {
  const scene = new Scene().add(ocean);
  disposers.push(() => ocean.dispose());
  return {
    label,
    step: (t) => {
      ocean.update(t);
      (renderer as WebGPURenderer).setRenderTarget(target);
      renderer.render(scene, camera);
    },
    finish,
    samples: [],
  };
}

/** A subject that only updates `ocean` (its FFT), each frame. */
function updateSubject(label: string, ocean: WebGLOcean | WebGPUOcean, finish: () => void | Promise<void>): Subject {
  disposers.push(() => ocean.dispose());
  return { label, step: (t) => ocean.update(t), finish, samples: [] };
}

/** The WebGL page's subjects. The WebGL Ocean's default frame, and its frame drawing what the WebGPU Ocean draws (no scene reflections or refractions, no local waves). */
async function webglSubjects(options: SessionOptions): Promise<Subject[]> {
  const gl = new WebGLRenderer({ antialias: false });
  gl.setPixelRatio(1);
  gl.setSize(options.width, options.height);
  gl.toneMapping = ACESFilmicToneMapping;
  document.body.append(gl.domElement); // shown, as frame.ts's
  disposers.push(() => {
    gl.dispose();
    gl.domElement.remove();
  });
  const glFinish = onePixelRead(gl.getContext());
  const sea = (more: OceanOptions) => new WebGLOcean(gl, { seed: 7, ...more });
  if (options.what === 'fft') {
    return [updateSubject('fragment passes (WebGL Ocean, path gpu)', sea({ resolution: options.resolution, path: 'gpu', foamAmount: 0, localWaves: false }), glFinish)];
  }
  const camera = viewCamera(options);
  const webgl2 = await webgpuRenderer(options, true);
  document.body.append(webgl2.domElement);
  disposers.push(() => webgl2.domElement.remove());
  const context = webgl2.getContext() as WebGL2RenderingContext;
  const readCanvas = onePixelRead(context);
  // three's WebGL2 backend caches its framebuffer bindings: read the canvas, then put its binding back.
  const webgl2Finish = () => {
    const bound = context.getParameter(context.READ_FRAMEBUFFER_BINDING) as WebGLFramebuffer | null;
    context.bindFramebuffer(context.READ_FRAMEBUFFER, null);
    readCanvas();
    context.bindFramebuffer(context.READ_FRAMEBUFFER, bound);
  };
  return [
    frameSubject('WebGL Ocean, defaults', sea({}), gl, camera, glFinish),
    frameSubject('WebGL Ocean, what the WebGPU Ocean draws', sea({ reflections: 'sky', refractions: 'sky', localWaves: false }), gl, camera, glFinish),
    frameSubject('WebGPU Ocean, defaults, WebGL2 backend', new WebGPUOcean(webgl2, { seed: 7 }), webgl2, camera, webgl2Finish),
  ];
}

/** The WebGPU page's subjects: the frame drawn into a target (a canvas loses its device headless, BROWSER.md); the compute FFT and the JS FFT. */
async function webgpuSubjects(options: SessionOptions): Promise<Subject[]> {
  const renderer = await webgpuRenderer(options, false);
  const device = (renderer.backend as unknown as { device: { queue: { onSubmittedWorkDone(): Promise<void> } } }).device;
  const finish = () => device.queue.onSubmittedWorkDone();
  const sea = (more: WebGPUOceanOptions) => new WebGPUOcean(renderer, { seed: 7, ...more });
  if (options.what === 'fft') {
    const fft = { resolution: options.resolution, foamAmount: 0 };
    return [
      updateSubject('compute (WebGPU Ocean, path gpu, WebGPU backend)', sea({ ...fft, path: 'gpu' }), finish),
      updateSubject('JS (WebGPU Ocean, path js, main thread)', sea({ ...fft, path: 'js', worker: false }), finish),
    ];
  }
  const target = new RenderTarget(options.width, options.height);
  target.texture.colorSpace = SRGBColorSpace;
  disposers.push(() => target.dispose());
  return [frameSubject('WebGPU Ocean, defaults, WebGPU backend', sea({}), renderer, viewCamera(options), finish, target)];
}

/** Makes this page's subjects for `options`; their labels. */
async function start(options: SessionOptions): Promise<string[]> {
  stop();
  subjects = await (backend === 'webgpu' ? webgpuSubjects(options) : webglSubjects(options));
  return subjects.map(({ label }) => label);
}

/** `warmup` untimed rounds, then `rounds` timed; each subject's samples (ms) of these rounds. */
async function run(warmup: number, rounds: number): Promise<Record<string, number[]>> {
  for (const subject of subjects) subject.samples = [];
  await timeRounds((subject) => subject.finish(), subjects, { warmup, rounds }, (subject, t) => subject.step(t));
  return Object.fromEntries(subjects.map(({ label, samples }) => [label, samples]));
}

/** Frees the session's Oceans, targets and renderers. */
function stop(): void {
  for (const dispose of disposers.reverse()) dispose();
  disposers = [];
  subjects = [];
}

declare global {
  interface Window {
    webgpuBench: { backend: string; start: typeof start; run: typeof run; stop: typeof stop };
  }
}
window.webgpuBench = { backend, start, run, stop };
document.title = 'ready';
