// A group of `npm run bench` (bench/run.mjs):
//
//   reflections  the frame at N = 256 with the default cascades and five boxes ahead of the camera,
//                with reflections 'sky' and 'scene' (src/render/sceneReflection.ts: the scene
//                rendered again from the mirrored camera at half the drawing buffer's size),
//                interleaved; reflections-cost gives the ratio.
import { emit, log } from '../lib/output.mjs';
import { CASCADE_N, FRAME_SIZE } from '../lib/settings.mjs';
import { stats } from '../lib/stats.mjs';
import { timeFrames } from './frame.mjs';

/** The reflections and reflections-cost rows, on the frame page (bench/pages/frame.html). */
export async function browser({ page, results }) {
  log(`reflections N=${CASCADE_N}: sky, scene at ${FRAME_SIZE.width}x${FRAME_SIZE.height}`);
  const frames = await timeFrames(
    page,
    {
      resolution: CASCADE_N,
      patchSizeSets: [],
      variants: [
        { label: 'sky', options: { reflections: 'sky', localWaves: false }, activeLocalWaves: false, boxes: true },
        { label: 'scene', options: { reflections: 'scene', localWaves: false }, activeLocalWaves: false, boxes: true },
      ],
    },
    2,
    'the reflections benchmark',
  );
  const ms = {};
  for (const frame of frames) {
    const row = stats(frame.samples);
    ms[frame.label] = row.ms;
    emit({ bench: 'reflections', N: CASCADE_N, reflections: frame.label, size: `${FRAME_SIZE.width}x${FRAME_SIZE.height}`, path: frame.path, ...row, timer: 'readpixels-sync' });
  }
  results.reflectionsCost = { sceneOverSky: ms.scene / ms.sky };
  emit({ bench: 'reflections-cost', ...results.reflectionsCost });
}
