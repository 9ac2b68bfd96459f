/**
 * The wave-layer contract: what every producer of the sea's motion gives the surface.
 *
 * A layer holds fields in the layout of src/fft/waveFieldLayout.ts (displacement (Dx, h, Dz,
 * ∂Dx/∂z) and derivatives (∂h/∂x, ∂h/∂z, ∂Dx/∂x, ∂Dz/∂z), horizontal parts for a choppiness of 1)
 * over a square of the sea. The surface material (src/render/oceanMaterial.ts), the queries
 * (surfaceQuery.ts) and the app's inspector take a list of layers and nothing else, and sum them:
 * the sea is the sum of its layers, with the horizontal parts scaled by the choppiness.
 *
 * The layers are equals: the simulation (oceanSimulation.ts) keeps one list of them, in the order
 * orderLayers gives, and updates each on one clock; the surface and the queries sum the list; the
 * whitecap foam reads its periodic layers. Today's layers are the FFT cascades (fftCascade.ts,
 * periodic patches of several sizes) and the local waves (localWaves.ts, a grid that follows the
 * camera or a boat); a user's own layer joins them through Ocean.addLayer. A new kind of layer is
 * one more class against this contract.
 *
 * The ordering rule: layers that do not repeat (periodic false) come first, then the periodic ones
 * from the smallest patch to the largest. The largest periodic layer, last, is drawn as a blend of
 * two copies so that its period does not show from altitude (patchBlend.ts), and the foam's
 * history is kept over its patch (whitecapFoam.ts).
 */
import type { Texture } from 'three';

/** Where a layer lies on the sea plane. */
export interface LayerFrame {
  /** Side of the square the textures cover, m. */
  readonly size: number;
  /** World (x, z) of the texture's texel (0, 0), m. */
  readonly origin: readonly [number, number];
  /** True when the fields repeat outside the square (REPEAT wrapping); false: zero outside. */
  readonly periodic: boolean;
  /** Texels per side. */
  readonly resolution: number;
}

/** The layer's fields on the CPU, texel (i, j) at origin + (i, j)·size/resolution, RGBA per texel. */
export interface LayerFieldsOnCpu {
  readonly displacement: Float32Array;
  readonly derivatives: Float32Array;
}

/** A layer's fields for the queries, for one time. Valid until the layer's next update or query at another time. */
export interface LayerQueryFields extends LayerFieldsOnCpu {
  /** The time the fields are for, s (the time asked, or one close to it). */
  readonly time: number;
  /**
   * Texels a side, over the layer's frame: its own resolution, or fewer (a cascade's queries may
   * read a coarser copy without its shortest waves, cascadeQueryFields.ts).
   */
  readonly resolution: number;
  /**
   * The time derivative of `displacement` at `time`: RGBA texels (∂Dx/∂t, ∂h/∂t, ∂Dz/∂t,
   * ∂²Dx/∂z∂t) in m/s, horizontal parts for a choppiness of 1, in the same texel layout. For
   * velocityAt, and to carry the displacement from `time` to the time asked. Computed on the first
   * call where the layer does not already have it.
   */
  velocities(): Float32Array;
}

export interface WaveLayer {
  /** What the surface samples; stable `{ value }` objects, so a material binds them once. */
  readonly textures: {
    readonly displacement: { value: Texture | null };
    readonly derivatives: { value: Texture | null };
  };
  readonly frame: LayerFrame;
  /**
   * False for a layer that only moves the surface up and down (its Dx, Dz and their derivatives are
   * 0, as the local waves'): the queries then leave it out while they look for the rest point.
   */
  readonly movesSideways: boolean;
  /** Advances the layer to time t (s); dt is the step since the last update (0 for a jump). */
  update(t: number, dt: number): void;
  /**
   * The layer's fields on the CPU for the queries (surfaceQuery.ts) at time t: the fields at t, or
   * fields the layer already has for a time close to it (finished by a worker while the main thread
   * drew), which the queries carry to t by their velocities. Layers compute on the main thread only
   * when they have nothing close enough.
   */
  queryFields(t: number): LayerQueryFields;
  /**
   * The layer's fields at time t on the CPU, computed now if the layer has none for t (a GPU layer
   * reads them back): for the foam on the JS path, at the times its warm-up steps through, and
   * for tests. Valid until the next call.
   */
  fieldsOnCpu(t: number): LayerFieldsOnCpu;
  /**
   * The fields the layer's textures hold now, where it keeps them on the CPU as well (the JS path);
   * null where it keeps them only on the GPU. The foam on the JS path reads what is drawn.
   */
  shownFieldsOnCpu(): LayerFieldsOnCpu | null;
  /** Frees every GPU resource and worker the layer made. */
  dispose(): void;
}

/**
 * The layers in the order the surface, the queries and the foam take them (the ordering rule in
 * this file's header): those that do not repeat first, in the order given, then the periodic ones
 * by patch size, the largest last. The order given decides between equal sizes.
 */
export function orderLayers(layers: readonly WaveLayer[]): WaveLayer[] {
  const local = layers.filter((layer) => !layer.frame.periodic);
  const periodic = layers.filter((layer) => layer.frame.periodic);
  return [...local, ...periodic.map((layer, i) => ({ layer, i })).sort((a, b) => a.layer.frame.size - b.layer.frame.size || a.i - b.i).map(({ layer }) => layer)];
}
