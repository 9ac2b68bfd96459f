/**
 * What a change of the app's state (from the panel, or oceanApp.set) does to the scene: the
 * ocean's parameters, shading, sun and path, the quality level, the wireframe, the extras, and a
 * hint when the caustics mode would look broken.
 */
import type { Ocean } from '../ocean';
import { AdaptiveQuality } from '../runtime/adaptiveQuality';
import type { FrameLoop } from '../runtime/frameLoop';
import { validateParameters, type SimulationParameters } from '../parameters/parameters';
import type { AppExtras } from './appExtras';
import type { StatusOverlay } from './statusOverlay';
import { roundTime, simulationParameters, type AppState } from './urlState';

/** What changes act on. */
export interface ChangeTarget {
  ocean: Ocean;
  state: AppState;
  loop: FrameLoop;
  extras: AppExtras;
  overlay: StatusOverlay;
  /** Puts the quality level in force for the simulation `asked`. */
  applyQuality(asked: Readonly<SimulationParameters>): void;
  /** Puts the open sea or the island in the scene (sceneChoice.ts). */
  showScene(choice: AppState['scene']): void;
}

/** Applies changes to the scene; throws (and changes nothing) when the ocean rejects a value. */
export function applyChanges({ ocean, state, loop, extras, overlay, applyQuality, showScene }: ChangeTarget, changes: Partial<AppState>): void {
  const has = (key: keyof AppState) => Object.hasOwn(changes, key);
  const simulation: Record<string, unknown> = Object.fromEntries(Object.entries(changes).filter(([key]) => key in ocean.parameters));
  // What is asked for must hold at every level (the grid and cascades may rise again later); the
  // ocean runs its grid and cascades within the level's (applyQualityStep), the rest as asked.
  const asked = validateParameters({ ...simulationParameters(state), ...simulation });
  const { resolution, patchSizes, ...rest } = simulation;
  if (Object.keys(rest).length > 0) ocean.setParameters(rest);
  const newQuality = changes.quality !== undefined || changes.targetFps !== undefined;
  if (newQuality) loop.quality = new AdaptiveQuality(changes.quality ?? state.quality, changes.targetFps ?? state.targetFps);
  if (newQuality || resolution !== undefined || patchSizes !== undefined) applyQuality(asked);
  const shading = {
    ior: changes.ior,
    absorption: changes.absorption,
    scatterColor: changes.scatterColor,
    causticPower: changes.causticPower,
    causticColor: changes.causticColor,
    shadingMode: changes.mode,
    refractions: changes.refractions,
    reflections: changes.reflections,
  };
  if (Object.values(shading).some((value) => value !== undefined)) ocean.setShading(shading);
  if (has('sunElevation') || has('sunAzimuth') || has('cloudCover')) {
    ocean.setSun({ elevation: changes.sunElevation ?? state.sunElevation, azimuth: changes.sunAzimuth ?? state.sunAzimuth, cloudCover: changes.cloudCover ?? state.cloudCover });
  }
  if (changes.path !== undefined) ocean.simulation.pathPreference = changes.path;
  if (changes.wireframe !== undefined) ocean.surface.material.wireframe = changes.wireframe;
  if (changes.inspector !== undefined) extras.showInspector(changes.inspector);
  if (changes.buoys !== undefined) extras.showBuoys(changes.buoys, state.t);
  if (changes.boat !== undefined) extras.showBoat(changes.boat);
  if (changes.scene !== undefined) showScene(changes.scene);
  if (changes.paused) changes.t = roundTime(state.t); // a paused t is exactly what the URL holds
  hintCaustics(overlay, changes.mode ?? state.mode, changes.sunElevation ?? state.sunElevation);
}

/**
 * The caustics mode (the report's Figure 9) is black under a low sun, which looks broken: say why.
 * Guardado's term (shaders/surface/caustics.glsl) lights the surface where a vertical ray leaving
 * the water points at the sun, which a sun lower than about 60° needs slopes steeper than waves have.
 */
export function hintCaustics(overlay: StatusOverlay, mode: AppState['mode'], sunElevation: number): void {
  if (mode === 'caustics' && sunElevation < 60) {
    overlay.warn('caustics', `caustics: a sun ${sunElevation.toFixed(0)}° high lights almost none of the sea in this term; raise the sun above 60° (Sun & shading) to see the pattern`);
  } else {
    overlay.clearWarning('caustics');
  }
}
