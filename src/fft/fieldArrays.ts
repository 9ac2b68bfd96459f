/**
 * The arrays a field worker (waveFieldWorker.ts) fills and hands over, and the main thread
 * (fieldWorker.ts) hands back: shared by both sides, apart from the worker script, which a page
 * must not import.
 */

/** A set of field arrays in the layout of waveFieldLayout.ts; `velocities` as CpuWaveFields.updateVelocities, or null. */
export interface FieldArrays {
  displacement: Float32Array;
  derivatives: Float32Array;
  velocities: Float32Array | null;
}

/** The buffers of a set of arrays, to transfer with the message that carries them. */
export function buffersOf(arrays: FieldArrays): ArrayBuffer[] {
  const { displacement, derivatives, velocities } = arrays;
  return [displacement, derivatives, ...(velocities ? [velocities] : [])].map((array) => array.buffer as ArrayBuffer);
}
