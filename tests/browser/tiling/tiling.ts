/**
 * Test page for tiling: renders the whole Ocean (simulation, generated sky, surface) as an app
 * would (ACES filmic tone mapping, sRGB output, camera.far beyond ocean.horizonDistance) from a
 * given camera, and hands the frame back as a PNG data URL. tests/browser/tiling/tiling.spec.ts measures
 * the picture's autocorrelation.
 */
import { ACESFilmicToneMapping, PerspectiveCamera, Scene, SRGBColorSpace, Vector3, WebGLRenderer } from 'three';
import { Ocean, type OceanOptions } from '../../../src/ocean';

const query = new URLSearchParams(location.search);
const size = Number(query.get('size') ?? 512);
const renderer = new WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
renderer.setPixelRatio(1);
renderer.setSize(size, size);
renderer.toneMapping = ACESFilmicToneMapping;
renderer.outputColorSpace = SRGBColorSpace;
document.body.appendChild(renderer.domElement);

/** Vertical field of view in degrees (the picture is square). */
const FOV = 55;
const camera = new PerspectiveCamera(FOV, 1, 0.5, 1e5);
let ocean: Ocean | null = null;
let scene = new Scene();

const harness = {
  fov: FOV,
  /**
   * Replaces the sea with a new Ocean of these options; `blend: false` draws the largest cascade
   * once (θ = 0 in src/layers/patchBlend.ts), for the control that shows what the measurement sees
   * without the blend. Without foam: it is drawn with a pattern of its own, repeating every
   * kilometre (shaders/surface/foam.glsl), which is not what the measurement looks for.
   */
  setup(options: OceanOptions, blend = true): void {
    if (ocean) {
      ocean.removeFromParent();
      ocean.dispose();
    }
    ocean = new Ocean(renderer, { path: 'gpu', worker: false, foamAmount: 0, ...options });
    if (!blend) {
      // setEye sets the blend (for the largest layer's size, at the eye) before each draw: amplitudes 0 keep θ = 0.
      const material = ocean.surface.material;
      const setEye = material.setEye.bind(material);
      material.setEye = (x, z) => {
        setEye(x, z);
        for (let j = 3; j < 12; j += 4) material.uniforms.patchBlend.value[j] = 0;
      };
    }
    scene = new Scene().add(ocean);
  },
  /**
   * Renders the sea at time t from `position` looking at `target` (with `up` as the camera's up, for
   * views straight down) and returns the frame as a PNG data URL and the horizon distance.
   */
  render(
    t: number,
    position: [number, number, number],
    target: [number, number, number],
    up: [number, number, number] = [0, 1, 0],
  ): { png: string; horizonDistance: number; far: number } {
    camera.position.fromArray(position);
    camera.up.fromArray(up);
    camera.lookAt(new Vector3().fromArray(target));
    camera.far = 1e5;
    camera.updateProjectionMatrix();
    camera.updateMatrixWorld();
    ocean!.update(t);
    renderer.render(scene, camera); // places the rings, so horizonDistance is known
    camera.far = Math.max(1e5, 1.5 * ocean!.horizonDistance);
    camera.updateProjectionMatrix();
    renderer.render(scene, camera);
    return { png: renderer.domElement.toDataURL('image/png'), horizonDistance: ocean!.horizonDistance, far: camera.far };
  },
};

declare global {
  interface Window {
    tiling: typeof harness;
  }
}
window.tiling = harness;
document.title = 'ready';
