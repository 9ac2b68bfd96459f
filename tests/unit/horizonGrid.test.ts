import { describe, expect, it } from 'vitest';
import { cellsPerRingForViewport, createHorizonGridGeometry, RING_COUNT, RingFrames } from '../../src/render/horizonGrid';
import { SeededRandom } from '../../src/spectrum/random';

describe('horizon grid geometry', () => {
  it('has a vertex count that follows the viewport, not one fixed mesh', () => {
    expect([225, 720, 1440].map(cellsPerRingForViewport)).toEqual([32, 64, 128]);
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

describe('RingFrames', () => {
  const cells = 64;
  const half = cells / 2;
  const texel = 250 / 256;
  const random = new SeededRandom(3);
  const cameras = Array.from({ length: 200 }, () => [
    (random.nextUniform() - 0.5) * 2e4,
    1 + random.nextUniform() ** 3 * 2000,
    (random.nextUniform() - 0.5) * 2e4,
  ]);

  it('snaps every ring centre to twice its cell size, so vertices sit on fixed world points', () => {
    const rings = new RingFrames();
    for (const [x, y, z] of cameras) {
      rings.update(x, z, y, 250, texel, cells);
      for (let r = 0; r <= RING_COUNT; r++) {
        const [cx, cz, cell] = rings.frames.subarray(4 * r, 4 * r + 3);
        for (const c of [cx, cz]) expect(Math.abs(c / (2 * cell) - Math.round(c / (2 * cell)))).toBeLessThan(1e-4);
        // The camera is inside its finest rings' central cells.
        if (r === 0) expect(Math.max(Math.abs(x - cx), Math.abs(z - cz))).toBeLessThanOrEqual(2 * cell * 1.0001);
      }
    }
  });

  it('leaves no gap: each ring’s hole lies inside the ring within it, wherever the camera is', () => {
    const rings = new RingFrames();
    // Ring r ≥ 1 draws every cell except those whose two coordinates lie in [−half/2 + 1, half/2 − 1]
    // (createHorizonGridGeometry); ring r − 1 covers centre_{r−1} ± half · cell_{r−1}.
    for (const [x, y, z] of cameras) {
      rings.update(x, z, y, 250, texel, cells);
      for (let r = 1; r < RING_COUNT; r++) {
        const [cx, cz, cell] = rings.frames.subarray(4 * r, 4 * r + 3);
        const [ix, iz, innerCell] = rings.frames.subarray(4 * (r - 1), 4 * (r - 1) + 3);
        const holeLow = (-half / 2 + 1) * cell;
        const holeHigh = (half / 2) * cell; // far edge of the last hole cell
        const slack = 1e-6 * cell;
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

  it('reaches about a thousand camera heights away before the skirt', () => {
    const rings = new RingFrames();
    for (const height of [1, 10, 100, 2000]) {
      rings.update(0, 0, height, 250, texel, cells);
      expect(rings.farEdgeDistance).toBeGreaterThan(1000 * height);
    }
  });
});
