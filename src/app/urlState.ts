/**
 * The app's whole state as URL query parameters, so a link (or a reload) shows the same scene.
 *
 * Names are the library's own option names (SimulationParameters, OceanShadingOptions, the sun)
 * plus a few for the app:
 *
 *   spectrum windSpeed windDirection fetch … seed        — simulation, every key of
 *                                                           SIMULATION_OPTIONS (src/parameters/parameters.ts),
 *                                                           written as parseParameterText reads them
 *   sunElevation sunAzimuth                                   — degrees
 *   cloudCover 0 (clear) … 1 (overcast)
 *   ior causticPower causticColor absorption scatterColor     — shading; absorption is "r,g,b";
 *                                                               colours are "r,g,b" (linear, ≥ 0)
 *                                                               or CSS ("%231a6b80" is #1a6b80, sRGB);
 *                                                               causticColour and scatterColour, the
 *                                                               British spellings, are read too
 *   mode       shading mode (full, fresnel, reflection, refraction, caustics, height)
 *   refractions  scene/sky: what is seen through the water (the scene's objects, or only the sky)
 *   reflections  scene/sky  what the sea reflects (the scene's objects, or its sky alone)
 *   wireframe  1/0        inspector  1/0        path  auto/gpu/js        buoys  1/0   boat  1/0
 *   renderer   webgl/webgpu (three's WebGLRenderer, or WebGPURenderer and three-fft-ocean/webgpu: appWebGPU.ts)
 *   scene      sea (the open sea) or island (src/objects/island.ts; sceneChoice.ts)
 *   timeScale  -1000…1000 paused     1/0        t     simulation time in seconds
 *   quality    auto/high/medium/low/lowest (adaptiveQuality.ts)      targetFps  frames per second 'auto' holds
 *   cam        x,y,z,yawDeg,pitchDeg (metres, degrees; see flyControls.ts)
 *   skybox     "generated" (the analytic sky), or the folder URL of six faces px.png … nz.png
 *
 * serializeState writes t and cam always and every other value only where it differs from its
 * default, in a fixed order. parseState reads any subset: a missing value takes its default, an
 * invalid one also takes its default and produces a warning naming the parameter. Pure: no DOM.
 */
import {
  DEFAULT_PARAMETERS,
  ParameterError,
  parseDecimal as parseNumber,
  SIMULATION_OPTIONS,
  validateParameters,
  type SimulationParameters,
} from '../parameters/parameters';
import { formatOptionText, optionAliases, parseOptionText, quoteText, type OptionTable } from '../parameters/options';
import {
  DEFAULT_SHADING,
  DEFAULT_SUN,
  SHADING_OPTIONS,
  SUN_OPTIONS,
  type RefractionSource,
  type Reflections,
  type Rgb,
  type ShadingMode,
} from '../parameters/sceneOptions';
import { clampPitch, MIN_HEIGHT, wrapYaw } from './flyControls';
import type { QualitySetting } from '../runtime/adaptiveQuality';
import { DEFAULT_QUALITY, QUALITY_OPTIONS } from '../parameters/qualityOptions';

import type { PathPreference } from '../layers/oceanSimulation';
import { DEFAULT_RUN, RUN_OPTIONS, type RendererChoice } from '../parameters/runOptions';
export type { Rgb };

/** What the sea is shown with (sceneChoice.ts): the open sea alone, or an island in it. */
export const SCENES = ['sea', 'island'] as const;
export type SceneChoice = (typeof SCENES)[number];

export interface AppState extends SimulationParameters {
  sunElevation: number;
  sunAzimuth: number;
  cloudCover: number;
  ior: number;
  causticPower: number;
  causticColor: Rgb;
  absorption: Rgb;
  scatterColor: Rgb;
  mode: ShadingMode;
  refractions: RefractionSource;
  reflections: Reflections;
  wireframe: boolean;
  inspector: boolean;
  /** A few floating buoys ahead of the camera (buoys.ts). */
  buoys: boolean;
  /** A boat going round a circle ahead of the camera, leaving a wake (boat.ts). */
  boat: boolean;
  /** The open sea, or the island with its reef, pier and moored boat (sceneChoice.ts). */
  scene: SceneChoice;
  /** three's WebGLRenderer ('webgl') or WebGPURenderer with three-fft-ocean/webgpu ('webgpu': appWebGPU.ts). */
  renderer: RendererChoice;
  path: PathPreference;
  /** 'auto' lowers and raises the render scale and grid to hold targetFps; a level stays fixed (adaptiveQuality.ts). */
  quality: QualitySetting;
  targetFps: number;
  timeScale: number;
  paused: boolean;
  /** Simulation time, seconds. */
  t: number;
  /** Camera x, y, z (metres), yaw and pitch (degrees). */
  cam: [number, number, number, number, number];
  /** 'generated', or the folder URL of a six-face skybox (SkyEnvironment.loadFaces). */
  skybox: string;
}

/** Shading and sun defaults are the library's (OceanMaterial, SkyEnvironment). */
export const DEFAULT_STATE: Readonly<AppState> = Object.freeze({
  ...DEFAULT_PARAMETERS,
  ...DEFAULT_SUN,
  ior: DEFAULT_SHADING.ior,
  causticPower: DEFAULT_SHADING.causticPower,
  causticColor: DEFAULT_SHADING.causticColor,
  absorption: DEFAULT_SHADING.absorption,
  scatterColor: DEFAULT_SHADING.scatterColor,
  mode: DEFAULT_SHADING.shadingMode,
  refractions: DEFAULT_SHADING.refractions,
  reflections: DEFAULT_SHADING.reflections,
  wireframe: false,
  inspector: false,
  buoys: false,
  boat: false,
  scene: 'sea',
  ...DEFAULT_RUN,
  ...DEFAULT_QUALITY,
  paused: false,
  t: 0,
  cam: [0, 12, 0, -53.13, -6.84] as AppState['cam'],
  skybox: 'generated',
});

/** A fresh, mutable copy of the defaults (arrays copied too). */
export function defaultState(): AppState {
  return cloneState(DEFAULT_STATE);
}

export function cloneState(state: Readonly<AppState>): AppState {
  return {
    ...state,
    causticColor: [...state.causticColor],
    absorption: [...state.absorption],
    scatterColor: [...state.scatterColor],
    patchSizes: [...state.patchSizes],
    cam: [...state.cam],
  };
}

/**
 * Copies `changes` into `target`, writing arrays element by element so that anything bound to
 * target's arrays (the panel's absorption sliders) stays bound.
 */
export function assignState(target: AppState, changes: Partial<AppState>): void {
  for (const key of Object.keys(changes) as (keyof AppState)[]) {
    const value = changes[key];
    const current = target[key];
    if (Array.isArray(current) && Array.isArray(value)) current.splice(0, current.length, ...value);
    else (target as unknown as Record<string, unknown>)[key] = value;
  }
}

const SIMULATION_KEYS = Object.keys(SIMULATION_OPTIONS) as (keyof SimulationParameters)[];

/** URL names in the order serializeState writes them. */
export const URL_KEYS: readonly (keyof AppState)[] = [
  ...SIMULATION_KEYS,
  'sunElevation',
  'sunAzimuth',
  'cloudCover',
  'ior',
  'causticPower',
  'causticColor',
  'absorption',
  'scatterColor',
  'mode',
  'refractions',
  'reflections',
  'wireframe',
  'inspector',
  'buoys',
  'boat',
  'scene',
  'renderer',
  'path',
  'quality',
  'targetFps',
  'timeScale',
  'paused',
  't',
  'cam',
  'skybox',
];

/** Other names the URL reads (older spellings of the shading options), each mapped to its key. */
const URL_ALIASES: Readonly<Record<string, string>> = optionAliases(SHADING_OPTIONS);

/** Keys written even when they equal their default. */
const ALWAYS_WRITTEN = new Set<keyof AppState>(['t', 'cam']);

/** A number as short text that parses back to a value within `digits` significant digits. */
function formatNumber(value: number, digits = 10): string {
  if (value === 0) return '0';
  return String(Number(value.toPrecision(digits)));
}

/** Fixed decimals without trailing zeros: 12.500 → "12.5". */
function formatFixed(value: number, decimals: number): string {
  const text = value.toFixed(decimals);
  return text.includes('.') ? text.replace(/\.?0+$/, '') : text;
}

/** Rounds the simulation time as the URL stores it (milliseconds), so a paused t round-trips exactly. */
export function roundTime(t: number): number {
  return Number(formatFixed(t, 3));
}

/** Rounds the camera as the URL stores it (millimetres, thousandths of a degree). */
export function roundCam(cam: AppState['cam']): AppState['cam'] {
  return cam.map((value) => Number(formatFixed(value, 3))) as AppState['cam'];
}

function formatValue(key: keyof AppState, value: AppState[keyof AppState]): string {
  if (isSimulationKey(key)) return formatOptionText(value);
  if (typeof value === 'boolean') return value ? '1' : '0';
  if (typeof value === 'string') return value;
  if (key === 't') return formatFixed(value as number, 3);
  if (key === 'cam') return roundCam(value as AppState['cam']).map((c) => formatFixed(c, 3)).join(',');
  if (Array.isArray(value)) return value.map((c) => formatNumber(c, 4)).join(',');
  return formatNumber(value as number);
}

/**
 * `value` as it comes back from the URL (rounded as serializeState writes it), so a value set in
 * the panel and the same value after a reload are identical.
 */
export function urlRounded<K extends keyof AppState>(key: K, value: AppState[K]): AppState[K] {
  if (typeof value !== 'number' && !Array.isArray(value)) return value;
  const result = parseValue(key, formatValue(key, value));
  return 'value' in result ? result.value : value;
}

function sameValue(a: unknown, b: unknown): boolean {
  if (Array.isArray(a) && Array.isArray(b)) return a.length === b.length && a.every((x, i) => x === b[i]);
  return a === b;
}

/** The query string (without "?") for `state`: t and cam always, everything else when not default. */
export function serializeState(state: Readonly<AppState>): string {
  const parts: string[] = [];
  for (const key of URL_KEYS) {
    const value = state[key];
    if (!ALWAYS_WRITTEN.has(key) && sameValue(formatValue(key, value), formatValue(key, DEFAULT_STATE[key]))) continue;
    // Commas are safe in a query and easier to read than %2C.
    parts.push(`${key}=${encodeURIComponent(formatValue(key, value)).replace(/%2C/g, ',')}`);
  }
  return parts.join('&');
}

export interface ParsedState {
  state: AppState;
  /** One per bad or unknown URL parameter, each starting with the parameter's name. */
  warnings: { parameter: string; message: string }[];
}

function parseList(text: string, count: number): number[] | null {
  const values = text.split(',').map(parseNumber);
  return values.length === count && values.every(Number.isFinite) ? values : null;
}

function parseFlag(text: string): boolean | null {
  const t = text.trim().toLowerCase();
  if (t === '1' || t === 'true' || t === 'yes' || t === 'on') return true;
  if (t === '0' || t === 'false' || t === 'no' || t === 'off') return false;
  return null;
}

function isSimulationKey(key: string): key is keyof SimulationParameters {
  return Object.hasOwn(SIMULATION_OPTIONS, key);
}

/**
 * Parses one URL value for `key`: the value, or an explanation of what is allowed. Simulation
 * parameters follow parameters.ts; the others mirror the checks of OceanMaterial.setShading and
 * SkyEnvironment.setSun.
 */
export function parseValue<K extends keyof AppState>(key: K, text: string): { value: AppState[K] } | { error: string } {
  const ok = (value: unknown) => ({ value: value as AppState[K] });
  const bad = (allowed: string) => ({ error: `${key} must be ${allowed}; got ${quoteText(text)}` });
  /** The value as the option's table reads it, reported under the URL's name `key`. */
  function fromTable<T>(table: OptionTable<T>, option: string): { value: AppState[K] } | { error: string } {
    try {
      return ok(parseOptionText(table, option, text));
    } catch (error) {
      if (error instanceof ParameterError) return { error: error.message.replace(option, key) };
      throw error;
    }
  }
  if (isSimulationKey(key)) return fromTable(SIMULATION_OPTIONS, key);
  if (Object.hasOwn(SUN_OPTIONS, key)) return fromTable(SUN_OPTIONS, key);
  if (Object.hasOwn(SHADING_OPTIONS, key)) return fromTable(SHADING_OPTIONS, key);
  switch (key) {
    case 'mode':
      return fromTable(SHADING_OPTIONS, 'shadingMode');
    case 'renderer':
    case 'path':
    case 'timeScale':
      return fromTable(RUN_OPTIONS, key);
    case 'quality':
    case 'targetFps':
      return fromTable(QUALITY_OPTIONS, key);
    case 'wireframe':
    case 'inspector':
    case 'buoys':
    case 'boat':
    case 'paused': {
      const v = parseFlag(text);
      return v === null ? bad('1 or 0') : ok(v);
    }
    case 'scene':
      return (SCENES as readonly string[]).includes(text.trim()) ? ok(text.trim()) : bad(SCENES.map((name) => `"${name}"`).join(' or '));
    case 't': {
      const v = parseNumber(text);
      return Number.isFinite(v) ? ok(v) : bad('a finite number of seconds');
    }
    case 'skybox':
      return text.trim() === '' ? bad('"generated" or the folder URL of six face images') : ok(text.trim());
    case 'cam': {
      const v = parseList(text, 5);
      if (!v) return bad('five numbers x,y,z,yawDeg,pitchDeg');
      // Out-of-range height and pitch are what the controls would allow, not errors.
      return ok([v[0], Math.max(MIN_HEIGHT, v[1]), v[2], wrapYaw(v[3]), clampPitch(v[4])]);
    }
  }
  return bad('a known parameter');
}

/** Reads the state from a query string ("?a=1&b=2" or "a=1&b=2"); see ParsedState. */
export function parseState(search: string): ParsedState {
  const state = defaultState();
  const warnings: ParsedState['warnings'] = [];
  const query = new URLSearchParams(search);
  const known = new Set<string>(URL_KEYS);
  for (const [name, text] of query) {
    const key = (Object.hasOwn(URL_ALIASES, name) ? URL_ALIASES[name] : name) as keyof AppState;
    if (!known.has(key)) {
      warnings.push({ parameter: name, message: `${name}: unknown URL parameter, ignored` });
      continue;
    }
    const result = parseValue(key, text);
    if ('error' in result) {
      warnings.push({ parameter: name, message: `${result.error} — using the default ${formatValue(key, DEFAULT_STATE[key])}` });
    } else {
      (state as unknown as Record<string, unknown>)[key] = result.value;
    }
  }
  // Values fine alone can clash (repeatPeriod too long for resolution and patchSize): reset the
  // parameter the check names to its default, until the combination passes.
  for (let attempt = 0; attempt < SIMULATION_KEYS.length; attempt++) {
    try {
      validateParameters(simulationParameters(state));
      break;
    } catch (error) {
      if (!(error instanceof ParameterError)) throw error;
      const key = error.parameter as keyof SimulationParameters;
      const fallback = (SIMULATION_KEYS as string[]).includes(key) && state[key] !== DEFAULT_PARAMETERS[key];
      warnings.push({ parameter: key, message: `${error.message} — using the default ${formatValue(key, DEFAULT_STATE[key])}` });
      if (fallback) {
        assignState(state, { [key]: DEFAULT_PARAMETERS[key] });
      } else {
        assignState(state, DEFAULT_PARAMETERS);
        break;
      }
    }
  }
  return { state, warnings };
}

export function simulationParameters(state: Readonly<AppState>): SimulationParameters {
  const result: Record<string, unknown> = {};
  for (const key of SIMULATION_KEYS) result[key] = state[key];
  return result as unknown as SimulationParameters;
}
