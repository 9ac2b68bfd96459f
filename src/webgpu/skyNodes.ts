/**
 * The WebGPU Ocean's sky in TSL: the WebGL Ocean's analytic sky (shaders/sky/analyticSky.glsl),
 * the same formulas node for node. The WebGL Ocean
 * draws the sky once into an RGBM cube (src/render/skyEnvironment.ts) and samples it; here it is
 * evaluated per pixel, which leaves out the cube's 8-bit encoding and bilinear filtering.
 */
import { Vector3 } from 'three';
import type { UniformNode } from 'three/webgpu';
import { asin, clamp, cos, degrees, distance, exp, float, Fn, log, max, min, mix, pow, select, smoothstep, sqrt, uniform, vec3 } from 'three/tsl';
import { skyLight } from '../render/daylight';
import { SKY_DEEP_WATER, SKY_SUN_INTENSITY, sunDirectionFromAngles, type SunAngles } from '../render/skyEnvironment';
import type { FloatNode, Vec3Node } from './nodeTypes';

/** The analytic sky's uniforms (analyticSky.glsl's sky… uniforms), and the sun's visibility the sea's light needs. */
export interface SkyUniforms {
  /** Unit direction towards the sun, y up (skySunDirection). */
  sunDirection: UniformNode<'vec3'>;
  /** The sky's light as a fraction of the day's (skyDaylight, daylight.ts). */
  daylight: UniformNode<'float'>;
  /** The fraction of the sun's disk above the horizon times what the clouds let through (skySunVisibility). */
  sunVisibility: UniformNode<'float'>;
  /** 0 clear … 1 overcast (skyCloudCover). */
  cloudCover: UniformNode<'float'>;
  /** The overcast zenith's luminance per unit of E_sun (skyOvercastZenith). */
  overcastZenith: UniformNode<'float'>;
  /** The direct sunlight the clouds let through (skyCloudSun). */
  cloudSun: UniformNode<'float'>;
  /** The sun's elevation and azimuth in degrees as last set (setSun keeps the one it is not given). */
  angles: SunAngles;
}

/** The uniforms for a sun at these angles (degrees) under this cloud cover, as SkyEnvironment.applySun sets them. */
export function skyUniforms(elevation: number, azimuth: number, cloudCover: number): SkyUniforms {
  const sky: SkyUniforms = {
    sunDirection: uniform(new Vector3()),
    daylight: uniform(0),
    sunVisibility: uniform(0),
    cloudCover: uniform(0),
    overcastZenith: uniform(0),
    cloudSun: uniform(0),
    angles: { elevation, azimuth },
  };
  setSkySun(sky, elevation, azimuth, cloudCover);
  return sky;
}

/** Moves `sky`'s sun to these angles (degrees) under this cloud cover (checked by the caller), as SkyEnvironment.applySun does. */
export function setSkySun(sky: SkyUniforms, elevation: number, azimuth: number, cloudCover: number): void {
  const light = skyLight(elevation, cloudCover);
  sunDirectionFromAngles(elevation, azimuth, sky.sunDirection.value);
  sky.daylight.value = light.daylight;
  sky.sunVisibility.value = light.sunVisibility;
  sky.cloudCover.value = cloudCover;
  sky.overcastZenith.value = light.overcastZenith;
  sky.cloudSun.value = light.cloudSun;
  sky.angles = { elevation, azimuth };
}

// analyticSky.glsl's constants (it cites their sources).
const RAYLEIGH_DEPTH = [0.0464, 0.108, 0.2648] as const;
const MIE_DEPTH = 0.021;
const MIE_G = 0.8;
const OZONE_DEPTH = [0.00975, 0.0282, 0.00128] as const;
const SUN_RADIUS = 0.00698;
const SUN_EDGE = 0.00175;
const SUN_DISK_GAIN = 40;
const HORIZON_BLEND = 0.0698;

/** analyticSky.glsl's skyAirMass: Kasten & Young (1989), 1 at the zenith, about 38 at the horizon. */
const airMass = Fn(([sinElevation]: [FloatNode]) => {
  const s = clamp(sinElevation, 0, 1);
  return float(1).div(s.add(pow(degrees(asin(s)).add(6.07995), -1.6364).mul(0.50572)));
});

/**
 * analyticSky.glsl's skyRadiance: the linear radiance of the sky (Hoffman & Preetham's single
 * scattering, the sun disk, the CIE overcast sky by cloud cover) in the unit direction `d`, fading
 * over the 4° below the horizon into the deep water's colour.
 */
export function analyticSkyRadiance(sky: SkyUniforms, d: Vec3Node): Vec3Node {
  return Fn(() => {
    const skyWeight = smoothstep(-HORIZON_BLEND, 0, d.y);
    const deepWater = vec3(...SKY_DEEP_WATER).mul(sky.daylight);
    const sun = sky.sunDirection;
    const rayleigh = vec3(...RAYLEIGH_DEPTH);
    const depth = rayleigh.add(MIE_DEPTH).add(vec3(...OZONE_DEPTH));
    const sunDepth = depth.mul(airMass(sun.y));
    const sunTransmittance = exp(sunDepth.negate());
    const scatteredTransmittance = float(1).sub(sunTransmittance).div(sunDepth);
    const sunIrradiance = vec3(SKY_SUN_INTENSITY).mul(sky.daylight);
    // γ from the chord |d − sun| = 2 sin(γ/2), accurate near the sun where acos is not.
    const gamma = asin(clamp(distance(d, sun).mul(0.5), 0, 1)).mul(2);
    const cosGamma = cos(gamma);
    const rayleighPhase = cosGamma.mul(cosGamma).add(1).mul(3 / (16 * Math.PI));
    const g2 = MIE_G * MIE_G;
    const miePhase = float(1 - g2).div(pow(cosGamma.mul(-2 * MIE_G).add(1 + g2), 1.5).mul(4 * Math.PI));
    const scattering = rayleigh.mul(rayleighPhase).add(miePhase.mul(MIE_DEPTH)).div(depth);
    const inScattered = sunIrradiance.mul(scatteredTransmittance).mul(scattering).mul(float(1).sub(exp(depth.mul(airMass(d.y)).negate())));
    // The sun disk, limb-darkened I(μ) = 1 − 0.6(1 − μ), hidden by the horizon.
    const r = min(gamma.div(SUN_RADIUS), 1);
    const limb = float(1).sub(float(1).sub(sqrt(float(1).sub(r.mul(r)))).mul(0.6));
    const disk = float(1).sub(smoothstep(SUN_RADIUS - SUN_EDGE, SUN_RADIUS + SUN_EDGE, gamma)).mul(limb).mul(smoothstep(-SUN_EDGE, SUN_EDGE, d.y));
    const clear = inScattered.add(sunIrradiance.mul(sunTransmittance).mul(disk.mul(sky.cloudSun).mul(SUN_DISK_GAIN)));
    // The CIE overcast sky, L(θ) = L_z·(1 + 2·cos θ)/3.
    const overcast = sunIrradiance.mul(sky.overcastZenith).mul(max(d.y, 0).mul(2).add(1)).div(3);
    const radiance = mix(clear, overcast, sky.cloudCover);
    // Linear in log radiance across the horizon; 1e-6 keeps log finite.
    const darkest = vec3(1e-6);
    const faded = exp(mix(log(max(deepWater, darkest)), log(max(radiance, darkest)), skyWeight));
    return select(skyWeight.lessThanEqual(0), deepWater, select(skyWeight.greaterThanEqual(1), radiance, faded));
  })() as unknown as Vec3Node;
}
