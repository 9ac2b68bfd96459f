// A group of `npm run bench` (bench/run.mjs):
//
//   living       the same frame at N = 256 with the default cascades and a 20 m/s wind, without foam
//                and local waves ("bare"), with whitecap foam ("foam"), and with foam and local waves
//                (a 256² grid) stepping every frame (a hull circling, a stone each second: "foam+local-waves"),
//                interleaved; living-cost gives what foam and local waves add to the bare frame.
import { emit, log } from '../lib/output.mjs';
import { CASCADE_N, FRAME_SIZE } from '../lib/settings.mjs';
import { stats } from '../lib/stats.mjs';
import { timeFrames } from './frame.mjs';

/** The local-wave grid of the living-surface frame (the 256², of 1 m texels). */
const LOCAL_WAVES_N = 256;

/** The living and living-cost rows, on the frame page (bench/pages/frame.html). */
export async function browser({ page, results }) {
  log(`living surface N=${CASCADE_N}: bare, foam, foam and local waves at ${FRAME_SIZE.width}x${FRAME_SIZE.height}`);
  const living = await timeFrames(
    page,
    {
      resolution: CASCADE_N,
      patchSizeSets: [],
      variants: [
        { label: 'bare', options: { windSpeed: 20, foamAmount: 0, localWaves: false }, activeLocalWaves: false },
        { label: 'foam', options: { windSpeed: 20, localWaves: false }, activeLocalWaves: false },
        { label: 'foam+local-waves', options: { windSpeed: 20, localWaves: { resolution: LOCAL_WAVES_N } }, activeLocalWaves: true },
      ],
    },
    3,
    'the living-surface benchmark',
  );
  const livingMs = {};
  for (const frame of living) {
    const row = stats(frame.samples);
    livingMs[frame.label] = row.ms;
    emit({ bench: 'living', N: CASCADE_N, variant: frame.label, size: `${FRAME_SIZE.width}x${FRAME_SIZE.height}`, path: frame.path, ...row, timer: 'readpixels-sync' });
  }
  results.livingCost = { foamMs: livingMs.foam - livingMs.bare, foamAndLocalWavesMs: livingMs['foam+local-waves'] - livingMs.bare, targetMs: 15 };
  emit({ bench: 'living-cost', ...results.livingCost });
}
