/**
 * Puts a quality level (adaptiveQuality.ts) in force on a render loop's renderer, output and
 * ocean: shared by the app and <fft-ocean>, so that a level means the same in both.
 */
import type { WebGLRenderer } from 'three';
import type { Ocean } from '../ocean';
import { ParameterError } from '../parameters/options';
import type { SimulationParameters } from '../parameters/parameters';
import type { SceneOutput } from '../render/sceneOutput';
import { simulationAtQuality, type QualityStep } from './adaptiveQuality';

export interface QualityTarget {
  renderer: WebGLRenderer;
  output: SceneOutput;
  ocean: Ocean;
  /** The pixel ratio at render scale 1 (the device's, capped). */
  pixelRatio: number;
}

/**
 * Sets the pixel ratio, MSAA, grid floor, refraction capture's scale and reflection size of `step`, and has the ocean run the grid and the cascades `asked`
 * for within the step's (the ocean is rebuilt only when they change).
 */
export function applyQualityStep({ renderer, output, ocean, pixelRatio }: QualityTarget, asked: Readonly<SimulationParameters>, step: QualityStep): void {
  renderer.setPixelRatio(pixelRatio * step.renderScale);
  output.msaa = step.msaa;
  ocean.surface.fewestCellsPerRing = step.fewestGridCells;
  ocean.surface.refraction.scale = step.refractionScale;
  ocean.surface.reflectionScale = step.reflectionScale;
  const wanted = simulationAtQuality(asked, step);
  const running = ocean.parameters;
  const samePatches = running.patchSizes.length === wanted.patchSizes.length && running.patchSizes.every((size, i) => size === wanted.patchSizes[i]);
  if (running.resolution === wanted.resolution && samePatches) return;
  // Cascades this far apart may need the finer grid (parameters.ts): then keep the grid and still
  // cut the cascades (fewer of the largest never need more); failing that, keep both.
  for (const changes of [wanted, { patchSizes: wanted.patchSizes }]) {
    try {
      ocean.setParameters(changes);
      return;
    } catch (error) {
      if (!(error instanceof ParameterError)) throw error;
    }
  }
}
