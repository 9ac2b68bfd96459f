/**
 * The island's ground (src/objects/island.ts): one analytic function gives the seabed the sea sees
 * and the terrain mesh, so the two must agree at every vertex; the function has no jumps (the
 * seabed is sampled anywhere), is negative depth on land and deep at the edge of its bounds; the
 * beach has the 1:30 slope it is built with; the reef's rocks reach 1–3 m below the surface.
 */
import { describe, expect, it } from 'vitest';
import type { BufferGeometry, Material, Mesh } from 'three';
import { captureChanges } from '../../src/render/sceneCapture';
import { BEACH_FACING, CLIFF_FACING, HILLS, Island, ISLAND_BOUNDS, islandSeabed, islandTerrainGeometry, SHALLOWS_DEPTH, WHOLE_FLOOR_DEPTH } from '../../src/objects/island';

const { depthAt, bounds } = islandSeabed();
const [xMin, zMin, xMax, zMax] = bounds;

/** A small seeded generator (an LCG), so the sample points are the same every run. */
function points(count: number, seed = 1): [number, number][] {
  let state = seed;
  const next = () => (state = (Math.imul(state, 1664525) + 1013904223) >>> 0) / 2 ** 32;
  return Array.from({ length: count }, () => [xMin + (xMax - xMin) * next(), zMin + (zMax - zMin) * next()]);
}

/** Where the ground meets mean sea level along the ray from the centre at `angle` (bisection). */
function waterline(angle: number): number {
  let land = 0;
  let sea = 400;
  for (let i = 0; i < 60; i++) {
    const r = (land + sea) / 2;
    if (depthAt(r * Math.cos(angle), r * Math.sin(angle)) < 0) land = r;
    else sea = r;
  }
  return land;
}

describe('islandSeabed', () => {
  it('gives its bounds, and a copy of them each call', () => {
    expect(bounds).toEqual(ISLAND_BOUNDS);
    expect(xMax).toBeGreaterThan(xMin);
    expect(zMax).toBeGreaterThan(zMin);
    islandSeabed().bounds[0] = 0;
    expect(islandSeabed().bounds).toEqual(ISLAND_BOUNDS);
  });

  it("is continuous: over 1 cm it changes by at most the cliff's slope × 1 cm, everywhere, across θ = ±π and at the centre", () => {
    // The steepest ground is the cliff's face: its profile drops 36 m over a smoothstep of 13 m,
    // at most 1.5 × 36 / 13 = 4.2 m per metre; 6 leaves room for the blend and the rocks.
    const step = 0.01;
    let steepest = 0;
    for (const [x, z] of points(8000)) {
      const d = depthAt(x, z);
      expect(Number.isFinite(d)).toBe(true);
      steepest = Math.max(steepest, Math.abs(depthAt(x + step, z) - d) / step, Math.abs(depthAt(x, z + step) - d) / step);
    }
    expect(steepest).toBeLessThan(6);
    // atan2's branch cut (x < 0, z = 0) and the centre, where the angle means nothing.
    for (let x = -600; x < 0; x += 7) expect(Math.abs(depthAt(x, 1e-9) - depthAt(x, -1e-9))).toBeLessThan(1e-6);
    for (const [dx, dz] of [[1, 0], [0, 1], [-1, 0], [0, -1]]) expect(Math.abs(depthAt(1e-6 * dx, 1e-6 * dz) - depthAt(0, 0))).toBeLessThan(1e-4);
  });

  it('is negative on land (the hills, the cliff top, behind the beach) and deep water (over 40 m) all round its bounds', () => {
    for (const [x, z, height] of HILLS) expect(depthAt(x, z)).toBeLessThan(-height / 2);
    const cliff = waterline(CLIFF_FACING);
    expect(depthAt((cliff - 15) * Math.cos(CLIFF_FACING), (cliff - 15) * Math.sin(CLIFF_FACING))).toBeLessThan(-15);
    const beach = waterline(BEACH_FACING);
    expect(depthAt((beach - 20) * Math.cos(BEACH_FACING), (beach - 20) * Math.sin(BEACH_FACING))).toBeLessThan(0);
    let shallowestEdge = Infinity;
    for (let i = 0; i <= 400; i++) {
      const t = i / 400;
      const x = xMin + t * (xMax - xMin);
      const z = zMin + t * (zMax - zMin);
      shallowestEdge = Math.min(shallowestEdge, depthAt(x, zMin), depthAt(x, zMax), depthAt(xMin, z), depthAt(xMax, z));
    }
    expect(shallowestEdge).toBeGreaterThan(40);
  });

  it('has a beach of 1:30 and a cliff that drops over 20 m within 15 m of its edge', () => {
    const [cos, sin] = [Math.cos(BEACH_FACING), Math.sin(BEACH_FACING)];
    const beach = waterline(BEACH_FACING);
    // 20 to 80 m offshore, clear of the reef (its nearest rock is 110 m out and 11 m wide).
    const slope = (depthAt((beach + 80) * cos, (beach + 80) * sin) - depthAt((beach + 20) * cos, (beach + 20) * sin)) / 60;
    expect(slope).toBeGreaterThan((1 / 30) * 0.95);
    expect(slope).toBeLessThan((1 / 30) * 1.05);
    const cliff = waterline(CLIFF_FACING);
    const [cx, cz] = [Math.cos(CLIFF_FACING), Math.sin(CLIFF_FACING)];
    expect(depthAt((cliff + 5) * cx, (cliff + 5) * cz) - depthAt((cliff - 10) * cx, (cliff - 10) * cz)).toBeGreaterThan(20);
  });

  it('has a reef off the beach whose rocks come to 1–3 m below the surface, and nothing shallower offshore', () => {
    const beach = waterline(BEACH_FACING);
    let shallowest = Infinity;
    let shallowRock = 0;
    for (let angle = BEACH_FACING - 0.5; angle <= BEACH_FACING + 0.5; angle += 0.002) {
      for (let r = beach + 40; r <= beach + 250; r += 0.5) {
        const depth = depthAt(r * Math.cos(angle), r * Math.sin(angle));
        shallowest = Math.min(shallowest, depth);
        // Where a rock stands over a floor that deep (1:30: at least 3.4 m there), the depth is under 3 m.
        if (r > beach + 100 && depth < 3) shallowRock++;
      }
    }
    expect(shallowest).toBeGreaterThan(0.9);
    expect(shallowest).toBeLessThan(3);
    expect(shallowRock).toBeGreaterThan(100);
  });
});

describe('Island', () => {
  const island = new Island();
  const geometry = island.terrain.geometry;

  it('builds its terrain from the seabed: every vertex at −depthAt(x, z), the mesh spanning the bounds', () => {
    const position = geometry.getAttribute('position');
    let worst = 0;
    for (let i = 0; i < position.count; i++) {
      // Float32 positions: x and z are rounded by up to 3e-5 m, which the slope (< 6) turns into 2e-4 m.
      worst = Math.max(worst, Math.abs(position.getY(i) + depthAt(position.getX(i), position.getZ(i))));
    }
    expect(worst).toBeLessThan(1e-3);
    geometry.computeBoundingBox();
    const box = geometry.boundingBox!;
    expect([box.min.x, box.min.z, box.max.x, box.max.z]).toEqual(bounds.map((v) => Math.fround(v)));
    expect(geometry.getAttribute('color').count).toBe(position.count);
  });

  it('splits its triangles at the shallows: the sea floor wholly under y = −3 m, its bounding box too, the rest reaching it, every triangle once', () => {
    const whole = islandTerrainGeometry().getIndex()!.count;
    const position = geometry.getAttribute('position');
    const highest = (part: BufferGeometry, i: number) => {
      const index = part.getIndex()!;
      return Math.max(position.getY(index.getX(i)), position.getY(index.getX(i + 1)), position.getY(index.getX(i + 2)));
    };
    const floor = island.seaFloor.geometry;
    expect(floor.getAttribute('position')).toBe(position);
    expect(island.seaFloor.material).toBe(island.terrain.material);
    let floorTop = -Infinity;
    for (let i = 0; i < floor.getIndex()!.count; i += 3) floorTop = Math.max(floorTop, highest(floor, i));
    let groundLowest = Infinity;
    for (let i = 0; i < geometry.getIndex()!.count; i += 3) groundLowest = Math.min(groundLowest, highest(geometry, i));
    expect(floorTop).toBeLessThan(-SHALLOWS_DEPTH);
    expect(groundLowest).toBeGreaterThanOrEqual(-SHALLOWS_DEPTH);
    expect(floor.getIndex()!.count + geometry.getIndex()!.count).toBe(whole);
    // What the reflection's capture judges (captureChanges): the floor's box, not every vertex's.
    expect(floor.boundingBox!.max.y).toBe(floorTop);
    // Most of the terrain is sea floor: the share the reflection no longer draws.
    console.log(`island: ${floor.getIndex()!.count / 3} of ${whole / 3} triangles under the shallows`);
    expect(floor.getIndex()!.count).toBeGreaterThan(whole / 2);
  });

  it("stands in for its sea floor in the sea's captures over the same vertices: whole down to 10 m, coarse deeper, leaving no sea-floor triangle uncovered", () => {
    const floor = island.seaFloor.geometry;
    const standIn = island.seaFloorStandIn;
    const position = floor.getAttribute('position');
    expect(standIn.getAttribute('position')).toBe(position);
    const side = Math.round(Math.sqrt(position.count));
    const key = (corners: number[]) => [...corners].sort((x, y) => x - y).join();
    // The stand-in's triangles: the floor's own (one grid cell wide), and coarse cells (two
    // triangles, `step` grid lines wide) by the grid vertex of their first corner.
    const whole = new Set<string>();
    const kept = new Set<number>();
    let step = 0;
    const coarse = standIn.getIndex()!;
    for (let t = 0; t < coarse.count; t += 3) {
      const corners = [coarse.getX(t), coarse.getX(t + 1), coarse.getX(t + 2)];
      const width = Math.max(...corners.map((v) => v % side)) - Math.min(...corners.map((v) => v % side));
      if (width === 1) whole.add(key(corners));
      else if (corners[2] - corners[0] === width) {
        // A cell's first triangle: its corner, its neighbour across the cell, the next along the row.
        step = width;
        kept.add(corners[0]);
      }
    }
    const fine = floor.getIndex()!;
    let uncovered = 0;
    let shallowNotWhole = 0;
    for (let t = 0; t < fine.count; t += 3) {
      const corners = [fine.getX(t), fine.getX(t + 1), fine.getX(t + 2)];
      const top = Math.max(...corners.map((v) => position.getY(v)));
      const i = Math.min(...corners.map((v) => v % side));
      const j = Math.min(...corners.map((v) => Math.floor(v / side)));
      const cell = (j - (j % step)) * side + (i - (i % step));
      if (top >= -WHOLE_FLOOR_DEPTH && !whole.has(key(corners))) shallowNotWhole++;
      if (!whole.has(key(corners)) && !kept.has(cell)) uncovered++;
    }
    expect(step).toBeGreaterThan(1);
    expect((side - 1) % step).toBe(0);
    expect(shallowNotWhole).toBe(0);
    expect(uncovered).toBe(0);
    console.log(`island: the sea floor's stand-in has ${coarse.count / 3} triangles for its ${fine.count / 3}`);
    expect(coarse.count).toBeLessThan(fine.count / 4);
  });

  it('has sand at the waterline of the beach and grass on the hill (vertex colours)', () => {
    const position = geometry.getAttribute('position');
    const colour = geometry.getAttribute('color');
    const nearest = (x: number, z: number) => {
      let best = 0;
      let distance = Infinity;
      for (let i = 0; i < position.count; i++) {
        const d = (position.getX(i) - x) ** 2 + (position.getZ(i) - z) ** 2;
        if (d < distance) [best, distance] = [i, d];
      }
      return [colour.getX(best), colour.getY(best), colour.getZ(best)];
    };
    const beach = waterline(BEACH_FACING) - 30;
    const [sr, sg, sb] = nearest(beach * Math.cos(BEACH_FACING), beach * Math.sin(BEACH_FACING));
    expect(sr).toBeGreaterThan(sb * 1.3); // sand: warm and light
    expect(sr).toBeGreaterThan(0.35);
    expect(sg).toBeGreaterThan(sb);
    const [gr, gg, gb] = nearest(HILLS[1][0], HILLS[1][1]);
    expect(gg).toBeGreaterThan(gr); // grass: green over red and blue
    expect(gg).toBeGreaterThan(gb);
  });

  it("dispose() frees every geometry and material it made, the sea floor's stand-in too, and takes the stand-in off", () => {
    const owned = new Set<BufferGeometry | Material>([island.seaFloorStandIn]);
    island.traverse((object) => {
      const mesh = object as Mesh;
      if (mesh.geometry) owned.add(mesh.geometry);
      if (mesh.material) owned.add(mesh.material as Material);
    });
    const freed = new Set<unknown>();
    for (const resource of owned) resource.addEventListener('dispose', () => freed.add(resource));
    const swapped = (): Mesh[] => {
      const swap: Mesh[] = [];
      captureChanges(island, undefined, [], swap);
      return swap;
    };
    expect(swapped()).toEqual([island.seaFloor]);
    island.dispose();
    expect(owned.size).toBeGreaterThanOrEqual(7); // terrain, its stand-in, posts, planks, wood, hull and cabin
    expect(freed.size).toBe(owned.size);
    expect(swapped()).toEqual([]);
  });
});
