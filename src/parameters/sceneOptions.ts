/**
 * The sun and the shading of the sea: their defaults, units, ranges and checks, for Ocean,
 * SkyEnvironment, OceanMaterial, the app's URL state and panel, <fft-ocean> and the shot CLI.
 */
import { between, finiteAngle, oneOf, rgb, type OptionTable } from './options';

export interface SunOptions {
  /** Sun elevation above the horizon in degrees, [-90, 90]. @defaultValue 30 */
  sunElevation: number;
  /** Sun azimuth in degrees from +x towards +z. @defaultValue 40 */
  sunAzimuth: number;
}

export const SUN_OPTIONS: OptionTable<SunOptions> = {
  sunElevation: { type: 'number', unit: '°', allowed: 'a number of degrees from -90 to 90', check: between(-90, 90) },
  sunAzimuth: { type: 'number', unit: '°', allowed: 'a finite angle in degrees (at most 1e6 in size)', check: finiteAngle },
};

export const DEFAULT_SUN: Readonly<SunOptions> = Object.freeze({ sunElevation: 30, sunAzimuth: 40 });

/** Shading modes; all but 'full' reproduce one of the course report's figures. */
export const SHADING_MODES = ['full', 'fresnel', 'reflection', 'refraction', 'caustics', 'height'] as const;
export type ShadingMode = (typeof SHADING_MODES)[number];
export type Rgb = [number, number, number];

export interface ShadingOptions {
  /** Refractive index of water n_w, (1, 3] (air is 1). @defaultValue 1.333 */
  ior: number;
  /** Beer–Lambert absorption σ per colour channel, 1/m, each in [0, 10000]. @defaultValue [0.45, 0.07, 0.04] */
  absorption: Rgb;
  /** Colour of light scattered back out of the water (linear RGB, each in [0, 100]). @defaultValue [0.0, 0.035, 0.06] */
  scatterColour: Rgb;
  /** Caustic sharpness p in K = (t·l)^p, (0, 10000]. @defaultValue 32 */
  causticPower: number;
  /** Caustic colour c_caustic (linear RGB, each in [0, 100]). @defaultValue [0.12, 0.12, 0.12] */
  causticColour: Rgb;
  /** @defaultValue 'full' */
  shadingMode: ShadingMode;
}

export const SHADING_OPTIONS: OptionTable<ShadingOptions> = {
  ior: { type: 'number', unit: '', allowed: 'a number > 1 and at most 3', check: (v) => typeof v === 'number' && v > 1 && v <= 3 },
  absorption: { type: 'numbers', unit: '1/m', allowed: 'three numbers from 0 to 10000 (1/m)', check: rgb(1e4) },
  scatterColour: { type: 'numbers', unit: '', allowed: 'three numbers from 0 to 100 (linear r,g,b)', check: rgb(100) },
  causticPower: { type: 'number', unit: '', allowed: 'a number > 0 and at most 10000', check: (v) => typeof v === 'number' && v > 0 && v <= 1e4 },
  causticColour: { type: 'numbers', unit: '', allowed: 'three numbers from 0 to 100 (linear r,g,b)', check: rgb(100) },
  shadingMode: { type: 'choice', unit: '', allowed: `one of ${SHADING_MODES.join(', ')}`, check: oneOf(SHADING_MODES), choices: SHADING_MODES },
};

export const DEFAULT_SHADING: Readonly<ShadingOptions> = Object.freeze({
  ior: 1.333,
  absorption: [0.45, 0.07, 0.04],
  scatterColour: [0.0, 0.035, 0.06],
  causticPower: 32,
  causticColour: [0.12, 0.12, 0.12],
  shadingMode: 'full',
} satisfies ShadingOptions);
