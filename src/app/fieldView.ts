/**
 * A view of one channel of a field texture, drawn by the GPU straight from the texture the
 * simulation wrote (no readback): used for the live height map while the app has no rendered sea.
 */
import { GLSL3, Mesh, OrthographicCamera, PlaneGeometry, ShaderMaterial, Vector4, type Texture, type WebGLRenderer } from 'three';
import { shaderSource } from '../shaderSource';

export class FieldView {
  private readonly material: ShaderMaterial;
  private readonly quad: Mesh;
  private readonly camera = new OrthographicCamera();

  constructor(texture: { value: Texture | null }, channel: number, scale: number, diverging: boolean) {
    this.material = new ShaderMaterial({
      glslVersion: GLSL3,
      vertexShader: shaderSource('app/fieldView.vert'),
      fragmentShader: shaderSource('app/fieldView.frag'),
      uniforms: {
        tField: texture,
        channelMask: { value: new Vector4().setComponent(channel, 1) },
        scale: { value: scale },
        diverging: { value: diverging },
      },
      depthTest: false,
      depthWrite: false,
    });
    this.quad = new Mesh(new PlaneGeometry(2, 2), this.material);
  }

  set scale(value: number) {
    this.material.uniforms.scale.value = value;
  }

  render(renderer: WebGLRenderer): void {
    renderer.render(this.quad, this.camera);
  }

  dispose(): void {
    this.material.dispose();
    this.quad.geometry.dispose();
  }
}
