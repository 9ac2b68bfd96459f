/**
 * What every GPU pass on WebGL 2 shares (WebGL2Device): one triangle that covers the render target (each fragment
 * is one texel, shaders/fft/fullscreen.vert), GLSL 3 materials with no depth, and a way to run
 * passes without disturbing the caller's renderer state (its render target, and WebXR, which
 * would otherwise draw each pass once per eye).
 */
import { BufferAttribute, BufferGeometry, GLSL3, Mesh, OrthographicCamera, ShaderMaterial, type WebGLRenderer } from 'three';
import { shaderSource } from '../../shaderSource';

export class FullscreenPass {
  private readonly mesh: Mesh;
  // The vertex shader ignores the camera, but three asks it for updateProjectionMatrix() under a
  // reversedDepthBuffer, which a bare Camera lacks.
  private readonly camera = new OrthographicCamera(-1, 1, 1, -1, 0, 1);

  constructor() {
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(new Float32Array([-1, -1, 0, 3, -1, 0, -1, 3, 0]), 3));
    this.mesh = new Mesh(geometry);
    this.mesh.frustumCulled = false;
  }

  /** Draws `material` over the whole current render target. */
  draw(renderer: WebGLRenderer, material: ShaderMaterial): void {
    this.mesh.material = material;
    renderer.render(this.mesh, this.camera);
  }

  dispose(): void {
    this.mesh.geometry.dispose();
  }
}

/** A material for a FullscreenPass: `fragmentShader` is GLSL source (see shaderSource). */
export function fullscreenMaterial(
  fragmentShader: string,
  uniforms: Record<string, { value: unknown }>,
  defines: Record<string, unknown> = {},
): ShaderMaterial {
  return new ShaderMaterial({
    glslVersion: GLSL3,
    defines,
    vertexShader: shaderSource('fft/fullscreen.vert'),
    fragmentShader,
    uniforms,
    depthTest: false,
    depthWrite: false,
  });
}

/** Runs `passes` with WebXR off, then gives the renderer back its render target and XR state. */
export function runPasses(renderer: WebGLRenderer, passes: () => void): void {
  const previousTarget = renderer.getRenderTarget();
  const previousXr = renderer.xr.enabled;
  renderer.xr.enabled = false;
  try {
    passes();
  } finally {
    renderer.xr.enabled = previousXr;
    renderer.setRenderTarget(previousTarget);
  }
}
