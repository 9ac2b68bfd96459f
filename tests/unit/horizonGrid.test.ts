import { describe, expect, it } from 'vitest';
import {
  cellsPerRingForViewport,
  createHorizonGridGeometry,
  farEdgeDistance,
  finestTexel,
  RING_COUNT,
  RingFrames,
  SKIRT_SCALE,
  type LayerGrid,
} from '../../src/render/horizonGrid';
import { SeededRandom } from '../../src/spectrum/random';

describe('horizon grid geometry', () => {
  it('has a vertex count that follows the viewport, not one fixed mesh', () => {
    expect([225, 720, 1440].map((height) => cellsPerRingForViewport(height))).toEqual([32, 64, 128]);
    // A lower floor (the quality level 'lowest') lets a small picture have a coarser grid, no larger one.
    expect([100, 216, 225, 720, 5000].map((height) => cellsPerRingForViewport(height, 16))).toEqual([16, 16, 16, 64, 128]);
    const counts = [32, 64, 128].map((cells) => createHorizonGridGeometry(cells).getAttribute('position').count);
    expect(counts[1]).toBeGreaterThan(3 * counts[0]);
    expect(counts[2]).toBeGreaterThan(3 * counts[1]);
  });

  it('holds grid coordinates: |x|, |z| ≤ half a ring, ring indices 0 … RING_COUNT − 1', () => {
    const cells = 32;
    const position = createHorizonGridGeometry(cells).getAttribute('position');
    for (let i = 0; i < position.count; i++) {
      expect(Math.max(Math.abs(position.getX(i)), Math.abs(position.getY(i)))).toBeLessThanOrEqual(cells / 2);
      expect(Number.isInteger(position.getZ(i)) && position.getZ(i) >= 0 && position.getZ(i) < RING_COUNT).toBe(true);
    }
  });
});

/** A periodic layer's frame: only its size and resolution matter to the rings. */
function periodicFrame(size: number, resolution: number): LayerGrid['frame'] {
  return { size, resolution, origin: [0, 0], periodic: true };
}

describe('RingFrames', () => {
  const cells = 64;
  const half = cells / 2;
  // One 250 m layer of 256 texels (the old single patch), and the default three cascades.
  const single: LayerGrid[] = [{ frame: periodicFrame(250, 256) }];
  const cascades: LayerGrid[] = [457, 13.7, 79.3].map((size) => ({ frame: periodicFrame(size, 256) }));
  const random = new SeededRandom(3);
  const cameras = [
    ...Array.from({ length: 200 }, () => [
      (random.nextUniform() - 0.5) * 2e4,
      1 + random.nextUniform() ** 3 * 2000,
      (random.nextUniform() - 0.5) * 2e4,
    ]),
    // Far from the origin, where a float32 world coordinate is good only to metres.
    [1e7 + 917.3, 2, 1e7 - 561.8],
    [-3e8 + 0.37, 40, 2e9 + 0.11],
  ];

  it('snaps every ring centre to twice its cell size, so vertices sit on fixed world points', () => {
    const rings = new RingFrames();
    for (const [x, y, z] of cameras) for (const layers of [single, cascades]) {
      rings.update(x, z, y, layers, cells);
      for (let r = 0; r <= RING_COUNT; r++) {
        const [fromEyeX, fromEyeZ, cell, level] = rings.frames.subarray(4 * r, 4 * r + 4);
        // The centres are snapped in double precision and stored for the shader as float32, relative
        // to the camera: off by float32 rounding, ≤ 2^−24·|c − camera| (under 2 mm for the
        // largest ring), against a whole cell (≥ 0.1 m here) for a centre that is not snapped. So:
        // the distance to the nearest multiple of the exact 2·cell (texel·2^(level+1), level an exact
        // integer) must be within that rounding, plus 1e-4 of a cell for the division.
        const [cx, cz] = [x + fromEyeX, z + fromEyeZ];
        const exactCell = finestTexel(layers) * 2 ** level;
        expect(Math.abs(cell / exactCell - 1)).toBeLessThan(1.2e-7);
        for (const c of [cx, cz]) {
          const off = Math.abs(c - Math.round(c / (2 * exactCell)) * 2 * exactCell);
          expect(off).toBeLessThanOrEqual(2 ** -24 * Math.max(Math.abs(fromEyeX), Math.abs(fromEyeZ)) + 1e-4 * exactCell);
        }
        // The camera is inside its finest rings' central cells.
        if (r === 0) expect(Math.max(Math.abs(x - cx), Math.abs(z - cz))).toBeLessThanOrEqual(2 * cell * 1.0001);
      }
    }
  });

  it('leaves no gap: each ring’s hole lies inside the ring within it, wherever the camera is', () => {
    const rings = new RingFrames();
    // Ring r ≥ 1 draws every cell except those whose two coordinates lie in [−half/2 + 1, half/2 − 1]
    // (createHorizonGridGeometry); ring r − 1 covers centre_{r−1} ± half · cell_{r−1}.
    for (const [x, y, z] of cameras) for (const layers of [single, cascades]) {
      rings.update(x, z, y, layers, cells);
      for (let r = 1; r < RING_COUNT; r++) {
        const [cx, cz, cell] = rings.frames.subarray(4 * r, 4 * r + 3);
        const [ix, iz, innerCell] = rings.frames.subarray(4 * (r - 1), 4 * (r - 1) + 3);
        const holeLow = (-half / 2 + 1) * cell;
        const holeHigh = (half / 2) * cell; // far edge of the last hole cell
        // Float32 rounding of the stored centres and cells (see the test above): ≤ 2^−24 of each
        // term, so 2^−22 of their sum bounds it; a ring misplaced by a cell breaks these by ≥ 0.1 m.
        const slack = 2 ** -22 * (Math.abs(ix) + Math.abs(cx) + Math.abs(iz) + Math.abs(cz) + half * cell) + 1e-6 * cell;
        expect(ix - half * innerCell).toBeLessThanOrEqual(cx + holeLow + slack);
        expect(ix + half * innerCell).toBeGreaterThanOrEqual(cx + holeHigh - slack);
        expect(iz - half * innerCell).toBeLessThanOrEqual(cz + holeLow + slack);
        expect(iz + half * innerCell).toBeGreaterThanOrEqual(cz + holeHigh - slack);
        // The inner ring is offset by whole cells of this ring, 0 or 1 (the shader relies on it).
        expect([0, 1]).toContain(rings.offsets[2 * (r - 1)]);
        expect([0, 1]).toContain(rings.offsets[2 * (r - 1) + 1]);
      }
    }
  });

  it('reaches about a thousand camera heights away before the skirt; farEdgeDistance is the skirt’s far corner', () => {
    const rings = new RingFrames();
    for (const height of [1, 10, 100, 2000]) {
      for (const layers of [single, cascades]) {
        rings.update(0, 0, height, layers, cells);
        const lastCell = rings.frames[4 * (RING_COUNT - 1) + 2];
        expect(half * lastCell).toBeGreaterThan(1000 * height);
        // The skirt's corner: half a ring (plus the two cells a snapped centre may be off) out,
        // SKIRT_SCALE times further, along the diagonal; plus the height.
        const corner = Math.SQRT2 * (half + 2) * lastCell * SKIRT_SCALE + height;
        expect(farEdgeDistance(height, layers, cells) / corner).toBeCloseTo(1, 6);
      }
    }
  });

  it('takes its finest cells from the finest layer’s texel, whatever the order of the layers', () => {
    expect(finestTexel(single)).toBe(250 / 256);
    expect(finestTexel(cascades)).toBe(13.7 / 256);
    expect(finestTexel([{ frame: periodicFrame(100, 64) }, { frame: periodicFrame(120, 1024) }])).toBe(120 / 1024);
    const rings = new RingFrames();
    for (const [x, y, z] of cameras) {
      for (const layers of [single, cascades, [...cascades].reverse()]) {
        rings.update(x, z, y, layers, cells);
        for (let r = 0; r <= RING_COUNT; r++) {
          const [, , cell, level] = rings.frames.subarray(4 * r, 4 * r + 4);
          // cell_r = texel·2^(level_r), level_r = level_0 + r, level_0 ≥ 0 (float32 storage: 1e-6).
          expect(Number.isInteger(level) && level >= r).toBe(true);
          expect(Math.abs(cell / (finestTexel(layers) * 2 ** level) - 1)).toBeLessThan(1e-6);
        }
        // Ring 0's cells are the finest texel·2^j with the smallest j ≥ 0 that keeps them at least
        // max(1, height)/(cellsPerRing/8), so ring 0 covers about 8 camera heights.
        const wanted = Math.max(1, y) / (cells / 8);
        const cell0 = finestTexel(layers) * 2 ** rings.frames[3];
        expect(cell0).toBeGreaterThanOrEqual(wanted * (1 - 1e-12));
        if (rings.frames[3] > 0) expect(cell0 / 2).toBeLessThan(wanted);
      }
    }
  });

  it('gives each layer the texture coordinate of each ring centre, [ring · layers + layer]', () => {
    const rings = new RingFrames();
    for (const [x, y, z] of cameras.slice(0, 50)) {
      for (const layers of [single, cascades]) {
        rings.update(x, z, y, layers, cells);
        expect(rings.uvOrigins).toHaveLength(2 * (RING_COUNT + 1) * layers.length);
        for (let r = 0; r <= RING_COUNT; r++) {
          // The centre as double precision would have it (cell sizes are texel·2^level: exact scaling).
          const cell = finestTexel(layers) * 2 ** rings.frames[4 * r + 3];
          const centre = [Math.floor(x / (2 * cell)) * 2 * cell, Math.floor(z / (2 * cell)) * 2 * cell];
          layers.forEach(({ frame: { size, resolution } }, layer) => {
            for (const axis of [0, 1]) {
              const uv = rings.uvOrigins[2 * (r * layers.length + layer) + axis];
              expect(uv >= 0 && uv < 1).toBe(true);
              // uv·size ≡ centre + ½ texel (mod size): GL samples texel i at u = (i + ½)/N.
              const want = centre[axis] / size + 0.5 / resolution;
              let turns = uv - want;
              turns -= Math.round(turns);
              // float32 of a value in [0, 1): ≤ 6e-8; the double arithmetic is far finer.
              expect(Math.abs(turns), `ring ${r}, layer ${layer}, axis ${axis}`).toBeLessThan(1.2e-7);
            }
          });
        }
      }
    }
  });
});
