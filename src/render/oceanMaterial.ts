/**
 * The ocean surface's ShaderMaterial: shaders/surface/ocean.vert and ocean.frag, the course
 * report's shading model (exact Fresnel, cubemap reflection and refraction, Beer–Lambert
 * absorption, Guardado caustics) plus a sun glint, and debug modes that reproduce the report's
 * figures. Typed setters check their values and keep the last good one when a value is bad. The
 * SeaSurfaceMaterial (seaSurfaceMaterial.ts) the surface drives, in GLSL: only this file names the
 * shaders' uniforms.
 */
import { Color, DoubleSide, Matrix4, ShaderMaterial, UniformsLib, UniformsUtils, Vector2, Vector3, type Texture } from 'three';
import { COPY_OFFSET, largestPeriodicLayer, patchBlendUniforms } from '../layers/patchBlend';
import type { Shore } from '../layers/shore';
import type { WaveLayer } from '../layers/waveLayer';
import { mergeOptions, ParameterError } from '../parameters/options';
import { DEFAULT_SHADING, SHADING_MODES, SHADING_OPTIONS, type ShadingChanges, type ShadingOptions } from '../parameters/sceneOptions';
import { shaderSource, withLayerCount } from '../shaderSource';
import { foamPatternDefines, foamPatternOrigin, foamPatternTextures } from './foamPattern';
import { finestTexel, RING_COUNT } from './horizonGrid';
import { SEA_SUN_COLOR, SLOPE_FILTER_LEVELS, seaLightingValues, VIEW_DEPTH } from './seaLighting';
import { beaufortAppearance } from './beaufortAppearance';
import { EYE_SIDE, type EyeSide, type RingPlacement, type SeaSurfaceMaterial } from './seaSurfaceMaterial';

/** Shading options as the Ocean takes them: ShadingChanges (src/parameters/sceneOptions.ts). */
export type OceanShadingOptions = ShadingChanges;

export interface OceanMaterialInputs {
  /** The environment cube, RGBM-encoded (SkyEnvironment.environment). */
  environment: { value: Texture | null };
  /** Towards the sun, unit length (SkyEnvironment.skyUniforms.skySunDirection: the sky's own sun). */
  sunDirection: { value: Vector3 };
  /**
   * How much light the sky and the sun still give (SkyEnvironment.skyUniforms: skyDaylight and
   * skySunVisibility, see daylight.ts); full daylight when left out.
   */
  daylight?: { skyDaylight: { value: number }; skySunVisibility: { value: number } };
}

export class OceanMaterial extends ShaderMaterial implements SeaSurfaceMaterial {
  /** The list of layers bound last (bindLayers). */
  private boundLayers: readonly WaveLayer[] | null = null;
  /** The patch size of the layer drawn blended (the last one bound). */
  private blendedSize = 1;
  /** The wind the sub-pixel slopes were set for (seaLighting.ts), with the layers bound then. */
  private litWindSpeed = Number.NaN;
  /** The wind (speed m/s, direction °) the streaks' and spray's uniforms were set for: bindLayers runs every frame, they change with the wind only. */
  private lookWind: [number, number] = [Number.NaN, Number.NaN];

  constructor(inputs: OceanMaterialInputs, options: OceanShadingOptions = {}, defines: Record<string, unknown> = {}) {
    super({
      // SHADING_MODE is a define, not a uniform: a mode change recompiles (rare), and the full
      // shading runs without the debug modes' branches (a few per cent of a SwiftShader frame).
      // LAYER_COUNT too (bindLayers): the sums over layers are unrolled. SCENE_REFLECTIONS and
      // SCENE_REFRACTIONS (the options reflections and refractions) leave the scene's lookups out of
      // the program where they are 'sky'.
      defines: { RING_COUNT, SHADING_MODE: 0, SCENE_REFLECTIONS: 1, SCENE_REFRACTIONS: 1, LAYER_COUNT: 1, SLOPE_FILTER_LEVELS, ...foamPatternDefines(), ...defines },
      vertexShader: withLayerCount(shaderSource('surface/ocean.vert'), 1),
      fragmentShader: withLayerCount(shaderSource('surface/ocean.frag'), 1),
      side: DoubleSide,
      fog: true,
      uniforms: UniformsUtils.merge([
        UniformsLib.common, // unused, keeps three's chunks happy
        UniformsLib.fog, // scene.fog, as three's own materials take it (fog: true below)
        {
          ringFrames: { value: new Float32Array(4 * (RING_COUNT + 1)) },
          ringLayerUvOrigins: { value: new Float32Array(2 * (RING_COUNT + 1)) },
          tLayerDisplacement: { value: [] as (Texture | null)[] },
          tLayerDerivatives: { value: [] as (Texture | null)[] },
          layerSizes: { value: [] as number[] },
          layerLodBias: { value: [] as number[] },
          choppiness: { value: 1 },
          tFoam: { value: null },
          tHullFoam: { value: null },
          patchBlend: { value: new Float32Array(12) },
          foamPatternOrigin: { value: new Vector2() },
          // Streaks and spray (beaufortAppearance.ts; foamStreaks.glsl, spray.glsl): none until bindLayers gives a wind.
          windAlong: { value: new Vector2(1, 0) },
          streakShare: { value: 0 },
          streakLength: { value: 0 },
          streakElongation: { value: 1 },
          streakGain: { value: 0 },
          sprayExtinction: { value: 0 },
          spindrift: { value: 0 },
          copyOffset: { value: new Vector2(...COPY_OFFSET) },
          ringOffsets: { value: new Float32Array(2 * (RING_COUNT + 1)) },
          halfRingCells: { value: 32 },
          sunColor: { value: new Color(...SEA_SUN_COLOR) },
          unresolvedSlopeVariance: { value: 0 },
          layerFilteredSlopes: { value: new Array<number>(SLOPE_FILTER_LEVELS).fill(0) },
          layerTexels: { value: [1] },
          waveHeightRms: { value: 0 },
          iorAir: { value: 1 },
          iorWater: { value: DEFAULT_SHADING.ior },
          absorption: { value: new Vector3(...DEFAULT_SHADING.absorption) },
          scatterColor: { value: new Vector3(...DEFAULT_SHADING.scatterColor) },
          viewDepth: { value: VIEW_DEPTH },
          causticPower: { value: DEFAULT_SHADING.causticPower },
          causticColor: { value: new Vector3(...DEFAULT_SHADING.causticColor) },
          heightScale: { value: 3 },
          eyeSide: { value: EYE_SIDE.above },
          eyeInWater: { value: false },
          captureRestPoint: { value: false },
          // Replaced by the surface's own (SceneReflection.uniforms); nothing is shown without it.
          sceneReflectionColor: { value: null },
          sceneReflectionDepth: { value: null },
          sceneReflectionToClip: { value: new Matrix4() },
          sceneReflectionFromClip: { value: new Matrix4() },
          sceneReflectionShown: { value: false },
          captureWidth: { value: 1 },
          captureHeight: { value: 1 },
        },
      ]),
    });
    // Shared uniform objects: whoever owns them updates them, this material never rebinds.
    this.uniforms.skyEnvironment = inputs.environment;
    this.uniforms.sunDirection = inputs.sunDirection;
    this.uniforms.skyDaylight = inputs.daylight?.skyDaylight ?? { value: 1 };
    this.uniforms.skySunVisibility = inputs.daylight?.skySunVisibility ?? { value: 1 };
    // The foam's detail (foamPattern.ts): this material's own textures (set after the merge above,
    // which would clone them), freed in dispose().
    const foamPattern = foamPatternTextures();
    this.uniforms.foamCoarseLattice = { value: foamPattern.coarse };
    this.uniforms.foamFineTile = { value: foamPattern.fine };
    this.setShading(options);
  }

  /**
   * Samples these layers (waveLayer.ts) with this choppiness, and this whitecap foam field (over the
   * last layer's patch, whitecapFoam.ts), from the next draw on. Called before every draw: for the
   * list it bound last it only sets the choppiness and the foam; a new list rebinds the textures
   * and sizes, and a new number of layers recompiles the shaders. `windSpeed` (m/s at 10 m) sets
   * the slopes finer than the layers (seaLighting.ts); with `windDirection` (°) the foam's streaks
   * and the spray (beaufortAppearance.ts).
   */
  bindLayers(layers: readonly WaveLayer[], choppiness: number, foam: { value: Texture | null }, windSpeed = 0, windDirection = 0): void {
    const u = this.uniforms;
    u.choppiness.value = choppiness;
    u.tFoam = foam;
    if (windSpeed !== this.lookWind[0] || windDirection !== this.lookWind[1]) {
      this.lookWind = [windSpeed, windDirection];
      const look = beaufortAppearance(windSpeed, windDirection);
      u.windAlong.value.fromArray(look.windAlong);
      u.streakShare.value = look.streakShare;
      u.streakLength.value = look.streakLength;
      u.streakElongation.value = look.streakElongation;
      u.streakGain.value = look.streakGain;
      u.sprayExtinction.value = look.sprayExtinction;
      u.spindrift.value = look.spindrift;
    }
    if (layers === this.boundLayers && windSpeed === this.litWindSpeed) return;
    this.litWindSpeed = windSpeed;
    const light = seaLightingValues(layers, windSpeed);
    u.unresolvedSlopeVariance.value = light.unresolvedSlopeVariance;
    u.layerFilteredSlopes.value = light.layerFilteredSlopes;
    u.layerTexels.value = light.layerTexels;
    u.waveHeightRms.value = light.heightRms;
    if (layers === this.boundLayers) return;
    // The shaders blend two copies of the last layer (src/layers/patchBlend.ts), as the queries do
    // for the largest periodic one: they must be the same layer.
    if (largestPeriodicLayer(layers) !== layers.length - 1) {
      throw new ParameterError('layers', layers, '', 'OceanMaterial.bindLayers: the last layer must be the largest periodic one (it is drawn blended)');
    }
    this.boundLayers = layers;
    if (layers.length !== this.defines.LAYER_COUNT) {
      this.defines.LAYER_COUNT = layers.length;
      this.vertexShader = withLayerCount(shaderSource('surface/ocean.vert'), layers.length);
      this.fragmentShader = withLayerCount(shaderSource('surface/ocean.frag'), layers.length);
      this.needsUpdate = true;
      u.tLayerDisplacement.value = new Array(layers.length);
      u.tLayerDerivatives.value = new Array(layers.length);
      u.layerSizes.value = new Array(layers.length);
      u.layerLodBias.value = new Array(layers.length);
    }
    const finest = finestTexel(layers);
    layers.forEach((layer, i) => {
      u.tLayerDisplacement.value[i] = layer.textures.displacement.value;
      u.tLayerDerivatives.value[i] = layer.textures.derivatives.value;
      u.layerSizes.value[i] = layer.frame.size;
      // Whole mip levels: the vertex stage then filters each layer bilinearly within one level.
      u.layerLodBias.value[i] = Math.round(Math.log2(finest / (layer.frame.size / layer.frame.resolution)));
    });
    this.blendedSize = layers[layers.length - 1].frame.size;
  }

  /**
   * Draws the foam of hulls under way (hullFoam.ts), a coverage over the grid of layer `layerIndex`
   * (the local waves), or none (−1: the HULL_FOAM_LAYER define is off). Before every draw, after
   * bindLayers; the define changes only when the local waves come or go.
   */
  bindHullFoam(layerIndex: number, texture: Texture | null): void {
    const layer = texture === null || layerIndex < 0 ? undefined : layerIndex;
    if (layer !== this.defines.HULL_FOAM_LAYER) {
      if (layer === undefined) delete this.defines.HULL_FOAM_LAYER;
      else this.defines.HULL_FOAM_LAYER = layer;
      this.needsUpdate = true;
    }
    this.uniforms.tHullFoam.value = texture;
  }

  /**
   * Draws the waves over this shore's seabed (shore.ts, shaders/surface/shoaling.glsl), or without
   * one (null, or a shore without a seabed: the SEABED define is off and the shaders are as if
   * there were no shore). Before every draw, with the eye's (x, z) in metres.
   */
  bindShore(shore: Shore | null, eyeX: number, eyeZ: number): void {
    const on = shore?.active === true;
    if (on !== (this.defines.SEABED !== undefined)) {
      if (on) this.defines.SEABED = '';
      else delete this.defines.SEABED;
      this.needsUpdate = true;
    }
    if (!on) return;
    Object.assign(this.uniforms, shore.uniforms); // the shore's own stable objects: assigning again changes nothing
    shore.setEye(eyeX, eyeZ);
  }

  /**
   * Where the eye is (x, z in metres, double precision): the vertex and fragment stages work in
   * metres from it (horizonGrid.glsl), so what depends on the absolute position, the blend's phases
   * and the foam pattern's origin, is reduced here. Before every draw, after bindLayers.
   */
  setEye(x: number, z: number): void {
    const u = this.uniforms;
    patchBlendUniforms(this.blendedSize, u.patchBlend.value, x, z);
    const w = u.windAlong.value;
    foamPatternOrigin(x, z, w.x, w.y, u.streakElongation.value, u.foamPatternOrigin.value);
  }

  setRings(rings: RingPlacement, cellsPerRing: number): void {
    const u = this.uniforms;
    u.ringFrames.value = rings.frames;
    u.ringLayerUvOrigins.value = rings.uvOrigins;
    u.ringOffsets.value = rings.offsets;
    u.halfRingCells.value = cellsPerRing / 2;
  }

  setEyeSide(side: EyeSide, inWater: boolean): void {
    this.uniforms.eyeSide.value = side;
    this.uniforms.eyeInWater.value = inWater;
  }

  /** The scatterColor uniform itself, which setShading updates in place. */
  get deepWater(): { readonly value: Vector3 } {
    return this.uniforms.scatterColor;
  }

  /** Changes shading options; throws a ParameterError naming the first bad one and changes nothing. */
  setShading(options: OceanShadingOptions): void {
    const next = mergeOptions(SHADING_OPTIONS, options, this.shading);
    const u = this.uniforms;
    u.iorWater.value = next.ior;
    u.absorption.value.fromArray(next.absorption);
    u.scatterColor.value.fromArray(next.scatterColor);
    u.causticPower.value = next.causticPower;
    u.causticColor.value.fromArray(next.causticColor);
    const mode = SHADING_MODES.indexOf(next.shadingMode);
    // Defines, as the mode: with 'sky' the shader has no capture lookups at all.
    const sceneReflections = next.reflections === 'scene' ? 1 : 0;
    const sceneRefractions = next.refractions === 'scene' ? 1 : 0;
    if (mode !== this.defines.SHADING_MODE || sceneReflections !== this.defines.SCENE_REFLECTIONS || sceneRefractions !== this.defines.SCENE_REFRACTIONS) {
      this.defines.SHADING_MODE = mode;
      this.defines.SCENE_REFLECTIONS = sceneReflections;
      this.defines.SCENE_REFRACTIONS = sceneRefractions;
      this.needsUpdate = true;
    }
  }

  /** Whether the shader looks up the scene under the surface: refractions 'scene', in the full shading. */
  get looksIntoScene(): boolean {
    return this.defines.SCENE_REFRACTIONS === 1 && this.defines.SHADING_MODE === SHADING_MODES.indexOf('full');
  }

  /**
   * Takes `uniforms` as they are, shared: their owner updates them (the scene's captures,
   * SceneRefraction and SceneReflection, whose lookups the shader makes where the options
   * refractions and reflections are 'scene').
   */
  shareUniforms<U extends { [K in keyof U]: { value: unknown } }>(uniforms: U): void {
    Object.assign(this.uniforms, uniforms);
  }

  /** Whether the sea reflects the scene's objects (the option reflections is 'scene'). */
  get reflectsScene(): boolean {
    return this.defines.SCENE_REFLECTIONS === 1;
  }

  /** Frees the program (ShaderMaterial) and the foam pattern's textures. */
  override dispose(): void {
    this.uniforms.foamCoarseLattice.value.dispose();
    this.uniforms.foamFineTile.value.dispose();
    super.dispose();
  }

  get shading(): ShadingOptions {
    const u = this.uniforms;
    return {
      ior: u.iorWater.value,
      absorption: u.absorption.value.toArray(),
      scatterColor: u.scatterColor.value.toArray(),
      causticPower: u.causticPower.value,
      causticColor: u.causticColor.value.toArray(),
      shadingMode: SHADING_MODES[this.defines.SHADING_MODE as number],
      refractions: this.defines.SCENE_REFRACTIONS === 1 ? 'scene' : 'sky',
      reflections: this.defines.SCENE_REFLECTIONS === 1 ? 'scene' : 'sky',
    };
  }
}
