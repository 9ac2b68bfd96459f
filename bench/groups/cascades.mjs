// A group of `npm run bench` (bench/run.mjs):
//
//   cascades     one update of every cascade ("wave layer") of C = 1, 3 and 4 FFT cascades at
//                N = 256 (patch sizes CASCADE_SETS, one cascade per size, all fields of each): the
//                JS path (CpuWaveFields.update of each cascade in turn) in Node ("js") and in
//                Chromium ("js-browser"), and the GPU path (GpuWaveFields.update of each, RGBA32F,
//                all cascades inside one timer query, "timer-query", and between two 1-pixel
//                readPixels, "readpixels-sync") as "gpu-rgba32f". The cascade counts are timed
//                interleaved, round by round. `passes` is the fragment passes over all cascades.
import { withTimeout } from '../lib/browser.mjs';
import { emit, emitGpu, log } from '../lib/output.mjs';
import { BROWSER_STEP_TIMEOUT_MS, BROWSER_WARMUP_ROUNDS, CASCADE_COUNTS, CASCADE_N, CASCADE_SETS } from '../lib/settings.mjs';
import { stats, timeInterleaved } from '../lib/stats.mjs';

/** Browser rounds of the cascades bench (each round times every cascade count and path once). */
const CASCADE_ROUNDS = 40;

/** The cascades rows of the JS path in Node ("js"); `server` loads the sources (ssrLoadModule). */
export async function node({ server, results }) {
  const { CpuWaveFields } = await server.ssrLoadModule('/src/fft/cpuWaveFields.ts');
  const { validateParameters } = await server.ssrLoadModule('/src/parameters/parameters.ts');
  const { createCascadeSpectra } = await server.ssrLoadModule('/src/spectrum/initialSpectrum.ts');
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
}

/** The cascades rows in Chromium: the GPU path (RGBA32F) and the JS path ("js-browser"), on the bench page. */
export async function browser({ page, results }) {
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
