/**
 * Web Worker that runs the JS simulation path off the main thread (used by CpuFieldTextures).
 * The result arrays are transferred both ways, so a frame allocates nothing.
 */
import { CpuWaveFields } from './cpuWaveFields';
import type { InitialSpectrum } from '../spectrum/initialSpectrum';

export type WorkerRequest =
  | { type: 'spectrum'; spectrum: InitialSpectrum }
  | { type: 'update'; t: number; displacement: Float32Array; derivatives: Float32Array };

export interface WorkerReply {
  t: number;
  displacement: Float32Array;
  derivatives: Float32Array;
}

let fields: CpuWaveFields | null = null;

self.onmessage = (event: MessageEvent<WorkerRequest>) => {
  const request = event.data;
  if (request.type === 'spectrum') {
    fields = new CpuWaveFields(request.spectrum);
    return;
  }
  if (!fields) throw new Error('waveFieldWorker: update before spectrum');
  fields.update(request.t);
  request.displacement.set(fields.displacement);
  request.derivatives.set(fields.derivatives);
  const reply: WorkerReply = { t: request.t, displacement: request.displacement, derivatives: request.derivatives };
  (self as unknown as Worker).postMessage(reply, [reply.displacement.buffer, reply.derivatives.buffer]);
};
