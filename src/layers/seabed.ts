/**
 * The sea floor under a rectangle of the sea: a depth map, metres below mean sea level (negative
 * over land), on a grid of nodes that includes the rectangle's edges, node (i, j) at
 *   x = xMin + i·(xMax − xMin)/(width − 1),   z = zMin + j·(zMax − zMin)/(height − 1),
 * read bilinearly between nodes, on the CPU (depthAt) and in the vertex shader
 * (shaders/surface/shoaling.glsl, the same formula on the same Float32Array, held as a float
 * DataTexture this map owns). Outside the rectangle the sea is as deep as the `depth` option.
 *
 * Made from one of three descriptions (Seabed): a function, a heightfield, or three.js meshes
 * drawn from above into a float render target (the highest surface over each node wins) and read
 * back. Everything is checked before anything is kept: a bad one is a ParameterError naming it.
 */
import {
  DataTexture,
  DoubleSide,
  FloatType,
  Mesh,
  NearestFilter,
  OrthographicCamera,
  RGFormat,
  RGBAFormat,
  Scene,
  ShaderMaterial,
  Vector2,
  Vector4,
  WebGLRenderTarget,
  Box3,
  Color,
  type BufferGeometry,
  type Object3D,
  type WebGLRenderer,
} from 'three';
import { ParameterError } from '../parameters/options';
import { shaderSource } from '../shaderSource';

/** [xMin, zMin, xMax, zMax] in metres, world space. */
export type SeabedBounds = readonly [number, number, number, number];

/** A sea floor given by a function: its depth (m below mean sea level; negative is land) at a world point. */
export interface SeabedFunction {
  depthAt(x: number, z: number): number;
  bounds: SeabedBounds;
  /** Nodes along each side of the depth map it is sampled on, 2 to 4096. @defaultValue 256 */
  resolution?: number;
}

/** A sea floor given as depths on width × height nodes over `bounds`, row by row (x fastest, z rows). */
export interface SeabedHeightfield {
  depths: ArrayLike<number>;
  width: number;
  height: number;
  bounds: SeabedBounds;
}

/** A sea floor given by three.js meshes, drawn from above into the depth map. */
export interface SeabedMeshes {
  meshes: readonly Object3D[];
  /** @defaultValue the meshes' bounding box */
  bounds?: SeabedBounds;
  /** Nodes along each side of the depth map, 2 to 4096. @defaultValue 256 */
  resolution?: number;
}

/** What Ocean.setSeabed and the `seabed` option take. */
export type Seabed = SeabedFunction | SeabedHeightfield | SeabedMeshes;

const DEFAULT_RESOLUTION = 256;
const LARGEST_RESOLUTION = 4096;

export class SeabedMap {
  /**
   * The depths and the bottom's slope |∇d| at each node (RG32F: depth, slope; nearest: the shader
   * interpolates it itself), owned and freed here.
   */
  readonly texture: DataTexture;
  /** |∇d| at node (i, j) at [j·width + i]: central differences (one-sided at the edges). */
  readonly slopes: Float32Array;

  constructor(
    readonly bounds: SeabedBounds,
    readonly width: number,
    readonly height: number,
    /** Depth at node (i, j) at [j·width + i], m. */
    readonly depths: Float32Array,
  ) {
    this.slopes = nodeSlopes(depths, width, height, bounds);
    const texels = new Float32Array(2 * width * height);
    for (let at = 0; at < width * height; at++) {
      texels[2 * at] = depths[at];
      texels[2 * at + 1] = this.slopes[at];
    }
    this.texture = new DataTexture(texels, width, height, RGFormat, FloatType);
    this.texture.minFilter = this.texture.magFilter = NearestFilter;
    this.texture.needsUpdate = true;
  }

  /** Depth (m) at the world point (x, z): bilinear between nodes, `outside` beyond the bounds. */
  depthAt(x: number, z: number, outside: number): number {
    return this.bilinear(this.depths, x, z, outside);
  }

  /** The bottom's slope |∇d| at the world point (x, z), bilinear between nodes; 0 beyond the bounds (flat). */
  slopeAt(x: number, z: number): number {
    return this.bilinear(this.slopes, x, z, 0);
  }

  private bilinear(d: Float32Array, x: number, z: number, outside: number): number {
    const [xMin, zMin, xMax, zMax] = this.bounds;
    const u = ((x - xMin) / (xMax - xMin)) * (this.width - 1);
    const v = ((z - zMin) / (zMax - zMin)) * (this.height - 1);
    if (!(u >= 0 && v >= 0 && u <= this.width - 1 && v <= this.height - 1)) return outside;
    const i = Math.min(Math.floor(u), this.width - 2);
    const j = Math.min(Math.floor(v), this.height - 2);
    const fu = u - i;
    const fv = v - j;
    const at = j * this.width + i;
    return (1 - fv) * ((1 - fu) * d[at] + fu * d[at + 1]) + fv * ((1 - fu) * d[at + this.width] + fu * d[at + this.width + 1]);
  }

  dispose(): void {
    this.texture.dispose();
  }
}

/** |∇d| at every node of a width × height map over `bounds`: central differences, one-sided at the edges. */
function nodeSlopes(depths: Float32Array, width: number, height: number, bounds: SeabedBounds): Float32Array {
  const [xMin, zMin, xMax, zMax] = bounds;
  const stepX = (xMax - xMin) / (width - 1);
  const stepZ = (zMax - zMin) / (height - 1);
  const slopes = new Float32Array(width * height);
  for (let j = 0; j < height; j++) {
    const below = Math.max(j - 1, 0);
    const above = Math.min(j + 1, height - 1);
    for (let i = 0; i < width; i++) {
      const left = Math.max(i - 1, 0);
      const right = Math.min(i + 1, width - 1);
      const gx = (depths[j * width + right] - depths[j * width + left]) / ((right - left) * stepX);
      const gz = (depths[above * width + i] - depths[below * width + i]) / ((above - below) * stepZ);
      slopes[j * width + i] = Math.hypot(gx, gz);
    }
  }
  return slopes;
}

/** The depth map a Seabed describes; throws a ParameterError naming what is wrong. */
export function createSeabedMap(seabed: Seabed, renderer: WebGLRenderer | null): SeabedMap {
  if (seabed === null || typeof seabed !== 'object') {
    throw new ParameterError('seabed', seabed, '{ depthAt(x, z), bounds }, { depths, width, height, bounds }, { meshes } or null');
  }
  if ('depthAt' in seabed) return fromFunction(seabed);
  if ('depths' in seabed) return fromHeightfield(seabed);
  if ('meshes' in seabed) {
    if (renderer === null) throw new ParameterError('seabed.meshes', seabed.meshes, '', 'seabed.meshes: meshes need a renderer to be drawn into the depth map');
    return fromMeshes(seabed, renderer);
  }
  throw new ParameterError('seabed', seabed, 'an object with depthAt(x, z), depths or meshes');
}

function checkBounds(bounds: unknown, name = 'seabed.bounds'): SeabedBounds {
  const ok =
    Array.isArray(bounds) && bounds.length === 4 && bounds.every((b) => typeof b === 'number' && Number.isFinite(b)) && bounds[2] > bounds[0] && bounds[3] > bounds[1];
  if (!ok) throw new ParameterError(name, bounds, '[xMin, zMin, xMax, zMax], finite metres with xMax > xMin and zMax > zMin (an area)');
  return [bounds[0], bounds[1], bounds[2], bounds[3]];
}

function checkResolution(resolution: unknown, name: string): number {
  if (resolution === undefined) return DEFAULT_RESOLUTION;
  if (!(Number.isInteger(resolution) && (resolution as number) >= 2 && (resolution as number) <= LARGEST_RESOLUTION)) {
    throw new ParameterError(name, resolution, `a whole number of nodes from 2 to ${LARGEST_RESOLUTION}`);
  }
  return resolution as number;
}

/** Throws unless every depth is finite: nothing NaN may reach the texture. */
function checkDepths(depths: Float32Array, width: number, name: string, where: (i: number, j: number) => string): void {
  for (let at = 0; at < depths.length; at++) {
    if (!Number.isFinite(depths[at])) {
      const i = at % width;
      throw new ParameterError(name, depths[at], `a finite depth in metres at every node (${where(i, (at - i) / width)})`);
    }
  }
}

function fromFunction(seabed: SeabedFunction): SeabedMap {
  if (typeof seabed.depthAt !== 'function') throw new ParameterError('seabed.depthAt', seabed.depthAt, 'a function (x, z) => depth in metres');
  const bounds = checkBounds(seabed.bounds);
  const n = checkResolution(seabed.resolution, 'seabed.resolution');
  const [xMin, zMin, xMax, zMax] = bounds;
  const depths = new Float32Array(n * n);
  for (let j = 0; j < n; j++) {
    const z = zMin + (j * (zMax - zMin)) / (n - 1);
    for (let i = 0; i < n; i++) {
      const x = xMin + (i * (xMax - xMin)) / (n - 1);
      let depth: unknown;
      try {
        depth = seabed.depthAt(x, z);
      } catch (error) {
        throw new ParameterError('seabed.depthAt', error, '', `seabed.depthAt threw at (${x}, ${z}): ${String(error)}`);
      }
      if (typeof depth !== 'number' || !Number.isFinite(depth)) {
        throw new ParameterError('seabed.depthAt', depth, `a finite depth in metres (it gave this at x = ${x}, z = ${z})`);
      }
      depths[j * n + i] = depth;
    }
  }
  return new SeabedMap(bounds, n, n, depths);
}

function fromHeightfield(seabed: SeabedHeightfield): SeabedMap {
  const bounds = checkBounds(seabed.bounds);
  const { width, height, depths } = seabed;
  for (const [name, value] of [
    ['seabed.width', width],
    ['seabed.height', height],
  ] as const) {
    if (!(Number.isInteger(value) && value >= 2 && value <= LARGEST_RESOLUTION)) throw new ParameterError(name, value, `a whole number of nodes from 2 to ${LARGEST_RESOLUTION}`);
  }
  if (depths === null || typeof depths !== 'object' || depths.length !== width * height) {
    throw new ParameterError('seabed.depths', depths, `an array of width × height = ${width * height} depths`);
  }
  const copy = Float32Array.from(depths);
  checkDepths(copy, width, 'seabed.depths', (i, j) => `node ${i}, ${j}`);
  return new SeabedMap(bounds, width, height, copy);
}

/**
 * Draws the meshes from above: each vertex is projected straight down onto the map's nodes
 * (an orthographic projection along −y, written out in shaders/seabed/depthMap.vert, so that
 * node (i, j) is the centre of pixel (i, j)), the highest surface over each node kept by the
 * depth test, its height y written into a float target and read back as the depth −y. Where no
 * mesh covers a node the map keeps the deepest depth any mesh reaches (the bottom goes on at it).
 */
function fromMeshes(seabed: SeabedMeshes, renderer: WebGLRenderer): SeabedMap {
  const meshes = seabed.meshes;
  if (!Array.isArray(meshes) || meshes.length === 0) throw new ParameterError('seabed.meshes', meshes, 'a non-empty array of three.js Object3D with meshes in them');
  const sources: Mesh[] = [];
  meshes.forEach((object, index) => {
    if ((object as { isObject3D?: unknown } | null)?.isObject3D !== true) throw new ParameterError(`seabed.meshes[${index}]`, object, 'a three.js Object3D');
    object.updateWorldMatrix(true, true);
    let found = 0;
    object.traverse((child: Object3D) => {
      if (!(child as Mesh).isMesh) return;
      const geometry = (child as Mesh).geometry as BufferGeometry | undefined;
      if (geometry?.getAttribute?.('position') === undefined) throw new ParameterError(`seabed.meshes[${index}]`, child, 'meshes whose geometry has positions');
      sources.push(child as Mesh);
      found++;
    });
    if (found === 0) throw new ParameterError(`seabed.meshes[${index}]`, object, 'an Object3D holding at least one mesh with a geometry');
  });
  const box = new Box3();
  for (const mesh of sources) box.expandByObject(mesh);
  if (box.isEmpty()) throw new ParameterError('seabed.meshes', meshes, 'meshes with some extent');
  const bounds = checkBounds(seabed.bounds ?? [box.min.x, box.min.z, box.max.x, box.max.z], seabed.bounds === undefined ? 'seabed.meshes (their extent in x and z)' : 'seabed.bounds');
  const n = checkResolution(seabed.resolution, 'seabed.resolution');
  if (!renderer.extensions.has('EXT_color_buffer_float')) {
    throw new ParameterError('seabed.meshes', meshes, '', 'seabed.meshes: this WebGL has no float render targets (EXT_color_buffer_float); give the seabed as a function or a heightfield');
  }
  const [xMin, zMin, xMax, zMax] = bounds;
  const material = new ShaderMaterial({
    vertexShader: shaderSource('seabed/depthMap.vert'),
    fragmentShader: shaderSource('seabed/depthMap.frag'),
    side: DoubleSide,
    uniforms: {
      mapFrame: { value: new Vector4(xMin, zMin, (n - 1) / (xMax - xMin), (n - 1) / (zMax - zMin)) },
      mapNodes: { value: new Vector2(n, n) },
      heightRange: { value: new Vector2(box.min.y - 1, box.max.y + 1) },
    },
  });
  const scene = new Scene();
  scene.overrideMaterial = material;
  for (const source of sources) {
    const proxy = new Mesh(source.geometry, material);
    proxy.matrixAutoUpdate = false;
    proxy.matrix.copy(source.matrixWorld);
    proxy.frustumCulled = false;
    scene.add(proxy);
  }
  const target = new WebGLRenderTarget(n, n, { type: FloatType, format: RGBAFormat, depthBuffer: true, minFilter: NearestFilter, magFilter: NearestFilter });
  const previousTarget = renderer.getRenderTarget();
  const previousClear = renderer.getClearColor(new Color());
  const previousAlpha = renderer.getClearAlpha();
  const texels = new Float32Array(4 * n * n);
  try {
    renderer.setRenderTarget(target);
    renderer.setClearColor(0x000000, 0); // alpha 0: no mesh over this node
    renderer.clear(true, true, false);
    renderer.render(scene, new OrthographicCamera()); // the projection is the shader's own
    renderer.readRenderTargetPixels(target, 0, 0, n, n, texels);
  } finally {
    renderer.setRenderTarget(previousTarget);
    renderer.setClearColor(previousClear, previousAlpha);
    target.dispose();
    material.dispose();
  }
  const depths = new Float32Array(n * n);
  const floor = -box.min.y;
  for (let p = 0; p < n * n; p++) depths[p] = texels[4 * p + 3] > 0.5 ? -texels[4 * p] : floor;
  checkDepths(depths, n, 'seabed.meshes', (i, j) => `node ${i}, ${j}`);
  return new SeabedMap(bounds, n, n, depths);
}
