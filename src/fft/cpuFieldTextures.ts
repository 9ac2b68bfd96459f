/**
 * The JS path's output as textures in the layout of waveFieldLayout.ts, so the surface material
 * samples the same thing whichever path runs. The fields are computed either right here
 * (`worker: false`: the result is in the textures as soon as update() returns) or in a Web Worker
 * (the page stays responsive; the textures show the latest finished time, usually one frame
 * behind). Owns its two DataTextures and the worker.
 *
 * A worker can fail: an exception in it, a script that cannot load, one terminated from outside
 * (it then just never answers), or workers blocked altogether (a Content-Security-Policy without
 * worker-src). A failed worker is replaced by a new one; a worker that cannot be made, or that
 * fails before its first answer, or the WORKER_REPLACEMENTS-th failure, moves the computation onto
 * the main thread for good. `workerFault` then says why (OceanSimulation reports it as its path).
 */
import {
  DataTexture,
  FloatType,
  LinearFilter,
  LinearMipmapLinearFilter,
  NearestFilter,
  RepeatWrapping,
  RGBAFormat,
  type WebGLRenderer,
} from 'three';
import { CpuWaveFields } from './cpuWaveFields';
import type { InitialSpectrum } from '../spectrum/initialSpectrum';
import { FIELD_TEXTURES } from './waveFieldLayout';
import type { WorkerReply, WorkerRequest } from './waveFieldWorker';

/** A worker that has not answered a request after this long (ms) counts as dead. */
const WORKER_TIMEOUT_MS = 4000;
/** Failed workers replaced before the main thread takes over. */
const WORKER_REPLACEMENTS = 3;

export class CpuFieldTextures {
  readonly displacement: DataTexture;
  readonly derivatives: DataTexture;
  private fields: CpuWaveFields | null = null;
  private worker: Worker | null = null;
  /** When the request in flight was sent (performance.now()), or null when none is. */
  private sentAt: number | null = null;
  /** Whether the current worker has answered yet (one that never did is taken to be blocked). */
  private answered = false;
  private replacements = 0;
  private fault: string | null = null;
  /** Whether the mipmap levels are computed in JS (float textures that filter but cannot be rendered to). */
  private readonly levelsInJs: boolean;
  /** Arrays to send to the worker for its next result (they travel back and forth, never reallocated). */
  private spare: { displacement: Float32Array; derivatives: Float32Array } | null;

  constructor(
    renderer: WebGLRenderer,
    private readonly spectrum: InitialSpectrum,
    useWorker: boolean,
  ) {
    const n = spectrum.resolution;
    const filterable = renderer.extensions.has('OES_texture_float_linear');
    // generateMipmap renders into the texture: RGBA32F must also be renderable (EXT_color_buffer_float),
    // or it fails (GL_INVALID_OPERATION) and the levels hold garbage. There the levels are made
    // here, by the same 2×2 box filter, and uploaded with the texture.
    const mipmapped = filterable && renderer.extensions.has('EXT_color_buffer_float');
    this.levelsInJs = filterable && !mipmapped;
    // Without a worker the textures show CpuWaveFields' own arrays: nothing is copied.
    this.fields = useWorker ? null : new CpuWaveFields(spectrum);
    const [displacement, derivatives] = FIELD_TEXTURES.map((name) =>
      fieldTexture(this.fields?.[name] ?? new Float32Array(4 * n * n), n, filterable, mipmapped, name),
    );
    this.displacement = displacement;
    this.derivatives = derivatives;
    this.spare = null;
    if (useWorker) this.startWorker();
  }

  /**
   * Why the fields are computed on the main thread although a worker was asked for (the worker
   * failed, or workers are blocked), or null.
   */
  get workerFault(): string | null {
    return this.fault;
  }

  update(t: number): void {
    if (this.fields) {
      this.fields.update(t);
      this.markUpdated();
      return;
    }
    if (this.sentAt !== null) {
      // Drop frames while the worker is busy; one silent for too long has died.
      if (performance.now() - this.sentAt > WORKER_TIMEOUT_MS) this.workerFailed(`it did not answer in ${WORKER_TIMEOUT_MS / 1000} s`);
      return;
    }
    const { displacement, derivatives } = this.spare!;
    const request: WorkerRequest = { type: 'update', t, displacement, derivatives };
    this.worker!.postMessage(request, [displacement.buffer, derivatives.buffer]);
    this.spare = null;
    this.sentAt = performance.now();
  }

  /** A new worker, given the spectrum and new arrays (a dead worker keeps the ones it was sent). */
  private startWorker(): void {
    const n = this.spectrum.resolution;
    this.spare = { displacement: new Float32Array(4 * n * n), derivatives: new Float32Array(4 * n * n) };
    this.sentAt = null;
    this.answered = false;
    let worker: Worker;
    try {
      worker = new Worker(new URL('./waveFieldWorker.ts', import.meta.url), { type: 'module' });
    } catch (error) {
      this.runOnMainThread(`workers are blocked here (${error instanceof Error ? error.message : String(error)})`);
      return;
    }
    worker.onmessage = (event: MessageEvent<WorkerReply>) => this.receive(event.data);
    worker.onerror = (event) => {
      event.preventDefault(); // handled here, not an uncaught error of the page
      this.workerFailed(event.message || 'its script failed to load');
    };
    worker.onmessageerror = () => this.workerFailed('a message could not be read');
    const request: WorkerRequest = { type: 'spectrum', spectrum: this.spectrum };
    worker.postMessage(request);
    this.worker = worker;
  }

  private workerFailed(why: string): void {
    this.worker?.terminate();
    this.worker = null;
    if (!this.answered) {
      this.runOnMainThread(`the JS worker failed before its first answer: ${why}`);
    } else if (++this.replacements > WORKER_REPLACEMENTS) {
      this.runOnMainThread(`the JS worker failed ${this.replacements} times, last: ${why}`);
    } else {
      console.warn(`three-fft-ocean: the JS worker failed (${why}); replaced by a new one.`);
      this.startWorker();
    }
  }

  /** From now on the fields are computed here, in the arrays the textures show. */
  private runOnMainThread(fault: string): void {
    this.fault = fault;
    console.warn(`three-fft-ocean: ${fault}; the JS path runs on the main thread.`);
    this.fields = new CpuWaveFields(this.spectrum);
    this.displacement.image.data = this.fields.displacement;
    this.derivatives.image.data = this.fields.derivatives;
    this.spare = null;
    this.sentAt = null;
  }

  private receive(reply: WorkerReply): void {
    this.sentAt = null;
    this.answered = true;
    // Swap: the finished arrays go into the textures, the ones they held go back out next time.
    this.spare = this.shownFields;
    this.displacement.image.data = reply.displacement;
    this.derivatives.image.data = reply.derivatives;
    this.markUpdated();
  }

  /** The arrays the textures show (the latest finished time). */
  get shownFields(): { displacement: Float32Array; derivatives: Float32Array } {
    return { displacement: this.displacement.image.data as Float32Array, derivatives: this.derivatives.image.data as Float32Array };
  }

  private markUpdated(): void {
    for (const texture of [this.displacement, this.derivatives]) {
      if (this.levelsInJs) setMipmapLevels(texture);
      texture.needsUpdate = true;
    }
  }

  dispose(): void {
    this.worker?.terminate();
    this.displacement.dispose();
    this.derivatives.dispose();
  }
}

/**
 * The texture's mipmap chain down to 1×1, from its image: each level the mean of 2×2 texels of the
 * one above, wrapping (the fields repeat), as generateMipmap's box filter does. Reuses the levels'
 * arrays from one update to the next.
 */
function setMipmapLevels(texture: DataTexture): void {
  const data = texture.image.data as Float32Array;
  let size = texture.image.width;
  const levels = texture.mipmaps as { data: Float32Array; width: number; height: number }[];
  levels[0] = { data, width: size, height: size };
  for (let level = 1; size > 1; level++) {
    const above = levels[level - 1].data;
    const half = size / 2;
    if (levels[level]?.width !== half) levels[level] = { data: new Float32Array(4 * half * half), width: half, height: half };
    const below = levels[level].data;
    for (let j = 0; j < half; j++) {
      for (let i = 0; i < half; i++) {
        const a = 4 * (2 * j * size + 2 * i);
        const b = a + 4 * size;
        for (let c = 0; c < 4; c++) below[4 * (j * half + i) + c] = 0.25 * (above[a + c] + above[a + 4 + c] + above[b + c] + above[b + 4 + c]);
      }
    }
    size = half;
  }
}

function fieldTexture(data: Float32Array, n: number, filterable: boolean, mipmapped: boolean, name: string): DataTexture {
  const texture = new DataTexture(data, n, n, RGBAFormat, FloatType);
  texture.name = name;
  texture.wrapS = texture.wrapT = RepeatWrapping;
  texture.magFilter = filterable ? LinearFilter : NearestFilter;
  // Filterable: mipmapped, by the GPU where it can render to the texture, else by setMipmapLevels.
  texture.minFilter = filterable ? LinearMipmapLinearFilter : NearestFilter;
  texture.generateMipmaps = mipmapped;
  if (filterable && !mipmapped) setMipmapLevels(texture);
  return texture;
}
