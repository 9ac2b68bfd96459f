/**
 * Test page for shores (tests/browser/seabed/seabed.spec.ts): an Ocean on the GPU path over a
 * 1:50 plane beach, drawn by the real shaders. It reads back every vertex the vertex shader
 * displaces (the material's CAPTURE_POSITIONS mode, as tests/browser/ocean does) and compares them
 * with the queries; it draws the beach as a terrain mesh, renders the picture, and makes a seabed
 * from meshes.
 */
import {
  ACESFilmicToneMapping,
  Mesh,
  MeshLambertMaterial,
  PerspectiveCamera,
  PlaneGeometry,
  Scene,
  SRGBColorSpace,
  Vector3,
  WebGLRenderer,
  AmbientLight,
  DirectionalLight,
  BufferGeometry,
} from 'three';
import { Ocean, type OceanOptions } from '../../../src/ocean';
import type { Shore } from '../../../src/layers/shore';
import { breakingHeight } from '../../../src/spectrum/shoaling';
import { swashLength, swashScale } from '../../../src/spectrum/swash';
import { OceanMaterial } from '../../../src/render/oceanMaterial';
import { captureVertices } from '../shared/vertexCapture';

const WIDTH = 480;
const HEIGHT = 270;
const renderer = new WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
renderer.setPixelRatio(1);
renderer.setSize(WIDTH, HEIGHT);
renderer.toneMapping = ACESFilmicToneMapping;
renderer.outputColorSpace = SRGBColorSpace;
document.body.appendChild(renderer.domElement);

/** The beach: depth x/50 (land at x < 0) over this rectangle; the `depth` option beyond it. */
const SLOPE = 1 / 50;
const BOUNDS = [-300, -800, 2500, 800] as const;
const beach = { depthAt: (x: number) => x * SLOPE, bounds: BOUNDS };
/** Two plane beaches side by side along the same waterline x = 0: 1:20 at z < 0, 1:50 at z > 0. */
const TWO_SLOPES = { steep: 1 / 20, gentle: 1 / 50 };
const twoBeaches = { depthAt: (x: number, z: number) => x * (z < 0 ? TWO_SLOPES.steep : TWO_SLOPES.gentle), bounds: BOUNDS };

const camera = new PerspectiveCamera(50, WIDTH / HEIGHT, 0.5, 1e5);
let ocean: Ocean | null = null;
const scene = new Scene();
/** The beach as the scene shows it: the plane y = −x/50, with the light to see it by. */
const terrainGeometry = new PlaneGeometry(BOUNDS[2] - BOUNDS[0], BOUNDS[3] - BOUNDS[1], 8, 8)
  .rotateX(-Math.PI / 2)
  .translate((BOUNDS[0] + BOUNDS[2]) / 2, 0, (BOUNDS[1] + BOUNDS[3]) / 2);
const corners = terrainGeometry.getAttribute('position');
for (let v = 0; v < corners.count; v++) corners.setY(v, -corners.getX(v) * SLOPE);
terrainGeometry.computeVertexNormals();
const terrain = new Mesh(terrainGeometry, new MeshLambertMaterial({ color: 0xd8c49a }));
const sun = new DirectionalLight(0xffffff, 2.5);
sun.position.set(-1, 2, 1);
scene.add(terrain, sun, new AmbientLight(0xffffff, 0.8));

function place(position: readonly number[], target: readonly number[]): void {
  camera.position.fromArray(position);
  camera.lookAt(new Vector3().fromArray(target));
  camera.far = 1e5;
  camera.updateProjectionMatrix();
  camera.updateMatrixWorld();
}

const harness = {
  /** A new Ocean over the beach (or over none, or over the two beaches of TWO_SLOPES), at time t, seen from `position`. */
  setup(seabed: boolean | 'twoSlopes', t: number, position: number[], target: number[], options: OceanOptions = {}): void {
    if (ocean) {
      ocean.removeFromParent();
      ocean.dispose();
    }
    ocean = new Ocean(renderer, { path: 'gpu', worker: false, ...options, seabed: seabed === 'twoSlopes' ? twoBeaches : seabed ? beach : null });
    scene.add(ocean);
    place(position, target);
    ocean.update(t, camera);
    renderer.render(scene, camera); // places the rings under the camera and binds the shore
  },

  /** The same Ocean at time t. */
  advance(t: number): void {
    ocean!.update(t, camera);
    renderer.render(scene, camera);
  },

  /**
   * Every vertex of the drawn surface, from the real vertex shader: its displaced position and its
   * rest point, world coordinates, and the foam the shore adds there (vShoreFoam: the surf and the
   * shoreline band, shoaling.glsl) (x, y, z, rest x, rest z, mip level, shore foam) per vertex; the
   * skirt left out.
   */
  capture(): number[][] {
    const o = ocean!;
    const surface = o.surface;
    const count = surface.geometry.getAttribute('position').count;
    const defines: Record<string, unknown> = { CAPTURE_POSITIONS: 1 };
    if (surface.material.defines.SEABED !== undefined) defines.SEABED = '';
    const material = new OceanMaterial({ environment: { value: null }, sunDirection: { value: new Vector3(0, 1, 0) } }, {}, defines);
    material.bindLayers(o.simulation.layers, o.parameters.choppiness, o.simulation.foam.texture);
    const shoreUniforms = ['tSeabed', 'seabedFrame', 'seabedNodes', 'seabedOutsideDepth', 'tShoaling', 'shoalingDepths', 'breakerDepth', 'swashSea'];
    for (const name of ['ringFrames', 'ringLayerUvOrigins', 'ringOffsets', 'halfRingCells', 'patchBlend', ...shoreUniforms]) {
      if (surface.material.uniforms[name]) material.uniforms[name] = surface.material.uniforms[name];
    }
    const { displaced, rest } = captureVertices(renderer, camera, surface.geometry as BufferGeometry, material);
    const eye = camera.position;
    const vertices: number[][] = [];
    for (let v = 0; v < count; v++) {
      const [rx, rz, lod] = rest.subarray(4 * v, 4 * v + 3);
      if (lod > 500) continue; // SKIRT_LOD: the far edge, flat by design
      vertices.push([displaced[4 * v] + eye.x, displaced[4 * v + 1] + eye.y, displaced[4 * v + 2] + eye.z, rx + eye.x, rz + eye.z, lod, displaced[4 * v + 3]]);
    }
    return vertices;
  },

  /**
   * The shore's part of the vertex shader, checked vertex by vertex on a sea of one layer: with the
   * seabed each vertex must be the same vertex without it (`plain`, same rest point, same mip
   * level) with its displacement × F(d at the rest point) and its height then limited in the water
   * column under the displaced point, d raised by the swash level ζ_t, and riding on it
   * (Shore.layerFactor, Shore.swashLevel of the height without the seabed, breakingHeight: what the
   * queries apply).
   * Returns the worst difference (m) over the vertices above the seabed, how many, and their RMS height.
   */
  shoreFormula(plain: number[][], over: number[][]) {
    const shore = (ocean as unknown as { shore: Shore }).shore;
    let worst = 0;
    let compared = 0;
    let sumSquares = 0;
    plain.forEach((p, v) => {
      const [x, y, z, rx, rz] = p;
      const o = over[v];
      if (o[3] !== rx || o[4] !== rz) throw new Error('the two captures hold different vertices');
      const depth = shore.depthAt(rx, rz);
      if (depth === Infinity) return;
      const factor = shore.layerFactor(0, depth);
      const ex = rx + factor * (x - rx);
      const ez = rz + factor * (z - rz);
      const column = shore.depthAt(ex, ez);
      const swash = shore.swashLevel(y, ex, ez, column);
      const ey = swash + breakingHeight(factor * y, column + swash);
      worst = Math.max(worst, Math.abs(o[0] - ex), Math.abs(o[1] - ey), Math.abs(o[2] - ez));
      compared++;
      sumSquares += o[1] * o[1];
    });
    return { worst, compared, rms: Math.sqrt(sumSquares / Math.max(compared, 1)) };
  },

  /**
   * Along each line of rest points of constant z, where the drawn water meets the beach (going out
   * to sea, between a vertex whose water lies under the ground and the next, above it: y > −depth)
   * against the nearest place where the queried surface meets it (heightAt), in units of the
   * distance between the two vertices (a cell of the grid); Infinity where none is near. With each,
   * where the drawn one is (x, z).
   */
  waterline(vertices: number[][]): { offsets: number[]; drawn: [number, number][] } {
    const o = ocean!;
    // A line of one ring: where two rings overlap, their vertices share rest points at different mip levels.
    const rows = new Map<string, number[][]>();
    for (const vertex of vertices) {
      const key = `${Math.round(vertex[4] * 1000)} ${vertex[5]}`;
      if (!rows.has(key)) rows.set(key, []);
      rows.get(key)!.push(vertex);
    }
    const wet = (p: number[]) => p[1] > -o.depthAt(p[0], p[2]);
    const offsets: number[] = [];
    const crossings: [number, number][] = [];
    for (const row of rows.values()) {
      row.sort((a, b) => a[3] - b[3]);
      for (let i = 1; i < row.length; i++) {
        if (wet(row[i - 1]) || !wet(row[i])) continue; // dry, then wet
        const z = row[i][2];
        const drawn = 0.5 * (row[i - 1][0] + row[i][0]);
        const cell = Math.hypot(row[i][0] - row[i - 1][0], row[i][2] - row[i - 1][2]);
        // The queried waterline nearest the drawn one: a dry-to-wet change of heightAt + depth,
        // scanned in twentieths of a cell over five cells either side.
        let nearest = Infinity;
        let before = o.heightAt(drawn - 5 * cell, z) > -o.depthAt(drawn - 5 * cell, z);
        for (let k = -99; k <= 100; k++) {
          const x = drawn + (k / 20) * cell;
          const now = o.heightAt(x, z) > -o.depthAt(x, z);
          if (now && !before) nearest = Math.min(nearest, Math.abs(x - cell / 40 - drawn));
          before = now;
        }
        offsets.push(nearest / cell);
        crossings.push([drawn, z]);
      }
    }
    return { offsets, drawn: crossings };
  },

  /**
   * The shore's foam (vShoreFoam) across the beach: the mean over the captured vertices whose rest
   * point lies at zMin ≤ z ≤ zMax, in bins of `bin` metres of rest x from xMin (`bins` of them),
   * every ring's vertices alike; a bin no vertex falls in (where the rings' cells are wider than a
   * bin) takes the linear interpolation of its neighbours', and `empty` counts them. With the depth
   * where the shoreline band ends (the shader's breakerDepth, Hs/0.78).
   */
  shoreFoamAcross(vertices: number[][], zMin: number, zMax: number, xMin: number, bin: number, bins: number): { foam: number[]; empty: number; breakerDepth: number } {
    const sums = new Array<number>(bins).fill(0);
    const counts = new Array<number>(bins).fill(0);
    for (const [, , , rx, rz, , foam] of vertices) {
      const b = Math.floor((rx - xMin) / bin);
      if (rz < zMin || rz > zMax || b < 0 || b >= bins) continue;
      sums[b] += foam;
      counts[b]++;
    }
    const filled = counts.map((count, b) => (count > 0 ? b : -1)).filter((b) => b >= 0);
    if (filled.length === 0) throw new Error('no vertex across the beach');
    const foam = counts.map((count, b) => {
      if (count > 0) return sums[b] / count;
      const below = [...filled].reverse().find((f) => f < b) ?? filled[0];
      const above = filled.find((f) => f > b) ?? filled[filled.length - 1];
      const [fb, fa] = [sums[below] / counts[below], sums[above] / counts[above]];
      return above === below ? fb : fb + ((fa - fb) * (b - below)) / (above - below);
    });
    const shore = (ocean as unknown as { shore: Shore }).shore;
    return { foam, empty: counts.filter((count) => count === 0).length, breakerDepth: shore.uniforms.breakerDepth.value };
  },

  /**
   * GPU memory (renderer.info.memory) before an Ocean over the beach is made, drawn, given a
   * second seabed (the first one's texture freed) and disposed, and after.
   */
  memoryCycle(): { before: number[]; after: number[] } {
    if (ocean) {
      ocean.removeFromParent();
      ocean.dispose();
      ocean = null;
    }
    renderer.render(scene, camera);
    const memory = () => [renderer.info.memory.textures, renderer.info.memory.geometries];
    const before = memory();
    const cycled = new Ocean(renderer, { path: 'gpu', worker: false, seabed: beach });
    scene.add(cycled);
    cycled.update(1, camera);
    renderer.render(scene, camera);
    cycled.setSeabed({ depths: [5, 5, 1, 1], width: 2, height: 2, bounds: [0, 0, 100, 100] });
    cycled.update(2, camera);
    renderer.render(scene, camera);
    cycled.dispose();
    renderer.render(scene, camera);
    return { before, after: memory() };
  },

  /**
   * Where the queried water first meets the beach going out to sea along the line of constant z
   * (x from −80 m, by 0.5 m steps, then bisection to a centimetre): the runup's edge.
   */
  queriedWaterline(z: number): number {
    const o = ocean!;
    const wet = (x: number) => o.heightAt(x, z) > -o.depthAt(x, z);
    let x = -80;
    while (!wet(x)) x += 0.5;
    let [dry, water] = [x - 0.5, x];
    while (water - dry > 0.01) {
      const mid = 0.5 * (dry + water);
      if (wet(mid)) water = mid;
      else dry = mid;
    }
    return 0.5 * (dry + water);
  },

  /** Stockdon et al. 2006's significant swash S (m) on the 1:50 beach for the simulated sea (Hs = 4·heightRms, as the Ocean gives the shore). */
  stockdonSwash(): number {
    return swashScale(swashLength(4 * ocean!.heightRms, ocean!.seaState.peakPeriod), SLOPE).swash;
  },

  /** The frame, as a PNG data URL; from `position` looking at `target` if given. */
  picture(position?: number[], target?: number[]): string {
    if (position && target) place(position, target);
    renderer.render(scene, camera);
    return renderer.domElement.toDataURL('image/png');
  },

  /** A seabed drawn from meshes: this beach as a tilted plane, its depths read back at points. */
  meshSeabed(points: [number, number][]): number[] {
    const o = ocean!;
    o.setSeabed({ meshes: [terrain], resolution: 128 });
    return points.map(([x, z]) => o.depthAt(x, z));
  },

  /** Sets a seabed and returns the ParameterError's parameter (or '' when none was thrown) and the depth at (1000, 0) after. */
  badSeabed(kind: string): { parameter: string; depthAfter: number } {
    const o = ocean!;
    const bad: Record<string, unknown> = {
      nan: { depthAt: () => NaN, bounds: [0, 0, 10, 10] },
      noGeometry: { meshes: [new Mesh()] },
      noArea: { depthAt: () => 1, bounds: [0, 0, 10, 0] },
    };
    let parameter = '';
    try {
      o.setSeabed(bad[kind] as never);
    } catch (error) {
      parameter = (error as { parameter?: string }).parameter ?? String(error);
    }
    return { parameter, depthAfter: o.depthAt(1000, 0) };
  },
};

declare global {
  interface Window {
    seabed: typeof harness;
  }
}
window.seabed = harness;
document.title = 'ready';
