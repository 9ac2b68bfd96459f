// `npm run bench`: timings of the simulation core, one JSON object per line on stdout (progress and
// errors on stderr). Figures, not assertions. Every `ms` is the median of `runs` timed runs after
// warm-up; q1/q3 are the quartiles.
//
// The groups run in this order, each documented at the top of its file in bench/groups/:
//
//   in Node      fft2d, fields, cascades (the JS path; Vite loads the TypeScript sources)
//   in Chromium  the `browser` row (what its WebGL2 supports; bench/lib/browser.mjs), then fields,
//                cascades, frame, lighting, living, reflections, island, queries (with query-frames and parameter-change), app
//                (with compare), webgpu (in a Chromium of its own, with WebGPU), and last the fields row with RGBA16F
//   always       targets, summary
//
// If the browser part fails, the Node rows and the summary are still printed and the exit code is 1.
// `npm run bench -- --only=queries,living` runs only the groups named (fft2d, fields, cascades,
// frame, lighting, living, reflections, island, queries, app, webgpu); the summary then has nulls for the others.
// `--island-rounds=3`, `--lighting-rounds=3` and `--webgpu-rounds=3` time only that many rounds in
// the island, lighting and webgpu rows (a quick check that they run).
// `--compare=<dir>` (or BENCH_COMPARE=<dir>) times dli/waves beside the app (bench/groups/compare.mjs);
// `--query-frames=256` sets the grids of the query-frames rows.
// BENCH_PORT=<port> sets the first port tried for the servers (default 5180; the next free ones after it).
//
// bench/lib/ holds what the groups share: settings.mjs (sizes, rounds, timeouts), stats.mjs
// (medians, quartiles, interleaved timing), output.mjs (rows and progress), servers.mjs (Vite, a
// static server, free ports), browser.mjs (Chromium and page helpers) and cpuTime.mjs (the CPU time
// Chromium's processes have run, for the island rows).
import { existsSync, statSync } from 'node:fs';
import { join, resolve } from 'node:path';
import * as app from './groups/app.mjs';
import * as cascades from './groups/cascades.mjs';
import { COMPARE_CLONE } from './groups/compare.mjs';
import * as fft2d from './groups/fft2d.mjs';
import * as fields from './groups/fields.mjs';
import * as frame from './groups/frame.mjs';
import * as island from './groups/island.mjs';
import * as lighting from './groups/lighting.mjs';
import * as living from './groups/living.mjs';
import * as reflections from './groups/reflections.mjs';
import * as webgpu from './groups/webgpu.mjs';
import * as parameterChange from './groups/parameter-change.mjs';
import * as queries from './groups/queries.mjs';
import * as queryFrames from './groups/query-frames.mjs';
import { emitSummary } from './groups/summary.mjs';
import { emitTargets } from './groups/targets.mjs';
import { openReady, withBenchBrowser } from './lib/browser.mjs';
import { log } from './lib/output.mjs';
import { createModuleServer } from './lib/servers.mjs';

const FIRST_PORT = process.env.BENCH_PORT ? Number(process.env.BENCH_PORT) : 5180;
if (!Number.isInteger(FIRST_PORT) || FIRST_PORT < 1024 || FIRST_PORT > 65000) throw new Error(`BENCH_PORT: not a port from 1024 to 65000: '${process.env.BENCH_PORT}'`);

/** The grids of the query-frames rows (`--query-frames=256` for one). */
/** The whole number above 0 given as `--<name>-rounds=<n>`, or undefined (the group's own default). */
function roundsArgument(name) {
  const prefix = `--${name}-rounds=`;
  const argument = process.argv.find((a) => a.startsWith(prefix));
  if (argument === undefined) return undefined;
  const rounds = Number(argument.slice(prefix.length));
  if (!(Number.isInteger(rounds) && rounds > 0)) throw new Error(`${prefix.slice(0, -1)}: not a whole number of rounds above 0: '${argument}'`);
  return rounds;
}
/** Frames timed per island, lighting and webgpu row (FRAME_ROUNDS by default; webgpu: its WEBGPU_ROUNDS). */
const ISLAND_ROUNDS = roundsArgument('island');
const LIGHTING_ROUNDS = roundsArgument('lighting');
const WEBGPU_ROUNDS = roundsArgument('webgpu');
const QUERY_FRAME_RESOLUTIONS = (process.argv.find((a) => a.startsWith('--query-frames='))?.slice(15) ?? '256,512,1024').split(',').map(Number);
const GROUPS = ['fft2d', 'fields', 'cascades', 'frame', 'lighting', 'living', 'reflections', 'island', 'queries', 'app', 'webgpu'];
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

/** The Node part: [group, step], in order; each step gets { server (Vite, for ssrLoadModule), results }. */
const NODE_STEPS = [
  ['fft2d', fft2d.node],
  ['fields', fields.node],
  ['cascades', cascades.node],
];

/**
 * The browser part: [group (null: always), step], in order; each step gets { browser, page (the
 * shared page), server, port, info, results, firstPort, compareDir, queryFrameResolutions }.
 */
const BROWSER_STEPS = [
  ['fields', fields.browser],
  ['cascades', cascades.browser],
  [null, ({ page, port }) => openReady(page, port, 'frame.html')], // frame, living, queries and parameter-change run there
  ['frame', frame.browser],
  ['lighting', lighting.browser],
  ['living', living.browser],
  ['reflections', reflections.browser],
  ['island', island.browser],
  ['queries', queries.browser],
  ['queries', queryFrames.browser],
  ['queries', parameterChange.browser],
  ['app', app.browser], // and compare
  ['webgpu', webgpu.browser], // in a Chromium of its own
  ['fields', fields.halfFloat], // back on the bench page
];

async function nodeBenchmarks(results) {
  log('loading src/sim through Vite (ssrLoadModule)');
  const server = await createModuleServer();
  try {
    for (const [group, step] of NODE_STEPS) if (wanted(group)) await step({ server, results });
  } finally {
    await server.close();
  }
}

async function browserBenchmarks(results) {
  await withBenchBrowser(FIRST_PORT, async (opened) => {
    const context = { ...opened, results, firstPort: FIRST_PORT, compareDir, queryFrameResolutions: QUERY_FRAME_RESOLUTIONS, islandRounds: ISLAND_ROUNDS, lightingRounds: LIGHTING_ROUNDS, webgpuRounds: WEBGPU_ROUNDS };
    for (const [group, step] of BROWSER_STEPS) if (group === null || wanted(group)) await step(context);
  });
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
  reflectionsCost: null,
  /** island-cost per quality and seabed-cost (bench/groups/island.mjs). */
  island: null,
  queries: null,
  app: {},
  /** dli/waves: { ms, N }, or { error }; null when not asked for (no --compare). */
  compare: null,
  /** The lighting group: { slopeLightCost, beaufortLookCostAtForce9 }. */
  lighting: null,
  /** The webgpu group: frameMs by subject, webgpuVsWebGL, webgpuVsWebGLSameDraw, fftMs by N and subject. */
  webgpu: null,
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

emitTargets(results);
emitSummary(results, browserError, started);
log(`done in ${((performance.now() - started) / 1000).toFixed(1)} s${exitCode ? ' (with failures, see above)' : ''}`);
process.stdout.write('', () => process.exit(exitCode));
