/**
 * The Ocean for three.js's WebGPURenderer (`three/webgpu`), on its WebGPU backend and on its WebGL2
 * backend (`forceWebGL: true`): `import { Ocean } from 'three-fft-ocean/webgpu'`.
 *
 *   const renderer = new WebGPURenderer();
 *   await renderer.init();
 *   const ocean = new Ocean(renderer, { windSpeed: 12, seed: 7 });
 *   scene.add(ocean);
 *   renderer.setAnimationLoop((ms) => { ocean.update(ms / 1000); renderer.render(scene, camera); });
 *
 * This first slice draws the FFT cascades of the same sea as the WebGL Ocean (the same parameters,
 * spectra and seeded amplitudes, computed by the JS FFT: src/fft/cpuFieldTextures.ts, in a worker
 * by default, uploaded as float textures each frame; there is no GPU FFT on WebGPURenderer yet),
 * displaced and lit in TSL (seaNodes.ts) by the sky's Fresnel reflection over the deep water's
 * colour, on a fixed grid around the origin (seaGrid.ts). heightAt and normalAt answer from the
 * same fields and code as the WebGL Ocean's (src/layers/surfaceQuery.ts), so for the same options
 * and time they return the same numbers.
 *
 * What it does not draw yet throws an UnsupportedError when asked for (NOT_YET), and what is on by
 * default in the WebGL Ocean but missing here (whitecap foam, the sun, the analytic sky) is named in
 * one console warning per page. Owns its cascades, textures, geometry and materials; dispose()
 * frees them, after which every method throws a DisposedError.
 */
import { Mesh, Object3D, SphereGeometry, Vector3 } from 'three';
import type { MeshBasicNodeMaterial, WebGPURenderer } from 'three/webgpu';
import { uniform } from 'three/tsl';
import { CpuFieldTextures, type FloatTextureSupport } from '../fft/cpuFieldTextures';
import { FftCascade, type FftBackend } from '../layers/fftCascade';
import { heightAt, normalAt } from '../layers/surfaceQuery';
import { orderLayers, type WaveLayer } from '../layers/waveLayer';
import { checkOptionNames, DisposedError, UnsupportedError } from '../parameters/options';
import { ParameterError, SIMULATION_OPTIONS, validateParameters, type SimulationParameters } from '../parameters/parameters';
import { colorToLinear, DEFAULT_SHADING, SHADING_OPTIONS, type ColorInput } from '../parameters/sceneOptions';
import { createCascadeSpectra } from '../spectrum/initialSpectrum';
import { seaGridGeometry } from './seaGrid';
import { seaMaterial, skyMaterial, type SeaUniforms } from './seaNodes';
import { checkCoordinates } from '../oceanQueries';
import { checkRenderer } from '../device/deviceFor';

export interface WebGPUOceanOptions extends Partial<SimulationParameters> {
  /** Refractive index of water n_w, (1, 3] (ShadingOptions.ior). @defaultValue 1.333 */
  ior?: number;
  /** Colour of the light deep water scatters back, any ColorInput (an array is linear RGB). @defaultValue [0.0, 0.035, 0.06] */
  scatterColor?: ColorInput;
  /** The sky's colour at the horizon, any ColorInput (an array is linear RGB). @defaultValue [0.45, 0.6, 0.8] */
  horizonColor?: ColorInput;
  /** The sky's colour straight up, any ColorInput (an array is linear RGB). @defaultValue [0.1, 0.25, 0.6] */
  zenithColor?: ColorInput;
  /** Compute the JS FFT in a Web Worker (SimulationOptions.worker). @defaultValue true where Worker exists */
  worker?: boolean;
  /** 'auto' or 'js': both the JS FFT here; 'gpu' throws (no GPU FFT on WebGPURenderer yet). @defaultValue 'auto' */
  path?: 'auto' | 'js' | 'gpu';
  /** Only 'sky' (the default here): scene reflections are not drawn yet. @defaultValue 'sky' */
  reflections?: 'sky' | 'scene';
  /** Only 'sky' (the default here): objects under the water are not drawn yet. @defaultValue 'sky' */
  refractions?: 'sky' | 'scene';
  /** Only false (the default here): local waves are not drawn yet. @defaultValue false */
  localWaves?: boolean | object;
  /** Only null (the default): no seabed yet. @defaultValue null */
  seabed?: object | null;
}

/** Options the WebGL Ocean has and this one does not yet: the value it draws, and what is missing. */
const NOT_YET: Record<string, { drawn: unknown; missing: string }> = {
  path: { drawn: 'js', missing: "the GPU FFT (path 'gpu'): the fields come from the JS FFT ('auto' or 'js')" },
  reflections: { drawn: 'sky', missing: "scene reflections (reflections: 'scene'): the sea reflects its sky" },
  refractions: { drawn: 'sky', missing: "objects seen under the water (refractions: 'scene')" },
  localWaves: { drawn: false, missing: 'local waves (stones, hulls)' },
  seabed: { drawn: null, missing: 'a seabed (shoaling, breaking, the shore)' },
  shadingMode: { drawn: 'full', missing: "the debug shading modes (shadingMode other than 'full')" },
  causticPower: { drawn: undefined, missing: 'caustics (causticPower)' },
  causticColor: { drawn: undefined, missing: 'caustics (causticColor)' },
  absorption: { drawn: undefined, missing: 'absorption along a shallow path (absorption): the sea is infinitely deep' },
  sunElevation: { drawn: undefined, missing: 'the sun and the analytic sky (sunElevation): the sky is a two-colour gradient' },
  sunAzimuth: { drawn: undefined, missing: 'the sun and the analytic sky (sunAzimuth)' },
  sunDirection: { drawn: undefined, missing: 'the sun and the analytic sky (sunDirection)' },
  cloudCover: { drawn: undefined, missing: 'the analytic sky (cloudCover)' },
};

/**
 * The options in `options` that ask for what this Ocean does not draw yet, each with what is
 * missing in words: the constructor refuses the first; <fft-ocean renderer="webgpu"> and the app
 * leave them out and say so.
 */
export function notDrawnYet(options: object): { name: string; missing: string }[] {
  return Object.entries(NOT_YET)
    .filter(([name, { drawn }]) => {
      const value = (options as Record<string, unknown>)[name];
      return value !== undefined && !(name === 'path' && value === 'auto') && value !== drawn;
    })
    .map(([name, { missing }]) => ({ name, missing }));
}

const SIMULATION_KEYS = Object.keys(SIMULATION_OPTIONS) as (keyof SimulationParameters)[];
const OPTION_KEYS: readonly string[] = [...SIMULATION_KEYS, 'ior', 'scatterColor', 'horizonColor', 'zenithColor', 'worker', ...Object.keys(NOT_YET)];

export const WEBGPU_OCEAN_DEFAULTS = Object.freeze({
  horizonColor: [0.45, 0.6, 0.8] as const,
  zenithColor: [0.1, 0.25, 0.6] as const,
});

/** The one warning of what the WebGL Ocean draws by default and this one does not, once per page. */
let warnedOfMissing = false;

export class Ocean extends Object3D {
  /** The FFT cascades, finest first (the JS FFT's fields as float textures). */
  private cascades: FftCascade<null>[] = [];
  private currentLayers: readonly WaveLayer[] = [];
  private parameters: SimulationParameters;
  private readonly uniforms: SeaUniforms;
  private readonly useWorker: boolean;
  private readonly support: FloatTextureSupport;
  private readonly surface: Mesh<ReturnType<typeof seaGridGeometry>, MeshBasicNodeMaterial>;
  private readonly skyMesh: Mesh<SphereGeometry, MeshBasicNodeMaterial>;
  private currentTime = 0;
  private lastTime = NaN;
  private disposed = false;

  constructor(renderer: WebGPURenderer, options: WebGPUOceanOptions = {}) {
    super();
    this.name = 'OceanWebGPU';
    this.support = floatTextureSupport(renderer);
    checkOptionNames(options, OPTION_KEYS, 'options', { allowed: 'an object of options, such as { windSpeed: 12 }' });
    const [first] = notDrawnYet(options);
    if (first) throw new UnsupportedError(first.name, `three-fft-ocean/webgpu does not draw ${first.missing} yet; use the WebGL Ocean (three-fft-ocean) for it`);
    const simulation: Partial<SimulationParameters> = {};
    for (const key of SIMULATION_KEYS) if (options[key] !== undefined) (simulation as Record<string, unknown>)[key] = options[key];
    this.parameters = validateParameters(simulation);
    const ior = options.ior ?? DEFAULT_SHADING.ior;
    if (!SHADING_OPTIONS.ior.check(ior)) throw new ParameterError('ior', ior, SHADING_OPTIONS.ior.allowed);
    this.uniforms = {
      choppiness: uniform(this.parameters.choppiness),
      ior: uniform(ior),
      scatterColor: uniform(new Vector3(...linearColor('scatterColor', options.scatterColor, DEFAULT_SHADING.scatterColor))),
      horizonColor: uniform(new Vector3(...linearColor('horizonColor', options.horizonColor, WEBGPU_OCEAN_DEFAULTS.horizonColor))),
      zenithColor: uniform(new Vector3(...linearColor('zenithColor', options.zenithColor, WEBGPU_OCEAN_DEFAULTS.zenithColor))),
    };
    this.useWorker = options.worker ?? typeof Worker !== 'undefined';
    this.buildCascades();
    this.surface = new Mesh(seaGridGeometry(), seaMaterial(this.currentLayers, this.uniforms));
    this.surface.name = 'OceanWebGPU surface';
    this.surface.frustumCulled = false; // the grid moves up and down by the waves
    this.skyMesh = new Mesh(new SphereGeometry(1, 32, 16), skyMaterial(this.uniforms));
    this.skyMesh.name = 'OceanWebGPU sky';
    this.skyMesh.frustumCulled = false;
    this.skyMesh.renderOrder = -Infinity; // first, under everything
    this.add(this.skyMesh, this.surface);
    if (!warnedOfMissing && this.parameters.foamAmount > 0) {
      warnedOfMissing = true;
      console.warn('three-fft-ocean/webgpu: not drawn yet on WebGPURenderer: whitecap foam (foamAmount), the sun and its glint, the analytic sky (a two-colour gradient instead), the horizon rings that follow the camera, quality levels.');
    }
  }

  /** Every wave layer (the cascades), in the order the surface and the queries sum them. */
  get waveLayers(): readonly WaveLayer[] {
    this.checkAlive('waveLayers');
    return this.currentLayers;
  }

  /** The time (s) of the last update. */
  get time(): number {
    this.checkAlive('time');
    return this.currentTime;
  }

  /** Computes the sea at time t (s, any finite value) and uploads its fields. */
  update(t: number): void {
    this.checkAlive('update');
    if (!Number.isFinite(t)) throw new ParameterError('time', t, 'a finite number of seconds');
    const step = Number.isNaN(this.lastTime) ? 0 : t - this.lastTime;
    for (const cascade of this.cascades) cascade.update(t, step);
    this.currentTime = this.lastTime = t;
  }

  /**
   * Height (m) of the water surface at the world point (x, z) at the last update's time: the same
   * answer as the WebGL Ocean's heightAt for the same options and time (surfaceQuery.ts).
   */
  heightAt(x: number, z: number): number {
    this.checkAlive('heightAt');
    checkCoordinates('heightAt', x, z);
    return heightAt(this.currentLayers, this.parameters.choppiness, this.currentTime, x, z);
  }

  /** Upward unit normal of the water surface over (x, z), written into `target` (surfaceQuery.ts). */
  normalAt(x: number, z: number, target: Vector3 = new Vector3()): Vector3 {
    this.checkAlive('normalAt');
    checkCoordinates('normalAt', x, z);
    return normalAt(this.currentLayers, this.parameters.choppiness, this.currentTime, x, z, target);
  }

  /** Changes some simulation parameters (a ParameterError names the first bad one and changes nothing). */
  setParameters(changes: Partial<SimulationParameters>): void {
    this.checkAlive('setParameters');
    const next = validateParameters(changes, this.parameters);
    const onlyChoppiness = (Object.keys(next) as (keyof SimulationParameters)[]).every((key) => key === 'choppiness' || next[key] === this.parameters[key]);
    this.parameters = next;
    this.uniforms.choppiness.value = next.choppiness;
    if (onlyChoppiness) return;
    for (const cascade of this.cascades) cascade.dispose();
    this.buildCascades();
    const old = this.surface.material;
    this.surface.material = seaMaterial(this.currentLayers, this.uniforms);
    old.dispose();
  }

  /** Frees the cascades (their textures and workers), the grid, the sky and the materials. */
  dispose(): void {
    if (this.disposed) return;
    for (const cascade of this.cascades) cascade.dispose();
    this.cascades = [];
    this.currentLayers = [];
    this.surface.geometry.dispose();
    this.surface.material.dispose();
    this.skyMesh.geometry.dispose();
    this.skyMesh.material.dispose();
    this.removeFromParent();
    this.disposed = true;
  }

  /** The cascades of the parameters: their textures ask nothing more of the renderer than `support`, read once. */
  private buildCascades(): void {
    const params = this.parameters;
    const backend: FftBackend<null> = (_none, spectrum) => new CpuFieldTextures(this.support, spectrum, this.useWorker);
    this.cascades = createCascadeSpectra(params).map((spectrum, cascade) => new FftCascade(null, spectrum, { params, cascade }, backend, this.useWorker));
    this.currentLayers = orderLayers(this.cascades);
    this.lastTime = NaN;
  }

  private checkAlive(what: string): void {
    if (this.disposed) throw new DisposedError(`Ocean.${what}`);
  }
}

/**
 * What the renderer's device does with RGBA32F textures. The surface samples them bilinearly, as
 * the queries do: without filtering it would differ from heightAt, so that is refused.
 */
function floatTextureSupport(renderer: WebGPURenderer): FloatTextureSupport {
  checkRenderer(renderer, 'three-fft-ocean/webgpu');
  if (!renderer.initialized) throw new UnsupportedError('renderer', 'the WebGPURenderer is not initialized yet: await renderer.init() before making the Ocean');
  const backend = renderer.backend as { isWebGPUBackend?: boolean };
  const filterable = backend.isWebGPUBackend
    ? renderer.hasFeature('float32-filterable')
    : (renderer.getContext() as WebGL2RenderingContext).getExtension('OES_texture_float_linear') !== null;
  if (!filterable) {
    throw new UnsupportedError('renderer', `this device cannot filter RGBA32F textures (${backend.isWebGPUBackend ? "WebGPU feature 'float32-filterable'" : 'WebGL2 extension OES_texture_float_linear'}), which three-fft-ocean/webgpu needs`);
  }
  // The mipmap levels are made in JS (CpuFieldTextures): three's mipmap generation is not asked to render into float textures.
  return { filterable, renderable: false };
}

function linearColor(name: string, value: ColorInput | undefined, fallback: readonly [number, number, number]): [number, number, number] {
  if (value === undefined) return [fallback[0], fallback[1], fallback[2]];
  const rgb = colorToLinear(value);
  if (rgb === undefined || !rgb.every((c) => Number.isFinite(c) && c >= 0 && c <= 100)) throw new ParameterError(name, value, 'a colour: a three.js Color, a CSS colour string, a hex number or linear [r, g, b] from 0 to 100');
  return rgb;
}
