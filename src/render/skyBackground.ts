/**
 * The sky behind everything: SkyEnvironment's cube seen from the eye, as a mesh drawn after the
 * opaque scene at the far plane (shaders/sky/background.vert), so it only shades the pixels that
 * nothing else covered. (A scene.background would be drawn first under every pixel, then mostly
 * hidden by the sea; under SwiftShader that cost a fifth of the frame.)
 *
 * It is one draw call of a unit box that needs no transform: frustum culling is off, and the
 * vertex shader centres it on the eye. Tone mapped like the sea, except a loaded face set, which
 * is already display-referred (LDR sRGB) and shows as it is. Owns its geometry and material;
 * dispose() frees them (not the SkyEnvironment).
 */
import { BackSide, BoxGeometry, Mesh, ShaderMaterial } from 'three';
import { shaderSource } from '../shaderSource';
import type { SkyEnvironment } from './skyEnvironment';

/** Drawn after opaque objects with a lower renderOrder (three.js sorts opaque objects by it first). */
const SKY_RENDER_ORDER = 1000;

export class SkyBackground extends Mesh<BoxGeometry, ShaderMaterial> {
  constructor(private readonly sky: SkyEnvironment) {
    const material = new ShaderMaterial({
      name: 'skyBackground',
      vertexShader: shaderSource('sky/background.vert'),
      fragmentShader: shaderSource('sky/background.frag'),
      uniforms: { skyEnvironment: sky.environment },
      side: BackSide,
      depthWrite: false, // depthTest stays on: LessEqual passes at the far plane where nothing was drawn
    });
    super(new BoxGeometry(1, 1, 1), material);
    this.name = 'SkyBackground';
    this.frustumCulled = false;
    this.renderOrder = SKY_RENDER_ORDER;
  }

  override onBeforeRender(): void {
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
