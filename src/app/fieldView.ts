/**
 * One inspector tile: a channel of a field texture drawn by the GPU straight from the texture
 * (no readback) with a colour map (shaders/app/fieldView.frag). Owns its material and quad.
 */
import { GLSL3, Mesh, OrthographicCamera, PlaneGeometry, ShaderMaterial, Vector4, type Texture, type WebGLRenderer } from 'three';
import { shaderSource } from '../shaderSource';

export interface FieldViewOptions {
  /** Texture channel shown (0–3); ignored for the Jacobian. */
  channel?: number;
  /** Value shown at mid colour. @defaultValue 0 */
  offset?: number;
  /** Value distance from `offset` shown at full colour. */
  scale: number;
  /** Blue–white–red (signed) rather than grey. */
  diverging?: boolean;
  /** Show log10 of the value (spectra). */
  logarithmic?: boolean;
  /** Put k = 0 in the middle (spectra, stored in FFT order). */
  centred?: boolean;
  /** Compute the Jacobian from derivatives (texture) and displacement (second). */
  jacobian?: { value: Texture | null };
}

export class FieldView {
  private readonly material: ShaderMaterial;
  private readonly quad: Mesh;
  private static readonly camera = new OrthographicCamera();

  constructor(texture: { value: Texture | null }, options: FieldViewOptions) {
    const defines: Record<string, number> = {};
    if (options.logarithmic) defines.LOG_SCALE = 1;
    if (options.jacobian) defines.JACOBIAN = 1;
    this.material = new ShaderMaterial({
      glslVersion: GLSL3,
      defines,
      vertexShader: shaderSource('app/fieldView.vert'),
      fragmentShader: shaderSource('app/fieldView.frag'),
      uniforms: {
        tField: texture,
        tSecond: options.jacobian ?? { value: null },
        channelMask: { value: new Vector4(0, 0, 0, 0).setComponent(options.channel ?? 0, 1) },
        offset: { value: options.offset ?? 0 },
        scale: { value: options.scale },
        diverging: { value: options.diverging ?? false },
        centred: { value: options.centred ?? false },
        zoom: { value: 1 },
      },
      depthTest: false,
      depthWrite: false,
      toneMapped: false,
    });
    this.quad = new Mesh(new PlaneGeometry(2, 2), this.material);
  }

  /** Shows (value − offset) / scale on the colour map's [−1, 1], magnified by zoom (centred views). */
  setScale(scale: number, offset: number, zoom = 1): void {
    this.material.uniforms.scale.value = scale;
    this.material.uniforms.offset.value = offset;
    this.material.uniforms.zoom.value = zoom;
  }

  render(renderer: WebGLRenderer): void {
    renderer.render(this.quad, FieldView.camera);
  }

  dispose(): void {
    this.material.dispose();
    this.quad.geometry.dispose();
  }
}
