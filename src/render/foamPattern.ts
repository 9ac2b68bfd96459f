/**
 * The whitecap foam's detail pattern (shaders/surface/foam.glsl draws it): smooth value noise in
 * octaves, computed here once per page into two small textures that the sea's fragment shader reads
 * with one lookup each, instead of hashing the lattice of every octave at every pixel. Under
 * SwiftShader, which runs the foam's code at every pixel of the sea whether or not it has foam,
 * the hashed pattern took 45 ms of a 190 ms sea at 1280×720.
 *
 * The pattern is the one foam.glsl hashed before: octaves of cells of 2.5 m, 0.9 m and 0.3 m
 * weighted 0.55, 0.3 and 0.15 (foam.glsl stretches their sum over [0, 1]), and the bubbles, an
 * octave of 15 cm cells.
 * - The coarse octave is a lattice, one texel a cell (COARSE_FOAM_LATTICE): foam.glsl interpolates
 *   it smoothly itself, so its contours have no texel-sized facets however close the eye (a tile
 *   of it interpolated linearly drew the patches as polygons close up).
 * - The finer octaves (their weighted sum) and the bubbles are sampled on a finer tile
 *   (FINE_FOAM_TILE), 3.8 texels to a bubble, interpolated linearly and mipmapped. Their repeat
 *   every 20 m runs under the coarse octave's 200 m; it did not show in the storm pictures
 *   (docs/sea-states/, docs/features/whitecaps.png).
 * Both repeat a whole number of times within FOAM_PATTERN_PERIOD, and every octave's cells within
 * its texture, so the pattern is periodic.
 */
import { DataTexture, LinearFilter, LinearMipmapLinearFilter, RedFormat, RepeatWrapping, RGFormat, UnsignedByteType, type Vector2 } from 'three';

/** The pattern repeats every this many metres (the eye's place is reduced modulo it, OceanMaterial.setEye). */
export const FOAM_PATTERN_PERIOD = 1000;

/**
 * The pattern's origin for an eye at (x, z) m, into `target`: the eye's place in the streaked
 * pattern's coordinates (foamStreaks.glsl's streakPatternPoint, which is linear, for a wind along
 * (windX, windZ) and an elongation E) modulo the period. The pattern repeats, so only the eye's
 * place within a period matters, a number small enough for float32 wherever the eye is.
 */
export function foamPatternOrigin(x: number, z: number, windX: number, windZ: number, elongation: number, target: Vector2): Vector2 {
  const along = (1 - 1 / elongation) * (x * windX + z * windZ);
  return target.set((x - along * windX) % FOAM_PATTERN_PERIOD, (z - along * windZ) % FOAM_PATTERN_PERIOD);
}

/** One octave of value noise: cells per metre, its weight in the pattern's sum, and a lattice offset that decorrelates it. */
export interface FoamOctave {
  cellsPerMetre: number;
  weight: number;
  lattice: number;
}

/** The coarse octave: its lattice values, one texel per cell over `size` metres. */
export const COARSE_FOAM_LATTICE = { size: 200, octave: { cellsPerMetre: 0.4, weight: 0.55, lattice: 0 } } as const;

/**
 * The finer octaves: `size` metres square on `texels` texels a side; R holds the octaves' weighted
 * sum over the sum of their weights (in [0, 1]), G the bubbles (in [0, 1]).
 */
export const FINE_FOAM_TILE = {
  size: 20,
  texels: 512,
  octaves: [
    { cellsPerMetre: 1.1, weight: 0.3, lattice: 17 },
    { cellsPerMetre: 3.3, weight: 0.15, lattice: -31 },
  ],
  bubbles: { cellsPerMetre: 6.7, weight: 1, lattice: 5 },
} as const;

/** A 2D integer hash (PCG-style mixing, as foam.glsl had) of a lattice point, in [0, 1]. */
export function latticeValue(x: number, y: number): number {
  let h = (Math.imul(x, 747796405) + Math.imul(y, 2891336453 | 0)) >>> 0;
  h = Math.imul((h >>> ((h >>> 28) + 4)) ^ h, 277803737) >>> 0;
  return (((h >>> 22) ^ h) >>> 0) / 4294967295;
}

/** Cells a side of an octave over `size` metres (a whole number: the octaves are chosen so). */
const cellsOver = (octave: FoamOctave, size: number): number => Math.round(size * octave.cellsPerMetre);

/** The coarse octave's cells a side, one texel each. */
const COARSE_CELLS = cellsOver(COARSE_FOAM_LATTICE.octave, COARSE_FOAM_LATTICE.size);

/** An octave's lattice values over `cells`² cells (row j, column i at j·cells + i). */
function latticeGrid(octave: FoamOctave, cells: number): Float32Array {
  const lattice = new Float32Array(cells * cells);
  for (let j = 0; j < cells; j++) for (let i = 0; i < cells; i++) lattice[j * cells + i] = latticeValue(i + octave.lattice, j);
  return lattice;
}

/**
 * Adds `scale` × one octave of smooth value noise, periodic over `size` metres (its cells fit a
 * whole number of times), sampled at the texel centres ((i + ½), (j + ½))·size/texels of a tile,
 * into `into` (row j, column i at j·texels + i): the lattice values at the cell's corners blended
 * with smoothstep weights w = f²(3 − 2f), as foam.glsl has the hardware's linear filter blend the
 * coarse octave's lattice (smoothLattice). The weights along x depend on the column only and those
 * along z on the row: computed once each.
 */
function addOctave(octave: FoamOctave, size: number, texels: number, scale: number, into: Float32Array): void {
  const period = cellsOver(octave, size);
  const lattice = latticeGrid(octave, period);
  // Per column (and, the same numbers, per row): the cell's first corner, the next one and the smoothstep weight.
  const first = new Int32Array(texels);
  const next = new Int32Array(texels);
  const weight = new Float32Array(texels);
  for (let i = 0; i < texels; i++) {
    const q = (((i + 0.5) * size) / texels) * octave.cellsPerMetre;
    const cell = Math.floor(q);
    const f = q - cell;
    first[i] = cell % period;
    next[i] = (cell + 1) % period;
    weight[i] = f * f * (3 - 2 * f);
  }
  // Row by row: first the lattice blended along z (one value per lattice column), then along x.
  const blended = new Float32Array(period);
  for (let j = 0; j < texels; j++) {
    const row0 = first[j] * period;
    const row1 = next[j] * period;
    const wz = weight[j];
    for (let x = 0; x < period; x++) blended[x] = scale * (lattice[row0 + x] + (lattice[row1 + x] - lattice[row0 + x]) * wz);
    const row = j * texels;
    for (let i = 0; i < texels; i++) into[row + i] += blended[first[i]] + (blended[next[i]] - blended[first[i]]) * weight[i];
  }
}

/** The coarse octave's lattice values (R8, one texel per cell), rounded to the nearest byte. */
export function coarseFoamLatticeBytes(): Uint8Array {
  return Uint8Array.from(latticeGrid(COARSE_FOAM_LATTICE.octave, COARSE_CELLS), (value) => value * 255 + 0.5);
}

/** The fine tile (RG8): R the finer octaves' weighted sum over their total weight, G the bubbles. */
export function fineFoamTileBytes(): Uint8Array {
  const { size, texels, octaves, bubbles } = FINE_FOAM_TILE;
  const totalWeight = octaves.reduce((sum, o) => sum + o.weight, 0);
  const [sum, bubbleValues] = [new Float32Array(texels * texels), new Float32Array(texels * texels)];
  for (const octave of octaves) addOctave(octave, size, texels, octave.weight / totalWeight, sum);
  addOctave(bubbles, size, texels, 1, bubbleValues);
  const bytes = new Uint8Array(2 * texels * texels);
  for (let t = 0; t < texels * texels; t++) {
    // Rounded to the nearest byte: a typed array's store truncates, and the values are in [0, 1].
    bytes[2 * t] = sum[t] * 255 + 0.5;
    bytes[2 * t + 1] = bubbleValues[t] * 255 + 0.5;
  }
  return bytes;
}

/** The textures' bytes, computed for the first material that asks and shared by the rest. */
let bytes: { coarse: Uint8Array; fine: Uint8Array } | null = null;

/**
 * The pattern's two textures, wrapping: the coarse lattice filtered linearly (foamPattern's smooth
 * interpolation needs exactly that), the fine tile mipmapped (far pixels average it rather than
 * alias it). The caller owns them and disposes them.
 */
export function foamPatternTextures(): { coarse: DataTexture; fine: DataTexture } {
  bytes ??= { coarse: coarseFoamLatticeBytes(), fine: fineFoamTileBytes() };
  const coarse = new DataTexture(bytes.coarse, COARSE_CELLS, COARSE_CELLS, RedFormat, UnsignedByteType);
  const fine = new DataTexture(bytes.fine, FINE_FOAM_TILE.texels, FINE_FOAM_TILE.texels, RGFormat, UnsignedByteType);
  for (const texture of [coarse, fine]) {
    texture.wrapS = texture.wrapT = RepeatWrapping;
    texture.magFilter = LinearFilter;
    texture.needsUpdate = true;
  }
  coarse.minFilter = LinearFilter;
  fine.minFilter = LinearMipmapLinearFilter;
  fine.generateMipmaps = true;
  return { coarse, fine };
}

/** The constants foam.glsl takes from here (its FOAM_* defines; the WebGPU Ocean's foamNodes.ts reads them as numbers). */
export const FOAM_PATTERN_CONSTANTS = {
  FOAM_COARSE_CELLS: COARSE_CELLS,
  FOAM_COARSE_CELLS_PER_METRE: COARSE_FOAM_LATTICE.octave.cellsPerMetre,
  FOAM_COARSE_WEIGHT: COARSE_FOAM_LATTICE.octave.weight,
  FOAM_FINE_TILE: FINE_FOAM_TILE.size,
  FOAM_FINE_WEIGHT: FINE_FOAM_TILE.octaves.reduce((sum, o) => sum + o.weight, 0),
  FOAM_PATTERN_PERIOD,
} as const;

/** FOAM_PATTERN_CONSTANTS as GLSL float literals. */
export function foamPatternDefines(): Record<string, string> {
  const float = (value: number) => (Number.isInteger(value) ? value.toFixed(1) : String(value));
  return Object.fromEntries(Object.entries(FOAM_PATTERN_CONSTANTS).map(([name, value]) => [name, float(value)]));
}
