/**
 * The sky behind everything: SkyEnvironment's cube seen from the eye, as a mesh drawn after the
 * opaque scene at the far plane (shaders/sky/background.vert), so it only shades the pixels that
 * nothing else covered. (A scene.background would be drawn first under every pixel, then mostly
 * hidden by the sea; under SwiftShader that cost a fifth of the frame.)
 *
 * It is one draw call of a triangle that covers the screen (in clip space: no transform, frustum
 * culling off); each corner gets the world direction of its view ray from the camera's inverse
 * projection and rotation, set before each draw. Tone mapped like the sea, except a loaded face set, which
 * is already display-referred (LDR sRGB) and shows as it is; dithered into an 8-bit picture. Owns its geometry and material;
 * dispose() frees them (not the SkyEnvironment).
 */
import { BufferGeometry, Float32BufferAttribute, Matrix3, Matrix4, Mesh, ShaderMaterial, UnsignedByteType, Vector3, type Camera, type Scene, type WebGLRenderer } from 'three';
import { shaderSource } from '../shaderSource';
import { BACKGROUND_WATER } from './seaSurfaceMaterial';
import type { SkyEnvironment } from './skyEnvironment';

export { BACKGROUND_WATER } from './seaSurfaceMaterial';

/** Drawn after opaque objects with a lower renderOrder (three.js sorts opaque objects by it first). */
const SKY_RENDER_ORDER = 1000;

export class SkyBackground extends Mesh<BufferGeometry, ShaderMaterial> {
  /**
   * @param underWater optional: where the deep water shows instead of the sky (BACKGROUND_WATER,
   *   set by the OceanSurface before each frame), and its radiance (the sea's scatterColor)
   */
  constructor(
    private readonly sky: SkyEnvironment,
    underWater: { backgroundWater: { value: number }; deepWater: { value: Vector3 } } = { backgroundWater: { value: BACKGROUND_WATER.none }, deepWater: { value: new Vector3() } },
  ) {
    const material = new ShaderMaterial({
      name: 'skyBackground',
      vertexShader: shaderSource('sky/background.vert'),
      fragmentShader: shaderSource('sky/background.frag'),
      uniforms: {
        skyEnvironment: sky.environment,
        skyProjectionInverse: { value: new Matrix4() },
        skyCameraRotation: { value: new Matrix3() },
        farDepth: { value: 1 },
        backgroundWater: underWater.backgroundWater,
        deepWater: underWater.deepWater,
        skyDaylight: sky.skyUniforms.skyDaylight,
        ditherStep: { value: 0 },
      },
      depthWrite: false, // depthTest stays on: LessEqual passes at the far plane where nothing was drawn
    });
    // Clip-space corners of a triangle that covers the screen [−1, 1]².
    const geometry = new BufferGeometry().setAttribute('position', new Float32BufferAttribute([-1, -1, 0, 3, -1, 0, -1, 3, 0], 3));
    super(geometry, material);
    this.name = 'SkyBackground';
    this.frustumCulled = false;
    this.renderOrder = SKY_RENDER_ORDER;
  }

  /**
   * Called by three.js before each render: takes the camera's projection and rotation, and the
   * depth convention of `renderer` (the sky goes at the far plane).
   */
  override onBeforeRender(renderer: WebGLRenderer, _scene: Scene, camera: Camera): void {
    const u = this.material.uniforms;
    // A reversed depth buffer (three's reversedDepthBuffer) has its far plane at depth 0, and
    // passes what is farther only where nothing nearer was drawn: the sky then goes there.
    u.farDepth.value = renderer.state.buffers.depth.getReversed?.() ? 0 : 1;
    u.skyProjectionInverse.value.copy(camera.projectionMatrixInverse);
    u.skyCameraRotation.value.setFromMatrix4(camera.matrixWorld);
    // Dithered where the picture is 8-bit (the canvas, or an 8-bit target such as SceneOutput's):
    // a float target keeps the sky's radiance exact (dither.glsl).
    const target = renderer.getRenderTarget();
    u.ditherStep.value = target === null || target.texture.type === UnsignedByteType ? 1 / 255 : 0;
    const toneMapped = !this.sky.usingFaces;
    if (this.material.toneMapped !== toneMapped) {
      this.material.toneMapped = toneMapped;
      this.material.needsUpdate = true;
    }
  }

  dispose(): void {
    this.geometry.dispose();
    this.material.dispose();
  }
}
