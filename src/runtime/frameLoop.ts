/**
 * The frame loop the app (src/app/app.ts) and <fft-ocean> (src/embed/fftOceanElement.ts) share:
 * per animated frame, simulated time advances by the real frame time × the time scale
 * (SimulationClock) and the adaptive quality measures the frame (AdaptiveQuality); per drawn
 * frame, the time is kept within what a double resolves (wrapLongTime, the one place it is
 * wrapped), the ocean is updated to it for the camera, the far plane reaches the horizon
 * (fitFarPlane) and the scene is rendered through the SceneOutput of the quality level.
 *
 * What calls it stays the shell's: the app runs a frame on every animation frame
 * (renderer.setAnimationLoop), the element only while it is on screen and animating or out of date.
 *
 *   const loop = new FrameLoop(new AdaptiveQuality('auto', 30), { t: 0 });
 *   // each frame:
 *   if (loop.advance(now, paused ? 0 : timeScale)) applyQualityStep(target, asked, loop.quality.step);
 *   loop.draw({ ocean, scene, camera, output });
 */
import type { PerspectiveCamera, Scene } from 'three';
import type { Ocean } from '../ocean';
import type { SceneOutput } from '../render/sceneOutput';
import type { AdaptiveQuality } from './adaptiveQuality';
import { fitFarPlane } from './farPlane';
import { SimulationClock, wrapLongTime } from './simulationClock';

/** What a frame draws: the ocean in its scene, seen by the camera, onto the output. */
export interface FrameScene {
  ocean: Ocean;
  scene: Scene;
  camera: PerspectiveCamera;
  output: SceneOutput;
}

/** Hooks into a drawn frame, for what the shell moves besides the sea. */
export interface FrameHooks {
  /** Puts the camera for time `t` (s), before the ocean is updated for it (the element's drifting view). */
  placeCamera?(t: number): void;
  /** After the ocean is updated to `t`, before the render: floating objects, lights. */
  beforeRender?(t: number): void;
}

export class FrameLoop {
  /** Real frame time × time scale per animated frame; restart() it when frames stop on purpose. */
  readonly clock = new SimulationClock();

  /**
   * @param quality the adaptive quality in force; replace it when its setting or target changes
   * @param time holds the simulated time shown (s), read and written by the loop: the app's
   *   state (its t), the element's own
   */
  constructor(
    public quality: AdaptiveQuality,
    readonly time: { t: number },
  ) {}

  /**
   * An animated frame at `nowMs` (a requestAnimationFrame timestamp): simulated time advances by
   * the real time since the last frame × `rate` (simulated seconds per real second; 0 while
   * paused), and, when `measure`, the adaptive quality measures the frame. Returns whether the
   * quality level changed: the caller puts the new level in force (applyQualityStep) before it draws.
   */
  advance(nowMs: number, rate: number, measure = true): boolean {
    this.time.t += this.clock.advance(nowMs, rate);
    return measure && this.quality.frame(this.clock.realStep);
  }

  /** The next frame advances nothing (a hidden tab, an element off screen, a lost context, paused). */
  restart(): void {
    this.clock.restart();
  }

  /**
   * Draws the time held: wraps it within what a double resolves (the same sea; a time set far
   * ahead, 1e300, would otherwise put the view where coordinates overflow, and t += dt would stand
   * still), places the camera (hooks), updates the ocean to it for the camera, moves the far plane
   * out to the horizon, and renders. Returns the time drawn.
   */
  draw(frame: FrameScene, hooks: FrameHooks = {}): number {
    const { ocean, scene, camera, output } = frame;
    const t = (this.time.t = wrapLongTime(this.time.t, ocean.repeatPeriod));
    hooks.placeCamera?.(t);
    ocean.update(t, camera);
    fitFarPlane(camera, ocean);
    hooks.beforeRender?.(t);
    output.render(scene, camera);
    return t;
  }
}
