/**
 * Test page for the rendered ocean: the real simulation, surface and environment in this page's
 * WebGL2 context (oceanPage.ts), with hooks for the Playwright tests: the surface read back from
 * its vertex shader (geometryCapture.ts), pictures (pictures.ts), the queries (queries.ts) and
 * the queries' workers (queryWorkers.ts).
 */
import { Color, PerspectiveCamera, Scene, Vector3 } from 'three';
import { DisposedError, Ocean } from '../../../src/ocean';
import { ParameterError } from '../../../src/parameters/options';
import type { WaveLayer } from '../../../src/layers/waveLayer';
import { geometryCheck } from './geometryCapture';
import { composerCheck, depthBufferCheck, fogCheck, foamBrightened, holesBelowHorizon, nightCheck, probe, snellWindow } from './pictures';
import { batchQueries, heightAtCheck, horizonCheck, localWavesQueriedOnGpu, queriesWithLocalWaves } from './queries';
import { queriesFromWorkers, warmUpLeavesNoTrace, workerFault } from './queryWorkers';
import { current, pixel, render, renderer, resetPage, setUniformEnvironment, setup, sunDirection, view } from './oceanPage';

const harness = {
  /** For tests of the Ocean's API. */
  renderer,
  Ocean,
  ParameterError,
  DisposedError,
  Color,
  Vector3,
  Scene,
  PerspectiveCamera,
  /** The page as it loaded, for the next test on a shared page. */
  reset: resetPage,
  setup,
  view,
  setUniformEnvironment,
  render,
  pixel,
  geometryCheck,
  /** Adds a layer to setup's simulation (the contract's way in, as Ocean.addLayer). */
  addLayer(layer: WaveLayer): void {
    current.simulation!.addLayer(layer);
  },
  foamBrightened,
  heightAtCheck,
  queriesWithLocalWaves,
  batchQueries,
  snellWindow,
  fogCheck,
  depthBufferCheck,
  composerCheck,
  nightCheck,
  warmUpLeavesNoTrace,
  queriesFromWorkers,
  localWavesQueriedOnGpu,
  workerFault,
  horizonCheck,
  probe,
  holesBelowHorizon,
  setSun(direction: [number, number, number]): void {
    sunDirection.fromArray(direction).normalize();
  },
};

declare global {
  interface Window {
    ocean: typeof harness;
  }
}
window.ocean = harness;

document.title = 'ready';
