/**
 * How the spectrum is split between FFT cascades, and how long each cascade's repeat period is.
 *
 * Cascades are square patches of different sides L (ascending; index 0 is the finest). Each
 * wavelength is simulated once: cascade c holds the waves with |k| in [low_c, high_c), in the modes
 * whose cells reach into that band, each with its cell's share (cellInBand). The
 * boundary between a cascade and the next finer one is the geometric mean of the finer grid's
 * fundamental 2π/L_finer and the coarser grid's Nyquist radius πN/L_coarser: both grids then have
 * the same margin, √(N·L_finer/(2·L_coarser)), the finer one that many rings of modes inside the
 * boundary to resolve directions, the coarser one that factor of headroom below its Nyquist
 * radius (4.7 for the default 256² cascades 5.8× apart). The boundary lies inside both grids as
 * long as L_coarser/L_finer ≤ N/2. (gasgiant/FFT-Ocean puts it at a fixed 6 fundamentals, which
 * fails for small N.) The coarsest cascade also keeps everything down to its fundamental, the
 * finest everything up to its grid's corner.
 *
 * Repeat period of a cascade (Tessendorf 2001, eq. 17). Each mode's ω is rounded to the nearest
 * multiple m·2π/T_c, an error of at most π/T_c, so the phase speed ω/k of every mode is within
 * PHASE_SPEED_TOLERANCE of the true one when π/T_c ≤ PHASE_SPEED_TOLERANCE·ω_slowest. T_c is the
 * user's repeat period T doubled until that holds: all T_c are T·2^j, so the whole sea still
 * repeats, after the longest of them.
 */
import { angularFrequency } from './dispersion';

/** Largest relative error of any simulated mode's phase speed. */
export const PHASE_SPEED_TOLERANCE = 0.01;

export interface CascadeBand {
  /** Side of the cascade's patch, m. */
  patchSize: number;
  /** The modes it keeps: low ≤ |k| < high, rad/m (high may be Infinity). */
  low: number;
  high: number;
}

/** Bands of cascades with these patch sizes (ascending) and N texels a side. */
export function cascadeBands(patchSizes: readonly number[], resolution: number): CascadeBand[] {
  // Between cascade c (finer) and c + 1 (coarser): √(2π/L_c · πN/L_{c+1}).
  const boundary = (c: number) => Math.sqrt(((2 * Math.PI) / patchSizes[c]) * ((Math.PI * resolution) / patchSizes[c + 1]));
  return patchSizes.map((patchSize, c) => ({
    patchSize,
    low: c === patchSizes.length - 1 ? 0 : boundary(c),
    high: c === 0 ? Infinity : boundary(c - 1),
  }));
}

/** Largest ratio of neighbouring patch sizes for which every boundary lies inside both grids. */
export function maxPatchRatio(resolution: number): number {
  return resolution / 2;
}

/** How much of a mode's cell lies in a band (cellInBand). */
export type CellOverlap = 'whole' | 'part' | 'none';

/**
 * Where mode (n, m)'s cell lies against the band: the square of side 2π/L centred on the mode, its
 * share of the k plane (initialSpectrum.ts weighs each mode by ∫Ψ over its cell's part in the band).
 * Decided in grid units from the cell's nearest and farthest points to k = 0. The cells of a grid
 * tile the plane, so the cells a band touches cover it exactly, however few lattice points lie
 * near its edge.
 */
export function cellInBand(band: CascadeBand, n: number, m: number): CellOverlap {
  const fundamental = (2 * Math.PI) / band.patchSize;
  const [low, high] = [band.low / fundamental, band.high / fundamental];
  const near = Math.hypot(Math.max(0, Math.abs(n) - 0.5), Math.max(0, Math.abs(m) - 0.5));
  const far = Math.hypot(Math.abs(n) + 0.5, Math.abs(m) + 0.5);
  if (far <= low || near >= high) return 'none';
  return near >= low && far < high ? 'whole' : 'part';
}

/**
 * Sub-cells a side over which ∫Ψ is summed in a cell the band's edge crosses: the share of the cell
 * in the band is then resolved to 1/64 of its area (the midpoint rule on an 8 × 8 split).
 */
export const EDGE_CELL_SPLIT = 8;

/**
 * The midpoints, in grid units, of the EDGE_CELL_SPLIT² sub-cells of mode (n, m)'s cell that lie in
 * the band, for a cell whose overlap is 'part'.
 */
export function edgeCellPoints(band: CascadeBand, n: number, m: number): [number, number][] {
  const fundamental = (2 * Math.PI) / band.patchSize;
  const [low, high] = [band.low / fundamental, band.high / fundamental];
  const points: [number, number][] = [];
  for (let b = 0; b < EDGE_CELL_SPLIT; b++) {
    for (let a = 0; a < EDGE_CELL_SPLIT; a++) {
      const [x, y] = [n - 0.5 + (a + 0.5) / EDGE_CELL_SPLIT, m - 0.5 + (b + 0.5) / EDGE_CELL_SPLIT];
      const radius = Math.hypot(x, y);
      if (radius >= low && radius < high) points.push([x, y]);
    }
  }
  return points;
}

/** The Nyquist radius πN/L of a cascade's grid: above it, directions are not all resolved. */
export function nyquistRadius(band: CascadeBand, resolution: number): number {
  return (Math.PI * resolution) / band.patchSize;
}

/**
 * |k| of the slowest nonzero mode a cascade keeps (a lower bound: a mode is kept when its cell
 * reaches into the band, so it lies at most half a cell's diagonal below the low edge; and no
 * nonzero mode is slower than the fundamental).
 */
export function slowestModeInBand(band: CascadeBand): number {
  const fundamental = (2 * Math.PI) / band.patchSize;
  return Math.max(band.low - fundamental * Math.SQRT1_2, fundamental);
}

/** |k| of the fastest mode a cascade keeps (an upper bound: half a cell's diagonal above its high edge, or its grid's corner). */
export function fastestModeInBand(band: CascadeBand, resolution: number): number {
  const fundamental = (2 * Math.PI) / band.patchSize;
  return Math.min(band.high + fundamental * Math.SQRT1_2, Math.SQRT2 * nyquistRadius(band, resolution));
}

/**
 * The period (s) after which the whole sea repeats exactly: every cascade's period is the base
 * period times a power of two (cascadeRepeatPeriod), so it is the longest of them.
 */
export function seaRepeatPeriod(params: { patchSizes: readonly number[]; resolution: number; depth: number; repeatPeriod: number }): number {
  return Math.max(...cascadeBands(params.patchSizes, params.resolution).map((band) => cascadeRepeatPeriod(band, params)));
}

/** T·2^j, the shortest that keeps every mode of the band within PHASE_SPEED_TOLERANCE (see above). */
export function cascadeRepeatPeriod(band: CascadeBand, params: { depth: number; repeatPeriod: number }): number {
  const needed = Math.PI / (PHASE_SPEED_TOLERANCE * angularFrequency(slowestModeInBand(band), params.depth));
  let period = params.repeatPeriod;
  while (period < needed) period *= 2;
  return period;
}
