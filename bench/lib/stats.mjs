// Statistics of timed samples: medians and quartiles, ratios, and interleaved timing in Node.

/** Timed runs at least, per task of timeInterleaved. */
const MIN_RUNS = 30;

function quantile(sorted, q) {
  const position = (sorted.length - 1) * q;
  const low = Math.floor(position);
  const high = Math.ceil(position);
  return sorted[low] + (sorted[high] - sorted[low]) * (position - low);
}

/** Median and quartiles of samples in ms, rounded to 0.1 µs. */
export function stats(samples) {
  const sorted = [...samples].sort((a, b) => a - b);
  const round = (ms) => Math.round(ms * 1e4) / 1e4;
  return {
    ms: round(quantile(sorted, 0.5)),
    runs: sorted.length,
    q1: round(quantile(sorted, 0.25)),
    q3: round(quantile(sorted, 0.75)),
  };
}

/** a / b to 3 decimals, or null unless both are positive. */
export const ratio = (a, b) => (a > 0 && b > 0 ? Math.round((a / b) * 1000) / 1000 : null);

/**
 * Warm-up, then timed rounds of each task in turn (interleaved, so machine noise hits them alike).
 * A task is { prepare(), run() }; prepare() is not timed. Warm-up lasts at least 5 rounds and
 * 300 ms; the timed rounds number at least MIN_RUNS and about budgetMs in total, at most 400.
 */
export function timeInterleaved(tasks, budgetMs) {
  const timeOnce = (task) => {
    task.prepare();
    const start = performance.now();
    task.run();
    return performance.now() - start;
  };
  const warmupStart = performance.now();
  const warmup = tasks.map(() => []);
  for (let round = 0; round < 500 && (round < 5 || performance.now() - warmupStart < 300); round++) {
    tasks.forEach((task, i) => warmup[i].push(timeOnce(task)));
  }
  const perRound = warmup.reduce((sum, samples) => sum + stats(samples.slice(-5)).ms, 0);
  const rounds = Math.max(MIN_RUNS, Math.min(400, Math.floor(budgetMs / Math.max(perRound, 1e-3))));
  const samples = tasks.map(() => []);
  for (let round = 0; round < rounds; round++) tasks.forEach((task, i) => samples[i].push(timeOnce(task)));
  return samples;
}

