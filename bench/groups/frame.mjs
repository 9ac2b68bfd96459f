// A group of `npm run bench` (bench/run.mjs):
//
//   frame        one frame of the Ocean (ocean.update(t), sky and surface) at 1280x720, from an
//                idle GPU to a 1-pixel readPixels of the canvas: at N = 256 with C = 1, 3 and 4
//                cascades (patchSizes as in CASCADE_SETS; C = 3 is the default sizes), interleaved
//                round by round, and at N = 512 with the default 3 cascades; then at N = 256 with
//                refractions 'scene' (the default: the scene drawn again without the sea, here
//                empty, and the sea's lookups into it) and 'sky', interleaved.
import { withTimeout } from '../lib/browser.mjs';
import { emit, log } from '../lib/output.mjs';
import { BROWSER_STEP_TIMEOUT_MS, CASCADE_COUNTS, CASCADE_N, CASCADE_SETS, FRAME_ROUNDS, FRAME_SIZE } from '../lib/settings.mjs';
import { stats } from '../lib/stats.mjs';

/**
 * window.frameBench.frames(options) in the frame page at FRAME_SIZE, 5 frames of warm-up and
 * FRAME_ROUNDS timed; `options` gives resolution, patchSizeSets (and for the living group variants).
 * Times out after `steps` browser steps. Shared with bench/groups/living.mjs.
 */
export function timeFrames(page, options, steps, what) {
  return withTimeout(
    page.evaluate((o) => window.frameBench.frames(o), { ...FRAME_SIZE, warmup: 5, rounds: FRAME_ROUNDS, ...options }),
    steps * BROWSER_STEP_TIMEOUT_MS,
    what,
  );
}

/** The frame rows, on the frame page (bench/pages/frame.html). */
export async function browser({ page, results }) {
  const frameRuns = [
    { resolution: CASCADE_N, counts: CASCADE_COUNTS },
    { resolution: 512, counts: [null] }, // the default patch sizes (3 cascades)
  ];
  for (const { resolution: n, counts } of frameRuns) {
    const what = counts[0] === null ? 'default cascades' : `C = ${counts.join(', ')} cascades`;
    log(`frame N=${n}, ${what}: simulation + sky + surface at ${FRAME_SIZE.width}x${FRAME_SIZE.height}`);
    const frames = await timeFrames(
      page,
      { resolution: n, patchSizeSets: counts.map((count) => (count === null ? undefined : CASCADE_SETS[count])) },
      counts.length,
      `the frame benchmark at N=${n}`,
    );
    for (const frame of frames) {
      const row = stats(frame.samples);
      if (n === CASCADE_N) results.frameByCascades[frame.cascades] = row.ms;
      // frameMs256At1280x720 has always been the 3-cascade frame (CASCADE_SETS[3], the default sizes).
      if (n !== CASCADE_N || frame.cascades === 3) results.frame[n] = row.ms;
      emit({
        bench: 'frame',
        N: n,
        cascades: frame.cascades,
        patchSizes: frame.patchSizes,
        size: `${FRAME_SIZE.width}x${FRAME_SIZE.height}`,
        path: frame.path,
        ...row,
        drawCalls: frame.calls,
        vertices: frame.vertices,
        triangles: frame.triangles,
        simulationPasses: frame.simulationPasses,
        timer: 'readpixels-sync',
      });
    }
  }
  log(`frame N=${CASCADE_N}, refractions scene and sky at ${FRAME_SIZE.width}x${FRAME_SIZE.height}`);
  const refractions = await timeFrames(
    page,
    {
      resolution: CASCADE_N,
      patchSizeSets: [],
      variants: ['scene', 'sky'].map((source) => ({ label: source, options: { refractions: source }, activeLocalWaves: false })),
    },
    2,
    'the refractions benchmark',
  );
  for (const frame of refractions) {
    emit({ bench: 'refractions', N: CASCADE_N, refractions: frame.label, size: `${FRAME_SIZE.width}x${FRAME_SIZE.height}`, path: frame.path, ...stats(frame.samples), drawCalls: frame.calls, timer: 'readpixels-sync' });
  }
}
