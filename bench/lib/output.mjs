// Output: rows, one JSON object per line, on stdout; progress and errors on stderr.
import { stats } from './stats.mjs';

export const log = (message) => process.stderr.write(`bench: ${message}\n`);
export const emit = (row) => process.stdout.write(`${JSON.stringify(row)}\n`);

/**
 * GPU rows of one subject (the fields and cascades groups); `head` starts each row (bench, N, and
 * for cascades the count). Returns the medians: { timerQuery (null without the timer query), readPixels }.
 */
export function emitGpu(head, path, samples) {
  const passes = samples.passCount;
  if (samples.gpuTimerQuery) {
    const row = { ...head, path, ...stats(samples.gpuTimerQuery), passes, timer: 'timer-query' };
    if (samples.disjointDiscarded) row.disjointDiscarded = samples.disjointDiscarded;
    emit(row);
  }
  const row = stats(samples.gpuReadPixels);
  emit({ ...head, path, ...row, passes, timer: 'readpixels-sync', syncMs: stats(samples.syncOnly).ms });
  return { timerQuery: samples.gpuTimerQuery ? stats(samples.gpuTimerQuery).ms : null, readPixels: row.ms };
}
