/**
 * Geometry that reaches the horizon: camera-centred square rings of grid cells, each ring with
 * cells twice the size of the ring inside it, and a skirt from the last ring out to far away.
 * (Geometry clipmaps, Losasso & Hoppe 2004, simplified; chosen over the course report's projected
 * grid because its vertices stay on fixed world points, which is what makes them provably right.)
 *
 * Ring r has cells of size cell_r = baseCell·2^r and spans cellsPerRing cells on a side around
 * its centre, which is the camera position snapped down to a multiple of 2·cell_r. Ring r ≥ 1 has
 * a hole where ring r − 1 lies; the snapping can put ring r − 1 one cell off-centre in either axis,
 * so the hole is one cell smaller on each side than ring r − 1 and the fragment shader drops the
 * overlap (shaders/surface/ocean.frag). The vertex stage places vertices: shaders/surface/horizonGrid.glsl.
 *
 * baseCell is the finest layer's texel size times a power of two that grows with the camera's height, so
 * the number of vertices on screen stays about the same from 1 m to 2 km up; cellsPerRing follows
 * the viewport's height. Mip level of ring r in a layer: log2(cell_r / the layer's texel), so far
 * rings sample filtered fields and each layer's detail fades where the cells can no longer show it,
 * without aliasing and without popping (the fields' own mipmaps do the filtering).
 */
import { BufferGeometry, Float32BufferAttribute, Uint32BufferAttribute } from 'three';

/**
 * Rings around the camera. The last one ends cellsPerRing/2 · baseCell · 2^(RING_COUNT−1) away,
 * about 1000 camera heights (baseCell grows with the height), and the skirt goes SKIRT_SCALE times
 * further: there the sea is less than 0.02° below the true horizon, under a pixel.
 */
export const RING_COUNT = 9;
export const SKIRT_SCALE = 4;
/** Width of the index-order stripes (see createHorizonGridGeometry). */
const STRIPE_CELLS = 8;

/**
 * The fewest cells on a side of a ring unless told otherwise (OceanSurface.fewestCellsPerRing): a
 * small picture (an embed a couple of hundred pixels high) keeps a grid as fine as its waves need.
 */
export const FEWEST_CELLS_PER_RING = 32;
/** The most: beyond, vertices cost more than the picture gains. */
export const MOST_CELLS_PER_RING = 128;

/**
 * Cells on a side of each ring for a viewport this many pixels high: about one per 10 pixels of
 * height, a power of two from `fewest` (a power of two) to MOST_CELLS_PER_RING.
 */
export function cellsPerRingForViewport(heightPixels: number, fewest = FEWEST_CELLS_PER_RING): number {
  const ideal = Math.log2(Math.max(1, heightPixels) / 10);
  return 2 ** Math.min(Math.log2(MOST_CELLS_PER_RING), Math.max(Math.log2(fewest), Math.round(ideal)));
}

/**
 * Static geometry in grid units. Attributes: position = (x, z, ring) with x, z in cells from the
 * ring centre (called position so three.js can draw it as a wireframe), farScale = 1 (or
 * SKIRT_SCALE for the skirt's far edge).
 */
export function createHorizonGridGeometry(cellsPerRing: number): BufferGeometry {
  const half = cellsPerRing / 2;
  const gridPosition: number[] = [];
  const farScale: number[] = [];
  const indices: number[] = [];
  let vertexCount = 0;
  const addVertex = (x: number, z: number, ring: number, scale: number): number => {
    gridPosition.push(x, z, ring);
    farScale.push(scale);
    return vertexCount++;
  };

  // Cells of a ring ≥ 1 whose two coordinates both lie in [holeLow, holeHigh] form its hole.
  const holeLow = -cellsPerRing / 4 + 1;
  const holeHigh = cellsPerRing / 4 - 1;
  for (let ring = 0; ring < RING_COUNT; ring++) {
    const index = new Map<number, number>();
    const vertex = (x: number, z: number): number => {
      const key = (x + half) * (cellsPerRing + 1) + (z + half);
      let id = index.get(key);
      if (id === undefined) {
        id = addVertex(x, z, ring, 1);
        index.set(key, id);
      }
      return id;
    };
    // Cells in stripes STRIPE_CELLS wide, row by row within a stripe: a row's vertices are still
    // in the GPU's post-transform cache when the next row uses them. Whole rows of the ring (65
    // to 129 vertices) overflowed SwiftShader's cache and shaded every vertex two to three times
    // (measured: a tenth of the frame).
    for (let stripe = -half; stripe < half; stripe += STRIPE_CELLS) {
      for (let cz = -half; cz < half; cz++) {
        for (let cx = stripe; cx < Math.min(stripe + STRIPE_CELLS, half); cx++) {
          const inHole = ring > 0 && cx >= holeLow && cx <= holeHigh && cz >= holeLow && cz <= holeHigh;
          if (inHole) continue;
          const a = vertex(cx, cz);
          const b = vertex(cx + 1, cz);
          const c = vertex(cx, cz + 1);
          const d = vertex(cx + 1, cz + 1);
          indices.push(a, c, b, b, c, d);
        }
      }
    }
  }

  // Skirt: quads from the last ring's edge (its even points, where its edge vertices land) out to
  // SKIRT_SCALE times as far, walking once around the square.
  const edge: [number, number][] = [];
  for (let s = -half; s < half; s += 2) edge.push([s, -half]);
  for (let s = -half; s < half; s += 2) edge.push([half, s]);
  for (let s = half; s > -half; s -= 2) edge.push([s, half]);
  for (let s = half; s > -half; s -= 2) edge.push([-half, s]);
  const lastRing = RING_COUNT - 1;
  const first = vertexCount;
  for (const [x, z] of edge) {
    addVertex(x, z, lastRing, 1);
    addVertex(x, z, lastRing, SKIRT_SCALE);
  }
  for (let i = 0; i < edge.length; i++) {
    const inner = first + 2 * i;
    const next = first + 2 * ((i + 1) % edge.length);
    indices.push(inner, inner + 1, next, next, inner + 1, next + 1);
  }

  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new Float32BufferAttribute(gridPosition, 3));
  geometry.setAttribute('farScale', new Float32BufferAttribute(farScale, 1));
  geometry.setIndex(new Uint32BufferAttribute(indices, 1));
  return geometry;
}

/** A layer as the rings see it: a square of `size` metres with `resolution` texels a side. */
export interface LayerGrid {
  readonly frame: { readonly size: number; readonly resolution: number; readonly origin: readonly [number, number]; readonly periodic: boolean };
}

/** Per-ring uniforms for shaders/surface/horizonGrid.glsl and ocean.vert, recomputed each frame. */
export class RingFrames {
  /**
   * (centre x, centre z, cell size, mip level of the finest layer) per ring, RING_COUNT + 1 of
   * them, the centre relative to the camera (computed in double precision): the vertex stage works
   * in metres from the eye, so that float32 keeps its precision however far from the world origin
   * the camera is (at 10⁷ m a float32 world coordinate is only good to a metre).
   */
  readonly frames = new Float32Array(4 * (RING_COUNT + 1));
  /**
   * Texture coordinate of each ring centre in each layer, [ring · layers + layer], (centre / size +
   * ½ texel) mod 1, in double precision. The half texel: texel i holds the field at
   * x = i·size/N, while GL samples texel i's value exactly at u = (i + ½)/N.
   */
  uvOrigins = new Float32Array(2 * (RING_COUNT + 1));
  /** (centre_r − centre_{r+1}) / cell_{r+1} per ring: whole numbers, 0 or 1. */
  readonly offsets = new Float32Array(2 * (RING_COUNT + 1));
  /** Ring centres in double precision (frames holds them as float32). */
  private readonly centres = new Float64Array(2 * (RING_COUNT + 1));

  /**
   * @param cameraX, cameraZ camera position on the sea plane (m)
   * @param cameraHeight camera height above the sea (m)
   * @param layers the wave layers the surface samples; the finest texel sets the finest cells
   */
  update(cameraX: number, cameraZ: number, cameraHeight: number, layers: readonly LayerGrid[], cellsPerRing: number): void {
    const texelSize = finestTexel(layers);
    if (this.uvOrigins.length !== 2 * (RING_COUNT + 1) * layers.length) this.uvOrigins = new Float32Array(2 * (RING_COUNT + 1) * layers.length);
    const level = finestRingLevel(cameraHeight, texelSize, cellsPerRing);
    for (let ring = 0; ring <= RING_COUNT; ring++) {
      const cell = texelSize * 2 ** (level + ring);
      const x = Math.floor(cameraX / (2 * cell)) * 2 * cell;
      const z = Math.floor(cameraZ / (2 * cell)) * 2 * cell;
      this.centres[2 * ring] = x;
      this.centres[2 * ring + 1] = z;
      this.frames[4 * ring] = x - cameraX;
      this.frames[4 * ring + 1] = z - cameraZ;
      this.frames[4 * ring + 2] = cell;
      this.frames[4 * ring + 3] = level + ring;
      layers.forEach(({ frame: { size, resolution, origin, periodic } }, layer) => {
        const at = 2 * (ring * layers.length + layer);
        const halfTexel = 0.5 / resolution;
        // A periodic layer repeats: only the fraction matters (and keeps float32 exact far away). A
        // local one is sampled from its origin and clamped outside (its edge texels are zero).
        const u = (x - origin[0]) / size + halfTexel;
        const v = (z - origin[1]) / size + halfTexel;
        this.uvOrigins[at] = periodic ? fractional(u) : u;
        this.uvOrigins[at + 1] = periodic ? fractional(v) : v;
      });
    }
    for (let ring = 0; ring < RING_COUNT; ring++) {
      const nextCell = 2 * this.frames[4 * ring + 2];
      this.offsets[2 * ring] = Math.round((this.centres[2 * ring] - this.centres[2 * ring + 2]) / nextCell);
      this.offsets[2 * ring + 1] = Math.round((this.centres[2 * ring + 1] - this.centres[2 * ring + 3]) / nextCell);
    }
  }
}

/**
 * Mip level of ring 0's cells in the finest layer (its cells are texelSize · 2^level): the texel
 * size, or coarser by powers of two once the camera is high enough that ring 0 would cover less
 * than about 8× the camera height.
 */
function finestRingLevel(cameraHeight: number, texelSize: number, cellsPerRing: number): number {
  const heightPerCell = Math.max(1, cameraHeight) / (cellsPerRing / 8);
  return Math.max(0, Math.ceil(Math.log2(heightPerCell / texelSize)));
}

/**
 * Distance from a camera `cameraHeight` metres above the sea to the far corner of the skirt of the
 * rings RingFrames.update places for it: the camera's far plane must reach it. It depends on the
 * height, the finest texel of the layers and the cells per ring, not on where the camera is.
 */
export function farEdgeDistance(cameraHeight: number, layers: readonly LayerGrid[], cellsPerRing: number): number {
  const texelSize = finestTexel(layers);
  const lastCell = texelSize * 2 ** (finestRingLevel(cameraHeight, texelSize, cellsPerRing) + RING_COUNT - 1);
  return Math.SQRT2 * (cellsPerRing / 2 + 2) * lastCell * SKIRT_SCALE + Math.max(0, cameraHeight);
}

/** The smallest texel of the layers, m: the rings' finest cells are this times a power of two. */
export function finestTexel(layers: readonly LayerGrid[]): number {
  let finest = Infinity;
  // The periodic layers cover the whole sea and set the grid; a local layer is sampled at the
  // density they give (its texels are coarser than the finest cascade's by default).
  for (const { frame } of layers) if (frame.periodic) finest = Math.min(finest, frame.size / frame.resolution);
  return finest;
}

function fractional(x: number): number {
  return x - Math.floor(x);
}
