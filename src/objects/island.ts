/**
 * An island to put in the sea (examples/island.html, the app's ?scene=island): a terrain with a
 * beach of 1:30 on its south side, a cliff to the south-east and a grassy hill, a reef of rocks 1–3 m
 * under the surface off the beach, a pier of wooden posts and planks, and a boat moored beside it.
 *
 * One analytic function, islandHeight(x, z) (metres above mean sea level, in world coordinates:
 * the island stays where it is built, at the origin), shapes the terrain mesh and gives the seabed
 * the sea sees (islandSeabed: its depth below mean sea level, negative on land), so the drawn sea
 * floor and the one the waves feel agree. The terrain is lit by three.js's standard lights
 * (MeshStandardMaterial with vertex colours: sand, wet sand, grass, rock). update(ocean) sets the
 * moored boat on the water of the ocean's time; dispose() frees every geometry and material.
 */
import {
  Box3,
  BoxGeometry,
  BufferGeometry,
  Color,
  Float32BufferAttribute,
  Group,
  InstancedMesh,
  Matrix4,
  Mesh,
  MeshStandardMaterial,
  Quaternion,
  Sphere,
  Uint32BufferAttribute,
  Vector3,
} from 'three';
import type { Ocean } from '../ocean';
import { setCaptureStandIn } from '../render/sceneCapture';
import { BoatModel } from './boat';

/** The sea floor under a rectangle of the sea, as Ocean.setSeabed takes it (issue 25). */
export interface Seabed {
  /** Depth of the floor below mean sea level at (x, z), metres; negative is land. */
  depthAt(x: number, z: number): number;
  /** [xMin, zMin, xMax, zMax], metres: where depthAt describes the floor. */
  bounds: [number, number, number, number];
}

/** Where the island's terrain (and its seabed) ends, m: deep water (over 40 m) all round its edge. */
export const ISLAND_BOUNDS: Seabed['bounds'] = [-620, -600, 620, 760];

/** The coast's mean radius from the island's centre (the origin), m. */
const COAST_RADIUS = 150;
/**
 * The shore's kinds, each facing a direction (radians from +x towards +z): the beach faces south
 * (+z, towards the app's view of it), the cliff south-east, rocky slopes the other ways. Between
 * them the profiles blend by a von Mises weight exp(κ cos(θ − θᵢ)), normalised.
 */
export const BEACH_FACING = 1.92;
export const CLIFF_FACING = 0.45;
const ROCKY_FACINGS = [3.6, 5.1];
const FACING_SHARPNESS = 8;
/** Within this distance of the centre the shore's shape fades out (θ means nothing at r = 0), m. */
const CENTRE_FADE = 60;

/** The beach's slope (1:30, a fine-sand beach: Dean 1991's equilibrium profiles are 1:20–1:50). */
const BEACH_SLOPE = 1 / 30;
/** Where the beach's shelf drops to deep water (m offshore of the waterline), and how steeply. */
const SHELF_EDGE = 300;
const DROP_SLOPE = 0.22;
/** The cliff: its top above the sea, and the foot below it (m). */
const CLIFF_TOP = 24;
const CLIFF_FOOT = -12;

/** Hills: centre x, z, height and radius (m). */
export const HILLS: readonly (readonly [number, number, number, number])[] = [
  [25, -20, 26, 85],
  [-70, -45, 16, 55],
];

/** A pier out from the beach: where it starts on the sand and its direction (unit, x and z). */
const PIER_START: [number, number] = [-76, 104];
const PIER_DIRECTION: [number, number] = [-0.26, 0.966];
const PIER_LENGTH = 85;
const PIER_WIDTH = 2.4;
/** The deck's height above mean sea level, m. */
const DECK_HEIGHT = 1.8;
const POST_SPACING = 5;
/** The planks lie across the pier (their long side along (−dz, dx)): a turn about y from +x. */
const PIER_ACROSS = new Quaternion().setFromAxisAngle(new Vector3(0, 1, 0), Math.PI / 2 - Math.atan2(PIER_DIRECTION[1], PIER_DIRECTION[0]));

/** The moored boat: off the pier's head (m along the pier and to its right), lying across it. */
const MOORING = { along: PIER_LENGTH + 7, across: 2 };


/** Terrain grid: cells along each side; the cells are finer near FOCUS, where the camera looks. */
const GRID_CELLS = 384;
const FOCUS: [number, number] = [-40, 150];
/** The share of a side's cells spent uniformly; the rest crowd towards FOCUS (a cubic warp). */
const UNIFORM_SHARE = 0.4;
/** The sea floor's stand-in in the sea's captures takes every this many grid lines where deep (seaFloorStandIn; it divides GRID_CELLS). */
const CAPTURE_COARSENING = 4;

/** Colours of the ground (sRGB, as on a palette; three converts them to linear). */
const SAND = new Color(0xdcc9a0);
const WET_SAND = new Color(0xa38e6c);
const GRASS = new Color(0x5b7a33);
const DRY_GRASS = new Color(0x8a8a4a);
const ROCK = new Color(0x7b7166);
const DARK_ROCK = new Color(0x4f4a44);
const REEF = new Color(0x5e5a44);

function smoothstep(edge0: number, edge1: number, x: number): number {
  const t = Math.min(1, Math.max(0, (x - edge0) / (edge1 - edge0)));
  return t * t * (3 - 2 * t);
}

/** log(1 + e^(x/k))·k: a ramp max(0, x) with its corner rounded over about k. */
function softplus(x: number, k: number): number {
  const t = x / k;
  return k * (t > 30 ? t : Math.log1p(Math.exp(t)));
}

/**
 * A fixed scatter of reef rocks along the beach, 110–160 m offshore (the floor 3.7–5.3 m deep
 * there), each as centre x, z, radius ρ (m) and its top's depth (m below mean sea level, 1–3 m).
 */
function reefRocks(): [number, number, number, number][] {
  // A small integer hash (Wellons' lowbias32): the same rocks on every machine, no generator state.
  const hash = (n: number) => {
    let h = n >>> 0;
    h = Math.imul(h ^ (h >>> 16), 0x7feb352d);
    h = Math.imul(h ^ (h >>> 15), 0x846ca68b);
    return ((h ^ (h >>> 16)) >>> 0) / 2 ** 32;
  };
  const rocks: [number, number, number, number][] = [];
  for (let i = 0; i < 22; i++) {
    const angle = BEACH_FACING - 0.42 + (0.84 * (i + 0.5 * hash(4 * i))) / 22;
    const offshore = 110 + 50 * hash(4 * i + 1);
    const r = COAST_RADIUS + offshore;
    rocks.push([r * Math.cos(angle), r * Math.sin(angle), 5 + 6 * hash(4 * i + 2), 1 + 2 * hash(4 * i + 3)]);
  }
  return rocks;
}

/** The shore profile of each kind: height (m) at signed distance s from the waterline (s > 0 offshore). */
function beachProfile(s: number): number {
  // The 1:30 plane, a drop past the shelf's edge, and a bank behind the sand.
  return -s * BEACH_SLOPE - DROP_SLOPE * softplus(s - SHELF_EDGE, 25) + 0.3 * softplus(-s - 45, 10);
}
function cliffProfile(s: number): number {
  return CLIFF_TOP + (CLIFF_FOOT - CLIFF_TOP) * smoothstep(-10, 3, s) - 0.15 * softplus(s - 3, 5);
}
function rockyProfile(s: number): number {
  return -18 * Math.tanh(s / 60) - 0.1 * softplus(s, 20);
}

/** The island's base (shore and hills, no reef), m above mean sea level. */
function baseHeight(x: number, z: number): number {
  const r = Math.sqrt(x * x + z * z);
  const theta = Math.atan2(z, x);
  const fade = smoothstep(0, CENTRE_FADE, r);
  const coast = COAST_RADIUS + fade * (14 * Math.sin(2 * theta + 1) + 8 * Math.sin(3 * theta + 2.5) + 5 * Math.sin(5 * theta + 0.7));
  const s = r - coast;
  const sharpness = FACING_SHARPNESS * fade;
  const beach = Math.exp(sharpness * Math.cos(theta - BEACH_FACING));
  const cliff = Math.exp(sharpness * Math.cos(theta - CLIFF_FACING));
  const rocky = Math.exp(sharpness * Math.cos(theta - ROCKY_FACINGS[0])) + Math.exp(sharpness * Math.cos(theta - ROCKY_FACINGS[1]));
  const shore = (beach * beachProfile(s) + cliff * cliffProfile(s) + rocky * rockyProfile(s)) / (beach + cliff + rocky);
  const inland = smoothstep(30, -30, s);
  let hills = 0;
  for (const [hx, hz, height, radius] of HILLS) hills += height * Math.exp(-((x - hx) ** 2 + (z - hz) ** 2) / radius ** 2);
  // Knolls and hollows on the land away from the sand.
  const relief =
    smoothstep(-25, -70, s) *
    (2.5 * Math.sin(0.041 * x + 0.5) * Math.sin(0.047 * z + 1.3) +
      1.2 * Math.sin(0.09 * x - 0.07 * z + 2) +
      0.3 * Math.sin(0.23 * x + 0.19 * z) * Math.sin(0.21 * z - 0.3));
  return shore + inland * hills + relief;
}

/**
 * The reef's rocks: centre x, z, radius ρ and how high each rises from the floor under it (m), so
 * that its top is at the depth reefRocks gave it.
 */
const REEF_ROCKS = reefRocks().map(([x, z, radius, top]) => [x, z, radius, -baseHeight(x, z) - top] as const);

/**
 * How much the reef's rocks raise the floor at (x, z), m: rounded tops, steep sides (exp(−(d/ρ)⁴)).
 * Where two overlap the higher one counts (a sum would lift the pair above both their tops).
 */
function reefHeight(x: number, z: number): number {
  let raised = 0;
  for (const [rx, rz, radius, rise] of REEF_ROCKS) {
    const d2 = ((x - rx) ** 2 + (z - rz) ** 2) / radius ** 2;
    if (d2 < 9) raised = Math.max(raised, rise * Math.exp(-d2 * d2)); // beyond 3ρ, exp(−81) is nothing
  }
  return raised;
}

/** The island's ground (land and sea floor) at (x, z), m above mean sea level. */
export function islandHeight(x: number, z: number): number {
  return baseHeight(x, z) + reefHeight(x, z);
}

/** The island's sea floor, as Ocean.setSeabed takes it: the terrain mesh is built from the same function. */
export function islandSeabed(): Seabed {
  return { depthAt: (x, z) => -islandHeight(x, z), bounds: [...ISLAND_BOUNDS] };
}

/**
 * Where a camera sees the island from a boat: offshore of the beach, 5 m up, the pier, the moored
 * boat and the cliff in view (the app's starting view when the island is chosen).
 */
export const ISLAND_VIEW: { position: [number, number, number]; target: [number, number, number] } = {
  position: [-75, 4, 265],
  target: [-45, 5, 121],
};

/** One side's vertex coordinates: GRID_CELLS + 1 of them from `min` to `max`, crowded towards `focus`. */
function warpedAxis(min: number, max: number, focus: number): Float64Array {
  const values = new Float64Array(GRID_CELLS + 1);
  // The uniform parameter t ∈ [−1, 1] with t = 0 at the focus; x = focus + span·(a·t + (1 − a)·t³).
  const split = (focus - min) / (max - min);
  for (let i = 0; i <= GRID_CELLS; i++) {
    const u = i / GRID_CELLS;
    const t = u < split ? (u - split) / split : (u - split) / (1 - split);
    const span = t < 0 ? focus - min : max - focus;
    values[i] = focus + span * (UNIFORM_SHARE * t + (1 - UNIFORM_SHARE) * t * t * t);
  }
  values[0] = min;
  values[GRID_CELLS] = max;
  return values;
}

/** The ground's colour at (x, z) of height h and slope |∇h| (linear RGB into `out`). */
function groundColour(x: number, z: number, h: number, slope: number, reef: number, out: Color): Color {
  // A little variation, so that no colour is one flat paint.
  const mottle = 0.5 + 0.5 * Math.sin(0.37 * x + 1.1) * Math.sin(0.29 * z + 0.4);
  const patches = 0.5 + 0.5 * Math.sin(0.045 * x - 0.8) * Math.sin(0.052 * z + 2.1);
  // Sand up to a little above the swash, grass above (drier on the heights), rock where steep.
  out.copy(GRASS).lerp(DRY_GRASS, smoothstep(0.3, 0.9, patches) * (0.4 + 0.6 * smoothstep(10, 35, h)));
  out.lerp(SAND, smoothstep(3.2 + 1.5 * mottle, 2 + mottle, h));
  out.lerp(WET_SAND, smoothstep(1.2, 0.3, h) * smoothstep(-1.5, -0.2, h)); // the swash zone
  const rocky = Math.max(smoothstep(0.8, 1.2, slope + 0.15 * (mottle - 0.5)), smoothstep(0.3, 1.2, reef));
  const rock = new Color().copy(ROCK).lerp(DARK_ROCK, 0.5 + 0.5 * Math.sin(h * 2.1) * mottle);
  if (reef > 0.3) rock.lerp(REEF, smoothstep(0.3, 1.2, reef));
  return out.lerp(rock, rocky);
}

/** The terrain mesh's geometry: positions are (x, islandHeight(x, z), z) on the warped grid. */
export function islandTerrainGeometry(): BufferGeometry {
  const [xMin, zMin, xMax, zMax] = ISLAND_BOUNDS;
  const xs = warpedAxis(xMin, xMax, FOCUS[0]);
  const zs = warpedAxis(zMin, zMax, FOCUS[1]);
  const side = GRID_CELLS + 1;
  const positions = new Float32Array(side * side * 3);
  const colours = new Float32Array(side * side * 3);
  for (let j = 0; j < side; j++) {
    for (let i = 0; i < side; i++) {
      const k = 3 * (j * side + i);
      positions[k] = xs[i];
      positions[k + 1] = islandHeight(xs[i], zs[j]);
      positions[k + 2] = zs[j];
    }
  }
  const indices = new Uint32Array(GRID_CELLS * GRID_CELLS * 6);
  let n = 0;
  for (let j = 0; j < GRID_CELLS; j++) {
    for (let i = 0; i < GRID_CELLS; i++) {
      const a = j * side + i;
      // Counter-clockwise seen from above (+y): a, a + side, a + 1.
      indices.set([a, a + side, a + 1, a + 1, a + side, a + side + 1], n);
      n += 6;
    }
  }
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new Float32BufferAttribute(positions, 3));
  geometry.setIndex(new Uint32BufferAttribute(indices, 1));
  geometry.computeVertexNormals();
  // The colours by height and slope: the slope |∇h| = tan of the normal's angle from the vertical.
  const normals = geometry.getAttribute('normal');
  const colour = new Color();
  for (let v = 0; v < side * side; v++) {
    const ny = normals.getY(v);
    const [x, h, z] = [positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]];
    groundColour(x, z, h, Math.sqrt(Math.max(0, 1 - ny * ny)) / ny, reefHeight(x, z), colour).toArray(colours, 3 * v);
  }
  geometry.setAttribute('color', new Float32BufferAttribute(colours, 3));
  return geometry;
}

/**
 * How deep the shallows reach, m: the sea's reflection keeps the scene down to the sea's RMS height
 * under the water (src/render/sceneReflection.ts), under 3 m for winds up to 24 m/s (a fully
 * developed sea's Hs = 0.21·U²/g, Pierson & Moskowitz 1964: 12.3 m, RMS Hs/4).
 */
export const SHALLOWS_DEPTH = 3;

/**
 * The terrain's triangles split into two geometries over the same vertices: those that reach
 * y = −SHALLOWS_DEPTH or above, and the sea floor wholly under it. The sea's reflection skips a mesh
 * wholly under its near plane (src/render/sceneCapture.ts), so the sea floor, most of the
 * triangles, is not drawn into it for nothing. Each part's bounding box is its own triangles':
 * three.js would take every vertex of the shared position attribute (the hills' too).
 */
export function splitAtShallows(geometry: BufferGeometry): { above: BufferGeometry; below: BufferGeometry } {
  const index = geometry.getIndex()!;
  const position = geometry.getAttribute('position');
  const above: number[] = [];
  const below: number[] = [];
  for (let i = 0; i < index.count; i += 3) {
    const [a, b, c] = [index.getX(i), index.getX(i + 1), index.getX(i + 2)];
    (Math.max(position.getY(a), position.getY(b), position.getY(c)) < -SHALLOWS_DEPTH ? below : above).push(a, b, c);
  }
  return { above: partOf(geometry, above), below: partOf(geometry, below) };
}

/** Some of `geometry`'s triangles (`indices`, three a triangle) over its vertices, with their own bounds. */
function partOf(geometry: BufferGeometry, indices: number[]): BufferGeometry {
  const position = geometry.getAttribute('position');
  const corner = new Vector3();
  const piece = new BufferGeometry();
  for (const name of Object.keys(geometry.attributes)) piece.setAttribute(name, geometry.getAttribute(name));
  piece.setIndex(new Uint32BufferAttribute(indices, 1));
  piece.boundingBox = new Box3();
  for (const v of indices) piece.boundingBox.expandByPoint(corner.fromBufferAttribute(position, v));
  piece.boundingSphere = piece.boundingBox.getBoundingSphere(new Sphere());
  return piece;
}

/**
 * Down to this depth (m) the sea floor's stand-in keeps every triangle (seaFloorStandIn): the reef
 * lies there, and the sea's default absorption (σ = 0.45, 0.07, 0.04 per m) still lets through half
 * the green and two-thirds of the blue from 10 m.
 */
export const WHOLE_FLOOR_DEPTH = 10;

/**
 * The sea floor's stand-in in the sea's captures (src/render/sceneCapture.ts, setCaptureStandIn),
 * over the terrain's vertices (so with the same heights, normals and colours there): the floor's
 * triangles whose top is within WHOLE_FLOOR_DEPTH of the surface, and deeper the terrain's grid
 * taken every CAPTURE_COARSENING lines, a coarse cell kept wherever any vertex inside it lies under
 * y = −WHOLE_FLOOR_DEPTH. Every deeper triangle lies inside a kept cell, so the stand-in leaves no
 * hole; the coarse cells overlap the finer triangles a little, under them where the ground bulges
 * up between their corners and over them where it dips.
 */
export function seaFloorStandIn(terrain: BufferGeometry): BufferGeometry {
  const position = terrain.getAttribute('position');
  const index = terrain.getIndex()!;
  const side = GRID_CELLS + 1;
  const indices: number[] = [];
  for (let i = 0; i < index.count; i += 3) {
    const [a, b, c] = [index.getX(i), index.getX(i + 1), index.getX(i + 2)];
    const top = Math.max(position.getY(a), position.getY(b), position.getY(c));
    if (top < -SHALLOWS_DEPTH && top >= -WHOLE_FLOOR_DEPTH) indices.push(a, b, c);
  }
  for (let j = 0; j < GRID_CELLS; j += CAPTURE_COARSENING) {
    for (let i = 0; i < GRID_CELLS; i += CAPTURE_COARSENING) {
      let lowest = Infinity;
      for (let dj = 0; dj <= CAPTURE_COARSENING; dj++) {
        for (let di = 0; di <= CAPTURE_COARSENING; di++) lowest = Math.min(lowest, position.getY((j + dj) * side + i + di));
      }
      if (lowest >= -WHOLE_FLOOR_DEPTH) continue;
      const a = j * side + i;
      const [right, down] = [CAPTURE_COARSENING, CAPTURE_COARSENING * side];
      // Counter-clockwise seen from above, as the terrain's own cells.
      indices.push(a, a + down, a + right, a + right, a + down, a + down + right);
    }
  }
  return partOf(terrain, indices);
}

export class Island extends Group {
  /** The sea floor the terrain is built from (give it to the ocean's seabed). */
  readonly seabed: Seabed = islandSeabed();
  /** The terrain's triangles that reach SHALLOWS_DEPTH under the water or above (its vertices are all of the terrain's). */
  readonly terrain: Mesh<BufferGeometry, MeshStandardMaterial>;
  /** The terrain's triangles wholly under SHALLOWS_DEPTH, over the same vertices and material. */
  readonly seaFloor: Mesh<BufferGeometry, MeshStandardMaterial>;
  /** What the sea's captures draw of the sea floor (seaFloorStandIn); this island owns it. */
  readonly seaFloorStandIn: BufferGeometry;
  /** The boat moored beside the pier's end. */
  readonly boat = new BoatModel();
  private readonly postGeometry = new BoxGeometry(0.3, 1, 0.3);
  private readonly plankGeometry = new BoxGeometry(PIER_WIDTH, 0.08, 0.28);
  private readonly woodMaterial = new MeshStandardMaterial({ color: 0x8a6a48, roughness: 0.9 });
  private readonly posts: InstancedMesh;
  private readonly planks: InstancedMesh;
  private readonly mooring: { x: number; z: number; heading: number };

  constructor() {
    super();
    this.name = 'island';
    const whole = islandTerrainGeometry();
    const { above, below } = splitAtShallows(whole);
    const ground = new MeshStandardMaterial({ vertexColors: true, roughness: 0.95 });
    this.terrain = new Mesh(above, ground);
    this.terrain.name = 'island terrain';
    this.seaFloor = new Mesh(below, ground);
    this.seaFloor.name = 'island sea floor';
    this.seaFloorStandIn = seaFloorStandIn(whole);
    setCaptureStandIn(this.seaFloor, this.seaFloorStandIn);
    const pier = new Group();
    pier.name = 'pier';
    this.posts = this.pierPosts();
    this.planks = this.pierDeck();
    pier.add(this.posts, this.planks);
    this.add(this.terrain, this.seaFloor, pier);
    const [dx, dz] = PIER_DIRECTION;
    this.mooring = {
      x: PIER_START[0] + MOORING.along * dx - MOORING.across * dz,
      z: PIER_START[1] + MOORING.along * dz + MOORING.across * dx,
      heading: Math.atan2(dz, dx) + Math.PI / 2,
    };
    this.boat.name = 'moored boat';
    this.boat.position.set(this.mooring.x, 0, this.mooring.z);
    this.add(this.boat);
  }

  /** The pier's posts: a pair every POST_SPACING m, from half a metre into the ground up to the deck. */
  private pierPosts(): InstancedMesh {
    const [dx, dz] = PIER_DIRECTION;
    const pairs = Math.floor(PIER_LENGTH / POST_SPACING) + 1;
    const posts = new InstancedMesh(this.postGeometry, this.woodMaterial, 2 * pairs);
    const matrix = new Matrix4();
    const scale = new Vector3();
    const place = new Vector3();
    for (let p = 0; p < pairs; p++) {
      for (const sideways of [-1, 1]) {
        const along = p * POST_SPACING;
        const x = PIER_START[0] + along * dx - sideways * (PIER_WIDTH / 2 - 0.15) * dz;
        const z = PIER_START[1] + along * dz + sideways * (PIER_WIDTH / 2 - 0.15) * dx;
        const bottom = islandHeight(x, z) - 0.5;
        const length = DECK_HEIGHT - bottom;
        matrix.compose(place.set(x, bottom + length / 2, z), PIER_ACROSS, scale.set(1, length, 1));
        posts.setMatrixAt(2 * p + (sideways + 1) / 2, matrix);
      }
    }
    posts.name = 'pier posts';
    return posts;
  }

  /** The pier's deck: planks across it, DECK_HEIGHT above the sea. */
  private pierDeck(): InstancedMesh {
    const [dx, dz] = PIER_DIRECTION;
    const matrix = new Matrix4();
    const place = new Vector3();
    const scale = new Vector3(1, 1, 1);
    const plankCount = Math.floor(PIER_LENGTH / 0.32);
    const planks = new InstancedMesh(this.plankGeometry, this.woodMaterial, plankCount);
    const shade = new Color();
    for (let i = 0; i < plankCount; i++) {
      const along = i * 0.32;
      matrix.compose(place.set(PIER_START[0] + along * dx, DECK_HEIGHT + 0.04, PIER_START[1] + along * dz), PIER_ACROSS, scale);
      planks.setMatrixAt(i, matrix);
      // Weathered boards: each a little lighter or darker.
      planks.setColorAt(i, shade.setScalar(0.8 + 0.35 * ((i * 0.618) % 1)));
    }
    planks.name = 'pier deck';
    return planks;
  }

  /** Sets the moored boat on the water of the ocean's current time (call after ocean.update). */
  update(ocean: Ocean): void {
    this.boat.setOnWater(ocean, this.mooring.x, this.mooring.z, this.mooring.heading);
  }

  dispose(): void {
    this.terrain.geometry.dispose();
    this.seaFloor.geometry.dispose();
    setCaptureStandIn(this.seaFloor, null);
    this.seaFloorStandIn.dispose();
    this.terrain.material.dispose();
    this.postGeometry.dispose();
    this.plankGeometry.dispose();
    this.woodMaterial.dispose();
    this.posts.dispose();
    this.planks.dispose();
    this.boat.dispose();
  }
}
