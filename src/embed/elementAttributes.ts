/**
 * The attributes of <fft-ocean> (src/embed/fftOceanElement.ts lists them for users): which ones it
 * reads, the settings they hold, and how a change reaches the ocean. Every option of the tables in
 * src/parameters/ is an attribute in kebab case (an alias too), read as parseOptionText reads it
 * and routed to ocean.setParameters, setSun or setShading; the element's own (path, time-scale,
 * quality, target-fps) are read by the same tables' rules, as the app's URL reads them; paused,
 * camera-height and boat are its own.
 *
 * A bad value logs a console warning that names the attribute and quotes the value as written,
 * and the last good value stays; removing an attribute restores its default.
 */
import type { Ocean, OceanOptions } from '../ocean';
import { AdaptiveQuality, simulationAtQuality, type QualitySetting, type QualityStep } from '../runtime/adaptiveQuality';
import type { FrameLoop } from '../runtime/frameLoop';
import { DEFAULT_QUALITY, QUALITY_OPTIONS } from '../parameters/qualityOptions';
import { formatOptionText, kebabCase, optionRoutes, parseOptionText, quoteText, type OptionRule } from '../parameters/options';
import { DEFAULT_RUN, RUN_OPTIONS, type RendererChoice } from '../parameters/runOptions';
import { DEFAULT_SHADING, DEFAULT_SUN, SHADING_OPTIONS, SUN_OPTIONS, type ShadingOptions, type SunOptions } from '../parameters/sceneOptions';
import type { PathPreference } from '../layers/oceanSimulation';
import { DEFAULT_PARAMETERS, parseDecimal, SIMULATION_OPTIONS, validateParameters, type SimulationParameters } from '../parameters/parameters';

/** The parts of the settings that attributes set from an option table. */
type Group = 'simulation' | 'sun' | 'shading';
const TABLES: Readonly<Record<Group, Readonly<Record<string, OptionRule>>>> = {
  simulation: SIMULATION_OPTIONS,
  sun: SUN_OPTIONS,
  shading: SHADING_OPTIONS,
};
const GROUP_DEFAULTS: Readonly<Record<Group, Readonly<Record<string, unknown>>>> = {
  simulation: DEFAULT_PARAMETERS,
  sun: DEFAULT_SUN,
  shading: DEFAULT_SHADING,
};

/** Attributes that map onto options: each option's name, and each alias, in kebab case. */
const OPTION_ATTRIBUTES = optionRoutes(TABLES, kebabCase);

/**
 * The element's own settings that a table's rule reads, as the app's URL reads them: path and
 * time-scale (parameters/runOptions.ts), quality and target-fps (parameters/qualityOptions.ts).
 */
const OWN_TABLES = { run: RUN_OPTIONS, quality: QUALITY_OPTIONS } as const;
const OWN_ATTRIBUTES = optionRoutes<keyof typeof OWN_TABLES>(OWN_TABLES, kebabCase);
type OwnKey = 'renderer' | 'path' | 'timeScale' | 'quality' | 'targetFps';

/** Every attribute the element reads. */
export const FFT_OCEAN_ATTRIBUTES = [...OPTION_ATTRIBUTES.keys(), ...OWN_ATTRIBUTES.keys(), 'paused', 'camera-height', 'boat'] as const;
export type FftOceanAttribute = (typeof FFT_OCEAN_ATTRIBUTES)[number];

/** The element's own attributes (beside the options), as its settings hold them. */
export interface ElementSettings {
  /**
   * Which of three's renderers draws: 'webgl' (WebGLRenderer, the Ocean of three-fft-ocean) or
   * 'webgpu' (WebGPURenderer, loaded only then, and the Ocean of three-fft-ocean/webgpu; on
   * WebGPURenderer's WebGL2 backend where the browser has no WebGPU adapter). A change makes the
   * renderer and the ocean again. @defaultValue 'webgl'
   */
  renderer: RendererChoice;
  /** Which simulation path runs: 'auto', 'gpu' or 'js' (the Ocean's path option). @defaultValue 'auto' */
  path: PathPreference;
  /** Simulated seconds per real second, [-1000, 1000]. @defaultValue 1 */
  timeScale: number;
  /** A boolean attribute: time stands still; the view still redraws on changes. @defaultValue false */
  paused: boolean;
  /** Height of the viewpoint above the mean sea level, m, (0, 10000]. @defaultValue 8 */
  cameraHeight: number;
  /** A boolean attribute: a boat circling ahead of the view, leaving a wake on the local waves. @defaultValue false */
  boat: boolean;
  /** 'auto' lowers and raises the quality level (render scale, MSAA, grid, cascades) to hold target-fps; high, medium, low or lowest stays fixed. @defaultValue 'auto' */
  quality: QualitySetting;
  /** The frame rate 'auto' holds, frames per second, [5, 240]. @defaultValue 30 */
  targetFps: number;
}

/** The element's current (last good) settings: the options its attributes set, and its own. */
export interface Settings extends ElementSettings {
  simulation: Partial<SimulationParameters>;
  sun: Partial<SunOptions>;
  shading: Partial<ShadingOptions>;
}

export const ELEMENT_DEFAULTS: Readonly<ElementSettings> = {
  renderer: DEFAULT_RUN.renderer,
  path: DEFAULT_RUN.path,
  timeScale: DEFAULT_RUN.timeScale,
  paused: false,
  cameraHeight: 8,
  boat: false,
  ...DEFAULT_QUALITY,
};

/** Settings before any attribute: every option at its default. */
export function defaultSettings(): Settings {
  return { simulation: {}, sun: {}, shading: {}, ...ELEMENT_DEFAULTS };
}

/** What an attribute's change acts on: the element's settings, its frame loop and its ocean. */
export interface AttributeTarget {
  readonly settings: Settings;
  readonly loop: FrameLoop;
  /** The ocean, or null while the element has none. */
  ocean(): Ocean | null;
  /** Puts the quality level in force for the simulation `asked` (default: the settings'), if there is an ocean. */
  applyQuality(asked?: Readonly<SimulationParameters>): void;
  /** Shows or hides the boat as the settings say, if there is an ocean. */
  showBoat(): void;
  /** The picture is out of date. */
  invalidate(): void;
}

/**
 * Whether attribute `name` sets an option of the Ocean (a table's option, or path): the WebGPU
 * Ocean, which cannot change them all in place yet, is made again when one changes.
 */
export function setsOceanOption(name: string): boolean {
  return OPTION_ATTRIBUTES.has(name) || name === 'path';
}

/** Reads attribute `name`, written `raw` (null: removed), into the settings and onto the ocean. */
export function applyAttribute(target: AttributeTarget, name: FftOceanAttribute, raw: string | null): void {
  const s = target.settings;
  const reject = (reason: string, kept: unknown): void => {
    console.warn(`<fft-ocean>: ignoring ${name}=${quoteText(raw ?? '')}: ${reason}; keeping ${formatOptionText(kept)}`);
  };
  const option = OPTION_ATTRIBUTES.get(name);
  const own = OWN_ATTRIBUTES.get(name);
  if (option) {
    const key = option.key;
    try {
      applyOption(target, option.group, key, option.name, raw);
    } catch (error) {
      reject(errorMessage(error), optionSetting(s, option.group, key));
      return;
    }
  } else if (own) {
    // The URL's rule and message, under the attribute's name.
    const key = own.key as OwnKey;
    try {
      const value = raw === null ? ELEMENT_DEFAULTS[key] : parseOptionText(OWN_TABLES[own.group] as Readonly<Record<string, OptionRule>>, own.name, raw);
      Object.assign(s, { [key]: value });
    } catch (error) {
      reject(errorMessage(error), s[key]);
      return;
    }
    const ocean = target.ocean();
    if (key === 'path' && ocean && ocean.simulation.pathPreference !== s.path) ocean.simulation.pathPreference = s.path;
    if (key === 'quality' || key === 'targetFps') {
      target.loop.quality = new AdaptiveQuality(s.quality, s.targetFps);
      target.applyQuality();
    }
  } else if (name === 'camera-height') {
    const value = raw === null ? ELEMENT_DEFAULTS.cameraHeight : parseDecimal(raw);
    if (!Number.isFinite(value) || value <= 0 || value > 10000) {
      reject('it must be a number of metres above 0 and at most 10000', s.cameraHeight);
      return;
    }
    s.cameraHeight = value;
  } else if (name === 'paused') {
    const paused = booleanAttribute(raw);
    if (paused !== s.paused) {
      s.paused = paused;
      target.loop.restart();
    }
  } else if (name === 'boat') {
    s.boat = booleanAttribute(raw);
    target.showBoat();
  }
  target.invalidate();
}

/** The option's current value in `settings`: its setting, or its default. */
export function optionSetting(settings: Settings, group: Group, key: string, groupSettings: object = settings[group]): unknown {
  return (groupSettings as Record<string, unknown>)[key] ?? GROUP_DEFAULTS[group][key];
}

/** The sun's azimuth in force (degrees): the default view and the boat's course turn with it. */
export function sunAzimuthOf(settings: Settings): number {
  return optionSetting(settings, 'sun', 'sunAzimuth') as number;
}

/** The options of a new Ocean for `settings`, its grid and cascades within the quality step's. */
export function oceanOptionsOf(settings: Settings, step: QualityStep): OceanOptions {
  return {
    ...settings.simulation,
    ...simulationAtQuality(validateParameters(settings.simulation), step),
    ...settings.sun,
    ...settings.shading,
    path: settings.path,
  };
}

/**
 * Sets the option `key`, named `name` (the key or an alias), as written in `raw` (null: back to
 * its default) in the settings and on the ocean; throws a ParameterError and changes nothing
 * when it is bad.
 */
function applyOption(target: AttributeTarget, group: Group, key: string, name: string, raw: string | null): void {
  const settings = target.settings;
  const next: Record<string, unknown> = { ...settings[group] };
  if (raw === null) delete next[key];
  else next[key] = parseOptionText(TABLES[group], name, raw);
  const ocean = target.ocean();
  if (group === 'simulation') {
    const asked = validateParameters(next); // throws a ParameterError naming the rule
    // The grid and the cascades run within the quality level's.
    if (key === 'resolution' || key === 'patchSizes') {
      target.applyQuality(asked);
    } else {
      ocean?.setParameters({ [key]: optionSetting(settings, group, key, next) });
    }
  } else if (group === 'sun') {
    ocean?.setSun({
      elevation: optionSetting(settings, group, 'sunElevation', next) as number,
      azimuth: optionSetting(settings, group, 'sunAzimuth', next) as number,
      cloudCover: optionSetting(settings, group, 'cloudCover', next) as number,
    });
  } else {
    ocean?.setShading({ [key]: optionSetting(settings, group, key, next) });
  }
  (settings as unknown as Record<Group, object>)[group] = next;
}

/** A boolean attribute: present is true, except written "false", as people write it. */
function booleanAttribute(raw: string | null): boolean {
  return raw !== null && raw.trim().toLowerCase() !== 'false';
}

function errorMessage(error: unknown): string {
  return error instanceof Error ? error.message : String(error);
}
