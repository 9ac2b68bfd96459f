/**
 * The foam a hull under way makes: white water pushed along its sides by the breaking bow wave,
 * left behind it as a wake that fades. Kept per texel of the local-wave grid (localWaves.ts),
 * which moves in whole texels and carries this field with it, so the foam stays where the water
 * is in the world (no drift of its own: "advected with nothing fancy").
 *
 * Where: the bow wave spreads from the bow within the Kelvin wedge, whose half-angle is
 * α = arcsin(1/3) = 19.47° whatever the speed (Thomson 1887, "On ship waves", Proc. Inst. Mech.
 * Eng. 38: 409–434; Lamb, "Hydrodynamics", §256). Each shoulder of a hull of beam B starts its own
 * wedge, so in the hull's frame, s metres behind the bow and n across its centre line, the water
 * that breaks is
 *     S(s, n) = 1 where 0 ≤ s ≤ L and |n| ≤ B/2 + s·tan α (soft over one texel), else 0:
 * along the hull's length L, from its sides out to the wedge's lines. Nothing is made ahead of the
 * bow. Behind the stern the field keeps what the hull left: a band as wide as the wedge at the
 * stern, fading with its age.
 *
 * How much: the coverage held in that zone grows with the hull's speed U through the water, in
 * proportion to its Froude number Fr = U/√(g·L), full at the hull speed Fr = 1/√(2π) ≈ 0.40, where
 * the transverse wave, of length 2πU²/g, is as long as the hull and a displacement hull's wave
 * making rises steeply (Newman, "Marine Hydrodynamics", 1977, §6.18; Faltinsen, "Hydrodynamics of
 * High-Speed Marine Vehicles", 2005, §1.2):
 *     C(U) = amount·min(1, Fr·√(2π)).
 * A hull at rest makes none.
 *
 * When: every texel fades as the whitecap foam does (foamModel.ts: Callaghan et al. 2012), with the
 * same persistence τ, and the zone under a hull is renewed to C, so per step of Δt
 *     F ← max(F·e^{−Δt/τ}, C·S),
 * exact in Δt for the fading; the zone is stamped at every sub-step's pose (localWaves.ts moves a
 * hull at most a quarter of its length per sub-step), so the wake has no gaps at any frame rate.
 *
 * The surface draws this coverage with the whitecaps' pattern and light (shaders/surface/foam.glsl),
 * joined to theirs as independent coverages are (ocean.frag). On the CPU on both local-wave paths:
 * a stamp and a fade of one small grid per step are cheaper than a render pass, and the field is
 * uploaded as one byte per texel only while it holds foam.
 */
import { ClampToEdgeWrapping, DataTexture, LinearFilter, LinearMipmapLinearFilter, RedFormat, UnsignedByteType } from 'three';
import { GRAVITY } from '../spectrum/dispersion';

/** tan α, the Kelvin wedge's half-angle α = arcsin(1/3) (Thomson 1887): 1/√8. */
export const KELVIN_WEDGE_TAN = 1 / Math.sqrt(8);
/** The Froude number at which a hull's foam is full: the hull speed 1/√(2π) (see the header). */
export const HULL_SPEED_FROUDE = 1 / Math.sqrt(2 * Math.PI);
/** Coverage below which a texel is taken as clear (under half of one step of the byte it is drawn from). */
const CLEAR_BELOW = 1 / 512;

/** C(U): the coverage a hull of waterline length `length` (m) keeps at speed `speed` (m/s), times `amount`. */
export function hullFoamCoverage(speed: number, length: number, amount: number): number {
  const froude = speed / Math.sqrt(GRAVITY * length);
  return amount * Math.min(1, froude / HULL_SPEED_FROUDE);
}

/**
 * S(s, n) of the header, softened over `soft` metres: `along` m ahead of the hull's centre (the
 * bow at +length/2), `across` m to its side.
 */
export function breakingZone(along: number, across: number, length: number, beam: number, soft: number): number {
  const behindBow = length / 2 - along;
  const edge = beam / 2 + Math.max(0, behindBow) * KELVIN_WEDGE_TAN;
  return ramp(behindBow / soft) * ramp((length - behindBow) / soft) * ramp((edge - Math.abs(across)) / soft);
}

/** 0 below −½, 1 above ½, linear between. */
function ramp(x: number): number {
  return Math.min(1, Math.max(0, x + 0.5));
}

/** The field: coverage per texel of an N×N grid of `cellSize` m texels, texel (i, j) at index j·N + i. */
export class HullFoam {
  /** Coverage in the red channel, texel (i, j) over the local waves' texel (i, j). */
  readonly texture: DataTexture;
  /** Coverage in [0, 1] per texel, texel (i, j) at index j·N + i, at the grid's origin + (i, j)·cellSize. */
  readonly coverage: Float32Array;
  private readonly bytes: Uint8Array;
  /** True while every texel is 0 (no fading, stamping or upload to do). */
  private empty = true;
  private changed = false;

  constructor(
    readonly resolution: number,
    readonly cellSize: number,
  ) {
    const n = resolution;
    this.coverage = new Float32Array(n * n);
    this.bytes = new Uint8Array(n * n);
    const texture = new DataTexture(this.bytes, n, n, RedFormat, UnsignedByteType);
    texture.name = 'hull foam';
    texture.wrapS = texture.wrapT = ClampToEdgeWrapping;
    texture.magFilter = LinearFilter;
    // Mip levels, so that far away a pixel shows the foam's average, not one texel of it.
    texture.minFilter = LinearMipmapLinearFilter;
    texture.generateMipmaps = true;
    texture.needsUpdate = true;
    this.texture = texture;
  }

  /** Moves the field by (shiftX, shiftZ) texels as the grid moves (texel i takes texel i + shift's value, or 0). */
  shift(shiftX: number, shiftZ: number): void {
    if (this.empty || (shiftX === 0 && shiftZ === 0)) return;
    const n = this.resolution;
    const field = this.coverage;
    // Walk in the direction that reads texels not yet overwritten.
    const jStep = shiftZ > 0 ? 1 : -1;
    const iStep = shiftX > 0 ? 1 : -1;
    const jStart = shiftZ > 0 ? 0 : n - 1;
    const iStart = shiftX > 0 ? 0 : n - 1;
    for (let j = jStart; j >= 0 && j < n; j += jStep) {
      const fromJ = j + shiftZ;
      for (let i = iStart; i >= 0 && i < n; i += iStep) {
        const fromI = i + shiftX;
        field[j * n + i] = fromI >= 0 && fromI < n && fromJ >= 0 && fromJ < n ? field[fromJ * n + fromI] : 0;
      }
    }
    this.changed = true;
  }

  /** Fades every texel over dt seconds with persistence τ (F ← F·e^{−Δt/τ}). */
  fade(dt: number, persistence: number): void {
    if (this.empty || dt <= 0) return;
    const decay = Math.exp(-dt / persistence);
    const field = this.coverage;
    let largest = 0;
    for (let at = 0; at < field.length; at++) {
      const faded = field[at] * decay;
      field[at] = faded;
      if (faded > largest) largest = faded;
    }
    if (largest < CLEAR_BELOW) this.clear();
    else this.changed = true;
  }

  /**
   * Renews the breaking zone of a hull (length, beam in m) whose centre is at (x, z) m from the
   * grid's texel (0, 0), heading (cos, sin), to the coverage `coverage` (hullFoamCoverage).
   */
  stamp(x: number, z: number, cos: number, sin: number, length: number, beam: number, coverage: number): void {
    if (!(coverage > CLEAR_BELOW)) return;
    const n = this.resolution;
    const cell = this.cellSize;
    const field = this.coverage;
    // The zone lies within the hull's length (plus a texel) of its centre along the heading and
    // within the wedge's half-width at the stern (plus a texel) across it.
    const reachAlong = length / 2 + cell;
    const reachAcross = beam / 2 + length * KELVIN_WEDGE_TAN + cell;
    const halfX = Math.abs(cos) * reachAlong + Math.abs(sin) * reachAcross;
    const halfZ = Math.abs(sin) * reachAlong + Math.abs(cos) * reachAcross;
    // The edge texels stay clear: the surface stops sampling the grid there (localWaveModel.ts).
    const i0 = Math.max(1, Math.floor((x - halfX) / cell));
    const i1 = Math.min(n - 2, Math.ceil((x + halfX) / cell));
    const j0 = Math.max(1, Math.floor((z - halfZ) / cell));
    const j1 = Math.min(n - 2, Math.ceil((z + halfZ) / cell));
    for (let j = j0; j <= j1; j++) {
      const dz = j * cell - z;
      for (let i = i0; i <= i1; i++) {
        const dx = i * cell - x;
        const renewed = coverage * breakingZone(dx * cos + dz * sin, dz * cos - dx * sin, length, beam, cell);
        if (renewed > field[j * n + i]) {
          field[j * n + i] = renewed;
          this.empty = false;
          this.changed = true;
        }
      }
    }
  }

  /** Every texel clear. */
  clear(): void {
    if (this.empty) return;
    this.coverage.fill(0);
    this.empty = true;
    this.changed = true;
  }

  /** Makes the texture show the field after shifts, fades, stamps or a clear (an upload only if it changed). */
  publish(): void {
    if (!this.changed) return;
    this.changed = false;
    const { coverage, bytes } = this;
    for (let at = 0; at < coverage.length; at++) bytes[at] = Math.round(Math.min(1, coverage[at]) * 255);
    this.texture.needsUpdate = true;
  }

  dispose(): void {
    this.texture.dispose();
  }
}
