/**
 * The sea's vertices read back from its real vertex shader: the horizon grid drawn as points with
 * a material compiled with CAPTURE_POSITIONS (shaders/surface/ocean.vert), one float texel per
 * vertex. Used by the ocean page's geometry check and the seabed page's capture.
 */
import { FloatType, Points, RGBAFormat, Scene, WebGLRenderTarget, type BufferGeometry, type Camera, type WebGLRenderer } from 'three';
import type { OceanMaterial } from '../../../src/render/oceanMaterial';

/** Width of the capture target, in vertices; its height is as many rows as the grid needs. */
const CAPTURE_WIDTH = 1024;

/**
 * Each vertex of `geometry` drawn by `material` (CAPTURE_POSITIONS, its other uniforms bound by the
 * caller) from `camera`: the displaced position from the eye with the shore's foam coverage there
 * (x, y, z, foam; foam 0 without a seabed) and the rest point from
 * the eye with its mip level and ring (x, z, lod, ring), four floats a vertex. Frees the material.
 */
export function captureVertices(
  renderer: WebGLRenderer,
  camera: Camera,
  geometry: BufferGeometry,
  material: OceanMaterial,
): { displaced: Float32Array; rest: Float32Array; width: number } {
  const height = Math.ceil(geometry.getAttribute('position').count / CAPTURE_WIDTH);
  material.uniforms.captureWidth.value = CAPTURE_WIDTH;
  material.uniforms.captureHeight.value = height;
  const points = new Points(geometry, material);
  points.frustumCulled = false;
  const captureScene = new Scene().add(points);
  const target = new WebGLRenderTarget(CAPTURE_WIDTH, height, { type: FloatType, format: RGBAFormat, depthBuffer: false });
  const read = (rest: boolean): Float32Array => {
    material.uniforms.captureRestPoint.value = rest;
    renderer.setRenderTarget(target);
    renderer.setClearColor(0x000000, 0);
    renderer.clear();
    renderer.render(captureScene, camera);
    const pixels = new Float32Array(4 * CAPTURE_WIDTH * height);
    renderer.readRenderTargetPixels(target, 0, 0, CAPTURE_WIDTH, height, pixels);
    renderer.setRenderTarget(null);
    return pixels;
  };
  const displaced = read(false);
  const rest = read(true);
  target.dispose();
  material.dispose();
  return { displaced, rest, width: CAPTURE_WIDTH };
}
