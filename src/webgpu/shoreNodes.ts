/**
 * The shore on the WebGPU Ocean's surface: TSL twins of the WebGL Ocean's GLSL, each method naming
 * the file and function it mirrors (the formulas' sources are cited there and in the shared JS):
 *   shaders/surface/shoaling.glsl  the seabed's depth under a point (seabedAt), each layer's
 *                                  shoaling factor F_layer(d) (shoalingFactor), the height limited
 *                                  by breaking (breaking) and the foam the shore adds (shoreFoam);
 *   shaders/surface/swash.glsl     the swash level ζ_t the water runs up and down a beach to.
 * They read the same depth map and factor table as the WebGL Ocean's shader and queries, which
 * src/layers/shore.ts makes and owns (SeabedMap's RG32F depths and slopes, the R32F table), and the
 * same uniforms' values, copied each frame by sync(). ShoreVertex gathers what the vertex stage does
 * with them, as shaders/surface/ocean.vert's SEABED blocks do. seabedMapFor makes the depth map
 * as the WebGL Ocean does, with its checks and errors (src/layers/seabed.ts), but for meshes.
 */
import type { Texture } from 'three';
import type { UniformNode } from 'three/webgpu';
import { abs, clamp, float, floor, int, ivec2, log, max, min, mix, select, sign, smoothstep, sqrt, tanh, textureLoad, uniform, varying, vec2, vec3 } from 'three/tsl';
import type { Shore } from '../layers/shore';
import { createSeabedMap, type Seabed, type SeabedMap } from '../layers/seabed';
import { UnsupportedError } from '../parameters/options';
import { BREAKER_INDEX, BREAKING_KNEE, LAND_DROP, SHOALING_DEPTHS, SHOALING_MIN_DEPTH } from '../spectrum/shoaling';
import { MAX_BEACH_SLOPE, SWASH_END, SWASH_FULL } from '../spectrum/swash';
import type { FloatNode, IntNode, Vec2Node, Vec3Node } from './nodeTypes';

/** What the vertex stage hands on over a seabed (ocean.vert's SEABED block after the displacement). */
export interface ShoreVertex {
  /** The surface's height: the swash level plus the shoaled height limited by breaking, m. */
  height: FloatNode;
  /** dη_limited/dη of the breaking limit, for the fragment stage's slopes (ocean.vert's vBreakingSlope). */
  breakingSlope: FloatNode;
  /** The foam the shore adds there, 0..1 (ocean.vert's vShoreFoam). */
  foam: FloatNode;
}

export class ShoreNodes {
  // shoaling.glsl's and swash.glsl's uniforms, with the values of Shore.uniforms (sync()).
  private readonly seabedFrame: UniformNode<'vec4'>;
  private readonly seabedNodes: UniformNode<'vec2'>;
  private readonly seabedOutsideDepth: UniformNode<'float'> = uniform(0);
  private readonly shoalingDepths: UniformNode<'vec3'>;
  private readonly breakerDepth: UniformNode<'float'> = uniform(1);
  private readonly swashSea: UniformNode<'vec2'>;
  private readonly seabed: Texture;
  private readonly table: Texture;

  /**
   * Nodes over `shore`'s depth map and factor table as they are now (a shore with a seabed, prepared
   * for the layers drawn): the Ocean makes its material again when it replaces either.
   */
  constructor(private readonly shore: Shore) {
    const values = shore.uniforms;
    if (values.tSeabed.value === null || values.tShoaling.value === null) throw new Error('ShoreNodes: the shore has no seabed or was not prepared');
    // The Shore changes these vectors in place: the nodes hold the same objects.
    this.seabedFrame = uniform(values.seabedFrame.value);
    this.seabedNodes = uniform(values.seabedNodes.value);
    this.shoalingDepths = uniform(values.shoalingDepths.value);
    this.swashSea = uniform(values.swashSea.value);
    this.seabed = values.tSeabed.value;
    this.table = values.tShoaling.value;
    this.sync();
  }

  /** Copies the shore's numbers (the depth outside the map, the breaker depth), which it replaces rather than changes in place. */
  sync(): void {
    const values = this.shore.uniforms;
    this.seabedOutsideDepth.value = values.seabedOutsideDepth.value;
    this.breakerDepth.value = values.breakerDepth.value;
  }

  /**
   * shoaling.glsl's seabedAt: (depth m, slope |∇d|) under the point `fromEye` (metres from the eye),
   * bilinear between the map's nodes, the `depth` option and a flat bottom outside the map.
   */
  seabedAt(fromEye: Vec2Node): Vec2Node {
    const node = this.seabedFrame.xy.add(fromEye.mul(this.seabedFrame.zw));
    const last = this.seabedNodes.sub(1);
    const outside = node.x.lessThan(0).or(node.y.lessThan(0)).or(node.x.greaterThan(last.x)).or(node.y.greaterThan(last.y));
    // Clamped to the map also where `outside` drops it: no fetch leaves the texture.
    const corner = clamp(floor(node), vec2(0, 0), this.seabedNodes.sub(2));
    const cell = ivec2(corner);
    const f = node.sub(corner);
    const at = (dx: number, dz: number): Vec2Node => textureLoad(this.seabed, cell.add(ivec2(dx, dz))).xy;
    const inside = mix(mix(at(0, 0), at(1, 0), f.x), mix(at(0, 1), at(1, 1), f.x), f.y);
    return select(outside, vec2(this.seabedOutsideDepth, 0), inside);
  }

  /**
   * shoaling.glsl's shoalingFactor: F of layer `layer` at depth d, linear in log d between the
   * table's entries, its first entry for d ≤ SHOALING_MIN_DEPTH, 1 from the deepest tabulated on.
   */
  shoalingFactor(layer: number, depth: FloatNode): FloatNode {
    const position = select(depth.lessThanEqual(SHOALING_MIN_DEPTH), float(0), log(max(depth, SHOALING_MIN_DEPTH)).sub(this.shoalingDepths.x).mul(this.shoalingDepths.y));
    const below = min(floor(position), SHOALING_DEPTHS - 2);
    const j = int(below);
    const f = position.sub(below);
    const entry = (at: IntNode): FloatNode => textureLoad(this.table, ivec2(at, layer)).x;
    return select(depth.greaterThanEqual(this.shoalingDepths.z), float(1), mix(entry(j), entry(j.add(1)), f));
  }

  /**
   * shoaling.glsl's breaking: the height η limited to ±0.39·d (McCowan), softly, unchanged up to the
   * knee and then bent by tanh towards the limit; over land (d ≤ 0) at max(d, −LAND_DROP).
   * (limited η, dη_limited/dη, how far past the knee 0..1: the surf).
   */
  breaking(height: FloatNode, depth: FloatNode): Vec3Node {
    const limit = depth.mul(0.5 * BREAKER_INDEX);
    const knee = limit.mul(BREAKING_KNEE);
    const size = abs(height);
    // The bend's width, kept above 0 where a branch below drops it (d ≤ 0).
    const bend = max(limit.sub(knee), 1e-30);
    // tanh of a large argument overflows in some implementations: 1 from 10 on in float32 (as the GLSL).
    const t = tanh(min(size.sub(knee).div(bend), 10));
    const bent = vec3(sign(height).mul(knee.add(bend.mul(t))), float(1).sub(t.mul(t)), t);
    const broken = select(size.lessThanEqual(knee), vec3(height, 1, 0), bent);
    return select(depth.lessThanEqual(0), vec3(max(depth, -LAND_DROP), 0, 0), broken);
  }

  /**
   * shoaling.glsl's shoreFoam: the surf where a wave breaks (`surf`, from breaking()) and a band
   * along the shoreline over the surf zone, out to where the sea's significant wave breaks.
   */
  shoreFoam(depth: FloatNode, surf: FloatNode): FloatNode {
    const band = float(1).sub(smoothstep(0, this.breakerDepth, depth));
    return select(depth.lessThanEqual(0), float(0), clamp(surf.mul(0.6).add(band.mul(band).mul(0.3)), 0, 1));
  }

  /**
   * swash.glsl's swashLevel: ζ_t at depth d (m) on a bottom of slope β where the sea's elevation
   * before shoaling is `deepHeight` (Stockdon et al. 2006's setup and swash, faded out with depth).
   */
  swashLevel(deepHeight: FloatNode, depth: FloatNode, slope: FloatNode): FloatNode {
    const beta = min(abs(slope), MAX_BEACH_SLOPE);
    const setup = beta.mul(0.35).mul(this.swashSea.x);
    const swash = this.swashSea.x.mul(sqrt(beta.mul(beta).mul(0.563).add(0.004)));
    const level = setup.add(swash.div(max(this.swashSea.y, 1e-30)).mul(deepHeight));
    const faded = level.mul(float(1).sub(smoothstep(swash.mul(SWASH_FULL), swash.mul(SWASH_END), depth)));
    return select(this.swashSea.x.equal(0), float(0), faded);
  }

  /**
   * ocean.vert's SEABED block after the displacement: breaking is limited by the water column under
   * the surface point, where the rest point `fromEye` moved to (by `chopped`, λ·(Dx, Dz)), the depth
   * there raised by the swash level, on which the waves ride. `shoaledHeight` is Σ F_layer·h, and
   * `deepHeight` Σ h, the sea's height before shoaling, which the swash follows.
   */
  vertex(fromEye: Vec2Node, chopped: Vec2Node, shoaledHeight: FloatNode, deepHeight: FloatNode): ShoreVertex {
    const column = this.seabedAt(fromEye.add(chopped)).toVar();
    const swash = this.swashLevel(deepHeight, column.x, column.y).toVar();
    const columnDepth = column.x.add(swash).toVar();
    const broken = this.breaking(shoaledHeight, columnDepth).toVar();
    return { height: swash.add(broken.x), breakingSlope: varying(broken.y), foam: varying(this.shoreFoam(columnDepth, broken.z)) };
  }
}

/**
 * The depth map of a seabed given as a function or a heightfield, checked as the WebGL Ocean checks
 * it (a ParameterError naming what is wrong). Meshes are drawn from above into the map by the WebGL
 * Ocean's WebGLRenderer (shaders/seabed/depthMap.*) and read back at once; WebGPURenderer reads a
 * target back only asynchronously (readRenderTargetPixelsAsync), so setSeabed could not return
 * with the map: they throw an UnsupportedError that says what to give instead.
 */
export function seabedMapFor(seabed: Seabed): SeabedMap {
  if (seabed !== null && typeof seabed === 'object' && 'meshes' in seabed) {
    throw new UnsupportedError(
      'seabed.meshes',
      'three-fft-ocean/webgpu does not draw meshes into a seabed depth map yet; give the seabed as { depthAt(x, z), bounds } or a heightfield { depths, width, height, bounds }, or use the WebGL Ocean (three-fft-ocean) for meshes',
    );
  }
  return createSeabedMap(seabed, null);
}
