/**
 * The WebGPU Ocean's grid: one square mesh of the rest plane y = 0, fixed in world space and
 * centred on the origin, fine near it and coarser outwards to the horizon. Its vertices never
 * move, so nothing swims; it does not follow the camera (the WebGL Ocean's camera-centred rings,
 * src/render/horizonGrid.ts, are not ported yet): a camera far from the origin sees coarse cells.
 *
 * Along each axis the vertices are `nearCell` apart out to `nearExtent` from the origin, and each
 * step after that is `growth` times the one before, until `farExtent`. Every vertex carries `cell`,
 * the larger of its two steps (m), from which the surface picks the mip level of each cascade (the
 * texels one cell averages, as the WebGL Ocean does).
 */
import { BufferAttribute, BufferGeometry } from 'three';

export interface SeaGridShape {
  /** Step between vertices near the origin, m. */
  nearCell: number;
  /** Half side of the square of fine cells, m. */
  nearExtent: number;
  /** Ratio between one step and the next beyond nearExtent (> 1). */
  growth: number;
  /** Half side of the whole grid, m. */
  farExtent: number;
}

/** 0.5 m cells within 32 m of the origin, growing by 10 % a step out to 20 km: 303 vertices a side. */
export const DEFAULT_SEA_GRID: Readonly<SeaGridShape> = Object.freeze({ nearCell: 0.5, nearExtent: 32, growth: 1.1, farExtent: 20_000 });

/** The vertices' coordinates along one axis, ascending and symmetric about 0. */
export function gridCoordinates({ nearCell, nearExtent, growth, farExtent }: SeaGridShape): number[] {
  const positive: number[] = [];
  let step = nearCell;
  for (let at = nearCell; at < farExtent; at += step) {
    positive.push(at);
    if (at >= nearExtent) step *= growth;
  }
  positive.push(farExtent);
  return [...positive.map((at) => -at).reverse(), 0, ...positive];
}

/** The grid as a BufferGeometry with `position` (x, 0, z) and `cell` (m), triangles facing up. */
export function seaGridGeometry(shape: SeaGridShape = DEFAULT_SEA_GRID): BufferGeometry {
  const axis = gridCoordinates(shape);
  const n = axis.length;
  const steps = axis.map((_, i) => Math.max(i > 0 ? axis[i] - axis[i - 1] : 0, i < n - 1 ? axis[i + 1] - axis[i] : 0));
  const positions = new Float32Array(3 * n * n);
  const cells = new Float32Array(n * n);
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      const v = j * n + i;
      positions[3 * v] = axis[i];
      positions[3 * v + 2] = axis[j];
      cells[v] = Math.max(steps[i], steps[j]);
    }
  }
  const indices = new Uint32Array(6 * (n - 1) * (n - 1));
  let k = 0;
  for (let j = 0; j < n - 1; j++) {
    for (let i = 0; i < n - 1; i++) {
      const a = j * n + i;
      const b = a + 1;
      const c = a + n;
      const d = c + 1;
      // Counter-clockwise seen from above (+y): a, c, b and b, c, d (z grows towards the viewer).
      indices.set([a, c, b, b, c, d], k);
      k += 6;
    }
  }
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(positions, 3));
  geometry.setAttribute('cell', new BufferAttribute(cells, 1));
  geometry.setIndex(new BufferAttribute(indices, 1));
  return geometry;
}
