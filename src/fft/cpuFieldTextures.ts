/**
 * The JS path's output as textures in the layout of waveFieldLayout.ts, so the surface material
 * samples the same thing whichever path runs. The fields are computed either right here
 * (`worker: false`: the result is in the textures as soon as update() returns) or in a Web Worker
 * (the page stays responsive; the textures show the latest finished time, usually one frame
 * behind). Owns its two DataTextures and the worker.
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

export class CpuFieldTextures {
  readonly displacement: DataTexture;
  readonly derivatives: DataTexture;
  private readonly fields: CpuWaveFields | null = null;
  private readonly worker: Worker | null = null;
  private inFlight = false;
  /** Arrays to send to the worker for its next result (they travel back and forth, never reallocated). */
  private spare: { displacement: Float32Array; derivatives: Float32Array } | null;

  constructor(renderer: WebGLRenderer, spectrum: InitialSpectrum, useWorker: boolean) {
    const n = spectrum.resolution;
    const filterable = renderer.extensions.has('OES_texture_float_linear');
    // Without a worker the textures show CpuWaveFields' own arrays: nothing is copied.
    this.fields = useWorker ? null : new CpuWaveFields(spectrum);
    const [displacement, derivatives] = FIELD_TEXTURES.map((name) =>
      fieldTexture(this.fields?.[name] ?? new Float32Array(4 * n * n), n, filterable, name),
    );
    this.displacement = displacement;
    this.derivatives = derivatives;
    this.spare = useWorker ? { displacement: new Float32Array(4 * n * n), derivatives: new Float32Array(4 * n * n) } : null;
    if (useWorker) {
      this.worker = new Worker(new URL('./waveFieldWorker.ts', import.meta.url), { type: 'module' });
      this.worker.onmessage = (event: MessageEvent<WorkerReply>) => this.receive(event.data);
      this.worker.onerror = (event) => console.error(`three-fft-ocean: the JS field worker failed: ${event.message}`);
      const request: WorkerRequest = { type: 'spectrum', spectrum };
      this.worker.postMessage(request);
    }
  }

  update(t: number): void {
    if (this.fields) {
      this.fields.update(t);
      this.markUpdated();
      return;
    }
    if (this.inFlight || !this.spare || !this.worker) return; // drop frames while the worker is busy
    const { displacement, derivatives } = this.spare;
    const request: WorkerRequest = { type: 'update', t, displacement, derivatives };
    this.worker.postMessage(request, [displacement.buffer, derivatives.buffer]);
    this.spare = null;
    this.inFlight = true;
  }

  private receive(reply: WorkerReply): void {
    this.inFlight = false;
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
    this.displacement.needsUpdate = true;
    this.derivatives.needsUpdate = true;
  }

  dispose(): void {
    this.worker?.terminate();
    this.displacement.dispose();
    this.derivatives.dispose();
  }
}

function fieldTexture(data: Float32Array, n: number, filterable: boolean, name: string): DataTexture {
  const texture = new DataTexture(data, n, n, RGBAFormat, FloatType);
  texture.name = name;
  texture.wrapS = texture.wrapT = RepeatWrapping;
  texture.magFilter = filterable ? LinearFilter : NearestFilter;
  texture.minFilter = filterable ? LinearMipmapLinearFilter : NearestFilter;
  texture.generateMipmaps = filterable;
  return texture;
}
