// A group of `npm run bench` (bench/run.mjs), always printed last:
//
//   summary      the key ratios; jsCascadesMs256, gpuCascadesMs256 and frameMs256ByCascades are
//                keyed by cascade count; webgpuFrameMs by subject, webgpuFftMs by N then subject.
import { emit } from '../lib/output.mjs';
import { CASCADE_COUNTS } from '../lib/settings.mjs';
import { ratio } from '../lib/stats.mjs';
import { gpuCascades } from './targets.mjs';

/** { 1: ms, 3: ms, 4: ms } (null where missing). */
const byCascades = (ms) => Object.fromEntries(CASCADE_COUNTS.map((count) => [count, ms(count) ?? null]));

/**
 * The summary row, from the figures in `results` (null where their group did not run);
 * `browserError` is the browser part's failure or null, `started` the run's performance.now() at its start.
 */
export function emitSummary(results, browserError, started) {
  const gpu = (n, timer) => results.gpu[n]?.[timer] ?? null;
  emit({
    bench: 'summary',
    jsSpeedupVsFftJs256: results.fftSpeedup[256] ?? null,
    jsSpeedupVsFftJs512: results.fftSpeedup[512] ?? null,
    jsFieldsMs256: results.jsFields[256] ?? null,
    jsFieldsMs512: results.jsFields[512] ?? null,
    gpuMs256: gpu(256, 'timerQuery') ?? gpu(256, 'readPixels'),
    gpuMs512: gpu(512, 'timerQuery') ?? gpu(512, 'readPixels'),
    gpuTimer: gpu(256, 'timerQuery') !== null ? 'timer-query' : gpu(256, 'readPixels') !== null ? 'readpixels-sync' : null,
    gpuReadPixelsMs256: gpu(256, 'readPixels'),
    gpuReadPixelsMs512: gpu(512, 'readPixels'),
    gpuHalfMs256: results.gpuHalf256?.timerQuery ?? results.gpuHalf256?.readPixels ?? null,
    jsBrowserFieldsMs256: results.jsBrowser[256] ?? null,
    jsBrowserFieldsMs512: results.jsBrowser[512] ?? null,
    // Wall clock against wall clock, both in the same browser run.
    gpuSpeedupVsJsBrowser256: ratio(results.jsBrowser[256], gpu(256, 'readPixels')),
    gpuSpeedupVsJsBrowser512: ratio(results.jsBrowser[512], gpu(512, 'readPixels')),
    frameMs256At1280x720: results.frame[256] ?? null,
    frameMs512At1280x720: results.frame[512] ?? null,
    livingCostMs: results.livingCost,
    reflectionsCost: results.reflectionsCost,
    // The app as opened and at each quality level, beside the bare 3-cascade frame of the same size.
    appFrameMs: Object.fromEntries(Object.entries(results.app).map(([quality, { ms }]) => [quality, ms])),
    appAsOpenedFps: results.app['as opened']?.fps ?? null,
    appAsOpenedLevel: results.app['as opened']?.level ?? null,
    // dli/waves at the same size in the same run (--compare), and app as opened / it (goal ≤ 0.5).
    compareDliWavesMs: results.compare?.ms ?? null,
    appAsOpenedVsDliWaves: ratio(results.app['as opened']?.ms, results.compare?.ms),
    queries1000Ms: results.queries,
    parameterChangeMs: results.parameterChange ?? null,
    jsCascadesMs256: byCascades((count) => results.jsCascades[count]),
    jsBrowserCascadesMs256: byCascades((count) => results.jsBrowserCascades[count]),
    gpuCascadesMs256: byCascades((count) => gpuCascades(results, count)),
    gpuCascadesReadPixelsMs256: byCascades((count) => results.gpuCascades[count]?.readPixels),
    gpuCascadesTimer: (results.gpuCascades[3]?.timerQuery ?? null) !== null ? 'timer-query' : results.gpuCascades[3] ? 'readpixels-sync' : null,
    frameMs256ByCascades: byCascades((count) => results.frameByCascades[count]),
    // The lighting group: issue 26's slope light over the 'high' frame without it (goal ≤ 1.1); the streaks and spray at force 9.
    slopeLightCost: results.lighting?.slopeLightCost ?? null,
    beaufortLookCostAtForce9: results.lighting?.beaufortLookCostAtForce9 ?? null,
    // The webgpu group: the frame at 1280x720 by subject, the WebGL2 backend's over the WebGL Ocean's (goal ≤ 1.2), the FFT update by N and subject.
    webgpuFrameMs: results.webgpu?.frameMs ?? null,
    webgpuVsWebGL: results.webgpu?.webgpuVsWebGL ?? null,
    webgpuVsWebGLSameDraw: results.webgpu?.webgpuVsWebGLSameDraw ?? null,
    webgpuFftMs: results.webgpu?.fftMs ?? null,
    browser: browserError === null ? 'ok' : 'failed',
    ...(browserError === null ? {} : { browserError }),
    seconds: Math.round((performance.now() - started) / 100) / 10,
  });
}
