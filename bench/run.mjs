// `npm run bench`: timings of the simulation core, one JSON object per line on stdout (progress and
// errors on stderr). Figures, not assertions. Every `ms` is the median of `runs` timed runs after
// warm-up; q1/q3 are the quartiles.
//
//   fft2d        BatchedInverseFft2D(N, 1).run() in Node ("js"), and the same inverse 2D complex
//                transform with fft.js row–column ("fft.js"), runs interleaved; fft2d-ratio rows
//                give jsSpeedup = fft.js ms / js ms.
//   fields       CpuWaveFields.update(t) in Node ("js"); in headless Chromium (SwiftShader WebGL2)
//                GpuWaveFields.update(t) ("gpu-rgba32f", "gpu-rgba16f"), timed with a timer query
//                and with a 1-pixel readPixels sync, and CpuWaveFields.update(t) ("js-browser").
//   cascades     one update of every cascade ("wave layer") of C = 1, 3 and 4 FFT cascades at
//                N = 256 (patch sizes CASCADE_SETS, one cascade per size, all fields of each): the
//                JS path (CpuWaveFields.update of each cascade in turn) in Node ("js") and in
//                Chromium ("js-browser"), and the GPU path (GpuWaveFields.update of each, RGBA32F,
//                all cascades inside one timer query, "timer-query", and between two 1-pixel
//                readPixels, "readpixels-sync") as "gpu-rgba32f". The cascade counts are timed
//                interleaved, round by round. `passes` is the fragment passes over all cascades.
//   frame        one frame of the Ocean (ocean.update(t), sky and surface) at 1280x720, from an
//                idle GPU to a 1-pixel readPixels of the canvas: at N = 256 with C = 1, 3 and 4
//                cascades (patchSizes as in CASCADE_SETS; C = 3 is the default sizes), interleaved
//                round by round, and at N = 512 with the default 3 cascades.
//   living       the same frame at N = 256 with the default cascades and a 20 m/s wind, without foam
//                and local waves ("bare"), with whitecap foam ("foam"), and with foam and local waves
//                (a 256² grid) stepping every frame (a hull circling, a stone each second: "foam+local-waves"),
//                interleaved; living-cost gives what foam and local waves add to the bare frame.
//   queries      1000 points in one heightsAt / velocitiesAt call from the page's main thread, the
//                fields for the time already computed (firstCallMs: the call that computes them).
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
//   parameter-change  (with queries) a new wind set on the GPU path at N = 256 with the default
//                cascades, as the app's panel sets it: the main thread's time in setParameters and
//                in each of the two frames after it (update, 5 points' heightAt and normalAt, render
//                at 1280x720), each from an idle GPU; `ms` is the median of their sum.
//   targets      the issue's targets next to the figures (reported, never asserted): per update of
//                three 256² cascades JS ≤ 9 ms and GPU ≤ 30 ms; a frame with three cascades
//                ≤ 100 ms at 1280x720.
//   summary      the key ratios; jsCascadesMs256, gpuCascadesMs256 and frameMs256ByCascades are
//                keyed by cascade count.
//
// If the browser part fails, the Node rows and the summary are still printed and the exit code is 1.
// `npm run bench -- --only=queries,living` runs only the groups named (fft2d, fields, cascades,
// frame, living, queries, app); the summary then has nulls for the others.
//   app          the app page as a user opens it (quality 'auto', after it adapted) and at each
//                fixed quality level, 1280x720: the median time between frames and the fps, with
//                the level's pixel ratio, MSAA, N and cascade count.
//                With --compare=<dir> (or BENCH_COMPARE=<dir>), a checkout of David Li's WebGL
//                FFT ocean (git clone https://github.com/dli/waves; MIT, not part of this
//                repository) is served from <dir> on a static server of its own and timed the
//                same way, right after the app as opened: the row `compare` (subject dli/waves,
//                with the FFT grid N its page sets), and `compare-ratio` (app ms / dli/waves ms
//                for each app row; the goal is ≤ 0.5 for the app as opened). Its page must
//                visibly draw (a screenshot is checked and saved), or the row is an error.
// BENCH_PORT=<port> sets the first port tried for the servers (default 5180; the next free ones after it).
import { existsSync, statSync } from 'node:fs';
import { readFile, writeFile } from 'node:fs/promises';
import { createServer as createHttpServer } from 'node:http';
import { createServer as createNetServer } from 'node:net';
import { tmpdir } from 'node:os';
import { extname, join, resolve, sep } from 'node:path';
import { chromium } from '@playwright/test';
import FFT from 'fft.js';
import { PNG } from 'pngjs';
import { createServer } from 'vite';
import { BROWSER_ARGS, findBrowser } from '../scripts/browser.mjs';

const SIZES = [64, 128, 256, 512];
const MIN_RUNS = 30;
/** Browser rounds per size (each round times every implementation once), after WARMUP_ROUNDS. */
const BROWSER_ROUNDS = { 64: 60, 128: 50, 256: 40, 512: 30 };
const BROWSER_WARMUP_ROUNDS = 6;
const BROWSER_STEP_TIMEOUT_MS = 150_000;
/** The full frame (simulation, sky and surface) is timed at this canvas size. */
const FRAME_SIZE = { width: 1280, height: 720 };
const FRAME_ROUNDS = 30;
/** Patch sizes (m) per cascade count for the cascades and frame rows: ascending, each ≥ 2× and ≤ N/2× the one before. */
const CASCADE_SETS = { 1: [457], 3: [13.7, 79.3, 457], 4: [2.37, 13.7, 79.3, 457] };
const CASCADE_COUNTS = [1, 3, 4];
const CASCADE_N = 256;
/** Browser rounds of the cascades bench (each round times every cascade count and path once). */
const CASCADE_ROUNDS = 40;
/** The local-wave grid of the living-surface frame (the issue's 256², of 1 m texels). */
const LOCAL_WAVES_N = 256;
const TARGETS = { jsCascades3Ms256: 9, gpuCascades3Ms256: 30, frameMs256Cascades3: 100 };
const FIRST_PORT = process.env.BENCH_PORT ? Number(process.env.BENCH_PORT) : 5180;
if (!Number.isInteger(FIRST_PORT) || FIRST_PORT < 1024 || FIRST_PORT > 65000) throw new Error(`BENCH_PORT: not a port from 1024 to 65000: '${process.env.BENCH_PORT}'`);

/** The app as opened adapts its quality for this long before it is timed, s; a fixed level warms up shorter. */
const APP_SETTLE_SECONDS = 20;
const APP_WARMUP_SECONDS = 5;
const APP_FRAMES = 30;

/** The comparison ocean: David Li's WebGL FFT ocean, a static page (index.html and scripts). */
const COMPARE_NAME = 'dli/waves';
const COMPARE_CLONE = 'git clone https://github.com/dli/waves';
/** The app as opened must take at most this fraction of the comparison's frame time (issue 10). */
const COMPARE_GOAL_RATIO = 0.5;
/** At least this fraction of the comparison's screenshot must be coloured (not grey, white or black): its sea. */
const COMPARE_MIN_DRAWN = 0.05;

/** The grids of the query-frames rows (`--query-frames=256` for one). */
const QUERY_FRAME_RESOLUTIONS = (process.argv.find((a) => a.startsWith('--query-frames='))?.slice(15) ?? '256,512,1024').split(',').map(Number);
const GROUPS = ['fft2d', 'fields', 'cascades', 'frame', 'living', 'queries', 'app'];
const compareArgument = process.argv.slice(2).find((argument) => argument.startsWith('--compare='));
/** The directory of a dli/waves checkout to time beside the app, or null. */
const compareDir = compareArgument ? resolve(compareArgument.slice('--compare='.length)) : process.env.BENCH_COMPARE ? resolve(process.env.BENCH_COMPARE) : null;
if (compareDir !== null && !(existsSync(join(compareDir, 'index.html')) && statSync(compareDir).isDirectory())) {
  throw new Error(`--compare / BENCH_COMPARE: ${compareDir} is not a directory with an index.html (get one with: ${COMPARE_CLONE})`);
}
const onlyArgument = process.argv.slice(2).find((argument) => argument.startsWith('--only='));
const only = onlyArgument ? onlyArgument.slice('--only='.length).split(',') : GROUPS;
for (const group of only) {
  if (!GROUPS.includes(group)) throw new Error(`--only: unknown group '${group}' (allowed: ${GROUPS.join(', ')})`);
}
/** True when the group of benchmarks is to run (all unless --only names some). */
const wanted = (group) => only.includes(group);
const started = performance.now();
const log = (message) => process.stderr.write(`bench: ${message}\n`);
const emit = (row) => process.stdout.write(`${JSON.stringify(row)}\n`);

function quantile(sorted, q) {
  const position = (sorted.length - 1) * q;
  const low = Math.floor(position);
  const high = Math.ceil(position);
  return sorted[low] + (sorted[high] - sorted[low]) * (position - low);
}

/** Median and quartiles of samples in ms, rounded to 0.1 µs. */
function stats(samples) {
  const sorted = [...samples].sort((a, b) => a - b);
  const round = (ms) => Math.round(ms * 1e4) / 1e4;
  return {
    ms: round(quantile(sorted, 0.5)),
    runs: sorted.length,
    q1: round(quantile(sorted, 0.25)),
    q3: round(quantile(sorted, 0.75)),
  };
}

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

const ratio = (a, b) => (a > 0 && b > 0 ? Math.round((a / b) * 1000) / 1000 : null);

/**
 * Warm-up, then timed rounds of each task in turn (interleaved, so machine noise hits them alike).
 * A task is { prepare(), run() }; prepare() is not timed. Warm-up lasts at least 5 rounds and
 * 300 ms; the timed rounds number at least MIN_RUNS and about budgetMs in total, at most 400.
 */
function timeInterleaved(tasks, budgetMs) {
  const timeOnce = (task) => {
    task.prepare();
    const start = performance.now();
    task.run();
    return performance.now() - start;
  };
  const warmupStart = performance.now();
  const warmup = tasks.map(() => []);
  for (let round = 0; round < 500 && (round < 5 || performance.now() - warmupStart < 300); round++) {
    tasks.forEach((task, i) => warmup[i].push(timeOnce(task)));
  }
  const perRound = warmup.reduce((sum, samples) => sum + stats(samples.slice(-5)).ms, 0);
  const rounds = Math.max(MIN_RUNS, Math.min(400, Math.floor(budgetMs / Math.max(perRound, 1e-3))));
  const samples = tasks.map(() => []);
  for (let round = 0; round < rounds; round++) tasks.forEach((task, i) => samples[i].push(timeOnce(task)));
  return samples;
}

/** A deterministic pseudo-random complex N×N matrix, index j·N + i (row j = z, column i = x). */
function randomMatrix(n, seed) {
  let state = seed >>> 0;
  const next = () => {
    state = (Math.imul(state, 1664525) + 1013904223) >>> 0;
    return state / 2 ** 32 - 0.5;
  };
  const re = new Float64Array(n * n);
  const im = new Float64Array(n * n);
  for (let k = 0; k < n * n; k++) {
    re[k] = next();
    im[k] = next();
  }
  return { re, im };
}

/** BatchedInverseFft2D with one field, refilled from the matrix before every run. */
function jsFft2d(BatchedInverseFft2D, n, { re, im }) {
  const fft = new BatchedInverseFft2D(n, 1);
  const sourceRe = new Float32Array(fft.inputReal.length);
  const sourceIm = new Float32Array(fft.inputImag.length);
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      sourceRe[fft.inputIndex(0, i, j)] = re[j * n + i];
      sourceIm[fft.inputIndex(0, i, j)] = im[j * n + i];
    }
  }
  return {
    prepare() {
      fft.inputReal.set(sourceRe);
      fft.inputImag.set(sourceIm);
    },
    run: () => fft.run(),
    /** Output (re, im) at column i, row j. */
    value: (i, j) => [fft.outputReal[fft.outputIndex(0, i, j)], fft.outputImag[fft.outputIndex(0, i, j)]],
  };
}

/**
 * fft.js (radix-4, interleaved re/im arrays from createComplexArray), row–column: each row is
 * transformed into a second set of rows, then each column is copied out, transformed and copied
 * back. fft.js's inverseTransform divides by N, so its result is ours / N².
 */
function fftJs2d(n, { re, im }) {
  const fft = new FFT(n);
  const rows = Array.from({ length: n }, () => fft.createComplexArray());
  const transformed = Array.from({ length: n }, () => fft.createComplexArray());
  const column = fft.createComplexArray();
  const columnOut = fft.createComplexArray();
  return {
    prepare() {
      for (let j = 0; j < n; j++) {
        const row = rows[j];
        for (let i = 0; i < n; i++) {
          row[2 * i] = re[j * n + i];
          row[2 * i + 1] = im[j * n + i];
        }
      }
    },
    run() {
      for (let j = 0; j < n; j++) fft.inverseTransform(transformed[j], rows[j]);
      for (let i = 0; i < n; i++) {
        const r = 2 * i;
        for (let j = 0; j < n; j++) {
          column[2 * j] = transformed[j][r];
          column[2 * j + 1] = transformed[j][r + 1];
        }
        fft.inverseTransform(columnOut, column);
        for (let j = 0; j < n; j++) {
          transformed[j][r] = columnOut[2 * j];
          transformed[j][r + 1] = columnOut[2 * j + 1];
        }
      }
    },
    value: (i, j) => [transformed[j][2 * i] * n * n, transformed[j][2 * i + 1] * n * n],
  };
}

/** max |a − b| / rms(a) over the whole matrix: both implementations compute the same transform. */
function relativeDifference(n, a, b) {
  let maxError = 0;
  let sumSquares = 0;
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      const [ar, ai] = a.value(i, j);
      const [br, bi] = b.value(i, j);
      maxError = Math.max(maxError, Math.hypot(ar - br, ai - bi));
      sumSquares += ar * ar + ai * ai;
    }
  }
  return maxError / Math.sqrt(sumSquares / (n * n));
}

async function nodeBenchmarks(results) {
  log('loading src/sim through Vite (ssrLoadModule)');
  const server = await createServer({
    server: { middlewareMode: true, watch: null },
    appType: 'custom',
    logLevel: 'silent',
    optimizeDeps: { noDiscovery: true },
  });
  try {
    const { BatchedInverseFft2D } = await server.ssrLoadModule('/src/fft/fft.ts');
    const { CpuWaveFields } = await server.ssrLoadModule('/src/fft/cpuWaveFields.ts');
    const { validateParameters } = await server.ssrLoadModule('/src/parameters/parameters.ts');
    const { createCascadeSpectra } = await server.ssrLoadModule('/src/spectrum/initialSpectrum.ts');

    for (const n of wanted('fft2d') ? SIZES : []) {
      log(`fft2d N=${n}: js vs fft.js`);
      const matrix = randomMatrix(n, n);
      const js = jsFft2d(BatchedInverseFft2D, n, matrix);
      const other = fftJs2d(n, matrix);
      js.prepare();
      js.run();
      other.prepare();
      other.run();
      const difference = relativeDifference(n, js, other);
      const [jsSamples, otherSamples] = timeInterleaved([js, other], 2000);
      const jsStats = stats(jsSamples);
      const otherStats = stats(otherSamples);
      const speedup = ratio(otherStats.ms, jsStats.ms);
      results.fftSpeedup[n] = speedup;
      emit({ bench: 'fft2d', N: n, path: 'js', ...jsStats });
      emit({ bench: 'fft2d', N: n, path: 'fft.js', ...otherStats });
      emit({ bench: 'fft2d-ratio', N: n, jsSpeedup: speedup, maxRelDiff: Number(difference.toPrecision(3)) });
    }

    for (const n of wanted('fields') ? SIZES : []) {
      log(`fields N=${n}: CpuWaveFields.update in Node`);
      const params = validateParameters({ resolution: n });
      const fields = new CpuWaveFields(createCascadeSpectra(params)[0]);
      let t = 1.25;
      const [samples] = timeInterleaved([{ prepare: () => (t += 0.0371), run: () => fields.update(t) }], 2000);
      const row = stats(samples);
      results.jsFields[n] = row.ms;
      emit({ bench: 'fields', N: n, path: 'js', ...row });
    }

    if (!wanted('cascades')) return;
    log(`cascades N=${CASCADE_N}: CpuWaveFields.update of each cascade in Node, C = ${CASCADE_COUNTS.join(', ')}`);
    const tasks = CASCADE_COUNTS.map((count) => {
      const params = validateParameters({ resolution: CASCADE_N, patchSizes: CASCADE_SETS[count] });
      const cascades = createCascadeSpectra(params).map((spectrum) => new CpuWaveFields(spectrum));
      if (cascades.length !== count) throw new Error(`${cascades.length} cascades for patchSizes ${CASCADE_SETS[count]}`);
      let t = 1.25;
      return {
        prepare: () => (t += 0.0371),
        run: () => cascades.forEach((fields) => fields.update(t)),
      };
    });
    timeInterleaved(tasks, 4000).forEach((samples, i) => {
      const count = CASCADE_COUNTS[i];
      const row = stats(samples);
      results.jsCascades[count] = row.ms;
      emit({ bench: 'cascades', N: CASCADE_N, cascades: count, patchSizes: CASCADE_SETS[count], path: 'js', ...row });
    });
  } finally {
    await server.close();
  }
}

/** The first port from `first` on that 127.0.0.1 lets us listen on. */
async function freePort(first = FIRST_PORT) {
  for (let port = first; port < first + 50; port++) {
    const free = await new Promise((resolve) => {
      const probe = createNetServer();
      probe.once('error', () => resolve(false));
      probe.listen(port, '127.0.0.1', () => probe.close(() => resolve(true)));
    });
    if (free) return port;
  }
  throw new Error(`no free port in ${first}-${first + 49}`);
}

function withTimeout(promise, ms, what) {
  let timer;
  const timeout = new Promise((_, reject) => {
    timer = setTimeout(() => reject(new Error(`${what} took more than ${ms / 1000} s`)), ms);
  });
  return Promise.race([promise, timeout]).finally(() => clearTimeout(timer));
}

/**
 * In the page: the real time between `count` successive frames (requestAnimationFrame
 * timestamps, ms), what users see. Shared by the app and the comparison so both are timed alike.
 */
async function frameIntervals(count) {
  const frame = () => new Promise((resolve) => requestAnimationFrame(resolve));
  const samples = [];
  let last = await frame();
  for (let i = 0; i < count; i++) {
    const now = await frame();
    samples.push(now - last);
    last = now;
  }
  return samples;
}

const STATIC_TYPES = { '.html': 'text/html', '.js': 'text/javascript', '.css': 'text/css', '.png': 'image/png', '.jpg': 'image/jpeg', '.json': 'application/json' };

/**
 * A static file server for `root` on 127.0.0.1:port (GET and HEAD, nothing outside root), with the
 * same cross-origin isolation headers as the app's Vite server, so both pages get the same timer
 * resolution. Resolves to the server once it listens.
 */
async function serveStatic(root, port) {
  const server = createHttpServer(async (request, response) => {
    if (request.method !== 'GET' && request.method !== 'HEAD') {
      response.writeHead(405).end();
      return;
    }
    let path;
    try {
      path = decodeURIComponent(new URL(request.url ?? '/', 'http://127.0.0.1').pathname);
    } catch {
      response.writeHead(400).end();
      return;
    }
    const file = resolve(root, `.${path.endsWith('/') ? `${path}index.html` : path}`);
    if (!file.startsWith(root + sep)) {
      response.writeHead(403).end();
      return;
    }
    try {
      const body = await readFile(file);
      response.writeHead(200, {
        'Content-Type': STATIC_TYPES[extname(file).toLowerCase()] ?? 'application/octet-stream',
        'Cross-Origin-Opener-Policy': 'same-origin',
        'Cross-Origin-Embedder-Policy': 'require-corp',
        'Cache-Control': 'no-store',
      });
      response.end(request.method === 'HEAD' ? undefined : body);
    } catch {
      response.writeHead(404).end();
    }
  });
  await new Promise((resolveListen, reject) => {
    server.once('error', reject);
    server.listen(port, '127.0.0.1', resolveListen);
  });
  return server;
}

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
 * dli/waves served from compareDir on a server of its own, timed like the app as opened: the same
 * browser, viewport, warm-up and number of frames (the app's page is blank meanwhile, so nothing
 * else draws). Requests off 127.0.0.1 (its page asks Google Fonts) are aborted. Returns the row.
 */
async function compareBenchmark(browser) {
  const port = await freePort(FIRST_PORT + 1);
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
 * The app as a user opens it (index.html, no URL parameters: its MSAA, panel, status line and
 * quality 'auto'), after APP_SETTLE_SECONDS to adapt, then at each fixed quality level, at
 * FRAME_SIZE: the median real time between frames (requestAnimationFrame), what users see.
 */
async function appBenchmarks(browser, server, port, results) {
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
      if (quality !== 'as opened') continue;
      // The comparison right after the app as opened, so that the two share the machine's load.
      if (compareDir === null) {
        log(`compare ${COMPARE_NAME}: skipped; to time it beside the app, ${COMPARE_CLONE} and pass --compare=<that directory> (or BENCH_COMPARE=<it>)`);
        continue;
      }
      await appPage.goto('about:blank'); // the app stops drawing while the comparison is timed
      try {
        const compare = await compareBenchmark(browser);
        results.compare = { ms: compare.ms, N: compare.N };
        emit(compare);
      } catch (error) {
        results.compare = { error: error.message ?? String(error) };
        log(`compare ${COMPARE_NAME} FAILED: ${error.stack ?? error}`);
      }
    }
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
  } finally {
    await appPage.close();
  }
}

async function browserBenchmarks(results) {
  const executablePath = findBrowser();
  if (!executablePath) throw new Error('no Chromium found (see scripts/browser.mjs; set CHROMIUM_PATH)');
  const port = await freePort();
  log(`starting Vite on http://127.0.0.1:${port}/`);
  const server = await createServer({
    logLevel: 'silent',
    optimizeDeps: { noDiscovery: true }, // no dependency discovery, so no reload mid-benchmark
    server: {
      port,
      strictPort: true,
      host: '127.0.0.1',
      // No file watcher and no HMR: an edit anywhere in the tree must not reload the page mid-run.
      watch: null,
      hmr: false,
      // Cross-origin isolation gives performance.now() 5 µs resolution instead of 100 µs.
      headers: { 'Cross-Origin-Opener-Policy': 'same-origin', 'Cross-Origin-Embedder-Policy': 'require-corp' },
    },
  });
  let browser;
  try {
    await server.listen();
    log(`launching ${executablePath}`);
    browser = await chromium.launch({ executablePath, args: BROWSER_ARGS });
    const page = await browser.newPage();
    page.on('pageerror', (error) => log(`page error: ${error.message}`));
    page.on('response', (response) => {
      if (response.status() >= 400) log(`HTTP ${response.status()} for ${response.url()}`);
    });
    page.on('console', (message) => {
      if (message.type() === 'error' || message.type() === 'warning') log(`page ${message.type()}: ${message.text()}`);
    });
    await page.goto(`http://127.0.0.1:${port}/bench/pages/bench.html`);
    await page.waitForFunction(() => document.title === 'ready', null, { timeout: 60_000 });
    const info = await page.evaluate(() => window.bench.info());
    emit({ bench: 'browser', ...info });
    if (info.supportedPrecision !== 'float32') throw new Error(`no RGBA32F render targets (supported: ${info.supportedPrecision})`);
    if (!info.timerQuery) log('EXT_disjoint_timer_query_webgl2 is missing: only readpixels-sync GPU rows');

    const runFields = (options) =>
      withTimeout(
        page.evaluate((o) => window.bench.fields(o), options),
        BROWSER_STEP_TIMEOUT_MS,
        `the browser benchmark at N=${options.resolution}`,
      );
    /** GPU rows of one subject; `head` starts each row (bench, N, and for cascades the count). */
    const emitGpu = (head, path, samples) => {
      const passes = samples.passCount;
      if (samples.gpuTimerQuery) {
        const row = { ...head, path, ...stats(samples.gpuTimerQuery), passes, timer: 'timer-query' };
        if (samples.disjointDiscarded) row.disjointDiscarded = samples.disjointDiscarded;
        emit(row);
      }
      const row = stats(samples.gpuReadPixels);
      emit({ ...head, path, ...row, passes, timer: 'readpixels-sync', syncMs: stats(samples.syncOnly).ms });
      return { timerQuery: samples.gpuTimerQuery ? stats(samples.gpuTimerQuery).ms : null, readPixels: row.ms };
    };

    for (const n of wanted('fields') ? SIZES : []) {
      log(`fields N=${n}: GPU (rgba32f) and JS in Chromium`);
      const samples = await runFields({
        resolution: n,
        gpu: 'float32',
        js: true,
        warmupRounds: BROWSER_WARMUP_ROUNDS,
        rounds: BROWSER_ROUNDS[n],
      });
      results.gpu[n] = emitGpu({ bench: 'fields', N: n }, 'gpu-rgba32f', samples);
      const jsRow = stats(samples.js);
      results.jsBrowser[n] = jsRow.ms;
      emit({ bench: 'fields', N: n, path: 'js-browser', ...jsRow });
    }
    if (wanted('cascades')) {
      log(`cascades N=${CASCADE_N}: GPU (rgba32f) and JS of every cascade in Chromium, C = ${CASCADE_COUNTS.join(', ')}`);
      const cascadeSamples = await withTimeout(
        page.evaluate((o) => window.bench.cascades(o), {
          resolution: CASCADE_N,
          patchSizeSets: CASCADE_COUNTS.map((count) => CASCADE_SETS[count]),
          gpu: 'float32',
          js: true,
          warmupRounds: BROWSER_WARMUP_ROUNDS,
          rounds: CASCADE_ROUNDS,
        }),
        2 * BROWSER_STEP_TIMEOUT_MS,
        `the cascades benchmark at N=${CASCADE_N}`,
      );
      for (const samples of cascadeSamples) {
        const head = { bench: 'cascades', N: CASCADE_N, cascades: samples.cascades, patchSizes: samples.patchSizes };
        results.gpuCascades[samples.cascades] = emitGpu(head, 'gpu-rgba32f', samples);
      }
      for (const samples of cascadeSamples) {
        const row = stats(samples.js);
        results.jsBrowserCascades[samples.cascades] = row.ms;
        emit({ bench: 'cascades', N: CASCADE_N, cascades: samples.cascades, patchSizes: samples.patchSizes, path: 'js-browser', ...row });
      }
    }
    await page.goto(`http://127.0.0.1:${port}/bench/pages/frame.html`);
    await page.waitForFunction(() => document.title === 'ready', null, { timeout: 60_000 });
    if (wanted('frame')) {
      const frameRuns = [
        { resolution: CASCADE_N, counts: CASCADE_COUNTS },
        { resolution: 512, counts: [null] }, // the default patch sizes (3 cascades)
      ];
      for (const { resolution: n, counts } of frameRuns) {
        const what = counts[0] === null ? 'default cascades' : `C = ${counts.join(', ')} cascades`;
        log(`frame N=${n}, ${what}: simulation + sky + surface at ${FRAME_SIZE.width}x${FRAME_SIZE.height}`);
        const frames = await withTimeout(
          page.evaluate((o) => window.frameBench.frames(o), {
            resolution: n,
            ...FRAME_SIZE,
            warmup: 5,
            rounds: FRAME_ROUNDS,
            patchSizeSets: counts.map((count) => (count === null ? undefined : CASCADE_SETS[count])),
          }),
          counts.length * BROWSER_STEP_TIMEOUT_MS,
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
    }
    if (wanted('living')) {
      log(`living surface N=${CASCADE_N}: bare, foam, foam and local waves at ${FRAME_SIZE.width}x${FRAME_SIZE.height}`);
      const living = await withTimeout(
        page.evaluate((o) => window.frameBench.frames(o), {
          resolution: CASCADE_N,
          ...FRAME_SIZE,
          warmup: 5,
          rounds: FRAME_ROUNDS,
          patchSizeSets: [],
          variants: [
            { label: 'bare', options: { windSpeed: 20, foamAmount: 0, localWaves: false }, activeLocalWaves: false },
            { label: 'foam', options: { windSpeed: 20, localWaves: false }, activeLocalWaves: false },
            { label: 'foam+local-waves', options: { windSpeed: 20, localWaves: { resolution: LOCAL_WAVES_N } }, activeLocalWaves: true },
          ],
        }),
        3 * BROWSER_STEP_TIMEOUT_MS,
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
    if (wanted('queries')) {
      log('queries: 1000 points, heightsAt and velocitiesAt from the main thread');
      const queryRuns = await withTimeout(
        page.evaluate((o) => window.frameBench.queries(o), { resolution: CASCADE_N, points: 1000, rounds: 30 }),
        BROWSER_STEP_TIMEOUT_MS,
        'the queries benchmark',
      );
      results.queries = {};
      for (const [name, { firstMs, samples }] of Object.entries(queryRuns)) {
        const row = stats(samples);
        results.queries[name] = row.ms;
        emit({ bench: 'queries', query: name, points: 1000, N: CASCADE_N, firstCallMs: firstMs, ...row, target: name === 'heightsAt' ? 2 : null });
      }
      // As an app asks them: a few points a frame while the workers compute the fields.
      results.queryFrames = {};
      for (const resolution of QUERY_FRAME_RESOLUTIONS) {
        log(`query frames: heightAt and normalAt at 5 points a frame, GPU path, N = ${resolution}`);
        // In a page of its own, as an app's first ocean: its first query meets code no query compiled yet.
        const queryPage = await browser.newPage();
        await queryPage.goto(`http://127.0.0.1:${port}/bench/pages/frame.html`);
        await queryPage.waitForFunction(() => document.title === 'ready', null, { timeout: 60_000 });
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
    if (wanted('queries')) {
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
    if (wanted('app')) await appBenchmarks(browser, server, port, results);
    if (!wanted('fields')) return;
    await page.goto(`http://127.0.0.1:${port}/bench/pages/bench.html`);
    await page.waitForFunction(() => document.title === 'ready', null, { timeout: 60_000 });
    if (info.halfFloat) {
      log('fields N=256: GPU (rgba16f) in Chromium');
      const samples = await runFields({
        resolution: 256,
        gpu: 'float16',
        js: false,
        warmupRounds: BROWSER_WARMUP_ROUNDS,
        rounds: BROWSER_ROUNDS[256],
      });
      results.gpuHalf256 = emitGpu({ bench: 'fields', N: 256 }, 'gpu-rgba16f', samples);
    } else {
      log('EXT_color_buffer_half_float is missing: no gpu-rgba16f row');
    }
  } finally {
    await browser?.close().catch(() => {});
    await server.close().catch(() => {});
  }
}

const results = {
  fftSpeedup: {},
  jsFields: {},
  jsBrowser: {},
  gpu: {},
  gpuHalf256: null,
  frame: {},
  jsCascades: {},
  jsBrowserCascades: {},
  gpuCascades: {},
  frameByCascades: {},
  livingCost: null,
  queries: null,
  app: {},
  /** dli/waves: { ms, N }, or { error }; null when not asked for (no --compare). */
  compare: null,
};
let exitCode = 0;
let browserError = null;
try {
  await nodeBenchmarks(results);
} catch (error) {
  log(`FAILED in the Node benchmarks: ${error.stack ?? error}`);
  exitCode = 1;
}
try {
  await browserBenchmarks(results);
} catch (error) {
  browserError = error.message ?? String(error);
  log(`FAILED in the browser benchmarks (GPU and js-browser rows missing): ${error.stack ?? error}`);
  exitCode = 1;
}
if (results.compare?.error !== undefined) exitCode = 1; // asked for with --compare, and not measured

const gpu = (n, timer) => results.gpu[n]?.[timer] ?? null;
const gpuCascades = (count) => results.gpuCascades[count]?.timerQuery ?? results.gpuCascades[count]?.readPixels ?? null;
/** { 1: ms, 3: ms, 4: ms } (null where missing). */
const byCascades = (ms) => Object.fromEntries(CASCADE_COUNTS.map((count) => [count, ms(count) ?? null]));
const target = (ms, limit) => ({ ms, target: limit, within: ms === null ? null : ms <= limit });
emit({
  bench: 'targets',
  N: CASCADE_N,
  cascades: 3,
  jsMs: target(results.jsCascades[3] ?? null, TARGETS.jsCascades3Ms256),
  gpuMs: target(gpuCascades(3), TARGETS.gpuCascades3Ms256),
  frameMs: target(results.frameByCascades[3] ?? null, TARGETS.frameMs256Cascades3),
  frameSize: `${FRAME_SIZE.width}x${FRAME_SIZE.height}`,
});
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
  gpuCascadesMs256: byCascades(gpuCascades),
  gpuCascadesReadPixelsMs256: byCascades((count) => results.gpuCascades[count]?.readPixels),
  gpuCascadesTimer: (results.gpuCascades[3]?.timerQuery ?? null) !== null ? 'timer-query' : results.gpuCascades[3] ? 'readpixels-sync' : null,
  frameMs256ByCascades: byCascades((count) => results.frameByCascades[count]),
  browser: browserError === null ? 'ok' : 'failed',
  ...(browserError === null ? {} : { browserError }),
  seconds: Math.round((performance.now() - started) / 100) / 10,
});
log(`done in ${((performance.now() - started) / 1000).toFixed(1)} s${exitCode ? ' (with failures, see above)' : ''}`);
process.stdout.write('', () => process.exit(exitCode));
