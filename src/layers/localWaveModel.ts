/**
 * Local waves: the linear water-wave equations solved on a square grid that follows the camera or a
 * boat, with the exact dispersion of every mode the grid holds. This file is the model both paths
 * share (the step's formulas, the absorbing border, the sources' shapes) and its JS solver; the GPU
 * solver (gpuLocalWaves.ts) runs the same step in fragment passes.
 *
 * The equations (linearised potential flow, e.g. Lamb, "Hydrodynamics", §227–229; Whitham, "Linear
 * and Nonlinear Waves" (1974), §13.1), for the surface height η, the surface velocity potential φ
 * and an applied surface pressure p, in Fourier space with K(k) = k·tanh(k·d):
 *   ∂η̂/∂t = K·φ̂,   ∂φ̂/∂t = −g·(η̂ + P̂),   P = p/(ρ·g) the pressure as a head of water (m),
 * so each mode oscillates at ω(k) = √(g·K) (dispersion.ts). With ψ̂ = φ̂·ω/g (a potential measured in
 * metres) and Z = η̂ + P̂ + i·ψ̂ they become one equation per mode, ∂Z/∂t = −i·ω·Z for a pressure held
 * during the step, solved exactly by Z ← Z·e^{−iωΔt}: no time-step limit and no numerical
 * dispersion, whatever Δt. iWave (Tessendorf 2004, "Interactive Water Surfaces") gets its dispersion
 * from a convolution kernel that approximates K in space; the spectral step has it exactly, at the
 * cost of two FFTs per step.
 *
 * So the state is, on the grid, η_s = η + P and ψ (both real; FFT of η_s + iψ gives Z). Under a
 * pressure held still the water settles to η = −P, η_s = 0: η_s is the sea "with the hull's
 * displacement filled in", which is what the surface draws and what a floating body feels (the
 * body itself is drawn over its own depression, and must not feel it as a loss of buoyancy).
 * Sources therefore work as changes of η_s: a stone adds a dip once; a moving hull adds
 * P(new pose) − P(old pose) each step. Waves then leave them with the exact dispersion: a ring
 * spreads at the group speed of its wavelength, a hull in steady motion draws the Kelvin wedge.
 *
 * Over a seabed (Ocean.setSeabed) an FFT step can take one depth only: ω is that of the mean depth of
 * the grid's wet texels (each counted at most as deep as the grid is wide, beyond which every mode it
 * holds is in deep water, tanh(k·d) > 0.996), so a ring in 2 m of water spreads at √(g·d), the
 * shallow-water limit of ω² = g·k·tanh(k·d) (Dean & Dalrymple 1991, "Water Wave Mechanics for
 * Engineers and Scientists", §3.4, eq. 3.34 and its limits); and η_s and ψ are held at zero over
 * land (depth ≤ 0), where the surface is the ground's (shaders/surface/shoaling.glsl), so a wave
 * that reaches the waterline stops there as at a wall (LocalWaveWater). A grid over water of very
 * different depths moves every wave at the mean depth's speed: the local waves neither shoal nor
 * refract (docs/shores.md).
 *
 * The border absorbs (the FFT's grid is periodic: what leaves one side would come back on the
 * other): a sponge layer (Israeli & Orszag 1981, "Approximation of radiation boundary conditions")
 * of SPONGE_WIDTH texels damps η_s and ψ with a rate that grows quadratically towards the edge,
 * and the edge texels are held at zero, so the layer also fades to nothing at its border, where the
 * surface stops sampling it.
 *
 * Per step, on both paths:
 *   1. space:    shift by whole texels when the grid moves (new texels zero), damp in the sponge,
 *                add the sources' height changes;
 *   2. forward FFT of η_s + iψ;
 *   3. spectrum: Z ← Z·e^{−iωΔt}/N², and the slopes' spectrum i·(kx + i·kz)·Ĥ with
 *                Ĥ = (Z(k) + Z*(−k))/2 the spectrum of η_s;
 *   4. inverse FFT of both: (η_s + iψ, ∂η_s/∂x + i·∂η_s/∂z) on the grid, × the wet mask.
 */
import { angularFrequency, GRAVITY } from '../spectrum/dispersion';
import { BatchedInverseFft2D } from '../fft/fft';

/** Texels of the absorbing sponge on each side. */
export const SPONGE_WIDTH_FRACTION = 1 / 8;
/**
 * Damping rate at the edge, per second, for a grid whose texels are `cellSize` m: the sponge must
 * damp a wave crossing it (at its group speed) by far more than it reflects. Scaled with the
 * crossing time of the slowest wave the grid resolves well (8 texels long), so that the same
 * number of e-foldings happens inside it for every grid. Tuned with the reflection test
 * (tests/unit/localWaves.test.ts): under 1 % of a packet's energy comes back, for 2–16 m waves.
 */
export function spongeEdgeRate(cellSize: number): number {
  const slowestGroupSpeed = 0.5 * Math.sqrt((GRAVITY * 8 * cellSize) / (2 * Math.PI));
  return (12 * slowestGroupSpeed) / cellSize / 8;
}

/** The grid the local waves are solved on. */
export interface LocalWaveGrid {
  /** Texels per side, a power of two. */
  readonly resolution: number;
  /** Side of a texel, m. */
  readonly cellSize: number;
  /** Water depth, m (Infinity: deep). */
  readonly depth: number;
}

/**
 * The water under the grid as it is now: the depth the step's dispersion uses (m, Infinity: deep)
 * and, over a seabed with land under the grid, 1 on wet texels and 0 on land (texel (i, j) at
 * j·N + i), else null (all wet). Made by LocalWaves from the seabed (localWaterUnder).
 */
export interface LocalWaveWater {
  readonly depth: number;
  readonly wet: Float32Array | null;
}

/** A sea floor as localWaterUnder reads it (SeabedMap): its depth, `outside` beyond `bounds` ([xMin, zMin, xMax, zMax], m). */
export interface LocalSeabed {
  depthAt(x: number, z: number, outside: number): number;
  readonly bounds: readonly [number, number, number, number];
}

/**
 * The water under an N×N grid whose texel (i, j) is at world (x0 + i·cell, z0 + j·cell), over
 * `seabed` (`openDepth` deep beyond its bounds): the wet texels' mean depth, each counted at most
 * the grid's side deep (see the file's comment), and the wet mask (null when no texel is land),
 * written into `mask` (N², reused from call to call). Water all deeper than the side counts as
 * max(side, openDepth) deep; a grid all over land (nothing moves on it) keeps `openDepth`. Only
 * the texels within the bounds (and one more round them, for rounding) are read; the rest are
 * open water, counted together.
 */
export function localWaterUnder(grid: LocalWaveGrid, x0: number, z0: number, seabed: LocalSeabed, openDepth: number, mask: Float32Array): LocalWaveWater {
  const n = grid.resolution;
  const cell = grid.cellSize;
  const side = n * cell;
  const [xMin, zMin, xMax, zMax] = seabed.bounds;
  // The texels the bounds may reach; Math.max/min also take infinite bounds to the grid's edges.
  const i0 = Math.max(0, Math.ceil((xMin - x0) / cell) - 1);
  const i1 = Math.min(n - 1, Math.floor((xMax - x0) / cell) + 1);
  const j0 = Math.max(0, Math.ceil((zMin - z0) / cell) - 1);
  const j1 = Math.min(n - 1, Math.floor((zMax - z0) / cell) + 1);
  mask.fill(1);
  let sum = 0;
  let count = 0;
  let read = 0;
  for (let j = j0; j <= j1; j++) {
    for (let i = i0; i <= i1; i++) {
      read++;
      const d = seabed.depthAt(x0 + i * cell, z0 + j * cell, openDepth);
      if (!(d > 0)) {
        mask[j * n + i] = 0;
        continue;
      }
      sum += Math.min(d, side);
      count++;
    }
  }
  const open = n * n - read;
  sum += open * Math.min(openDepth, side);
  count += open;
  if (count === 0) return { depth: openDepth, wet: mask };
  const depth = sum / count >= side ? Math.max(openDepth, side) : sum / count;
  return { depth, wet: count === n * n ? null : mask };
}

/**
 * A change of the surface height added in one step, centred at (x, z) in metres from the grid's
 * texel (0, 0): height·exp(−(u/halfLength)² − (v/halfBeam)²), u along the heading (cos, sin), v
 * across it. A stone's dip, or half of a moving hull's pressure change.
 */
export interface HeightImpulse {
  x: number;
  z: number;
  cos: number;
  sin: number;
  halfLength: number;
  halfBeam: number;
  height: number;
}

/** What one step does: the grid's move in whole texels, the sources' height changes, and Δt (s). */
export interface LocalWaveStep {
  shiftX: number;
  shiftZ: number;
  impulses: readonly HeightImpulse[];
  dt: number;
}

/** The impulses one step can take on the GPU (a uniform array); the layer splits longer lists. */
export const MAX_IMPULSES_PER_STEP = 16;

/** Damping factor per step of duration dt at texel (i, j) of an N×N grid: 0 on the edge itself. */
export function spongeFactor(i: number, j: number, grid: LocalWaveGrid, dt: number): number {
  const n = grid.resolution;
  const fromEdge = Math.min(i, j, n - 1 - i, n - 1 - j);
  if (fromEdge === 0) return 0;
  const width = n * SPONGE_WIDTH_FRACTION;
  if (fromEdge >= width) return 1;
  const depthIn = (width - fromEdge) / width;
  return Math.exp(-spongeEdgeRate(grid.cellSize) * depthIn * depthIn * dt);
}

/** The height change of an impulse at (x, z) (metres from texel (0, 0)). */
export function impulseHeight(impulse: HeightImpulse, x: number, z: number): number {
  const dx = x - impulse.x;
  const dz = z - impulse.z;
  const along = (dx * impulse.cos + dz * impulse.sin) / impulse.halfLength;
  const across = (dz * impulse.cos - dx * impulse.sin) / impulse.halfBeam;
  return impulse.height * Math.exp(-(along * along + across * across));
}

/** Signed wavenumber index of FFT bin i of N: i for i < N/2, i − N above. */
export function signedIndex(i: number, n: number): number {
  return i < n / 2 ? i : i - n;
}

/**
 * The JS solver: the state η_s, ψ and the slopes on the grid, texel (i, j) at index j·N + i, in
 * metres. step() runs one step of the file's scheme.
 */
export class CpuLocalWaves {
  /** η_s, the height the surface draws (m). */
  readonly height: Float64Array;
  /** ψ = φ·ω/g per mode (m). */
  readonly potential: Float64Array;
  /** ∂η_s/∂x, ∂η_s/∂z. */
  readonly slopeX: Float64Array;
  readonly slopeZ: Float64Array;
  private readonly forward: BatchedInverseFft2D;
  private readonly inverse: BatchedInverseFft2D;
  /** ω(k) per frequency texel, and the wavenumbers kx, kz of each column and row (0 at Nyquist for slopes). */
  private readonly omega: Float64Array;
  private readonly slopeWavenumber: Float64Array;
  private velocityFft: BatchedInverseFft2D | null = null;
  /** The depth ω is for, m, and the wet mask (null: all wet). */
  private omegaDepth = NaN;
  private wet: Float32Array | null = null;

  constructor(readonly grid: LocalWaveGrid) {
    const n = grid.resolution;
    this.height = new Float64Array(n * n);
    this.potential = new Float64Array(n * n);
    this.slopeX = new Float64Array(n * n);
    this.slopeZ = new Float64Array(n * n);
    this.forward = new BatchedInverseFft2D(n, 1);
    this.inverse = new BatchedInverseFft2D(n, 2);
    const dk = (2 * Math.PI) / (n * grid.cellSize);
    this.slopeWavenumber = Float64Array.from({ length: n }, (_, i) => (i === n / 2 ? 0 : signedIndex(i, n) * dk));
    this.omega = new Float64Array(n * n);
    this.setWater({ depth: grid.depth, wet: null });
  }

  /** The water under the grid from the next step on: ω(k) for its depth, and its land held at zero. */
  setWater({ depth, wet }: LocalWaveWater): void {
    this.wet = wet;
    if (depth === this.omegaDepth) return;
    this.omegaDepth = depth;
    const n = this.grid.resolution;
    const dk = (2 * Math.PI) / (n * this.grid.cellSize);
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        this.omega[j * n + i] = angularFrequency(Math.hypot(signedIndex(i, n), signedIndex(j, n)) * dk, depth);
      }
    }
  }

  /**
   * ∂η_s/∂t on the grid, from the potential ψ (texel t's at index t·stride of `potential`): per mode
   * ∂η̂/∂t = ω·ψ̂ (the file's equations), so ∂η/∂t = IFFT(ω·FFT(ψ)). Written as RGBA texels
   * (0, ∂η/∂t, 0, 0) into `out`, the layout of a layer's velocities.
   */
  verticalVelocity(potential: ArrayLike<number>, stride: number, out: Float32Array): void {
    const n = this.grid.resolution;
    this.velocityFft ??= new BatchedInverseFft2D(n, 1);
    const fft = this.velocityFft;
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const at = fft.inputIndex(0, i, j);
        fft.inputReal[at] = potential[(j * n + i) * stride];
        fft.inputImag[at] = 0;
      }
    }
    fft.run(); // the inverse transform of a real field is the conjugate of its forward one
    const norm = 1 / (n * n);
    const spectrumRe = Float64Array.from({ length: n * n }, (_, t) => fft.outputReal[fft.outputIndex(0, t % n, Math.floor(t / n))] * norm);
    const spectrumIm = Float64Array.from({ length: n * n }, (_, t) => -fft.outputImag[fft.outputIndex(0, t % n, Math.floor(t / n))] * norm);
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const at = fft.inputIndex(0, i, j);
        fft.inputReal[at] = this.omega[j * n + i] * spectrumRe[j * n + i];
        fft.inputImag[at] = this.omega[j * n + i] * spectrumIm[j * n + i];
      }
    }
    fft.run();
    out.fill(0);
    for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) out[4 * (j * n + i) + 1] = fft.outputReal[fft.outputIndex(0, i, j)];
  }

  /** Clears the sea on the grid. */
  clear(): void {
    for (const field of [this.height, this.potential, this.slopeX, this.slopeZ]) field.fill(0);
  }

  step({ shiftX, shiftZ, impulses, dt }: LocalWaveStep): void {
    const n = this.grid.resolution;
    const { height, potential, forward, inverse } = this;
    this.shiftAndDamp(shiftX, shiftZ, dt);
    const cell = this.grid.cellSize;
    for (const impulse of impulses) {
      // exp(−16) < 1.2e-7: beyond 4 half-lengths the impulse adds nothing a float32 field holds.
      const reach = 4 * Math.max(impulse.halfLength, impulse.halfBeam);
      const [i0, i1] = [Math.max(0, Math.floor((impulse.x - reach) / cell)), Math.min(n - 1, Math.ceil((impulse.x + reach) / cell))];
      const [j0, j1] = [Math.max(0, Math.floor((impulse.z - reach) / cell)), Math.min(n - 1, Math.ceil((impulse.z + reach) / cell))];
      for (let j = j0; j <= j1; j++) for (let i = i0; i <= i1; i++) height[j * n + i] += impulseHeight(impulse, i * cell, j * cell);
    }
    // Forward transform as the conjugate of the inverse of the conjugate.
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const at = forward.inputIndex(0, i, j);
        forward.inputReal[at] = height[j * n + i];
        forward.inputImag[at] = -potential[j * n + i];
      }
    }
    forward.run();
    const norm = 1 / (n * n);
    const re = forward.outputReal;
    const im = forward.outputImag;
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const at = forward.outputIndex(0, i, j);
        const phase = this.omega[j * n + i] * dt;
        const [c, s] = [Math.cos(phase) * norm, -Math.sin(phase) * norm];
        const zRe = re[at];
        const zIm = -im[at];
        re[at] = zRe * c - zIm * s;
        im[at] = zRe * s + zIm * c;
      }
    }
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const at = forward.outputIndex(0, i, j);
        const mirror = forward.outputIndex(0, (n - i) % n, (n - j) % n);
        const hRe = 0.5 * (re[at] + re[mirror]);
        const hIm = 0.5 * (im[at] - im[mirror]);
        const kx = this.slopeWavenumber[i];
        const kz = this.slopeWavenumber[j];
        const state = inverse.inputIndex(0, i, j);
        inverse.inputReal[state] = re[at];
        inverse.inputImag[state] = im[at];
        const slopes = inverse.inputIndex(1, i, j);
        inverse.inputReal[slopes] = -kz * hRe - kx * hIm;
        inverse.inputImag[slopes] = kx * hRe - kz * hIm;
      }
    }
    inverse.run();
    const wet = this.wet;
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const state = inverse.outputIndex(0, i, j);
        const slopes = inverse.outputIndex(1, i, j);
        const water = wet === null ? 1 : wet[j * n + i];
        height[j * n + i] = inverse.outputReal[state] * water;
        potential[j * n + i] = inverse.outputImag[state] * water;
        this.slopeX[j * n + i] = inverse.outputReal[slopes] * water;
        this.slopeZ[j * n + i] = inverse.outputImag[slopes] * water;
      }
    }
  }

  /** Moves the fields by (shiftX, shiftZ) texels (texel i takes texel i + shift's value, or 0) and damps them in the sponge. */
  private shiftAndDamp(shiftX: number, shiftZ: number, dt: number): void {
    const n = this.grid.resolution;
    const { height, potential } = this;
    // Walk in the direction that reads texels not yet overwritten.
    const rows = shiftZ > 0 ? ascending(n) : descending(n);
    const columns = shiftX > 0 ? ascending(n) : descending(n);
    for (const j of rows) {
      for (const i of columns) {
        const fromI = i + shiftX;
        const fromJ = j + shiftZ;
        const inside = fromI >= 0 && fromI < n && fromJ >= 0 && fromJ < n;
        const damping = spongeFactor(i, j, this.grid, dt);
        height[j * n + i] = inside ? height[fromJ * n + fromI] * damping : 0;
        potential[j * n + i] = inside ? potential[fromJ * n + fromI] * damping : 0;
      }
    }
  }
}

function ascending(n: number): number[] {
  return Array.from({ length: n }, (_, i) => i);
}

function descending(n: number): number[] {
  return Array.from({ length: n }, (_, i) => n - 1 - i);
}
