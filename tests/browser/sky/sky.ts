/**
 * Test page for SkyEnvironment: renders small views of its cube (through SkyBackground, the way
 * the app shows it, or through shaders/sky/environmentLookup.glsl, the way materials sample it),
 * or of the analytic sky shader itself, into a float target and hands the Playwright tests pixel
 * summaries in linear RGB.
 */
import {
  BackSide,
  BoxGeometry,
  FloatType,
  GLSL3,
  Mesh,
  PerspectiveCamera,
  Scene,
  ShaderMaterial,
  Vector3,
  WebGLRenderer,
  WebGLRenderTarget,
} from 'three';
import { shaderSource } from '../../../src/shaderSource';
import { ParameterError } from '../../../src/parameters/options';
import { SkyBackground } from '../../../src/render/skyBackground';
import {
  SHIPPED_SKYBOX,
  SkyEnvironment,
  skyboxFaceUrls,
  sunDirectionFromAngles,
  type CubeFaceUrls,
  type SkyEnvironmentOptions,
} from '../../../src/render/skyEnvironment';

const renderer = new WebGLRenderer({ canvas: document.createElement('canvas') });
const camera = new PerspectiveCamera(20, 1, 0.1, 10);
const viewScene = new Scene();
let view = new WebGLRenderTarget(1, 1, { type: FloatType });
let sky: SkyEnvironment | null = null;
/** The current SkyEnvironment's background, made on the first view through it. */
let background: SkyBackground | null = null;

/** A box around the eye showing `radiance(direction)` from the given GLSL. */
function directionBox(glsl: string, uniforms: ShaderMaterial['uniforms']): Mesh<BoxGeometry, ShaderMaterial> {
  const material = new ShaderMaterial({
    glslVersion: GLSL3,
    vertexShader: shaderSource('sky/skyBox.vert'),
    fragmentShader: `${glsl}
in vec3 vDirection;
out vec4 fragColor;
void main() { fragColor = vec4(radiance(normalize(vDirection)), 1.0); }`,
    uniforms,
    side: BackSide,
    depthTest: false,
    depthWrite: false,
  });
  const box = new Mesh(new BoxGeometry(1, 1, 1), material);
  box.frustumCulled = false;
  return box;
}
const lookupBox = directionBox(`${shaderSource('sky/environmentLookup.glsl')}
vec3 radiance(vec3 d) { return environmentRadiance(d); }`, { skyEnvironment: { value: null } });
const analyticBox = directionBox(`${shaderSource('sky/analyticSky.glsl')}
vec3 radiance(vec3 d) { return skyRadiance(d); }`, {});

export type Vec3 = [number, number, number];

/** A size×size view along `direction` (fov in degrees), in linear RGB. */
export interface ViewSummary {
  /** Linear RGB mean over the view. */
  mean: Vec3;
  /** Pixel offset of the brightest pixel (by luminance) from the centre, and its value. */
  brightest: { dx: number; dy: number; value: Vec3 };
  /** Every pixel, RGB, row by row from the bottom. */
  pixels: number[];
  /**
   * With options.blocks = b: RGB means of b×b blocks (row by row from the bottom) of the pixels
   * after options.toneMapKnee's shoulder (see scripts/make-skybox-faces.mjs), if given.
   */
  blocks: number[];
}

export interface ViewOptions {
  /** SkyBackground, environmentLookup.glsl, or the analytic sky shader (not the cube). */
  via?: 'background' | 'lookup' | 'analytic';
  fov?: number;
  size?: number;
  blocks?: number;
  toneMapKnee?: number;
}

function current(): SkyEnvironment {
  if (!sky) throw new Error('call create() first');
  return sky;
}

function render(direction: Vec3, { via = 'background', fov = 20, size = 17, blocks = 0, toneMapKnee }: ViewOptions): ViewSummary {
  const s = current();
  if (view.width !== size) {
    view.dispose();
    view = new WebGLRenderTarget(size, size, { type: FloatType });
  }
  camera.fov = fov;
  camera.updateProjectionMatrix();
  const d = new Vector3(...direction).normalize();
  camera.up.set(0, 1, 0);
  if (Math.abs(d.y) > 0.99) camera.up.set(0, 0, 1);
  camera.position.set(0, 0, 0);
  camera.lookAt(d);

  viewScene.clear();
  if (via === 'background') {
    background ??= new SkyBackground(s);
    viewScene.add(background);
  } else if (via === 'lookup') {
    lookupBox.material.uniforms.skyEnvironment = s.environment;
    viewScene.add(lookupBox);
  } else {
    analyticBox.material.uniforms = { ...s.skyUniforms };
    analyticBox.material.needsUpdate = true;
    viewScene.add(analyticBox);
  }
  renderer.setRenderTarget(view);
  renderer.render(viewScene, camera);
  renderer.setRenderTarget(null);
  const rgba = new Float32Array(4 * size * size);
  renderer.readRenderTargetPixels(view, 0, 0, size, size, rgba);

  const mean: Vec3 = [0, 0, 0];
  const pixels: number[] = [];
  let best = -Infinity;
  let brightest = { dx: 0, dy: 0, value: [0, 0, 0] as Vec3 };
  for (let y = 0; y < size; y++) {
    for (let x = 0; x < size; x++) {
      const i = 4 * (y * size + x);
      const value: Vec3 = [rgba[i], rgba[i + 1], rgba[i + 2]];
      pixels.push(...value);
      for (let c = 0; c < 3; c++) mean[c] += value[c] / (size * size);
      const luminance = 0.2126 * value[0] + 0.7152 * value[1] + 0.0722 * value[2];
      if (luminance > best) {
        best = luminance;
        brightest = { dx: x - (size - 1) / 2, dy: y - (size - 1) / 2, value };
      }
    }
  }
  const blockMeans: number[] = [];
  if (blocks > 0) {
    const knee = toneMapKnee ?? Infinity;
    const toneMap = (x: number) => (x <= knee ? x : knee + (1 - knee) * (1 - Math.exp(-(x - knee) / (1 - knee))));
    const blockSize = size / blocks;
    for (let by = 0; by < blocks; by++) {
      for (let bx = 0; bx < blocks; bx++) {
        for (let c = 0; c < 3; c++) {
          let sum = 0;
          for (let y = by * blockSize; y < (by + 1) * blockSize; y++) {
            for (let x = bx * blockSize; x < (bx + 1) * blockSize; x++) sum += toneMap(pixels[3 * (y * size + x) + c]);
          }
          blockMeans.push(sum / blockSize ** 2);
        }
      }
    }
  }
  return { mean, brightest, pixels, blocks: blockMeans };
}

const skyHarness = {
  shipped: SHIPPED_SKYBOX,
  shippedUrls: skyboxFaceUrls(`/skybox/${SHIPPED_SKYBOX.name}/`),

  create(options?: SkyEnvironmentOptions): void {
    disposeSky();
    sky = new SkyEnvironment(renderer, options);
  },

  /** setCloudCover's error as "<name>: <message>", or null; and the cover in force after. */
  setCloudCover(cloudCover: number): { error: string | null; cloudCover: number } {
    try {
      current().setCloudCover(cloudCover);
      return { error: null, cloudCover: current().cloudCover };
    } catch (error) {
      return { error: error instanceof Error ? `${error.name}: ${error.message}` : String(error), cloudCover: current().cloudCover };
    }
  },

  /** A view of the environment in use along `direction`. */
  view(direction: Vec3, options: ViewOptions = {}): ViewSummary {
    return render(direction, options);
  },

  sunDirection: (): Vec3 => current().sunDirection.toArray() as Vec3,
  directionFromAngles: (elevation: number, azimuth: number): Vec3 => sunDirectionFromAngles(elevation, azimuth).toArray() as Vec3,
  deepWaterColor: (): Vec3 => current().skyUniforms.skyDeepWaterColor.value.toArray() as Vec3,

  /** setSun's error as "<name>: <message>" (e.g. "ParameterError: sunElevation must be …"), or null if it did not throw. */
  setSun(elevation: number, azimuth: number): string | null {
    try {
      current().setSun(elevation, azimuth);
      return null;
    } catch (error) {
      return error instanceof Error ? `${error.name}: ${error.message}` : `non-Error thrown: ${String(error)}`;
    }
  },

  /** What loadFaces did: its rejection message (null if it resolved) and the environment after. */
  async loadFaces(urls: CubeFaceUrls, then?: 'useGeneratedSky' | 'dispose'): Promise<{ error: string | null; environment: ReturnType<typeof describe> }> {
    const s = current();
    const pending = s.loadFaces(urls);
    if (then === 'useGeneratedSky') s.useGeneratedSky();
    if (then === 'dispose') disposeSky();
    let error: string | null = null;
    try {
      await pending;
    } catch (e) {
      error = e instanceof ParameterError ? `${e.name} on ${e.parameter}: ${e.message}` : `not a ParameterError: ${String(e)}`;
    }
    return { error, environment: describe() };
  },

  useGeneratedSky: () => current().useGeneratedSky(),
  describe: () => describe(),
  memory: () => ({ ...renderer.info.memory }),
  dispose(): void {
    current();
    disposeSky();
  },
};

function disposeSky(): void {
  background?.dispose();
  background = null;
  sky?.dispose();
  sky = null;
}

/** The environment and the loaded faces in use (if any), as plain data. */
function describe() {
  const s = sky;
  const faces = s?.faces ?? null;
  const images = faces && Array.isArray(faces.images) ? (faces.images as HTMLImageElement[]) : [];
  return {
    disposed: s === null,
    environmentIsRenderTarget: s?.environment.value.isRenderTargetTexture ?? false,
    usingFaces: s?.usingFaces ?? false,
    faces: faces && {
      isCubeTexture: faces.isCubeTexture === true,
      colorSpace: faces.colorSpace,
      images: images.map((image) => ({
        complete: image instanceof HTMLImageElement && image.complete,
        width: image instanceof HTMLImageElement ? image.naturalWidth : 0,
        src: image instanceof HTMLImageElement ? image.src : '',
      })),
    },
  };
}

declare global {
  interface Window {
    skyHarness: typeof skyHarness;
  }
}
window.skyHarness = skyHarness;
document.title = 'ready';
