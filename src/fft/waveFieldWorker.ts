/**
 * Web Worker that computes one cascade's JS fields off the main thread (driven by fieldWorker.ts):
 * the fields at the time asked, and with `velocities` their time derivative too (for the queries).
 * The result arrays are transferred both ways, so a frame allocates nothing.
 */
import { CpuWaveFields, type SpectrumForFields } from './cpuWaveFields';

/** A set of field arrays in the layout of waveFieldLayout.ts; `velocities` as CpuWaveFields.updateVelocities, or null. */
export interface FieldArrays {
  displacement: Float32Array;
  derivatives: Float32Array;
  velocities: Float32Array | null;
}

export type WorkerRequest = { type: 'spectrum'; spectrum: SpectrumForFields } | ({ type: 'update'; t: number } & FieldArrays);

export interface WorkerReply extends FieldArrays {
  t: number;
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
  request.velocities?.set(fields.updateVelocities(request.t));
  const { t, displacement, derivatives, velocities } = request;
  const reply: WorkerReply = { t, displacement, derivatives, velocities };
  (self as unknown as Worker).postMessage(reply, [displacement.buffer, derivatives.buffer, ...(velocities ? [velocities.buffer] : [])]);
};
