/**
 * Puts a quality level (adaptiveQuality.ts) in force on a render loop's renderer, output and
 * ocean, WebGL or WebGPU: shared by the app and <fft-ocean>, so that a level means the same in all.
 */
import type { WebGLRenderer } from 'three';
import type { WebGPURenderer } from 'three/webgpu';
import type { Ocean } from '../ocean';
import type { Ocean as WebGPUOcean } from '../webgpu/ocean';
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

/** A render loop's WebGPURenderer and WebGPU Ocean. */
export interface WebGPUQualityTarget {
  renderer: WebGPURenderer;
  ocean: WebGPUOcean;
  /** The pixel ratio at render scale 1. */
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
  simulateAtQuality(ocean, asked, step);
}

/**
 * The same level on the WebGPU Ocean (src/webgpu/ocean.ts): the pixel ratio, the grid floor, and
 * the grid and cascades. Not its MSAA (WebGPURenderer takes its samples once, when made: the app
 * and <fft-ocean> make it without) nor the captures' scales (it draws no scene captures yet).
 */
export function applyWebGPUQualityStep({ renderer, ocean, pixelRatio }: WebGPUQualityTarget, asked: Readonly<SimulationParameters>, step: QualityStep): void {
  renderer.setPixelRatio(pixelRatio * step.renderScale);
  ocean.fewestCellsPerRing = step.fewestGridCells;
  simulateAtQuality(ocean, asked, step);
}

/** Has `ocean` run the grid and the cascades `asked` for within `step`'s (rebuilt only when they change). */
function simulateAtQuality(ocean: Pick<Ocean, 'parameters' | 'setParameters'>, asked: Readonly<SimulationParameters>, step: QualityStep): void {
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
