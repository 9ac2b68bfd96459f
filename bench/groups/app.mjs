// A group of `npm run bench` (bench/run.mjs):
//
//   app          the app page as a user opens it (quality 'auto', after it adapted) and at each
//                fixed quality level, 1280x720: the median time between frames and the fps, with
//                the level's pixel ratio, MSAA, N and cascade count.
//                With --compare, dli/waves is timed right after the app as opened (bench/groups/compare.mjs).
import { frameIntervals, withTimeout } from '../lib/browser.mjs';
import { emit, log } from '../lib/output.mjs';
import { APP_FRAMES, APP_SETTLE_SECONDS, BROWSER_STEP_TIMEOUT_MS, FRAME_SIZE } from '../lib/settings.mjs';
import { stats } from '../lib/stats.mjs';
import * as compare from './compare.mjs';

/** A fixed quality level warms up this long before it is timed, s. */
const APP_WARMUP_SECONDS = 5;

/**
 * The app as a user opens it (index.html, no URL parameters: its MSAA, panel, status line and
 * quality 'auto'), after APP_SETTLE_SECONDS to adapt, then at each fixed quality level, at
 * FRAME_SIZE: the median real time between frames (requestAnimationFrame), what users see.
 */
export async function browser(context) {
  const { browser, server, port, results } = context;
  const { QUALITY_LEVELS } = await server.ssrLoadModule('/src/runtime/adaptiveQuality.ts');
  const appPage = await browser.newPage({ viewport: FRAME_SIZE });
  appPage.on('pageerror', (error) => log(`app page error: ${error.message}`));
  try {
    for (const quality of ['as opened', ...QUALITY_LEVELS]) {
      log(`the app at ${FRAME_SIZE.width}x${FRAME_SIZE.height}, quality ${quality}`);
      // A fresh dev server compiles the app's modules at the first visit: more than the default 30 s on a busy machine.
      await appPage.goto(`http://127.0.0.1:${port}/${quality === 'as opened' ? '' : `?quality=${quality}`}`, { timeout: 120_000 });
      await appPage.waitForFunction(() => window.oceanApp !== undefined, null, { timeout: 60_000 });
      await appPage.waitForTimeout(1000 * (quality === 'as opened' ? APP_SETTLE_SECONDS : APP_WARMUP_SECONDS));
      const samples = await withTimeout(appPage.evaluate(frameIntervals, APP_FRAMES), BROWSER_STEP_TIMEOUT_MS, `the app at quality ${quality}`);
      const run = await appPage.evaluate(() => {
        const app = window.oceanApp;
        return {
          level: app.quality.level,
          pixelRatio: app.renderer.getPixelRatio(),
          msaa: app.output.msaa,
          resolution: app.ocean.parameters.resolution,
          cascades: app.ocean.parameters.patchSizes.length,
          path: app.ocean.simulation.path,
        };
      });
      const row = stats(samples);
      results.app[quality] = { ms: row.ms, fps: 1000 / row.ms, level: run.level, N: run.resolution };
      emit({
        bench: 'app',
        quality,
        level: run.level,
        size: `${FRAME_SIZE.width}x${FRAME_SIZE.height}`,
        fps: Math.round(10000 / row.ms) / 10,
        pixelRatio: run.pixelRatio,
        msaa: run.msaa,
        N: run.resolution,
        cascades: run.cascades,
        path: run.path,
        ...row,
      });
      // The comparison right after the app as opened, so that the two share the machine's load.
      if (quality === 'as opened') await compare.browser(context, appPage);
    }
    compare.emitRatio(results);
  } finally {
    await appPage.close();
  }
}
