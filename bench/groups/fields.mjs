// A group of `npm run bench` (bench/run.mjs):
//
//   fields       CpuWaveFields.update(t) in Node ("js"); in headless Chromium (SwiftShader WebGL2)
//                GpuWaveFields.update(t) ("gpu-rgba32f", "gpu-rgba16f"), timed with a timer query
//                and with a 1-pixel readPixels sync, and CpuWaveFields.update(t) ("js-browser").
//   spectrum     (in Node, after the fields) createCascadeSpectra of the default cascades at
//                N = 256: what building the sea's initial spectra costs (the unit tests bound its
//                work, in evaluations of the spectrum, not its time).
import { openReady, withTimeout } from '../lib/browser.mjs';
import { emit, emitGpu, log } from '../lib/output.mjs';
import { BROWSER_ROUNDS, BROWSER_STEP_TIMEOUT_MS, BROWSER_WARMUP_ROUNDS, CASCADE_N, SIZES } from '../lib/settings.mjs';
import { stats, timeInterleaved } from '../lib/stats.mjs';

/** The fields rows of CpuWaveFields in Node ("js"); `server` loads the sources (ssrLoadModule). */
export async function node({ server, results }) {
  const { CpuWaveFields } = await server.ssrLoadModule('/src/fft/cpuWaveFields.ts');
  const { validateParameters } = await server.ssrLoadModule('/src/parameters/parameters.ts');
  const { createCascadeSpectra } = await server.ssrLoadModule('/src/spectrum/initialSpectrum.ts');
  for (const n of SIZES) {
    log(`fields N=${n}: CpuWaveFields.update in Node`);
    const params = validateParameters({ resolution: n });
    const fields = new CpuWaveFields(createCascadeSpectra(params)[0]);
    let t = 1.25;
    const [samples] = timeInterleaved([{ prepare: () => (t += 0.0371), run: () => fields.update(t) }], 2000);
    const row = stats(samples);
    results.jsFields[n] = row.ms;
    emit({ bench: 'fields', N: n, path: 'js', ...row });
  }
  log(`spectrum N=${CASCADE_N}: createCascadeSpectra in Node`);
  const params = validateParameters({ resolution: CASCADE_N });
  const [builds] = timeInterleaved([{ prepare: () => {}, run: () => createCascadeSpectra(params) }], 2000);
  emit({ bench: 'spectrum', N: CASCADE_N, cascades: params.patchSizes.length, path: 'js', ...stats(builds) });
}

/** window.bench.fields(options) in the bench page, within the step timeout. */
const runFields = (page, options) =>
  withTimeout(
    page.evaluate((o) => window.bench.fields(o), options),
    BROWSER_STEP_TIMEOUT_MS,
    `the browser benchmark at N=${options.resolution}`,
  );

/** The fields rows in Chromium: GPU (RGBA32F) and JS ("js-browser") at each N, on the bench page. */
export async function browser({ page, results }) {
  for (const n of SIZES) {
    log(`fields N=${n}: GPU (rgba32f) and JS in Chromium`);
    const samples = await runFields(page, {
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
}

/** Last of the browser groups, back on the bench page: the GPU row with RGBA16F, if the page has it. */
export async function halfFloat({ page, port, info, results }) {
  await openReady(page, port, 'bench.html');
  if (info.halfFloat) {
    log('fields N=256: GPU (rgba16f) in Chromium');
    const samples = await runFields(page, {
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
}
