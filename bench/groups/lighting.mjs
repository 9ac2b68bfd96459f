// A group of `npm run bench` (bench/run.mjs):
//
//   lighting     what issue 26's lighting adds to the 'high' frame at 1280x720 (pixel ratio 1, 4x
//                MSAA on the canvas, N = 256, the 3 default cascades; the frame page, bench/pages/frame.ts),
//                four variants interleaved round by round: the default sea (12 m/s, force 6) whole,
//                and with its sub-pixel slope light left out (the six slope taps of
//                shaders/surface/slopeTaps.glsl made one mirror tap, no crest glow:
//                bench/pages/lightingCost.ts edits the shader on the bench page, the shipped code has
//                no switch for it); a force 9 sea (23 m/s) whole, and with its streaks and spray off
//                through their own uniforms (what they are below force 7 and 9). slope-light-cost is
//                whole over without (issue 26: at most 1.10); beaufort-look-cost the same at force 9.
//                The Beaufort look costs nothing below force 7 by design (a uniform branch). Not left
//                out: the unresolved slope variance's terms in the glint (one microfacet lobe where
//                a Phong lobe was) and the foam model, which have no such seam.
//                `--lighting-rounds=<n>` times n frames of each (FRAME_ROUNDS by default).
import { emit, log } from '../lib/output.mjs';
import { FRAME_ROUNDS, FRAME_SIZE } from '../lib/settings.mjs';
import { ratio, stats } from '../lib/stats.mjs';
import { timeFrames } from './frame.mjs';

const VARIANTS = [
  { label: 'whole', options: {}, activeLocalWaves: false },
  { label: 'without slope light', options: {}, activeLocalWaves: false, surface: 'without slope light' },
  { label: 'force 9, whole', options: { windSpeed: 23 }, activeLocalWaves: false },
  { label: 'force 9, without streaks and spray', options: { windSpeed: 23 }, activeLocalWaves: false, surface: 'without Beaufort look' },
];

/** The lighting rows, on the frame page; `lightingRounds` (--lighting-rounds) frames of each. */
export async function browser({ page, results, lightingRounds = FRAME_ROUNDS }) {
  const size = `${FRAME_SIZE.width}x${FRAME_SIZE.height}`;
  log(`lighting at ${size}, 'high' (N = 256, 4x MSAA): ${VARIANTS.map(({ label }) => label).join('; ')}`);
  const frames = await timeFrames(page, { resolution: 256, patchSizeSets: [], antialias: true, rounds: lightingRounds, variants: VARIANTS }, VARIANTS.length, 'the lighting benchmark');
  const ms = {};
  for (const frame of frames) {
    const row = stats(frame.samples);
    ms[frame.label] = row.ms;
    emit({ bench: 'lighting', variant: frame.label, N: 256, size, msaa: 4, path: frame.path, ...row, timer: 'readpixels-sync' });
  }
  results.lighting = {
    slopeLightCost: ratio(ms.whole, ms['without slope light']),
    beaufortLookCostAtForce9: ratio(ms['force 9, whole'], ms['force 9, without streaks and spray']),
  };
  emit({ bench: 'lighting-cost', size, slopeLightCost: results.lighting.slopeLightCost, target: 1.1, beaufortLookCostAtForce9: results.lighting.beaufortLookCostAtForce9 });
}
