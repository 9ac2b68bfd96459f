/**
 * Test page for the scene's reflection in the sea (src/render/sceneReflection.ts): one Ocean and a
 * red box on a 960×540 renderer, drawn with reflections 'scene' or 'sky', read back as RGBA rows
 * (base64, bottom row first, as readPixels gives them) for reflections.spec.ts.
 */
import { BoxGeometry, Mesh, MeshBasicMaterial, PerspectiveCamera, Scene, Vector3, WebGLRenderer } from 'three';
import { Ocean } from '../../../src/ocean';
import type { Reflections } from '../../../src/parameters/sceneOptions';

export const WIDTH = 960;
export const HEIGHT = 540;

const renderer = new WebGLRenderer({ antialias: false });
renderer.setPixelRatio(1);
renderer.setSize(WIDTH, HEIGHT);
document.body.append(renderer.domElement);
const scene = new Scene();
const camera = new PerspectiveCamera(40, WIDTH / HEIGHT, 0.5, 20000);
const box = new Mesh(new BoxGeometry(1, 1, 1), new MeshBasicMaterial({ color: 0xff0000 }));
scene.add(box);
let ocean: Ocean | null = null;

export type Vec3 = [number, number, number];

export interface View {
  windSpeed: number;
  reflections: Reflections;
  /** The box's centre and size (m). */
  centre: Vec3;
  size: Vec3;
  eye: Vec3;
  target: Vec3;
  t: number;
  /** 'height' draws each sea pixel's height (ocean.frag's height mode, y/heightScale about grey 0.5). */
  shadingMode?: 'full' | 'height';
  heightScale?: number;
  /** Leave the surface out (the sky background stays). */
  hideSurface?: boolean;
  hideBox?: boolean;
}

function pose(view: View): void {
  box.position.set(...view.centre);
  box.scale.set(...view.size);
  box.visible = view.hideBox !== true;
  camera.position.set(...view.eye);
  camera.lookAt(new Vector3(...view.target));
  camera.updateMatrixWorld();
}

/** The ocean of `windSpeed`, made once per wind speed. */
function oceanFor(windSpeed: number): Ocean {
  if (ocean?.parameters.windSpeed === windSpeed) return ocean;
  ocean?.removeFromParent();
  ocean?.dispose();
  ocean = new Ocean(renderer, { windSpeed, resolution: 64, seed: 5, localWaves: false, worker: false });
  scene.add(ocean);
  return ocean;
}

const harness = {
  WIDTH,
  HEIGHT,
  /** Draws `view` and returns its pixels (RGBA, rows from the bottom) as base64. */
  render(view: View): string {
    const sea = oceanFor(view.windSpeed);
    // The refraction is left out: these tests tell the reflection's pixels by what changes with the
    // box, and the box seen through the water (refractions 'scene') would change the sea around it too.
    sea.setShading({ reflections: view.reflections, refractions: 'sky', shadingMode: view.shadingMode ?? 'full' });
    sea.surface.material.uniforms.heightScale.value = view.heightScale ?? 3;
    sea.surface.visible = view.hideSurface !== true;
    pose(view);
    sea.update(view.t, camera);
    renderer.render(scene, camera);
    const gl = renderer.getContext();
    const data = new Uint8Array(4 * WIDTH * HEIGHT);
    gl.readPixels(0, 0, WIDTH, HEIGHT, gl.RGBA, gl.UNSIGNED_BYTE, data);
    let text = '';
    for (let i = 0; i < data.length; i += 0x8000) text += String.fromCharCode(...data.subarray(i, i + 0x8000));
    return btoa(text);
  },
  /** Where world points fall on the canvas, in pixels from its top left (after render's pose). */
  project(view: View, points: Vec3[]): [number, number][] {
    pose(view);
    return points.map((p) => {
      const v = new Vector3(...p).project(camera);
      return [((v.x + 1) / 2) * WIDTH, ((1 - v.y) / 2) * HEIGHT];
    });
  },
  /** The unit ray from the eye through the centre of pixel (x, y) (from the top left). */
  pixelRay(view: View, x: number, y: number): Vec3 {
    pose(view);
    const d = new Vector3(((x + 0.5) / WIDTH) * 2 - 1, 1 - ((y + 0.5) / HEIGHT) * 2, 0.5).unproject(camera).sub(camera.position).normalize();
    return [d.x, d.y, d.z];
  },
  /** The sea's height and upward normal over (x, z) at the time of the last render (Ocean.heightAt, normalAt). */
  surfaceAt(points: [number, number][]): { height: number; normal: Vec3 }[] {
    return points.map(([x, z]) => {
      const n = ocean!.normalAt(x, z);
      return { height: ocean!.heightAt(x, z), normal: [n.x, n.y, n.z] };
    });
  },
  /** The sea's height over (x, z) at time t with this wind (for a box floating at the waterline). */
  heightAt(windSpeed: number, t: number, x: number, z: number): number {
    const sea = oceanFor(windSpeed);
    sea.update(t, camera);
    return sea.heightAt(x, z);
  },
  /**
   * `view` drawn with the box made transparent and writing no depth, once with the one Ocean and
   * once with a second Ocean in the scene too: how many pixels grew redder than without the box,
   * and the GL error after both.
   */
  crowd(view: View): { glError: number; reflectionPixels: { one: number; two: number } } {
    const material = box.material;
    const redder = (a: string, b: string) => {
      const [p, q] = [a, b].map((text) => Uint8Array.from(atob(text), (c) => c.charCodeAt(0)));
      let count = 0;
      for (let i = 0; i < p.length; i += 4) if (p[i] - q[i] > 8 && p[i + 2] - q[i + 2] <= 0) count++;
      return count;
    };
    box.material = new MeshBasicMaterial({ color: 0xff0000, transparent: true, opacity: 0.7, depthWrite: false });
    try {
      const one = redder(harness.render(view), harness.render({ ...view, hideBox: true }));
      const second = new Ocean(renderer, { windSpeed: view.windSpeed, resolution: 32, seed: 9, localWaves: false, worker: false });
      scene.add(second);
      second.update(view.t, camera);
      const two = redder(harness.render(view), harness.render({ ...view, hideBox: true }));
      scene.remove(second);
      second.dispose();
      return { glError: renderer.getContext().getError(), reflectionPixels: { one, two } };
    } finally {
      box.material.dispose();
      box.material = material;
    }
  },
  /** Shading options the Ocean takes or refuses (the ParameterError's name and message). */
  setShading(changes: Record<string, unknown>): { error: string | null; name: string | null; parameter: string | null; reflections: string } {
    const sea = oceanFor(1);
    try {
      sea.setShading(changes);
      return { error: null, name: null, parameter: null, reflections: sea.shading.reflections };
    } catch (error) {
      const e = error as Error & { parameter?: string };
      return { error: e.message, name: e.name, parameter: e.parameter ?? null, reflections: sea.shading.reflections };
    }
  },
};

declare global {
  interface Window {
    reflections: typeof harness;
  }
}
window.reflections = harness;
document.title = 'ready';
