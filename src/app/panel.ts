/**
 * The control panel (lil-gui), bound to the app's state (urlState.ts's AppState). Every change
 * goes through `apply`, which sets the ocean; if that throws (a ParameterError from
 * ocean.setParameters / setShading, or the sun's range check) the panel shows a warning naming
 * the parameter and goes back to the last good value, which the ocean also still has.
 *
 * Every controller's element carries data-key="<URL name>" (and the colour and absorption ones
 * data-key="absorption.0" etc.), for the browser tests.
 */
import GUI, { type Controller } from 'lil-gui';
import 'lil-gui/dist/lil-gui.css'; // as a file (see vite.config.ts): GUI's injected <style> breaks under a strict CSP
import { Color } from 'three';
import { colorToLinear, REFLECTIONS, REFRACTION_SOURCES, SHADING_MODES } from '../parameters/sceneOptions';
import { ParameterError, SPECTRUM_MODELS, SPREADING_MODELS } from '../parameters/parameters';
import { beaufortPreset, presetCloudCover, SEA_PRESETS } from '../spectrum/presets';
import { MIN_TARGET_FPS } from '../parameters/qualityOptions';
import { PATH_PREFERENCES } from '../layers/oceanSimulation';
import { assignState, cloneState, urlRounded, type AppState, type Rgb } from './urlState';
import { QUALITY_SETTINGS, type QualitySetting } from '../runtime/adaptiveQuality';

/**
 * The presets the panel offers: the named sea states, then Beaufort forces 0–12, each with the sky
 * it goes with (presetCloudCover: overcast from force 8).
 */
export const PANEL_PRESETS: Readonly<Record<string, Partial<AppState>>> = Object.freeze(
  Object.fromEntries(
    Object.entries({
      ...SEA_PRESETS,
      ...Object.fromEntries(Array.from({ length: 13 }, (_, force) => [`Beaufort ${force}`, beaufortPreset(force)])),
    }).map(([name, preset]) => [name, { ...preset, cloudCover: presetCloudCover(preset) }]),
  ),
);

export const RESOLUTIONS = [16, 32, 64, 128, 256, 512, 1024];

export interface PanelActions {
  /** Applies the changes to the scene; throws (ParameterError or Error) and changes nothing if one is bad. */
  apply(changes: Partial<AppState>): void;
  /** After a change was applied (e.g. to update the URL). */
  changed(): void;
  warn(parameter: string, message: string): void;
  clearWarning(parameter: string): void;
  copyLink(): void;
  /** Text for the read-only "running" line (the FFT path in use). */
  runningPath(): string;
  /** Text for the read-only sea-state line (significant wave height and peak period). */
  seaState(): string;
}

type Key = keyof AppState;

export class Panel {
  readonly gui: GUI;
  /** Controllers by URL name (the absorption channels as absorption.0 … absorption.2). */
  readonly controllers = new Map<string, Controller>();
  /** The last values the scene accepted. */
  private good: AppState;
  private readonly colours: { causticColor: string; scatterColor: string };
  private readonly depthProxy: { deep: boolean; metres: number };
  private readonly running = { path: '', seaState: '' };
  /** The preset menu's selection, and the patch sizes as text ("13.7,79.3,457"). */
  private readonly presetProxy = { preset: '' };
  private readonly patchSizesProxy = { text: '' };
  /** The Phillips amplitude in units of 10⁻⁶, which reads better on a slider. */
  private readonly amplitudeProxy = { micro: 0 };

  constructor(
    private readonly state: AppState,
    closed: boolean,
    private readonly actions: PanelActions,
  ) {
    this.good = cloneState(state);
    this.colours = { causticColor: toHex(state.causticColor), scatterColor: toHex(state.scatterColor) };
    this.depthProxy = { deep: state.depth === Infinity, metres: state.depth === Infinity ? 50 : state.depth };
    this.running.path = actions.runningPath();
    this.amplitudeProxy.micro = state.amplitude * 1e6;
    this.patchSizesProxy.text = state.patchSizes.join(',');

    const gui = (this.gui = new GUI({ title: 'Ocean', width: 280, injectStyles: false }));
    gui.domElement.classList.add('ocean-panel');

    const sea = gui.addFolder('Sea state');
    const preset = sea.add(this.presetProxy, 'preset', ['', ...Object.keys(PANEL_PRESETS)]).name('preset');
    preset.onChange((name: string) => name && this.preset(name));
    this.register('preset', preset);
    this.register('seaState', sea.add(this.running, 'seaState').name('Hs, Tp').disable());
    this.bind(sea.add(state, 'spectrum', SPECTRUM_MODELS as unknown as string[]).name('spectrum'), 'spectrum');
    this.number(sea, 'windSpeed', 'wind speed U10 (m/s)', 0, 60, 0.1);
    this.number(sea, 'windDirection', 'wind direction (°)', -180, 180, 1);
    this.number(sea, 'fetch', 'fetch (km)', 0.1, 2000, 0.1);
    this.number(sea, 'peakEnhancement', 'peak enhancement γ', 1, 10, 0.1);
    this.bind(sea.add(state, 'spreading', SPREADING_MODELS as unknown as string[]).name('spreading'), 'spreading');
    this.number(sea, 'spreadingExponent', 'cos-2s exponent s', 0, 100, 0.5);
    this.number(sea, 'swellHeight', 'swell height Hs (m)', 0, 30, 0.1);
    this.number(sea, 'swellPeriod', 'swell period Tp (s)', 1, 40, 0.1);
    this.number(sea, 'swellDirection', 'swell direction (°)', -180, 180, 1);
    this.number(sea, 'swellElongation', 'swell elongation ξ', 0, 1, 0.01);
    const amplitude = sea.add(this.amplitudeProxy, 'micro', 0, 20, 0.01).name('Phillips A (×10⁻⁶)');
    amplitude.onChange(() => this.change('amplitude', this.amplitudeProxy.micro * 1e-6));
    this.register('amplitude', amplitude);
    this.number(sea, 'choppiness', 'choppiness λ', 0, 4, 0.01);
    this.number(sea, 'foamAmount', 'whitecap foam (× physical)', 0, 10, 0.05);
    this.number(sea, 'foamPersistence', 'foam persistence τ (s)', 0.1, 30, 0.1);

    const sim = gui.addFolder('Simulation');
    this.bind(sim.add(state, 'resolution', RESOLUTIONS).name('resolution N'), 'resolution');
    const patchSizes = sim.add(this.patchSizesProxy, 'text').name('cascade sizes (m)');
    patchSizes.onFinishChange((text: string) => this.change('patchSizes', text.split(',').map(Number)));
    this.register('patchSizes', patchSizes);
    this.number(sim, 'smallWaveCutoff', 'small-wave cutoff ℓ (m)', 0, 2, 0.001);
    const deep = sim.add(this.depthProxy, 'deep').name('deep water');
    const depth = sim.add(this.depthProxy, 'metres', 0.5, 200, 0.5).name('depth (m)');
    deep.onChange(() => this.change('depth', this.depthProxy.deep ? Infinity : this.depthProxy.metres));
    depth.onChange(() => this.change('depth', this.depthProxy.metres));
    this.register('depth.deep', deep);
    this.register('depth', depth);
    this.number(sim, 'repeatPeriod', 'repeat period (s)', 10, 10000, 1);
    this.bind(sim.add(state, 'seed').name('seed').step(1), 'seed');
    const seedActions = { newSeed: () => this.change('seed', Math.floor(Math.random() * 2 ** 32)) };
    this.register('newSeed', sim.add(seedActions, 'newSeed').name('new seed'));
    this.bind(sim.add(state, 'path', [...PATH_PREFERENCES]).name('FFT path'), 'path');
    this.register('running', sim.add(this.running, 'path').name('running').disable());

    const look = gui.addFolder('Sun & shading');
    this.number(look, 'sunElevation', 'sun elevation (°)', -10, 90, 0.5);
    this.number(look, 'sunAzimuth', 'sun azimuth (°)', -180, 180, 1);
    this.number(look, 'cloudCover', 'cloud cover', 0, 1, 0.05);
    this.bind(look.add(state, 'mode', SHADING_MODES as unknown as string[]).name('shading mode'), 'mode');
    this.bind(look.add(state, 'refractions', REFRACTION_SOURCES as unknown as string[]).name('seen through the water'), 'refractions');
    this.bind(look.add(state, 'reflections', REFLECTIONS as unknown as string[]).name('reflections'), 'reflections');
    this.number(look, 'ior', 'refractive index', 1.01, 2.5, 0.001);
    this.number(look, 'causticPower', 'caustic power p', 1, 256, 1);
    this.colour(look, 'causticColor', 'caustic colour');
    (['r', 'g', 'b'] as const).forEach((channel, i) => {
      const c = look.add(state.absorption as unknown as Record<string, number>, String(i), 0, 2, 0.005).name(`absorption ${channel} (1/m)`);
      c.onChange(() => this.change('absorption', [...state.absorption] as Rgb));
      this.register(`absorption.${i}`, c);
    });
    this.colour(look, 'scatterColor', 'scatter colour');
    this.bind(look.add(state, 'wireframe').name('wireframe'), 'wireframe');

    const time = gui.addFolder('Time & view');
    this.number(time, 'timeScale', 'time scale', 0, 4, 0.05);
    this.bind(time.add(state, 'paused').name('pause'), 'paused');
    this.bind(time.add(state, 't').name('time t (s)').step(0.001).decimals(2).listen(), 't');
    this.bind(time.add(state, 'inspector').name('inspector tiles'), 'inspector');
    this.bind(time.add(state, 'buoys').name('buoys'), 'buoys');
    this.bind(time.add(state, 'boat').name('boat (wake)'), 'boat');
    this.bind(time.add(state, 'scene', { 'open sea': 'sea', island: 'island' }).name('scene'), 'scene');
    this.bind(time.add(state, 'quality', QUALITY_SETTINGS as QualitySetting[]).name('quality'), 'quality');
    this.number(time, 'targetFps', "'auto' holds (fps)", MIN_TARGET_FPS, 120, 1);
    this.register('copyLink', time.add({ copyLink: () => actions.copyLink() }, 'copyLink').name('copy link'));

    this.syncDepthControls();
    // Less used folders start closed so the panel fits a laptop screen.
    look.close();
    if (closed) gui.close();
  }

  /** Call once per frame: refreshes the read-only lines (the path running, the sea state's Hs and Tp). */
  update(): void {
    const path = this.actions.runningPath();
    if (path !== this.running.path) {
      this.running.path = path;
      this.controllers.get('running')?.updateDisplay();
    }
    const seaState = this.actions.seaState();
    if (seaState !== this.running.seaState) {
      this.running.seaState = seaState;
      this.controllers.get('seaState')?.updateDisplay();
    }
  }

  /** Shows the state again after it changed outside the panel (and takes it as the last good one). */
  refresh(): void {
    this.good = cloneState(this.state);
    this.colours.causticColor = toHex(this.state.causticColor);
    this.colours.scatterColor = toHex(this.state.scatterColor);
    this.amplitudeProxy.micro = Number((this.state.amplitude * 1e6).toPrecision(10));
    this.patchSizesProxy.text = this.state.patchSizes.join(',');
    this.depthProxy.deep = this.state.depth === Infinity;
    if (!this.depthProxy.deep) this.depthProxy.metres = this.state.depth;
    this.syncDepthControls();
    for (const controller of this.gui.controllersRecursive()) controller.updateDisplay();
  }

  /** Applies a preset's simulation parameters and its sky's cloud cover (all or nothing). */
  preset(name: string): void {
    this.changeMany(PANEL_PRESETS[name], `preset ${name}`);
    this.presetProxy.preset = '';
    this.controllers.get('preset')?.updateDisplay();
  }

  /** Sets one value as if it had been entered in the panel. */
  change<K extends Key>(key: K, value: AppState[K]): boolean {
    return this.changeMany({ [key]: value } as Partial<AppState>, key);
  }

  private changeMany(changes: Partial<AppState>, label: string): boolean {
    const rounded: Partial<AppState> = {};
    for (const key of Object.keys(changes) as Key[]) {
      (rounded as Record<string, unknown>)[key] = urlRounded(key, changes[key] as AppState[Key]);
    }
    try {
      this.actions.apply(rounded);
    } catch (error) {
      const parameter = error instanceof ParameterError ? error.parameter : label;
      const message = error instanceof Error ? error.message.replace(/^SkyEnvironment: /, '') : String(error);
      const keys = Object.keys(changes) as Key[];
      const kept = keys.map((key) => `${key} ${describe(this.good[key])}`).join(', ');
      this.actions.warn(parameter, `${message} — keeping ${kept}`);
      // Back to the last good values (the scene kept them: the setters change nothing on error).
      const { t, cam } = this.state;
      assignState(this.state, { ...cloneState(this.good), t, cam });
      this.refresh();
      return false;
    }
    assignState(this.state, rounded);
    for (const key of Object.keys(rounded) as Key[]) {
      (this.good as unknown as Record<string, unknown>)[key] = cloneState(this.state)[key];
      this.actions.clearWarning(key);
    }
    this.actions.clearWarning(label);
    this.refresh();
    this.actions.changed();
    return true;
  }

  private register(key: string, controller: Controller): Controller {
    controller.domElement.dataset.key = key;
    this.controllers.set(key, controller);
    return controller;
  }

  /** A controller bound straight to state[key]: lil-gui has already set the value when onChange runs. */
  private bind(controller: Controller, key: Key): Controller {
    controller.onChange((value: unknown) => {
      // Undo lil-gui's write so `good` comparisons and the revert see the old value, then apply.
      (this.state as unknown as Record<string, unknown>)[key] = this.good[key];
      this.change(key, value as AppState[Key]);
    });
    return this.register(key, controller);
  }

  private number(folder: GUI, key: Key, name: string, min: number, max: number, step: number): Controller {
    return this.bind(folder.add(this.state, key, min, max, step).name(name), key);
  }

  private colour(folder: GUI, key: 'causticColor' | 'scatterColor', name: string): void {
    const controller = folder.addColor(this.colours, key).name(`${name} (sRGB)`);
    // The picker's sRGB hex, as linear RGB.
    controller.onChange((hex: string) => this.change(key, colorToLinear(hex)!));
    this.register(key, controller);
  }

  private syncDepthControls(): void {
    this.controllers.get('depth')?.enable(!this.depthProxy.deep);
  }
}

/** Linear RGB (the shader's units) → sRGB hex for the colour picker. */
function toHex(rgb: Rgb): string {
  return `#${new Color().setRGB(rgb[0], rgb[1], rgb[2]).getHexString()}`;
}


function describe(value: unknown): string {
  if (value === Infinity) return 'deep';
  if (Array.isArray(value)) return value.join(',');
  return String(value);
}
