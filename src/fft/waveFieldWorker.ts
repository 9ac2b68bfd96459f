/**
 * Web Worker that computes one cascade's JS fields off the main thread (driven by fieldWorker.ts),
 * from the spectrum it is sent or that it builds from the parameters: the fields at the time
 * asked, and with `velocities` their time derivative too (for the queries).
 * The result arrays are transferred both ways and reused, so a frame allocates nothing; arrays not
 * given back yet (the first requests) are made here, not on the main thread.
 */
import { CpuWaveFields, type SpectrumForFields } from './cpuWaveFields';
import { buffersOf, type FieldArrays } from './fieldArrays';
import { createCascadeSpectrum, type SpectrumOrigin } from '../spectrum/initialSpectrum';

/**
 * A cascade named by what makes it, for a worker to build itself: createCascadeSpectrum(params,
 * cascade, resolution), on a grid of `resolution` texels a side (its reducedSpectrum when below
 * the cascade's).
 */
export interface CascadeOrigin extends SpectrumOrigin {
  resolution: number;
}

export type WorkerRequest =
  | { type: 'spectrum'; spectrum: SpectrumForFields }
  | { type: 'cascade'; origin: CascadeOrigin }
  /** `spare`: arrays to fill (transferred), or null; `velocities`: whether to compute them. */
  | { type: 'update'; t: number; velocities: boolean; spare: FieldArrays | null };

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
  if (request.type === 'cascade') {
    const { params, cascade, resolution } = request.origin;
    fields = new CpuWaveFields(createCascadeSpectrum(params, cascade, resolution));
    return;
  }
  if (!fields) throw new Error('waveFieldWorker: update before spectrum');
  const { t, spare } = request;
  const length = fields.displacement.length;
  fields.update(t);
  const displacement = spare?.displacement ?? new Float32Array(length);
  const derivatives = spare?.derivatives ?? new Float32Array(length);
  displacement.set(fields.displacement);
  derivatives.set(fields.derivatives);
  let velocities: Float32Array | null = null;
  if (request.velocities) {
    velocities = spare?.velocities ?? new Float32Array(length);
    velocities.set(fields.updateVelocities(t));
  }
  const reply: WorkerReply = { t, displacement, derivatives, velocities };
  (self as unknown as Worker).postMessage(reply, buffersOf(reply));
};
