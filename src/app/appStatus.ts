/**
 * The figures the app's status line shows (statusOverlay.ts draws them): the sea state, the FFT
 * path and why, the frame's CPU times averaged over half a second, the time, the fly speed and the
 * quality level; refreshed at most every 250 ms.
 */
import type { Ocean, OceanPath } from '../ocean';
import type { SceneOutput } from '../render/sceneOutput';
import type { FrameLoop } from '../runtime/frameLoop';
import type { FlyControls } from './flyControls';
import { describeSeaState, PATH_LABELS, TimingAverager, type StatusOverlay } from './statusOverlay';
import type { AppState } from './urlState';

export class AppStatus {
  private readonly averager = new TimingAverager(500);
  private lastStatus = 0;

  constructor(
    private readonly overlay: StatusOverlay,
    private readonly parts: { ocean: Ocean; state: AppState; loop: FrameLoop; output: SceneOutput; controls: FlyControls },
  ) {}

  /** A frame started at `start`, had the sea simulated by `simulated` and rendered by `rendered` (ms). */
  frame(start: number, simulated: number, rendered: number): void {
    const { ocean, state, loop, output, controls } = this.parts;
    this.averager.add(rendered, simulated - start, rendered - simulated);
    if (rendered - this.lastStatus <= 250) return;
    const time = { t: state.t, paused: state.paused, timeScale: state.timeScale, ratio: loop.clock.timeRatio };
    const { pathReason, pathPreference } = ocean.simulation;
    const { quality } = loop;
    const qualityStatus = {
      level: quality.level,
      auto: quality.setting === 'auto',
      targetFps: quality.targetFps,
      frameMs: quality.medianFrameMs,
      renderScale: quality.step.renderScale,
      msaa: output.msaa,
      resolution: ocean.parameters.resolution,
      cascades: ocean.parameters.patchSizes.length,
    };
    this.overlay.show(describeSeaState(ocean), ocean.simulation.path, this.averager.latest, time, controls.speed, pathPreference === 'js' ? '' : pathReason, qualityStatus);
    this.lastStatus = rendered;
  }
}

/**
 * The status line of the app on WebGPURenderer (appWebGPU.ts): the renderer and its backend (and
 * why not WebGPU), the FFT that runs (the compute FFT, or the JS FFT in workers or on the main
 * thread: ocean.path.running) and why not a better one, and the quality level.
 */
export function webgpuStatusLine(backend: string, fallback: string | null, path: OceanPath, quality: { level: string; auto: boolean }): string {
  const fft = path.running.startsWith('gpu') ? 'compute shaders' : path.running === 'js' ? 'JS (main thread)' : PATH_LABELS[path.running];
  const why = path.reason && path.preference !== 'js' ? ` (${path.reason})` : '';
  return `WebGPURenderer, ${backend} backend${fallback ? ` (${fallback})` : ''} · three-fft-ocean/webgpu · FFT: ${fft}${why} · quality ${quality.level}${quality.auto ? ' (auto)' : ''}`;
}
