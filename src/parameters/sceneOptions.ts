/**
 * The sun and the shading of the sea: their defaults, units, ranges and checks, for Ocean,
 * SkyEnvironment, OceanMaterial, the app's URL state and panel, <fft-ocean> and the shot CLI.
 */
import { Color, LinearSRGBColorSpace, type RGB } from 'three';
import { between, finiteAngle, oneOf, rgb, type OptionRule, type OptionTable } from './options';

export interface SunOptions {
  /** Sun elevation above the horizon in degrees, [-90, 90]. Below the horizon the sky and the sea darken together through twilight (a hundredth of the light at 5.8° below) into night. @defaultValue 30 */
  sunElevation: number;
  /** Sun azimuth in degrees from +x towards +z. @defaultValue 40 */
  sunAzimuth: number;
  /**
   * How much of the sky is cloud, [0, 1]: 0 a clear sky, 1 overcast. The generated sky greys
   * towards the CIE standard overcast sky (Moon & Spencer 1942: three times brighter at the zenith
   * than at the horizon) and the sun's disk and direct light (glint, caustics) dim as Kasten &
   * Czeplak (1980) measured under N/8 oktas of cloud, to nothing when overcast. @defaultValue 0
   */
  cloudCover: number;
}

export const SUN_OPTIONS: OptionTable<SunOptions> = {
  sunElevation: { type: 'number', unit: '°', allowed: 'a number of degrees from -90 to 90', check: between(-90, 90) },
  sunAzimuth: { type: 'number', unit: '°', allowed: 'a finite angle in degrees (at most 1e6 in size)', check: finiteAngle },
  cloudCover: { type: 'number', unit: '', allowed: 'a fraction of the sky from 0 (clear) to 1 (overcast)', check: between(0, 1) },
};

export const DEFAULT_SUN: Readonly<SunOptions> = Object.freeze({ sunElevation: 30, sunAzimuth: 40, cloudCover: 0 });

/** Shading modes; all but 'full' reproduce one of the course report's figures. */
export const SHADING_MODES = ['full', 'fresnel', 'reflection', 'refraction', 'caustics', 'height'] as const;
export type ShadingMode = (typeof SHADING_MODES)[number];
/** What the sea reflects: the scene's objects over its sky, or its sky alone. */
export const REFLECTIONS = ['scene', 'sky'] as const;
export type Reflections = (typeof REFLECTIONS)[number];
export type Rgb = [number, number, number];
/** What the ray refracted into the water shows: the scene under the surface, or the sky alone. */
export const REFRACTION_SOURCES = ['scene', 'sky'] as const;
export type RefractionSource = (typeof REFRACTION_SOURCES)[number];

/**
 * A colour as the shading options take it: a THREE.Color, a hex number (0x1a6b80), a CSS colour
 * string ('#1a6b80', 'rgb(26, 107, 128)', 'teal'), or linear [r, g, b]. See colorToLinear.
 */
export type ColorInput = Color | number | string | Readonly<Rgb>;

/**
 * A colour as linear RGB (what the shader uses), or undefined when `value` is not a ColorInput. A
 * hex number or a CSS string is an sRGB colour as authored, converted as `new Color(value)` does
 * (three's ColorManagement); a THREE.Color holds its colour in three's working colour space
 * already; an [r, g, b] array is taken as linear, as it is.
 */
export function colorToLinear(value: unknown): Rgb | undefined {
  if (Array.isArray(value)) return value.length === 3 ? [value[0], value[1], value[2]] : undefined;
  const color = new Color(NaN, NaN, NaN);
  // Duck-typed (as three does), so a Color from another copy of three counts too.
  if (typeof value === 'object' && value !== null && (value as { isColor?: unknown }).isColor === true) color.copy(value as Color);
  else if (typeof value === 'number' && Number.isInteger(value) && value >= 0 && value <= 0xffffff) color.setHex(value);
  else if (typeof value === 'string' && readsSilently(value)) color.setStyle(value); // leaves the NaNs when three cannot read it
  const { r, g, b } = color.getRGB({} as RGB, LinearSRGBColorSpace);
  return [r, g, b].some(Number.isNaN) ? undefined : [r, g, b];
}

/**
 * Whether Color.setStyle takes `style` without a console warning of its own: a colour function of
 * the models it knows (rgb, rgba, hsl, hsla; one it cannot read leaves the colour as it was), a
 * hex colour of 3 or 6 digits, or a colour name. For anything else it warns ("Unknown color"),
 * which would tell a caller, beside the ParameterError that names the option, of no option at all.
 */
function readsSilently(style: string): boolean {
  const model = /^(\w+)\(([^)]*)\)/.exec(style)?.[1];
  if (model !== undefined) return ['rgb', 'rgba', 'hsl', 'hsla'].includes(model);
  if (style.startsWith('#')) return /^#([\da-f]{3}|[\da-f]{6})$/i.test(style);
  return Object.hasOwn(Color.NAMES, style.toLowerCase());
}

const colorRule = (max: number): OptionRule => ({
  type: 'color',
  unit: '',
  allowed:
    `a colour: a THREE.Color, a hex number (0x1a6b80), a CSS colour ("#1a6b80", "rgb(26, 107, 128)", "teal") ` +
    `or linear r,g,b, each channel from 0 to ${max}`,
  check: rgb(max),
  coerce: colorToLinear,
});

export interface ShadingOptions {
  /** Refractive index of water n_w, (1, 3] (air is 1). @defaultValue 1.333 */
  ior: number;
  /** Beer–Lambert absorption σ per colour channel, 1/m, each in [0, 10000]. @defaultValue [0.45, 0.07, 0.04] */
  absorption: Rgb;
  /**
   * Colour of light scattered back out of the water, stored as linear RGB (each in [0, 100]); the
   * setters take any ColorInput, and the alias scatterColour. @defaultValue [0.0, 0.035, 0.06]
   */
  scatterColor: Rgb;
  /** Caustic sharpness p in K = (t·l)^p, (0, 10000]. @defaultValue 32 */
  causticPower: number;
  /**
   * Caustic colour c_caustic, stored as linear RGB (each in [0, 100]); the setters take any
   * ColorInput, and the alias causticColour. @defaultValue [0.12, 0.12, 0.12]
   */
  causticColor: Rgb;
  /** What the sea shows: 'full' shading, or one of its terms alone, to inspect it. @defaultValue 'full' */
  shadingMode: ShadingMode;
  /**
   * What is seen through the water: 'scene', the scene's objects under the surface (captured each
   * frame without the sea, render/sceneRefraction.ts), bent by Snell's law and dimmed by the water
   * over the path the light travels in it, with a foam line where they pierce the surface; or
   * 'sky', the sky's light through the water alone (nothing under the surface shows). The quality
   * level 'lowest' skips the capture (runtime/adaptiveQuality.ts). @defaultValue 'scene'
   */
  refractions: RefractionSource;
  /**
   * What the sea reflects: 'scene', the scene's objects (those on OceanSurface.reflectionLayers)
   * over its sky, rendered from the camera mirrored in the sea and read along each wave's reflected
   * ray (src/render/sceneReflection.ts); or 'sky', the sky alone. 'scene' shows the sky where the
   * quality level turns reflections off (OceanSurface.reflectionScale 0: 'lowest'), for cameras
   * that are not perspective ones and with a logarithmic or reversed depth buffer.
   * @defaultValue 'scene'
   */
  reflections: Reflections;
}

export const SHADING_OPTIONS: OptionTable<ShadingOptions> = {
  ior: { type: 'number', unit: '', allowed: 'a number > 1 and at most 3', check: (v) => typeof v === 'number' && v > 1 && v <= 3 },
  absorption: { type: 'numbers', unit: '1/m', allowed: 'three numbers from 0 to 10000 (1/m)', check: rgb(1e4) },
  scatterColor: { ...colorRule(100), aliases: ['scatterColour'] },
  causticPower: { type: 'number', unit: '', allowed: 'a number > 0 and at most 10000', check: (v) => typeof v === 'number' && v > 0 && v <= 1e4 },
  causticColor: { ...colorRule(100), aliases: ['causticColour'] },
  shadingMode: { type: 'choice', unit: '', allowed: `one of ${SHADING_MODES.join(', ')}`, check: oneOf(SHADING_MODES), choices: SHADING_MODES },
  refractions: { type: 'choice', unit: '', allowed: `one of ${REFRACTION_SOURCES.join(', ')}`, check: oneOf(REFRACTION_SOURCES), choices: REFRACTION_SOURCES },
  reflections: { type: 'choice', unit: '', allowed: `one of ${REFLECTIONS.join(', ')}`, check: oneOf(REFLECTIONS), choices: REFLECTIONS },
};

export const DEFAULT_SHADING: Readonly<ShadingOptions> = Object.freeze({
  ior: 1.333,
  absorption: [0.45, 0.07, 0.04],
  scatterColor: [0.0, 0.035, 0.06],
  causticPower: 32,
  causticColor: [0.12, 0.12, 0.12],
  shadingMode: 'full',
  refractions: 'scene',
  reflections: 'scene',
} satisfies ShadingOptions);

/**
 * Shading options as Ocean and OceanMaterial take them: any subset, colours in any ColorInput form,
 * and the British spellings as aliases.
 */
export interface ShadingChanges extends Partial<Omit<ShadingOptions, 'scatterColor' | 'causticColor'>> {
  /** ShadingOptions.scatterColor in any ColorInput form (an array is linear). @defaultValue [0.0, 0.035, 0.06] */
  scatterColor?: ColorInput;
  /** ShadingOptions.causticColor in any ColorInput form (an array is linear). @defaultValue [0.12, 0.12, 0.12] */
  causticColor?: ColorInput;
  /** @deprecated Another name for scatterColor (its British spelling), still accepted. @defaultValue [0.0, 0.035, 0.06] */
  scatterColour?: ColorInput;
  /** @deprecated Another name for causticColor (its British spelling), still accepted. @defaultValue [0.12, 0.12, 0.12] */
  causticColour?: ColorInput;
}
