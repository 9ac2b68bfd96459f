// A group of `npm run bench` (bench/run.mjs):
//
//   parameter-change  (with queries) a new wind set on the GPU path at N = 256 with the default
//                cascades, as the app's panel sets it: the main thread's time in setParameters and
//                in each of the two frames after it (update, 5 points' heightAt and normalAt, render
//                at 1280x720), each from an idle GPU; `ms` is the median of their sum.
import { withTimeout } from '../lib/browser.mjs';
import { emit, log } from '../lib/output.mjs';
import { BROWSER_STEP_TIMEOUT_MS, CASCADE_N } from '../lib/settings.mjs';
import { stats } from '../lib/stats.mjs';

/** The parameter-change row, on the frame page (bench/pages/frame.html). */
export async function browser({ page, results }) {
  log('parameter change: setParameters (new wind) and the next two frames, GPU path, N = 256');
  const run = await withTimeout(
    page.evaluate((o) => window.frameBench.parameterChanges(o), { resolution: CASCADE_N, rounds: 9, width: 1280, height: 720 }),
    BROWSER_STEP_TIMEOUT_MS,
    'the parameter change',
  );
  const totals = run.setMs.map((ms, i) => ms + run.firstFrameMs[i] + run.secondFrameMs[i]);
  results.parameterChange = stats(totals).ms;
  emit({
    bench: 'parameter-change',
    N: CASCADE_N,
    setParametersMs: stats(run.setMs).ms,
    firstFrameMs: stats(run.firstFrameMs).ms,
    secondFrameMs: stats(run.secondFrameMs).ms,
    ...stats(totals),
  });
}
