// A group of `npm run bench` (bench/run.mjs):
//
//   queries      1000 points in one heightsAt / velocitiesAt call from the page's main thread, the
//                fields for the time already computed (firstCallMs: the call that computes them);
//                heightsAt again over a seabed (a 1:50 beach under the points: shoaling and breaking).
import { withTimeout } from '../lib/browser.mjs';
import { emit, log } from '../lib/output.mjs';
import { BROWSER_STEP_TIMEOUT_MS, CASCADE_N } from '../lib/settings.mjs';
import { stats } from '../lib/stats.mjs';

/** The queries rows, on the frame page (bench/pages/frame.html). */
export async function browser({ page, results }) {
  log('queries: 1000 points, heightsAt and velocitiesAt from the main thread');
  const queryRuns = await withTimeout(
    page.evaluate((o) => window.frameBench.queries(o), { resolution: CASCADE_N, points: 1000, rounds: 30 }),
    BROWSER_STEP_TIMEOUT_MS,
    'the queries benchmark',
  );
  results.queries = {};
  for (const [name, { firstMs, samples }] of Object.entries(queryRuns)) {
    const row = stats(samples);
    results.queries[name] = row.ms;
    emit({ bench: 'queries', query: name, points: 1000, N: CASCADE_N, firstCallMs: firstMs, ...row, target: name === 'heightsAt' ? 2 : null });
  }
}
