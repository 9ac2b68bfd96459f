/**
 * Marks the browser tests scripts/test-three-range.mjs also runs against the oldest supported
 * three.js release (its --grep): those that read back what the GPU computed or drew, where a
 * three.js release that renders differently shows. Few enough to take about two minutes there.
 */
export const ALSO_ON_OLDEST_THREE = { tag: '@three-range' };
