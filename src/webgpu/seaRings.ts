/**
 * The WebGPU Ocean's grid: the WebGL Ocean's horizon rings (src/render/horizonGrid.ts, its geometry
 * and its per-frame placement RingFrames, used as they are), square rings of cells round the
 * camera, each twice as coarse as the one inside, anchored on fixed world points, and a skirt to
 * the horizon. ringPoint is the TSL twin of shaders/surface/horizonGrid.glsl's horizonGridPoint,
 * which places a vertex; SeaRings holds the uniforms it reads and places them under a camera.
 */
import { Vector2, Vector4, type Camera } from 'three';
import type { UniformNode } from 'three/webgpu';
import { abs, attribute, float, int, max, mod, positionGeometry, select, uniform, uniformArray, vec2, vec4 } from 'three/tsl';
import { RING_COUNT, RingFrames } from '../render/horizonGrid';
import { patchBlendUniforms } from '../layers/patchBlend';
import type { WaveLayer } from '../layers/waveLayer';
import type { FloatNode, IntNode, Vec2Node, Vec4Node } from './nodeTypes';

/** horizonGrid.glsl's SKIRT_LOD: beyond any mip level, so the skirt samples the coarsest (flat, the mean sea). */
const SKIRT_LOD = 1000;

/** horizonGrid.glsl's GridPoint: where a vertex lies on the rest plane. */
export interface RingPoint {
  /** Rest position (x, z) from the eye, metres. */
  fromEye: Vec2Node;
  /** Rest position from the centre of the ring whose frame placed it, metres. */
  fromCentre: Vec2Node;
  /** That ring (the next one out for a vertex on a ring's outer edge). */
  frameRing: IntNode;
  /** Mip level of the finest layer matching the cell size. */
  lod: FloatNode;
  /** The ring whose mesh holds the vertex. */
  ring: IntNode;
}

/** The rings' uniforms for one set of layers, and the per-frame placement that fills them. */
export class SeaRings {
  /** (centre x, centre z from the eye, cell size, mip level) per ring (RingFrames.frames). */
  readonly frames = uniformArray(Array.from({ length: RING_COUNT + 1 }, () => new Vector4()), 'vec4');
  /** (centre_r − centre_{r+1}) / cell_{r+1} per ring (RingFrames.offsets). */
  readonly offsets = uniformArray(Array.from({ length: RING_COUNT + 1 }, () => new Vector2()), 'vec2');
  /** Each ring centre's texture coordinates in each layer, [ring · layers + layer] (RingFrames.uvOrigins). */
  readonly uvOrigins: ReturnType<typeof uniformArray>;
  /** Cells from a ring's centre to its edge. */
  readonly halfRingCells: UniformNode<'float'> = uniform(16);
  /** The largest layer's blend components (kx, kz, φ at the eye, a), patchBlend.ts. */
  readonly patchBlend = uniformArray(Array.from({ length: 3 }, () => new Vector4()), 'vec4');
  private readonly placement = new RingFrames();
  private readonly blend = new Float64Array(12);
  private readonly eye = { x: 0, y: 0, z: 0 };

  constructor(private readonly layers: readonly WaveLayer[]) {
    this.uvOrigins = uniformArray(Array.from({ length: (RING_COUNT + 1) * layers.length }, () => new Vector2()), 'vec2');
  }

  /** Centres the rings under `camera` for a grid of `cellsPerRing` cells a side (before every draw). */
  place(camera: Camera, cellsPerRing: number): void {
    const e = camera.matrixWorld.elements;
    Object.assign(this.eye, { x: e[12], y: e[13], z: e[14] });
    this.placement.update(this.eye.x, this.eye.z, this.eye.y, this.layers, cellsPerRing);
    // After the update: it replaces uvOrigins when the number of layers changes.
    const { frames, offsets, uvOrigins } = this.placement;
    (this.frames.array as Vector4[]).forEach((v, i) => v.fromArray(frames, 4 * i));
    (this.offsets.array as Vector2[]).forEach((v, i) => v.fromArray(offsets, 2 * i));
    (this.uvOrigins.array as Vector2[]).forEach((v, i) => v.fromArray(uvOrigins, 2 * i));
    this.halfRingCells.value = cellsPerRing / 2;
    patchBlendUniforms(this.layers[this.layers.length - 1].frame.size, this.blend, this.eye.x, this.eye.z);
    (this.patchBlend.array as Vector4[]).forEach((v, i) => v.fromArray(this.blend, 4 * i));
  }

  /** horizonGrid.glsl's horizonGridPoint: the grid's `position` is (x, z in cells from the ring centre, ring). */
  point(): RingPoint {
    const ring = int(positionGeometry.z);
    const cells = positionGeometry.xy;
    // On a ring's outer edge: into the next ring's frame (cells twice as large, odd ones onto their even neighbour).
    const onEdge = max(abs(cells.x), abs(cells.y)).equal(this.halfRingCells);
    const edgeCells = (this.offsets.element(ring) as unknown as Vec2Node).add(cells.sub(mod(cells, vec2(2, 2))).mul(0.5));
    const frameRing = select(onEdge, ring.add(1), ring) as unknown as IntNode;
    const frame = this.frames.element(frameRing) as unknown as Vec4Node;
    const farScale = attribute<'float'>('farScale', 'float');
    const metres = (select(onEdge, edgeCells, cells) as unknown as Vec2Node).mul(frame.z.mul(farScale));
    return {
      fromEye: frame.xy.add(metres),
      fromCentre: metres,
      frameRing,
      lod: select(farScale.greaterThan(1), float(SKIRT_LOD), frame.w) as unknown as FloatNode,
      ring,
    };
  }

  /** Texture coordinates of `point` in layer `index` of `size` metres (ocean.vert's vLayerUv). */
  layerUv(point: RingPoint, index: number, size: number): Vec2Node {
    const origin = this.uvOrigins.element(point.frameRing.mul(this.layers.length).add(index)) as unknown as Vec2Node;
    return origin.add(point.fromCentre.div(size));
  }

  /**
   * (centre from the eye, half side) of the ring inside `point`'s, whose square it must not draw
   * again (ocean.vert's vInnerRing; a negative half side for ring 0, which has none).
   */
  innerRing(point: RingPoint): Vec4Node {
    const inner = this.frames.element(select(point.ring.greaterThan(0), point.ring.sub(1), int(0))) as unknown as Vec4Node;
    return select(point.ring.greaterThan(0), vec4(inner.xy, inner.z.mul(this.halfRingCells).mul(1 - 1e-4), 0), vec4(0, 0, -1, 0)) as unknown as Vec4Node;
  }
}

