// A group of `npm run bench` (bench/run.mjs):
//
//   webgpu       three-fft-ocean/webgpu beside the WebGL Ocean (issue 23), in a Chromium of its own
//                launched with --enable-unsafe-webgpu (SwiftShader's WebGPU adapter), on two pages
//                of bench/pages/webgpu.ts: the WebGL page (the WebGL Ocean on a WebGLRenderer and
//                the WebGPU Ocean on WebGPURenderer's WebGL2 backend, forceWebGL) and the WebGPU
//                page (the WebGPU backend); a page whose WebGPU device lives cannot also hold a
//                WebGLRenderer. Within a page the subjects are interleaved round by round; the
//                group alternates blocks of WEBGPU_BLOCK rounds between the pages, so that the
//                machine's drifts fall on both.
//                - frame: one frame at 1280x720 (ocean.update(t) and render), seed 7, default
//                  options otherwise: the WebGL Ocean's ("WebGL Ocean, defaults"), the WebGL Ocean
//                  drawing what the WebGPU Ocean draws (reflections and refractions 'sky', no local
//                  waves), and the WebGPU Ocean's on the WebGL2 backend, each into its canvas and
//                  timed from an idle GPU to a 1-pixel readPixels of it; and the WebGPU Ocean's on
//                  the WebGPU backend, into a 1280x720 RGBA8 target (a WebGPU canvas loses its
//                  device headless after one frame: ../shared/BROWSER.md), so without the output
//                  pass (tone mapping, colour space) WebGPURenderer adds for a canvas, timed to
//                  device.queue.onSubmittedWorkDone(). webgpuVsWebGL is the WebGL2 backend's frame
//                  over the WebGL Ocean's default (issue 23: at most 1.2 under SwiftShader), and
//                  webgpuVsWebGLSameDraw over the WebGL Ocean drawing the same.
//                - fft: ocean.update(t) alone, the 3 default cascades at N = 256 and 512, foam off:
//                  compute (the WebGPU Ocean, path 'gpu', WebGPU backend, to onSubmittedWorkDone),
//                  fragment passes (the WebGL Ocean, path 'gpu', to a 1-pixel readPixels) and JS
//                  (the WebGPU Ocean, path 'js' on the main thread; its textures upload at the next
//                  draw, not timed here).
//                Figures of SwiftShader's WebGPU and WebGL2, both on the CPU: see README "Performance".
//                WEBGPU_ROUNDS rounds of each are timed (15: SwiftShader's compute FFT at N = 512 took
//                20 s an update under a load of 28), `--webgpu-rounds=<n>` n (3: a quick check).
import { chromium } from '@playwright/test';
import { BROWSER_ARGS, findBrowser } from '../../scripts/browser.mjs';
import { openReady, withTimeout } from '../lib/browser.mjs';
import { emit, log } from '../lib/output.mjs';
import { BROWSER_STEP_TIMEOUT_MS, FRAME_SIZE } from '../lib/settings.mjs';
import { ratio, stats } from '../lib/stats.mjs';

/** Rounds a page runs before the other page's turn. */
const WEBGPU_BLOCK = 5;
const WARMUP_ROUNDS = 5;
/** Rounds timed on each page by default. */
const WEBGPU_ROUNDS = 15;

/**
 * Times `session` (bench/pages/webgpu.ts SessionOptions) on both pages: warm-up on each, then
 * alternating blocks until `rounds` are timed on each. Returns { label: samples } of both pages.
 */
async function timeBothPages(pages, session, rounds, what) {
  const samples = {};
  for (const page of pages) {
    await withTimeout(page.evaluate((s) => window.webgpuBench.start(s), session), BROWSER_STEP_TIMEOUT_MS, `starting ${what}`);
    await withTimeout(page.evaluate((n) => window.webgpuBench.run(n, 0), WARMUP_ROUNDS), BROWSER_STEP_TIMEOUT_MS, `warming up ${what}`);
  }
  for (let done = 0; done < rounds; done += WEBGPU_BLOCK) {
    const block = Math.min(WEBGPU_BLOCK, rounds - done);
    for (const page of pages) {
      const timed = await withTimeout(page.evaluate((n) => window.webgpuBench.run(0, n), block), BROWSER_STEP_TIMEOUT_MS, what);
      for (const [label, ms] of Object.entries(timed)) (samples[label] ??= []).push(...ms);
    }
  }
  for (const page of pages) await page.evaluate(() => window.webgpuBench.stop());
  return samples;
}

/** The webgpu rows; `webgpuRounds` (--webgpu-rounds) sets the rounds timed. */
export async function browser({ port, results, webgpuRounds = WEBGPU_ROUNDS }) {
  const webgpuBrowser = await chromium.launch({ executablePath: findBrowser() ?? undefined, args: [...BROWSER_ARGS, '--enable-unsafe-webgpu'] });
  try {
    const pages = [];
    for (const backend of ['webgl', 'webgpu']) {
      const page = await webgpuBrowser.newPage();
      page.on('pageerror', (error) => log(`page error (${backend}): ${error.message}`));
      page.on('console', (message) => {
        if (message.type() === 'error' || message.type() === 'warning') log(`page ${message.type()} (${backend}): ${message.text()}`);
      });
      await openReady(page, port, `webgpu.html?backend=${backend}`);
      pages.push(page);
    }
    const size = `${FRAME_SIZE.width}x${FRAME_SIZE.height}`;
    log(`webgpu frame at ${size}: the WebGL Ocean, the WebGPU Ocean on WebGL2 and on WebGPU`);
    const frames = await timeBothPages(pages, { what: 'frame', ...FRAME_SIZE }, webgpuRounds, 'the webgpu frame benchmark');
    const ms = {};
    for (const [label, samples] of Object.entries(frames)) {
      const row = stats(samples);
      ms[label] = row.ms;
      emit({ bench: 'webgpu-frame', subject: label, size, ...row });
    }
    const webgl2 = ms['WebGPU Ocean, defaults, WebGL2 backend'];
    results.webgpu = {
      frameMs: ms,
      webgpuVsWebGL: ratio(webgl2, ms['WebGL Ocean, defaults']),
      webgpuVsWebGLSameDraw: ratio(webgl2, ms['WebGL Ocean, what the WebGPU Ocean draws']),
      fftMs: {},
    };
    emit({ bench: 'webgpu-frame-ratio', size, webgpuVsWebGL: results.webgpu.webgpuVsWebGL, webgpuVsWebGLSameDraw: results.webgpu.webgpuVsWebGLSameDraw, target: 1.2 });
    for (const resolution of [256, 512]) {
      log(`webgpu fft N=${resolution}: compute, fragment passes, JS (ocean.update, 3 cascades, foam off)`);
      const ffts = await timeBothPages(pages, { what: 'fft', ...FRAME_SIZE, resolution }, webgpuRounds, `the webgpu fft benchmark at N=${resolution}`);
      results.webgpu.fftMs[resolution] = {};
      for (const [label, samples] of Object.entries(ffts)) {
        const row = stats(samples);
        results.webgpu.fftMs[resolution][label] = row.ms;
        emit({ bench: 'webgpu-fft', N: resolution, subject: label, ...row });
      }
    }
  } finally {
    await webgpuBrowser.close().catch(() => {});
  }
}
