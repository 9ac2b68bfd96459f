/**
 * What the sea's surface (oceanSurface.ts) and the sky behind it (skyBackground.ts, through the
 * Ocean) ask of the sea's material: the layers, the eye, the rings, the shore and the shading, in
 * words rather than in a shading language's uniform names. OceanMaterial (GLSL ShaderMaterial, for
 * WebGLRenderer) implements it; a material for another renderer (a TSL NodeMaterial for
 * WebGPURenderer) implements the same, and the surface drives it unchanged.
 */
import type { Material, Texture, Vector3 } from 'three';
import type { Shore } from '../layers/shore';
import type { WaveLayer } from '../layers/waveLayer';
import type { ShadingChanges, ShadingOptions } from '../parameters/sceneOptions';

/** Where the eye is against the sea surface (the uniform eyeSide of ocean.frag). */
export const EYE_SIDE = { above: 0, below: 1, near: 2 } as const;
export type EyeSide = (typeof EYE_SIDE)[keyof typeof EYE_SIDE];

/** Where the sky background shows the deep water (the eye under or at the surface) instead of the sky (background.frag's backgroundWater). */
export const BACKGROUND_WATER = { none: 0, belowHorizon: 1, everywhere: 2 } as const;

/**
 * No crest rises above this height (m) and no trough sinks below its negative, for a sea of this
 * RMS height: 6 RMS (a crest that high comes once in ~10⁸ waves, Rayleigh heights) plus the local
 * waves' metre.
 */
export function surfaceBoundFor(heightRms: number): number {
  return 6 * heightRms + 1;
}

/** Metres from the surface within which the eye is taken to be at the waterline (about a camera's near distance). */
const WATERLINE_BAND = 0.5;

/** The rings of the horizon grid as placed around the eye (horizonGrid.ts' RingFrames, which has the layout of each). */
export interface RingPlacement {
  /** (centre x, centre z relative to the eye, cell size, mip level) per ring. */
  readonly frames: Float32Array;
  /** Texture coordinate of each ring's centre in each layer. */
  readonly uvOrigins: Float32Array;
  /** (centre_r − centre_{r+1}) / cell_{r+1} per ring. */
  readonly offsets: Float32Array;
}

export interface SeaSurfaceMaterial {
  /**
   * Samples these layers (waveLayer.ts) with this choppiness, and this whitecap foam field (over the
   * last layer's patch, whitecapFoam.ts), from the next draw on; `windSpeed` (m/s at 10 m) and
   * `windDirection` (°) set the slopes finer than the layers, the foam's streaks and the spray.
   * Before every draw; the last layer must be the largest periodic one (it is drawn blended).
   */
  bindLayers(layers: readonly WaveLayer[], choppiness: number, foam: { value: Texture | null }, windSpeed?: number, windDirection?: number): void;
  /** Draws the foam of hulls under way over the grid of layer `layerIndex`, or none (−1 or no texture). Before every draw, after bindLayers. */
  bindHullFoam(layerIndex: number, texture: Texture | null): void;
  /** Draws the waves over this shore's seabed, or without one (null). Before every draw, with the eye's (x, z) in metres. */
  bindShore(shore: Shore | null, eyeX: number, eyeZ: number): void;
  /** Where the eye is (x, z in metres, double precision). Before every draw, after bindLayers. */
  setEye(x: number, z: number): void;
  /** The rings of the horizon grid as placed around the eye (horizonGrid.ts), `cellsPerRing` cells on a side. Before every draw. */
  setRings(rings: RingPlacement, cellsPerRing: number): void;
  /** Which side of the sea the eye is on, and, when near the surface, whether it is under the water there. */
  setEyeSide(side: EyeSide, inWater: boolean): void;
  /** Changes shading options; throws a ParameterError naming the first bad one and changes nothing. */
  setShading(options: ShadingChanges): void;
  readonly shading: ShadingOptions;
  /** Whether the shading looks up the scene under the surface (refractions 'scene', in the full shading). */
  readonly looksIntoScene: boolean;
  /** Whether the shading reflects the scene's objects (reflections 'scene'). */
  readonly reflectsScene: boolean;
  /** The deep water's radiance (the scatterColor option, linear RGB), a live value the sky background shows under water. */
  readonly deepWater: { readonly value: Vector3 };
  /**
   * Takes the inputs of a scene capture (SceneRefraction.uniforms, SceneReflection.uniforms) as they
   * are, shared: their owner updates them.
   */
  shareUniforms<U extends { [K in keyof U]: { value: unknown } }>(uniforms: U): void;
  /** Frees what the material holds. */
  dispose(): void;
}

/** A SeaSurfaceMaterial that three.js can draw: what OceanSurface takes. */
export type SeaSurfaceMeshMaterial = Material & SeaSurfaceMaterial;

/**
 * Which side of the sea the eye at `position` is on (OceanSurface and the WebGPU Ocean ask). A ray
 * from an eye in the air meets the surface first from above, one from an eye in the water first
 * from below, so one test of the eye decides for the whole picture; only within WATERLINE_BAND of
 * the surface, where the near plane crosses it, each triangle tells by the side it shows
 * (ocean.frag). `surfaceBound`: no crest rises above it and no trough sinks below its negative (m;
 * without it the eye is taken to be above the sea). The water's height is asked only between the
 * highest crest and the lowest trough; `inWater` says whether the eye is below the water's height
 * there (what the farther triangles follow when it is near).
 */
export function eyeSide(position: Vector3, surfaceBound: number | undefined, waterHeightAt: ((x: number, z: number) => number) | undefined): { side: EyeSide; inWater: boolean } {
  if (surfaceBound === undefined || position.y > surfaceBound + WATERLINE_BAND) return { side: EYE_SIDE.above, inWater: false };
  if (position.y < -surfaceBound - WATERLINE_BAND) return { side: EYE_SIDE.below, inWater: true };
  const above = waterHeightAt === undefined ? 0 : position.y - waterHeightAt(position.x, position.z);
  const side = above > WATERLINE_BAND ? EYE_SIDE.above : above < -WATERLINE_BAND ? EYE_SIDE.below : EYE_SIDE.near;
  return { side, inWater: above < 0 };
}

/**
 * What the sky background shows (background.frag) with the eye on `side`: under the water, the
 * depths wherever no surface is drawn; with the eye at the surface, the depths below the horizon only.
 */
export function backgroundWaterFor(side: EyeSide): (typeof BACKGROUND_WATER)[keyof typeof BACKGROUND_WATER] {
  return side === EYE_SIDE.below ? BACKGROUND_WATER.everywhere : side === EYE_SIDE.near ? BACKGROUND_WATER.belowHorizon : BACKGROUND_WATER.none;
}
