/**
 * Test page for the sea's light (src/render/seaLighting.ts, shaders/surface/seaLighting.glsl): a
 * whole Ocean on the GPU path at a quality level's grid and render scale, seen from a camera the
 * test places, rendered once (ACES, sRGB, as the app) and read back as 8-bit pixels; or the same
 * view rendered at k× the size and box-averaged k×k down (a supersampled reference).
 */
import { FloatType, Vector3, WebGLRenderTarget } from 'three';
import { Ocean } from '../../../src/ocean';
import { DEFAULT_PARAMETERS } from '../../../src/parameters/parameters';
import { DEFAULT_SHADING, type ShadingMode } from '../../../src/parameters/sceneOptions';
import { QUALITY_STEPS, simulationAtQuality, type QualityLevel } from '../../../src/runtime/adaptiveQuality';
import { fitFarPlane } from '../../../src/runtime/farPlane';
import { pictureRenderer } from '../shared/pictureRenderer';
import { SceneOutput } from '../../../src/render/sceneOutput';

export interface ViewRequest {
  windSpeed: number;
  quality: QualityLevel;
  /** Picture size in CSS pixels, before the level's render scale. */
  width: number;
  height: number;
  /** Rendered this many times larger in each direction and box-averaged back (1: as it is). */
  supersample?: number;
  /** Camera height (m), the angle it looks below the horizon (°) and its azimuth from +x towards +z (°). */
  eyeHeight: number;
  pitch: number;
  yaw: number;
  fov: number;
  sunElevation: number;
  sunAzimuth: number;
  /** SunOptions.cloudCover, 0 clear … 1 overcast (0 when left out). */
  cloudCover?: number;
  time: number;
  /** Keep a PNG of the picture (for looking at it). */
  png?: boolean;
  /** Linear radiance (no tone mapping) from a float target instead of the 8-bit picture. */
  linear?: boolean;
  /** Draw multisampled where the level has MSAA (QualityStep.msaa), through SceneOutput as the app does. */
  msaa?: boolean;
  /** False: the sun's light on the water (glint, foam, crests) left out, the sky's reflection kept. */
  sunlit?: boolean;
  /**
   * False: the slopes the mip levels filter out of the normal are left out of the light
   * (seaLighting.ts' per-level variances set to 0; the slopes finer than the grid stay), the
   * reference the flicker test compares with.
   */
  filteredSlopes?: boolean;

  /** ShadingOptions.scatterColor, linear RGB (DEFAULT_SHADING's when left out). */
  scatterColor?: [number, number, number];
  /** SimulationParameters.foamAmount (1 when left out; 0 turns the foam off). */
  foamAmount?: number;
  /** ShadingOptions.shadingMode ('full' when left out); 'height' shows each pixel's height. */
  shadingMode?: ShadingMode;
}

export interface ViewResult {
  /**
   * RGBA, rows from the top, width × height (the request's size, whatever the scale): 8-bit sRGB,
   * or linear radiance when asked for.
   */
  pixels: number[];
  width: number;
  height: number;
  png: string | null;
}

const { canvas, renderer, scene, camera } = pictureRenderer();
const output = new SceneOutput(renderer);
let ocean: Ocean | null = null;
let built = '';

function render(request: ViewRequest): ViewResult {
  const step = QUALITY_STEPS[request.quality];
  const grid = simulationAtQuality(DEFAULT_PARAMETERS, step);
  const foamAmount = request.foamAmount ?? 1;
  const key = JSON.stringify([request.windSpeed, foamAmount, grid]);
  if (key !== built) {
    ocean?.removeFromParent();
    ocean?.dispose();
    ocean = new Ocean(renderer, { windSpeed: request.windSpeed, foamAmount, seed: 5, path: 'gpu', worker: false, ...grid });
    scene.add(ocean);
    built = key;
  }
  const o = ocean!;
  o.surface.fewestCellsPerRing = step.fewestGridCells;
  o.setSun({ elevation: request.sunElevation, azimuth: request.sunAzimuth, cloudCover: request.cloudCover ?? 0 });
  o.setShading({ scatterColor: request.scatterColor ?? DEFAULT_SHADING.scatterColor, shadingMode: request.shadingMode ?? 'full' });
  const k = request.supersample ?? 1;
  // The level's render scale as the app applies it (applyQuality.ts), times the supersampling.
  const scale = step.renderScale * k;
  renderer.setPixelRatio(1);
  const [w, h] = [Math.round(request.width * scale), Math.round(request.height * scale)];
  renderer.setSize(w, h, false);
  camera.fov = request.fov;
  camera.aspect = w / h;
  camera.position.set(0, request.eyeHeight, 0);
  const pitch = (request.pitch * Math.PI) / 180;
  const yaw = (request.yaw * Math.PI) / 180;
  camera.lookAt(new Vector3(Math.cos(pitch) * Math.cos(yaw), request.eyeHeight - Math.sin(pitch), Math.cos(pitch) * Math.sin(yaw)));
  camera.updateMatrixWorld();
  fitFarPlane(camera, o);
  o.update(request.time, camera);
  const sunColor = o.surface.material.uniforms.sunColor.value;
  const sun = sunColor.clone();
  if (request.sunlit === false) sunColor.setRGB(0, 0, 0);
  // The lighting's uniforms are set as the layers are bound, before each draw (bindLayers): the
  // per-level variances are zeroed after that, for this render only.
  const material = o.surface.material;
  const bindLayers = material.bindLayers;
  if (request.filteredSlopes === false) {
    material.bindLayers = (...args) => {
      bindLayers.apply(material, args);
      material.uniforms.layerFilteredSlopes.value = (material.uniforms.layerFilteredSlopes.value as number[]).map(() => 0);
    };
  }
  let raw: Uint8Array | Float32Array;
  if (request.linear) {
    // Into a float target three.js applies no tone mapping and no output colour space.
    const target = new WebGLRenderTarget(w, h, { type: FloatType });
    renderer.setRenderTarget(target);
    renderer.render(scene, camera);
    raw = new Float32Array(4 * w * h);
    renderer.readRenderTargetPixels(target, 0, 0, w, h, raw);
    renderer.setRenderTarget(null);
    target.dispose();
  } else {
    output.msaa = request.msaa === true && step.msaa;
    output.render(scene, camera);
    const gl = renderer.getContext();
    raw = new Uint8Array(4 * w * h);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, raw);
  }
  sunColor.copy(sun);
  material.bindLayers = bindLayers;
  const png = request.png ? canvas.toDataURL('image/png') : null;
  return { pixels: resample(raw, w, h, request.width, request.height), width: request.width, height: request.height, png };
}

/**
 * The picture read bottom-up at w × h, as `width` × `height` rows from the top: box-averaged when
 * it is an exact multiple (supersampling), else the nearest pixel (a level's render scale, which
 * the app shows stretched to the canvas the same way).
 */
function resample(raw: Uint8Array | Float32Array, w: number, h: number, width: number, height: number): number[] {
  const out: number[] = new Array(4 * width * height).fill(0);
  const k = w / width;
  const whole = Number.isInteger(k) && h === k * height;
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      for (let c = 0; c < 4; c++) {
        let sum = 0;
        if (whole) {
          for (let j = 0; j < k; j++) for (let i = 0; i < k; i++) sum += raw[4 * ((h - 1 - (y * k + j)) * w + x * k + i) + c];
          sum /= k * k;
        } else {
          const sx = Math.min(w - 1, Math.floor(((x + 0.5) * w) / width));
          const sy = Math.min(h - 1, Math.floor(((y + 0.5) * h) / height));
          sum = raw[4 * ((h - 1 - sy) * w + sx) + c];
        }
        out[4 * (y * width + x) + c] = sum;
      }
    }
  }
  return out;
}

const harness = { render };
declare global {
  interface Window {
    lightingHarness: typeof harness;
  }
}
window.lightingHarness = harness;
document.title = 'ready';
