/**
 * Test page for the Beaufort appearance (src/render/beaufortAppearance.ts: foam streaks from force
 * 7, spray from force 9): a whole Ocean on the GPU path with a Beaufort preset, its wind blowing
 * towards +x, under the sky the preset goes with (presetCloudCover), rendered once (ACES, sRGB, as
 * the app) and read back as 8-bit pixels, rows from the top.
 */
import { Vector3 } from 'three';
import { Ocean } from '../../../src/ocean';
import { beaufortPreset, presetCloudCover } from '../../../src/spectrum/presets';
import { fitFarPlane } from '../../../src/runtime/farPlane';
import { pictureRenderer } from '../shared/pictureRenderer';

export interface BeaufortView {
  force: number;
  /** Multiplies the whitecaps made (the foamAmount parameter); 1 when left out. */
  foamAmount?: number;
  width: number;
  height: number;
  /** Camera height (m); looking straight down when pitch is 90 (then the picture's x is +x, the wind's way). */
  eyeHeight: number;
  /** Degrees below the horizon, and azimuth from +x towards +z. */
  pitch: number;
  yaw: number;
  fov: number;
  time: number;
  png?: boolean;
}

export interface BeaufortPicture {
  /** RGBA, rows from the top. */
  pixels: number[];
  png: string | null;
}

const { canvas, renderer, scene, camera } = pictureRenderer();
let ocean: Ocean | null = null;

function render(view: BeaufortView): BeaufortPicture {
  const preset = beaufortPreset(view.force);
  const parameters = { ...preset, windDirection: 0, foamAmount: view.foamAmount ?? 1 };
  if (ocean === null) {
    ocean = new Ocean(renderer, { ...parameters, seed: 7, path: 'gpu', worker: false });
    scene.add(ocean);
  } else {
    ocean.setParameters(parameters);
  }
  ocean.setSun({ elevation: 35, azimuth: 200, cloudCover: presetCloudCover(preset) });
  renderer.setSize(view.width, view.height, false);
  camera.fov = view.fov;
  camera.aspect = view.width / view.height;
  camera.position.set(0, view.eyeHeight, 0);
  const pitch = (view.pitch * Math.PI) / 180;
  const yaw = (view.yaw * Math.PI) / 180;
  // Straight down, the picture's top is −z, so its x is +x.
  camera.up.set(0, view.pitch === 90 ? 0 : 1, view.pitch === 90 ? -1 : 0);
  camera.lookAt(new Vector3(Math.cos(pitch) * Math.cos(yaw), view.eyeHeight - Math.sin(pitch), Math.cos(pitch) * Math.sin(yaw)));
  camera.updateMatrixWorld();
  fitFarPlane(camera, ocean);
  ocean.update(view.time, camera);
  renderer.render(scene, camera);
  const gl = renderer.getContext();
  const raw = new Uint8Array(4 * view.width * view.height);
  gl.readPixels(0, 0, view.width, view.height, gl.RGBA, gl.UNSIGNED_BYTE, raw);
  const pixels: number[] = new Array(raw.length);
  const row = 4 * view.width;
  for (let y = 0; y < view.height; y++) for (let i = 0; i < row; i++) pixels[y * row + i] = raw[(view.height - 1 - y) * row + i];
  return { pixels, png: view.png ? canvas.toDataURL('image/png') : null };
}

const harness = { render };
declare global {
  interface Window {
    beaufortHarness: typeof harness;
  }
}
window.beaufortHarness = harness;
document.title = 'ready';
