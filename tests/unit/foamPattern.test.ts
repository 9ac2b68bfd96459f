// The whitecap foam's detail pattern (src/render/foamPattern.ts), as shaders/surface/foam.glsl
// reads it: the textures against value noise evaluated point by point here, the pattern's period,
// and its coverage (foam.glsl draws foam where p < coverage, so p must be about uniform).
import { describe, expect, it } from 'vitest';
import {
  COARSE_FOAM_LATTICE,
  coarseFoamLatticeBytes,
  FINE_FOAM_TILE,
  fineFoamTileBytes,
  FOAM_PATTERN_PERIOD,
  latticeValue,
  type FoamOctave,
} from '../../src/render/foamPattern';

/**
 * Value noise of one octave at (x, z) metres, periodic over `size` metres, evaluated directly:
 * the lattice values at the four corners of the point's cell blended with smoothstep weights
 * f²(3 − 2f) (lattice value noise: Peachey, "Building procedural textures", in Ebert et al.,
 * Texturing and Modeling, 3rd ed., 2003, §2; foam.glsl's texture lookup gives the same blend for
 * the coarse octave).
 */
function octaveAt(octave: FoamOctave, size: number, x: number, z: number): number {
  const period = Math.round(size * octave.cellsPerMetre);
  const wrap = (c: number) => ((c % period) + period) % period;
  const [qx, qz] = [x * octave.cellsPerMetre, z * octave.cellsPerMetre];
  const [cx, cz] = [Math.floor(qx), Math.floor(qz)];
  const smooth = (f: number) => f * f * (3 - 2 * f);
  const [wx, wz] = [smooth(qx - cx), smooth(qz - cz)];
  const at = (i: number, j: number) => latticeValue(wrap(i) + octave.lattice, wrap(j));
  const near = at(cx, cz) * (1 - wx) + at(cx + 1, cz) * wx;
  const far = at(cx, cz + 1) * (1 - wx) + at(cx + 1, cz + 1) * wx;
  return near * (1 - wz) + far * wz;
}

/** foam.glsl's pattern p at (x, z) from the octaves themselves: smoothstep(0.2, 0.8, Σ weight·octave). */
function patternAt(x: number, z: number): number {
  const sum =
    COARSE_FOAM_LATTICE.octave.weight * octaveAt(COARSE_FOAM_LATTICE.octave, COARSE_FOAM_LATTICE.size, x, z) +
    FINE_FOAM_TILE.octaves.reduce((total, o) => total + o.weight * octaveAt(o, FINE_FOAM_TILE.size, x, z), 0);
  const t = Math.min(1, Math.max(0, (sum - 0.2) / 0.6));
  return t * t * (3 - 2 * t);
}

describe('the foam pattern', () => {
  it('repeats within FOAM_PATTERN_PERIOD: each texture a whole number of times, each octave\'s cells a whole number of times in its texture', () => {
    for (const size of [COARSE_FOAM_LATTICE.size, FINE_FOAM_TILE.size]) expect(Number.isInteger(FOAM_PATTERN_PERIOD / size)).toBe(true);
    const octaves: [FoamOctave, number][] = [
      [COARSE_FOAM_LATTICE.octave, COARSE_FOAM_LATTICE.size],
      ...FINE_FOAM_TILE.octaves.map((o): [FoamOctave, number] => [o, FINE_FOAM_TILE.size]),
      [FINE_FOAM_TILE.bubbles, FINE_FOAM_TILE.size],
    ];
    for (const [octave, size] of octaves) expect(Math.abs(size * octave.cellsPerMetre - Math.round(size * octave.cellsPerMetre))).toBeLessThan(1e-9);
    // And so the noise itself: the same value a period away.
    for (const [octave, size] of octaves) expect(octaveAt(octave, size, 3.37 + size, -1.91)).toBeCloseTo(octaveAt(octave, size, 3.37, -1.91), 12);
  });

  it('the coarse lattice holds the lattice values and the fine tile the finer octaves and the bubbles at its texel centres (to the byte)', () => {
    const coarse = coarseFoamLatticeBytes();
    const cells = Math.round(COARSE_FOAM_LATTICE.size * COARSE_FOAM_LATTICE.octave.cellsPerMetre);
    expect(coarse.length).toBe(cells * cells);
    for (const [i, j] of [[0, 0], [7, 3], [cells - 1, cells - 2], [40, 61]]) {
      expect(coarse[j * cells + i]).toBe(Math.round(255 * latticeValue(i + COARSE_FOAM_LATTICE.octave.lattice, j)));
    }
    const fine = fineFoamTileBytes();
    const { size, texels, octaves, bubbles } = FINE_FOAM_TILE;
    const totalWeight = octaves.reduce((sum, o) => sum + o.weight, 0);
    let worst = 0;
    for (let k = 0; k < 500; k++) {
      const [i, j] = [(k * 97) % texels, (k * 389 + 11) % texels];
      const [x, z] = [((i + 0.5) * size) / texels, ((j + 0.5) * size) / texels];
      const sum = octaves.reduce((total, o) => total + o.weight * octaveAt(o, size, x, z), 0) / totalWeight;
      worst = Math.max(worst, Math.abs(fine[2 * (j * texels + i)] - 255 * sum), Math.abs(fine[2 * (j * texels + i) + 1] - 255 * octaveAt(bubbles, size, x, z)));
    }
    expect(worst).toBeLessThanOrEqual(0.5 + 1e-3); // rounding to the nearest byte
  });

  it('covers about a fraction c of the sea where p < c (within 0.05 of c, from 0.1 to 0.9)', () => {
    // 300 × 300 points over a coarse tile, off the lattices' grids.
    const samples: number[] = [];
    for (let j = 0; j < 300; j++) for (let i = 0; i < 300; i++) samples.push(patternAt(i * 0.6667 + 0.13, j * 0.6667 + 0.29));
    const coverage = [0.1, 0.3, 0.5, 0.7, 0.9].map((c) => samples.filter((p) => p < c).length / samples.length);
    console.log(`foam pattern: p < c over ${coverage.map((f) => f.toFixed(3)).join(', ')} of the sea for c = 0.1, 0.3, 0.5, 0.7, 0.9`);
    [0.1, 0.3, 0.5, 0.7, 0.9].forEach((c, k) => expect(Math.abs(coverage[k] - c)).toBeLessThan(0.05));
  });
});
