// A group of `npm run bench` (bench/run.mjs):
//
//   query-frames heightAt and normalAt at 5 points a frame (a boat and four buoys) on the GPU path at
//                N = 256, 512, 1024, each in a page of its own, frames of 50 ms with steps of 1/60 s, from the first frame after
//                the ocean is built: ms and quartiles of the calls after 40 frames (the query workers
//                started), the calls over 1 ms over all frames (goal: none) and within the 40, the
//                first frame's calls together, how often fields were computed here after the 40,
//                and a control: after each call a fixed few microseconds of arithmetic, timed, whose
//                calls over 1 ms count the times the machine held the main thread up anyway. Each
//                call runs in a task of its own, traced: the `Cpu` figures count the main thread's
//                CPU time in it (at most the task's thread time), where other threads cannot hold
//                it up (firstCallCpuMs: the first call, which compiles the code).
//
// Run with the queries group; `--query-frames=256` (a comma-separated list) sets the grids.
import { openReady, withTimeout } from '../lib/browser.mjs';
import { emit, log } from '../lib/output.mjs';
import { BROWSER_STEP_TIMEOUT_MS } from '../lib/settings.mjs';
import { stats } from '../lib/stats.mjs';

/**
 * Each call's main-thread CPU time (ms), at most: the thread time of the task it ran in (the trace's
 * FunctionCall around its `<kind>-call-<i>` mark, bench/pages/frame.ts), or its wall time
 * `wallMs[i]` where that is less (the task also makes the mark and queues the next). A call whose
 * wall time is long and CPU time short was held up by other threads, not by its own work.
 */
function callThreadTimes(traceEvents, kind, wallMs) {
  const marks = new Map();
  const markName = new RegExp(`^${kind}-call-(\\d+)$`);
  for (const event of traceEvents) {
    const match = markName.exec(event.name);
    if (match) marks.set(Number(match[1]), event);
  }
  const tasks = traceEvents.filter((event) => event.name === 'FunctionCall' && event.ph === 'X');
  return wallMs.map((ms, i) => {
    const mark = marks.get(i);
    const task = mark && tasks.find((t) => t.tid === mark.tid && t.ts <= mark.ts && mark.ts <= t.ts + t.dur);
    if (!task) throw new Error(`the trace has no task around ${kind} call ${i}`);
    return Math.min(ms, task.tdur / 1000);
  });
}

/** The query-frames rows at each grid of `queryFrameResolutions`, each in a page of its own, traced. */
export async function browser({ browser, port, queryFrameResolutions, results }) {
  // As an app asks them: a few points a frame while the workers compute the fields.
  results.queryFrames = {};
  for (const resolution of queryFrameResolutions) {
    log(`query frames: heightAt and normalAt at 5 points a frame, GPU path, N = ${resolution}`);
    // In a page of its own, as an app's first ocean: its first query meets code no query compiled yet.
    const queryPage = await browser.newPage();
    await openReady(queryPage, port, 'frame.html');
    await browser.startTracing(queryPage, { categories: ['devtools.timeline', 'blink.user_timing'] });
    const run = await withTimeout(
      queryPage.evaluate((o) => window.frameBench.queryFrames(o), { resolution, warmUp: 40, frames: 60, frameMs: 50 }),
      BROWSER_STEP_TIMEOUT_MS,
      `the query frames at N = ${resolution}`,
    );
    const trace = JSON.parse((await browser.stopTracing()).toString()).traceEvents;
    await queryPage.close();
    const callCpuMs = callThreadTimes(trace, 'query', run.callMs);
    const controlCpuMs = callThreadTimes(trace, 'control', run.controlMs);
    const afterWarmUp = run.callMs.slice(run.warmUpCalls);
    const row = stats(afterWarmUp);
    const over1Ms = (times) => times.filter((ms) => ms > 1).length;
    const largestCallMs = Math.max(...run.callMs);
    const callsOver1Ms = over1Ms(run.callMs);
    const callsOver1MsCpu = over1Ms(callCpuMs);
    const controlCallsOver1Ms = over1Ms(run.controlMs);
    results.queryFrames[resolution] = { ms: row.ms, largestCallMs, callsOver1Ms, callsOver1MsCpu, controlCallsOver1Ms, firstFrameMs: run.firstFrameMs, computedHere: run.computedHere };
    emit({
      bench: 'query-frames',
      N: resolution,
      calls: run.callMs.length,
      ...row,
      largestCallMs,
      callsOver1Ms,
      callsOver1MsInWarmUp: over1Ms(run.callMs.slice(0, run.warmUpCalls)),
      largestCallCpuMs: Math.max(...callCpuMs),
      firstCallCpuMs: callCpuMs[0],
      callsOver1MsCpu,
      // Which: [frame, point, 'height' or 'normal', CPU ms] (bench/pages/frame.ts calls them in that order).
      callsOver1MsCpuAt: callCpuMs.flatMap((ms, i) => (ms > 1 ? [[Math.floor(i / 10), Math.floor(i / 2) % 5, i % 2 ? 'normal' : 'height', ms]] : [])),
      controlCalls: run.controlMs.length,
      controlCallsOver1Ms,
      controlLargestMs: Math.max(...run.controlMs),
      controlCallsOver1MsCpu: over1Ms(controlCpuMs),
      controlCallsOver1MsCpuAt: controlCpuMs.flatMap((ms, i) => (ms > 1 ? [[Math.floor(i / 10), ms]] : [])), // [frame, CPU ms]
      computedHereAfterWarmUp: run.computedHere,
      firstFrameMs: run.firstFrameMs,
      target: 'no call over 1 ms',
    });
  }
}
