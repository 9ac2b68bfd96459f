/**
 * When and how <fft-ocean> draws: it draws only while it is active (near the screen with a
 * context, on screen, its tab visible), every animation frame while time runs and on changes while
 * paused; the shared frame loop (src/runtime/frameLoop.ts) advances the time, holds the quality
 * level, updates the sea for the drifting view (defaultView.ts), fits the far plane and renders.
 * The drawing buffer follows the element's box.
 */
import { Vector2 } from 'three';
import { AdaptiveQuality } from '../runtime/adaptiveQuality';
import { applyQualityStep, applyWebGPUQualityStep } from '../runtime/applyQuality';
import { FrameLoop } from '../runtime/frameLoop';
import { validateParameters, type SimulationParameters } from '../parameters/parameters';
import { ELEMENT_DEFAULTS, sunAzimuthOf, type Settings } from './elementAttributes';
import { placeCamera } from './defaultView';
import type { Live } from './elementScene';
import { drawWebGPU, type WebGPULive } from './elementWebGPU';

/** What the frames need of their element. */
export interface FramesHost {
  /** The element: its box's size, and what the frames' events are dispatched on. */
  readonly element: HTMLElement;
  readonly settings: Readonly<Settings>;
  /** The live parts (with either renderer), or null while the element holds none. */
  live(): Live | WebGPULive | null;
  /** Whether a part of the element is inside the viewport. */
  onScreen(): boolean;
  /** Drawing failed: say so and stop. */
  fail(text: string, error: unknown): void;
}

/** The drawing of one element. */
export class ElementFrames {
  /**
   * The frame loop (runtime/frameLoop.ts): its clock, restarted whenever drawing stops or pauses,
   * its adaptive quality (the quality and target-fps attributes; kept while the element has no
   * context) and the simulated time shown.
   */
  readonly loop = new FrameLoop(new AdaptiveQuality(ELEMENT_DEFAULTS.quality, ELEMENT_DEFAULTS.targetFps), { t: 0 });
  /** Frames drawn since the element was created. */
  framesDrawn = 0;
  private frameRequest = 0;
  private needsDraw = true;

  constructor(private readonly host: FramesHost) {}

  /** Whether the element draws frames now (on the page, on screen, tab visible, context alive). */
  isActive(): boolean {
    const live = this.host.live();
    return !!live && this.host.onScreen() && !live.contextLost && document.visibilityState !== 'hidden';
  }

  /** Something changed that affects whether frames are drawn. */
  activityChanged(): void {
    this.loop.restart(); // the time that passed while inactive is not simulated
    this.invalidate();
  }

  /** The picture is out of date: draw on the next frame if active. */
  invalidate(): void {
    this.needsDraw = true;
    this.schedule();
  }

  /** No more frames (the live parts are going): the next ones start afresh. */
  stop(): void {
    if (this.frameRequest) cancelAnimationFrame(this.frameRequest);
    this.frameRequest = 0;
    this.loop.restart();
    this.needsDraw = true;
  }

  /**
   * Puts the quality level in force for the simulation `asked`: pixel ratio, MSAA, grid and
   * cascades (applyQuality.ts); with the WebGPU Ocean the same but MSAA.
   */
  applyQuality(live: Live | WebGPULive, asked: Readonly<SimulationParameters> = validateParameters(this.host.settings.simulation)): void {
    if (live.kind === 'webgl') applyQualityStep(live, asked, this.loop.quality.step);
    else applyWebGPUQualityStep(live, asked, this.loop.quality.step);
  }

  /** Fits the camera and the drawing buffer to the element's box. */
  resize(): void {
    const live = this.host.live();
    if (!live) return;
    const width = Math.max(1, this.host.element.clientWidth);
    const height = Math.max(1, this.host.element.clientHeight);
    live.camera.aspect = width / height;
    live.camera.updateProjectionMatrix();
    // The ResizeObserver's first report after start() is of the size start() set: keep the picture.
    const current = live.renderer.getSize(new Vector2());
    if (current.x === width && current.y === height) return;
    live.renderer.setSize(width, height, false);
    // Resizing clears the canvas: draw again right away so it never shows blank.
    if (this.isActive()) this.draw(live);
    else this.needsDraw = true;
  }

  /** Draws the current time now. */
  draw(live: Live | WebGPULive): void {
    this.needsDraw = false;
    const { settings, element } = this.host;
    const sunAzimuth = sunAzimuthOf(settings);
    const place = (t: number) => placeCamera(live.camera, t, settings.cameraHeight, sunAzimuth);
    if (live.kind === 'webgpu') {
      drawWebGPU(live, this.loop.time.t, place);
    } else {
      // The time wrapped as a double resolves it, the sea updated for the drifting view, the far plane, the render.
      this.loop.draw(live, {
        placeCamera: place,
        beforeRender: () => {
          live.boat?.boat.update();
          live.boat?.light.update();
        },
      });
    }
    this.framesDrawn++;
    if (this.framesDrawn === 1) element.dispatchEvent(new CustomEvent('fft-ocean-ready'));
  }

  private schedule(): void {
    if (this.frameRequest === 0 && this.isActive()) this.frameRequest = requestAnimationFrame(this.tick);
  }

  private readonly tick = (now: number): void => {
    this.frameRequest = 0;
    const live = this.host.live();
    if (!live || !this.isActive()) {
      this.loop.restart();
      return;
    }
    const { settings, element } = this.host;
    const animating = !settings.paused;
    // Only frames drawn one after another tell how fast they come (paused, frames come on changes).
    if (animating && this.loop.advance(now, settings.timeScale)) {
      this.applyQuality(live);
      const { level, medianFrameMs } = this.loop.quality;
      element.dispatchEvent(new CustomEvent('fft-ocean-quality-change', { detail: { level, medianFrameMs } }));
    }
    if (animating || this.needsDraw) {
      try {
        this.draw(live);
      } catch (error) {
        // Nothing to recover with: say so in the box and to the page (fft-ocean-error), and stop.
        this.host.fail('Drawing the ocean failed; it has stopped.', error);
        return; // no further frames
      }
    }
    if (animating) this.schedule();
  };
}
