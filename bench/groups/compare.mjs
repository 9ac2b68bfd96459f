// A group of `npm run bench` (bench/run.mjs):
//
//   compare      With --compare=<dir> (or BENCH_COMPARE=<dir>), a checkout of David Li's WebGL
//                FFT ocean (git clone https://github.com/dli/waves; MIT, not part of this
//                repository) is served from <dir> on a static server of its own and timed the
//                same way, right after the app as opened: the row `compare` (subject dli/waves,
//                with the FFT grid N its page sets), and `compare-ratio` (app ms / dli/waves ms
//                for each app row; the goal is ≤ 0.5 for the app as opened). Its page must
//                visibly draw (a screenshot is checked and saved), or the row is an error.
//
// Run with the app group (bench/groups/app.mjs), right after the app as opened.
import { writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { PNG } from 'pngjs';
import { frameIntervals, withTimeout } from '../lib/browser.mjs';
import { emit, log } from '../lib/output.mjs';
import { freePort, serveStatic } from '../lib/servers.mjs';
import { APP_FRAMES, APP_SETTLE_SECONDS, BROWSER_STEP_TIMEOUT_MS, FRAME_SIZE } from '../lib/settings.mjs';
import { ratio, stats } from '../lib/stats.mjs';

/** The comparison ocean: David Li's WebGL FFT ocean, a static page (index.html and scripts). */
export const COMPARE_NAME = 'dli/waves';
export const COMPARE_CLONE = 'git clone https://github.com/dli/waves';
/** The app as opened must take at most this fraction of the comparison's frame time (issue 10). */
const COMPARE_GOAL_RATIO = 0.5;
/** At least this fraction of the comparison's screenshot must be coloured (not grey, white or black): its sea. */
const COMPARE_MIN_DRAWN = 0.05;

/**
 * The fraction of a PNG screenshot's pixels that are coloured: channels apart by more than 40 of
 * 255 (not white, black or grey). A sea drawn under WebGL is; a blank, black or error page is not.
 */
function colouredFraction(png) {
  const { data, width, height } = PNG.sync.read(png);
  let coloured = 0;
  for (let k = 0; k < data.length; k += 4) {
    const r = data[k];
    const g = data[k + 1];
    const b = data[k + 2];
    if (Math.max(r, g, b) - Math.min(r, g, b) > 40) coloured++;
  }
  return coloured / (width * height);
}

/**
 * dli/waves served from `compareDir` on a server of its own, timed like the app as opened: the same
 * browser, viewport, warm-up and number of frames (the app's page is blank meanwhile, so nothing
 * else draws). Requests off 127.0.0.1 (its page asks Google Fonts) are aborted. Returns the row.
 */
async function compareBenchmark({ browser, compareDir, firstPort }) {
  const port = await freePort(firstPort + 1);
  const server = await serveStatic(compareDir, port);
  const origin = `http://127.0.0.1:${port}/`;
  log(`${COMPARE_NAME} from ${compareDir} on ${origin} at ${FRAME_SIZE.width}x${FRAME_SIZE.height}`);
  const page = await browser.newPage({ viewport: FRAME_SIZE });
  page.on('pageerror', (error) => log(`${COMPARE_NAME} page error: ${error.message}`));
  try {
    await page.route('**/*', (route) => (route.request().url().startsWith(origin) ? route.continue() : route.abort()));
    await page.goto(origin);
    await page.waitForTimeout(1000 * APP_SETTLE_SECONDS);
    const samples = await withTimeout(page.evaluate(frameIntervals, APP_FRAMES), BROWSER_STEP_TIMEOUT_MS, COMPARE_NAME);
    // The page's own globals (shared.js): the FFT grid and the mesh it displaces; WebGL 1, whose
    // context it made on #simulator (getContext returns that one).
    const info = await page.evaluate(() => {
      const canvas = document.getElementById('simulator');
      const gl = canvas instanceof HTMLCanvasElement ? canvas.getContext('webgl') : null;
      const error = document.getElementById('error');
      return {
        N: typeof window.RESOLUTION === 'number' ? window.RESOLUTION : null,
        grid: typeof window.GEOMETRY_RESOLUTION === 'number' ? window.GEOMETRY_RESOLUTION : null,
        canvas: canvas instanceof HTMLCanvasElement ? `${canvas.width}x${canvas.height}` : null,
        webgl: gl === null ? null : gl.getParameter(gl.VERSION),
        contextLost: gl === null ? null : gl.isContextLost(),
        errorShown: error !== null && getComputedStyle(error).display !== 'none',
        devicePixelRatio,
      };
    });
    const screenshot = await page.screenshot();
    const shotPath = join(tmpdir(), 'bench-compare-dli-waves.png');
    await writeFile(shotPath, screenshot);
    const drawn = Math.round(colouredFraction(screenshot) * 1000) / 1000;
    log(`${COMPARE_NAME} screenshot: ${shotPath} (${(drawn * 100).toFixed(1)} % coloured pixels)`);
    if (info.errorShown || info.webgl === null || info.contextLost || drawn < COMPARE_MIN_DRAWN) {
      throw new Error(`${COMPARE_NAME} did not draw (${JSON.stringify(info)}, ${drawn} coloured): not a measurement; see ${shotPath}`);
    }
    const row = stats(samples);
    return {
      bench: 'compare',
      subject: COMPARE_NAME,
      size: `${FRAME_SIZE.width}x${FRAME_SIZE.height}`,
      fps: Math.round(10000 / row.ms) / 10,
      N: info.N,
      fft: info.N === null ? null : `one ${info.N}x${info.N} GPU FFT (WebGL 1, OES_texture_float)`,
      grid: info.grid === null ? null : `${info.grid}x${info.grid} vertices`,
      canvas: info.canvas,
      pixelRatio: info.devicePixelRatio,
      webgl: info.webgl,
      drawnFraction: drawn,
      ...row,
    };
  } finally {
    await page.close();
    await new Promise((resolveClose) => server.close(resolveClose));
  }
}

/**
 * The compare row, timed with the app's page `appPage` blank (the app stops drawing meanwhile), or
 * a message when no checkout was given (`compareDir` null); a failure is logged and kept in results.compare.
 */
export async function browser(context, appPage) {
  const { compareDir, results } = context;
  if (compareDir === null) {
    log(`compare ${COMPARE_NAME}: skipped; to time it beside the app, ${COMPARE_CLONE} and pass --compare=<that directory> (or BENCH_COMPARE=<it>)`);
    return;
  }
  await appPage.goto('about:blank'); // the app stops drawing while the comparison is timed
  try {
    const compare = await compareBenchmark(context);
    results.compare = { ms: compare.ms, N: compare.N };
    emit(compare);
  } catch (error) {
    results.compare = { error: error.message ?? String(error) };
    log(`compare ${COMPARE_NAME} FAILED: ${error.stack ?? error}`);
  }
}

/** The compare-ratio row, after all the app rows, when the comparison was measured. */
export function emitRatio(results) {
  if (results.compare?.ms !== undefined) {
    const asOpened = results.app['as opened'];
    const ratioOf = (quality) => ratio(results.app[quality].ms, results.compare.ms);
    emit({
      bench: 'compare-ratio',
      subject: COMPARE_NAME,
      // app ms / dli/waves ms: below 1 the app draws its frames faster.
      asOpened: ratioOf('as opened'),
      goal: COMPARE_GOAL_RATIO,
      within: ratioOf('as opened') <= COMPARE_GOAL_RATIO,
      appAsOpenedMs: asOpened.ms,
      appAsOpenedLevel: asOpened.level,
      appAsOpenedN: asOpened.N,
      compareMs: results.compare.ms,
      compareN: results.compare.N,
      sameN: asOpened.N === results.compare.N,
      byQuality: Object.fromEntries(Object.keys(results.app).map((quality) => [quality, ratioOf(quality)])),
      NByQuality: Object.fromEntries(Object.entries(results.app).map(([quality, { N }]) => [quality, N])),
    });
  }
}
