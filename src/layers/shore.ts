/**
 * The shore: a seabed's depth map (seabed.ts) and, for each wave layer, its shoaling factors F_c(d)
 * over depth (src/spectrum/shoaling.ts), which the surface (shaders/surface/shoaling.glsl) and the
 * queries (surfaceQuery.ts) apply alike: each layer's fields × F_layer(d) at the rest point, then
 * the height limited by breaking, riding on the swash level (src/spectrum/swash.ts). FFT cascades shoal by their spectrum; other layers (local waves,
 * the user's) are left as they are (factor 1). Owns the depth map and the factors' texture.
 */
import { DataTexture, FloatType, NearestFilter, RedFormat, Vector2, Vector3, Vector4 } from 'three';
import type { InitialSpectrum } from '../spectrum/initialSpectrum';
import { BREAKER_INDEX, cascadeShoalingRow, shoalingDepths, shoalingFactor, SHOALING_DEPTHS, type ShoalingDepths } from '../spectrum/shoaling';
import { swashLength, swashLevel } from '../spectrum/swash';
import type { SeabedMap } from './seabed';
import type { WaveLayer } from './waveLayer';

/** float32's stand-in for a sea deeper than anything (the `depth` option's Infinity). */
const DEEP = 1e30;

export class Shore {
  private map: SeabedMap | null = null;
  private table = new Float32Array(0);
  private tableTexture: DataTexture | null = null;
  private depths: ShoalingDepths = shoalingDepths(1, Infinity);
  private preparedFor: { layers: readonly WaveLayer[] | null; referenceDepth: number } = { layers: null, referenceDepth: NaN };
  /** The depth outside the map (the `depth` option), m. */
  private outside = Infinity;
  /** The uniforms of shaders/surface/shoaling.glsl, shared with the material (stable objects). */
  readonly uniforms = {
    tSeabed: { value: null as DataTexture | null },
    // ((eye x − xMin)·nodes per metre, (eye z − zMin)·…, nodes per metre along x, along z): the
    // rest point's node coordinates from its place relative to the eye, reduced in double precision.
    seabedFrame: { value: new Vector4() },
    seabedNodes: { value: new Vector2(2, 2) },
    seabedOutsideDepth: { value: DEEP },
    tShoaling: { value: null as DataTexture | null },
    // (log of the shallowest tabulated depth, entries per unit of log d, the deepest tabulated)
    shoalingDepths: { value: new Vector3() },
    // Depth at which the sea's significant wave breaks, Hs/κ (McCowan): where the surf zone begins.
    breakerDepth: { value: 1 },
    // (√(H0·L0) m, Hs m) of the sea, for the swash (shaders/surface/swash.glsl); x = 0: none.
    swashSea: { value: new Vector2(0, 1) },
  };

  /** Whether there is a seabed (else the surface and the queries are as without a shore). */
  get active(): boolean {
    return this.map !== null;
  }

  get seabed(): SeabedMap | null {
    return this.map;
  }

  /** Puts this depth map under the sea (null: none); frees the one before. */
  setMap(map: SeabedMap | null): void {
    this.map?.dispose();
    this.map = map;
    this.uniforms.tSeabed.value = map?.texture ?? null;
    if (map) this.uniforms.seabedNodes.value.set(map.width, map.height);
  }

  /**
   * Makes the factors for these layers (`cascades` those of them that shoal by their spectrum) in
   * a sea made for `referenceDepth`, with significant wave height `significantHeight` (m) and peak
   * period `peakPeriod` (s; the swash's scale); nothing more to do when neither the list nor the
   * depth changed since the last call.
   */
  prepare(layers: readonly WaveLayer[], cascades: readonly (WaveLayer & { spectrum: InitialSpectrum })[], referenceDepth: number, significantHeight: number, peakPeriod: number): void {
    this.outside = referenceDepth;
    this.uniforms.seabedOutsideDepth.value = Math.min(referenceDepth, DEEP);
    this.uniforms.breakerDepth.value = Math.max(significantHeight / BREAKER_INDEX, 0.01);
    this.uniforms.swashSea.value.set(swashLength(significantHeight, peakPeriod), significantHeight);
    if (layers === this.preparedFor.layers && referenceDepth === this.preparedFor.referenceDepth) return;
    this.preparedFor = { layers, referenceDepth };
    const longest = Math.max(1, ...cascades.map((cascade) => cascade.spectrum.patchSize));
    this.depths = shoalingDepths(longest, referenceDepth);
    if (this.table.length !== SHOALING_DEPTHS * layers.length) {
      this.table = new Float32Array(SHOALING_DEPTHS * layers.length);
      this.tableTexture?.dispose();
      this.tableTexture = new DataTexture(this.table, SHOALING_DEPTHS, layers.length, RedFormat, FloatType);
      this.tableTexture.minFilter = this.tableTexture.magFilter = NearestFilter;
      this.uniforms.tShoaling.value = this.tableTexture;
    }
    layers.forEach((layer, i) => {
      const cascade = cascades.find((c) => c === layer);
      if (cascade) cascadeShoalingRow(cascade.spectrum, this.depths, referenceDepth, this.table, i * SHOALING_DEPTHS);
      else this.table.fill(1, i * SHOALING_DEPTHS, (i + 1) * SHOALING_DEPTHS);
    });
    this.tableTexture!.needsUpdate = true;
    const { logMin, perLog, max } = this.depths;
    this.uniforms.shoalingDepths.value.set(logMin, perLog, max);
  }

  /** Where the eye is (x, z, double precision): the shader finds the seabed's nodes from it. */
  setEye(x: number, z: number): void {
    const map = this.map;
    if (map === null) return;
    const [xMin, zMin, xMax, zMax] = map.bounds;
    const perX = (map.width - 1) / (xMax - xMin);
    const perZ = (map.height - 1) / (zMax - zMin);
    this.uniforms.seabedFrame.value.set((x - xMin) * perX, (z - zMin) * perZ, perX, perZ);
  }

  /** Depth (m) under the world point (x, z): the map's, or the `depth` option's outside it. */
  depthAt(x: number, z: number): number {
    return this.map === null ? this.outside : this.map.depthAt(x, z, this.outside);
  }

  /**
   * The swash level ζ_t (m, src/spectrum/swash.ts) at the world point (x, z) of depth `depth`,
   * where the sea's height before shoaling is `deepHeight`.
   */
  swashLevel(deepHeight: number, x: number, z: number, depth: number): number {
    const sea = this.uniforms.swashSea.value;
    return this.map === null ? 0 : swashLevel(deepHeight, depth, this.map.slopeAt(x, z), sea.x, sea.y);
  }

  /** F of layer `layer` (its index in the prepared list) at depth d. */
  layerFactor(layer: number, depth: number): number {
    return shoalingFactor(this.table, layer * SHOALING_DEPTHS, this.depths, depth);
  }

  dispose(): void {
    this.setMap(null);
    this.tableTexture?.dispose();
    this.tableTexture = null;
    this.uniforms.tShoaling.value = null;
  }
}
