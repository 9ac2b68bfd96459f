// A group of `npm run bench` (bench/run.mjs), always printed after the others:
//
//   targets      the targets next to the figures (reported, never asserted): per update of
//                three 256² cascades JS ≤ 9 ms and GPU ≤ 30 ms; a frame with three cascades
//                ≤ 100 ms at 1280x720.
import { emit } from '../lib/output.mjs';
import { CASCADE_N, FRAME_SIZE } from '../lib/settings.mjs';

const TARGETS = { jsCascades3Ms256: 9, gpuCascades3Ms256: 30, frameMs256Cascades3: 100 };

/** The GPU path's ms for `count` cascades of the cascades group: the timer query, else readPixels; null without. */
export const gpuCascades = (results, count) => results.gpuCascades[count]?.timerQuery ?? results.gpuCascades[count]?.readPixels ?? null;
const target = (ms, limit) => ({ ms, target: limit, within: ms === null ? null : ms <= limit });

/** The targets row, from the figures in `results` (null where their group did not run). */
export function emitTargets(results) {
  emit({
    bench: 'targets',
    N: CASCADE_N,
    cascades: 3,
    jsMs: target(results.jsCascades[3] ?? null, TARGETS.jsCascades3Ms256),
    gpuMs: target(gpuCascades(results, 3), TARGETS.gpuCascades3Ms256),
    frameMs: target(results.frameByCascades[3] ?? null, TARGETS.frameMs256Cascades3),
    frameSize: `${FRAME_SIZE.width}x${FRAME_SIZE.height}`,
  });
}
