/**
 * The WebGPU Ocean's surface as a TSL NodeMaterial: the same formulas as the WebGL Ocean's GLSL
 * (each node cites the GLSL file it follows), written once more in TSL because WebGPURenderer does
 * not run ShaderMaterial (three.js #26925). TSL compiles to WGSL on the WebGPU backend and to GLSL
 * on WebGPURenderer's WebGL2 backend.
 *
 *   vertex:   P = x0 + Σ (λ·Dx, h, λ·Dz) over the cascades at the rest point x0, the largest one as
 *             cos θ·P(x0) + sin θ·P(x0 + o) (shaders/surface/ocean.vert, src/layers/patchBlend.ts)
 *   fragment: the normal from the summed slopes (shaders/surface/choppyNormal.glsl), then
 *             ocean.frag's c = R·c_sky + (1 − R)·c_water + K·c_caustic + glint + crest glow, R the
 *             exact Fresnel reflectance, c_sky the analytic sky (skyNodes.ts) reflected by the
 *             pixel's unresolved slopes, the glint a Cox–Munk lobe (lightNodes.ts, twins of
 *             seaLighting.glsl, absorption.glsl, caustics.glsl and fresnel.glsl); then the
 *             whitecap foam over it, its streaks and the spray (foamNodes.ts, twins of foam.glsl,
 *             foamCells.glsl, foamStreaks.glsl and spray.glsl)
 */
import { BackSide, type Texture } from 'three';
import { MeshBasicNodeMaterial, type UniformNode } from 'three/webgpu';
import {
  abs,
  Discard,
  cameraPosition,
  cameraProjectionMatrix,
  cameraViewMatrix,
  cos,
  cross,
  clamp,
  dFdx,
  dFdy,
  Fn,
  float,
  fwidth,
  max,
  mix,
  normalize,
  positionGeometry,
  positionWorld,
  refract,
  select,
  sin,
  texture,
  varying,
  vec2,
  vec3,
  vec4,
} from 'three/tsl';
import { COPY_OFFSET } from '../layers/patchBlend';
import { finestTexel } from '../render/horizonGrid';
import type { SeaRings } from './seaRings';
import type { WaveLayer } from '../layers/waveLayer';
import { SEA_SUN_COLOR, VIEW_DEPTH, type SeaLightingValues } from '../render/seaLighting';
import { analyticSkyRadiance, type SkyUniforms } from './skyNodes';
import { causticBrightness, crestGlow, facingEye, filteredSkyReflection, footprintLevel, subPixelSlopeVariance, sunGlint, throughWater } from './lightNodes';
import type { FloatNode, Vec2Node, Vec3Node, Vec4Node } from './nodeTypes';
import type { BeaufortAppearance } from '../render/beaufortAppearance';
import {
  blendedFoam,
  FOAM_MEAN_BUBBLES,
  FOAM_VISIBLE,
  foamCellOpacity,
  foamOpacity,
  foamPattern,
  foamPatternShown,
  foamRadiance,
  restFootprint,
  streakedFoam,
  streakedMeanFoam,
  streakPatternPoint,
  throughSpray,
  type FoamShading,
} from './foamNodes';

/** The uniforms the surface and the sky share, which the Ocean sets. */
export interface SeaUniforms {
  /** λ, the choppiness. */
  choppiness: UniformNode<'float'>;
  /** n_w, water's refractive index. */
  ior: UniformNode<'float'>;
  /** Linear RGB of the light deep water scatters back. */
  scatterColor: UniformNode<'vec3'>;
  /** Beer–Lambert absorption σ per channel, 1/m. */
  absorption: UniformNode<'vec3'>;
  /** The caustics' exponent p and linear colour. */
  causticPower: UniformNode<'float'>;
  causticColor: UniformNode<'vec3'>;
  /** The analytic sky and its sun (skyNodes.ts). */
  sky: SkyUniforms;
}

/** The whitecap foam the surface draws. */
export interface SeaFoam {
  /** The coverage over the largest layer's patch, as many texels as that layer's fields (whitecapFoam.ts). */
  coverage: Texture;
  /** The pattern's textures and origin (foamNodes.ts). */
  shading: FoamShading;
  /** The wind's streaks and spray (beaufortAppearance.ts). */
  look: BeaufortAppearance;
}

/**
 * θ and its gradient of the largest layer's blend at the rest point `fromEye` (metres from the eye),
 * (cos θ, sin θ, ∂θ/∂x, ∂θ/∂z): waveLayers.glsl's blendWeights, over the rings' patchBlend.
 */
function blendWeights(rings: SeaRings, fromEye: Vec2Node): Vec4Node {
  let theta: FloatNode = float(0);
  let gradient: Vec2Node = vec2(0, 0);
  for (let j = 0; j < 3; j++) {
    const component = rings.patchBlend.element(j) as unknown as Vec4Node;
    const phase = fromEye.dot(component.xy).add(component.z);
    theta = theta.add(sin(phase).mul(component.w));
    gradient = gradient.add(component.xy.mul(cos(phase).mul(component.w)));
  }
  return vec4(cos(theta), sin(theta), gradient);
}

/**
 * The surface's material over `layers` (the periodic FFT cascades, the largest last as
 * orderLayers gives them, with the textures they hold now), on the grid `rings` places.
 */
export function seaMaterial(layers: readonly WaveLayer[], uniforms: SeaUniforms, lighting: SeaLightingValues, rings: SeaRings, foam: SeaFoam): MeshBasicNodeMaterial {
  const material = new MeshBasicNodeMaterial();
  material.name = 'OceanWebGPU';
  const point = rings.point();
  const largest = layers.length - 1;
  const copyOffset = vec2(COPY_OFFSET[0], COPY_OFFSET[1]);
  const blend = blendWeights(rings, point.fromEye);
  const finest = finestTexel(layers);

  // Vertex (ocean.vert): the displacement summed at the ring's mip level, whole levels apart between layers.
  let displacement: Vec4Node = vec4(0, 0, 0, 0);
  let blendSlope: Vec2Node = vec2(0, 0);
  // The foam coverage at the largest layer's mip level (ocean.vert's vFoam), for the far sea.
  let vertexFoam: FloatNode = float(0);
  const uvs = layers.map((layer, i) => {
    const uv = rings.layerUv(point, i, layer.frame.size);
    const level = point.lod.add(Math.round(Math.log2(finest / (layer.frame.size / layer.frame.resolution))));
    const map = layer.textures.displacement.value as Texture;
    const first = texture(map, uv).level(level);
    if (i !== largest) {
      displacement = displacement.add(first);
      return varying(uv);
    }
    const copy = texture(map, uv.add(copyOffset)).level(level);
    displacement = displacement.add(first.mul(blend.x)).add(copy.mul(blend.y));
    // The blend's own change adds (−sin θ·h1 + cos θ·h2)·∇θ to the height's slope (ocean.vert's vBlendSlope).
    blendSlope = blend.zw.mul(copy.y.mul(blend.x).sub(first.y.mul(blend.y)));
    vertexFoam = blendedFoam(blend.xy, texture(foam.coverage, uv).level(level).r, texture(foam.coverage, uv.add(copyOffset)).level(level).r);
    return varying(uv);
  });
  const choppiness = uniforms.choppiness;
  // World coordinates: the eye's plus the rest point and displacement from it.
  material.positionNode = vec3(point.fromEye.x.add(displacement.x.mul(choppiness)), displacement.y, point.fromEye.y.add(displacement.z.mul(choppiness))).add(vec3(cameraPosition.x, 0, cameraPosition.z));
  // Per vertex, as the WebGL Ocean: λ·∂Dx/∂z (a second-order part of the normal) and the blend's slope.
  const crossDerivative = varying(displacement.w.mul(choppiness));
  const blendSlopeAtFragment = varying(blendSlope);
  const blendAtFragment = varying(blend.xy);
  const restAtFragment = varying(point.fromEye);
  const innerRing = varying(rings.innerRing(point));
  const foamAtVertex = varying(vertexFoam);
  const { look } = foam;
  const largestSize = layers[largest].frame.size;

  // Fragment: Σ (∂h/∂x, ∂h/∂z, ∂Dx/∂x, ∂Dz/∂z), mipmapped by the pixel's footprint (ocean.frag).
  let derivatives: Vec4Node = vec4(0, 0, 0, 0);
  layers.forEach((layer, i) => {
    const map = layer.textures.derivatives.value as Texture;
    if (i !== largest) {
      derivatives = derivatives.add(texture(map, uvs[i]));
      return;
    }
    derivatives = derivatives.add(texture(map, uvs[i]).mul(blendAtFragment.x)).add(texture(map, uvs[i].add(copyOffset)).mul(blendAtFragment.y));
  });
  material.colorNode = Fn(() => {
    // The slopes this pixel's normal does not show (seaLighting.glsl) and the foam's pattern (foam.glsl),
    // from the rest point's change to the next pixel: taken first, as ocean.frag does, since
    // derivatives need the whole 2×2 quad.
    const restPerPixelX = dFdx(restAtFragment).toVar();
    const restPerPixelY = dFdy(restAtFragment).toVar();
    const slopeVariance = subPixelSlopeVariance(lighting, footprintLevel(restPerPixelX, restPerPixelY)).toVar();
    const foamRestPoint = streakPatternPoint(restAtFragment, look).add(foam.shading.origin).toVar();
    const foamDetail = foamPattern(foam.shading, foamRestPoint).toVar();
    const foamDetailPerPixel = fwidth(foamDetail.x).toVar();
    // Each point of the rest plane is drawn by one ring: a ring drops its overlap with the one inside (ocean.frag).
    const fromInner = abs(restAtFragment.sub(innerRing.xy));
    Discard(max(fromInner.x, fromInner.y).lessThan(innerRing.z));
    const slopes = derivatives.xy.add(blendSlopeAtFragment);
    const stretch = derivatives.zw.mul(choppiness);
    // choppyNormal.glsl: ∂P/∂z0 × ∂P/∂x0 with ∂P/∂x0 = (1 + λ∂Dx/∂x, ∂h/∂x, λ∂Dx/∂z), ∂P/∂z0 = (λ∂Dx/∂z, ∂h/∂z, 1 + λ∂Dz/∂z).
    const alongX = vec3(stretch.x.add(1), slopes.x, crossDerivative);
    const alongZ = vec3(crossDerivative, slopes.y, stretch.y.add(1));
    const view = normalize(positionWorld.sub(cameraPosition));
    const normal = facingEye(view, normalize(cross(alongZ, alongX))).toVar();
    const [air, water] = [float(1), uniforms.ior];
    const sky = uniforms.sky;
    const skyRadiance = (direction: Vec3Node) => analyticSkyRadiance(sky, direction);
    // ocean.frag's full shading, without what is not drawn here yet (scene reflections and refractions).
    const reflection = filteredSkyReflection(view, normal, slopeVariance, air, water, skyRadiance);
    const reflectance = reflection.reflectance.toVar();
    const refracted = refract(view, normal, air.div(water));
    const deepWater = uniforms.scatterColor.mul(sky.daylight);
    const below = throughWater(skyRadiance(refracted), refracted, uniforms.absorption, deepWater, VIEW_DEPTH);
    const caustic = causticBrightness(normal, sky.sunDirection, water.div(air), uniforms.causticPower);
    const sunLight = vec3(...SEA_SUN_COLOR).mul(sky.sunVisibility);
    const glint = sunLight.mul(sunGlint(view, normal, sky.sunDirection, slopeVariance, air, water));
    const crest = crestGlow(view, normal, sky.sunDirection, positionWorld.y, lighting.heightRms, reflectance, sunLight, uniforms.scatterColor);
    const colour = reflection.radiance.mul(reflectance).add(below.mul(float(1).sub(reflectance))).add(uniforms.causticColor.mul(caustic.mul(sky.sunVisibility))).add(glint).add(crest);
    // The foam coverage (ocean.frag): where its pattern shows, read for each pixel; farther, the vertex stage's.
    const foamShown = foamPatternShown(restFootprint(restPerPixelX, restPerPixelY)).toVar();
    const largestUv = uvs[largest];
    const pixelFoam = blendedFoam(blendAtFragment, texture(foam.coverage, largestUv).r, texture(foam.coverage, largestUv.add(copyOffset)).r);
    const foamCoverage = mix(streakedMeanFoam(foamAtVertex, look), streakedFoam(foam.coverage, largestUv, copyOffset, blendAtFragment, largestSize, pixelFoam, look), foamShown).toVar();
    // Where the pattern does not show, whole white cells with the coverage's share (foamCells.glsl).
    const foamTexel = largestSize / (foam.coverage.image as { width: number }).width;
    const far = select(foamShown.lessThan(1), foamCellOpacity(foamCoverage, foamRestPoint, restPerPixelX, restPerPixelY, foamTexel, FOAM_MEAN_BUBBLES), float(0));
    const opacity = select(foamCoverage.greaterThan(FOAM_VISIBLE), foamOpacity(foamCoverage, foamDetail, foamDetailPerPixel, foamShown, far), float(0));
    const foamed = mix(colour, foamRadiance(normal, sky.sunDirection, sunLight, skyRadiance(normal)), clamp(opacity, 0, 1));
    const fromEye = positionWorld.sub(cameraPosition);
    return throughSpray(foamed, fromEye, positionWorld.y, lighting.heightRms, skyRadiance(normalize(vec3(view.x, 0, view.z))), look);
  })();
  return material;
}

/**
 * The sky behind everything: a unit sphere seen from inside, drawn first without depth, at the far
 * plane in every direction from the eye (so any camera's far plane holds it), shaded as the WebGL
 * Ocean's SkyBackground (background.frag, skyNodes.ts).
 */
export function skyMaterial(uniforms: SeaUniforms): MeshBasicNodeMaterial {
  const material = new MeshBasicNodeMaterial({ side: BackSide, depthTest: false, depthWrite: false });
  material.name = 'OceanWebGPUSky';
  const direction = positionGeometry;
  material.vertexNode = Fn(() => {
    const clip = cameraProjectionMatrix.mul(vec4(cameraViewMatrix.mul(vec4(direction, 0)).xyz, 1));
    // Just inside the far plane: z = w would be clipped by rounding.
    return vec4(clip.x, clip.y, clip.w.mul(0.99999), clip.w);
  })();
  // background.frag with backgroundWater 'none', as the WebGL Ocean draws it for an eye above the
  // waves: the environment in every direction (the eye at or under the surface is not drawn here yet).
  material.colorNode = analyticSkyRadiance(uniforms.sky, normalize(varying(direction)));
  return material;
}
