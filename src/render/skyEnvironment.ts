/**
 * The sky and the deep water below the horizon, as one cube map the ocean reflects and refracts
 * and SkyBackground (skyBackground.ts) shows behind everything.
 *
 * By default the cube is the analytic sky of shaders/sky/analyticSky.glsl (clear-sky scattering,
 * a sun disk, dark deep-water blue below the horizon). A set of six face images (e.g.
 * public/skybox/clear-afternoon/, made by scripts/make-skybox-faces.mjs) can replace it; if they
 * fail to load, the generated sky stays in use. Either is drawn into one cube render target in
 * linear HDR, RGBM-encoded in 8 bits and without mipmaps (shaders/sky/rgbm.glsl says why: under
 * SwiftShader that samples several times faster than half floats); read it through
 * shaders/sky/environmentLookup.glsl.
 *
 * Owns: the cube render target, the sky box geometry and its two materials (analytic sky, face
 * copy), the cube camera's scene, and the loaded face texture (if any, kept to redraw the cube
 * after a lost context). dispose() frees all of them.
 *
 * Usage:
 *   const sky = new SkyEnvironment(renderer, { sunElevation: 30, sunAzimuth: 40 });
 *   scene.add(new SkyBackground(sky.environment));
 *   oceanMaterial.uniforms.skyEnvironment = sky.environment;          // bound once, stays current
 *   oceanMaterial.uniforms.sunDirection = sky.skyUniforms.skySunDirection; // live; sunDirection is a copy
 *   await sky.loadFaces(skyboxFaceUrls('/skybox/clear-afternoon/'));   // optional
 *
 * The generated sky is linear HDR (sky about 0.05–2, the sun disk clipped at the RGBM range), so
 * the renderer's tone mapping applies to it. Face images are LDR sRGB, never brighter than 1.
 *
 * Conventions: directions are world space with y up; azimuth is measured from +x towards +z.
 */
import {
  BackSide,
  BoxGeometry,
  Color,
  CubeCamera,
  CubeTextureLoader,
  GLSL3,
  LinearFilter,
  LoadingManager,
  Mesh,
  RGBAFormat,
  Scene,
  ShaderMaterial,
  SRGBColorSpace,
  UnsignedByteType,
  Vector3,
  WebGLCubeRenderTarget,
  type CubeTexture,
  type Texture,
  type WebGLRenderer,
} from 'three';
import { skyLight } from './daylight';
import { shaderSource } from '../shaderSource';
import { checkOption, checkOptionNames, DisposedError, ParameterError } from '../parameters/options';
import { DEFAULT_SUN, SUN_OPTIONS } from '../parameters/sceneOptions';

/** URLs of the six faces, in three.js's naming (p/n = positive/negative axis). */
export interface CubeFaceUrls {
  px: string;
  nx: string;
  py: string;
  ny: string;
  pz: string;
  nz: string;
}

export interface SkyEnvironmentOptions {
  /** Degrees above the horizon, in [-90, 90]. @defaultValue 30 */
  sunElevation?: number;
  /** Degrees from +x towards +z. @defaultValue 40 */
  sunAzimuth?: number;
  /** How much of the sky is cloud, [0, 1]: 0 a clear sky, 1 overcast (see SunOptions.cloudCover). @defaultValue 0 */
  cloudCover?: number;
  /** Cube face size in texels, up to the renderer's largest cube map. @defaultValue 256 */
  resolution?: number;
}

/** The defaults of SkyEnvironmentOptions (the sun's are DEFAULT_SUN's). */
export const DEFAULT_SKY_ENVIRONMENT: Readonly<Required<SkyEnvironmentOptions>> = Object.freeze({ ...DEFAULT_SUN, resolution: 256 });

/** The names SkyEnvironmentOptions has: any other is a misspelling. */
const SKY_ENVIRONMENT_OPTION_KEYS: readonly (keyof SkyEnvironmentOptions)[] = ['sunElevation', 'sunAzimuth', 'cloudCover', 'resolution'];

/**
 * The face set shipped in public/skybox/ and where its sun is: pass these to setSun() so
 * sunDirection matches the faces (the script that makes them uses the same values).
 */
export const SHIPPED_SKYBOX = { name: 'clear-afternoon', sunElevation: 30, sunAzimuth: 40 } as const;

/** The six face URLs of a face set in directory `base` (px.png, nx.png, … ; base ends with /). */
export function skyboxFaceUrls(base: string): CubeFaceUrls {
  return {
    px: `${base}px.png`,
    nx: `${base}nx.png`,
    py: `${base}py.png`,
    ny: `${base}ny.png`,
    pz: `${base}pz.png`,
    nz: `${base}nz.png`,
  };
}

/** A direction in world space (y up): a Vector3 or [x, y, z]. */
export type SunDirection = Vector3 | readonly [number, number, number];

/** A sun's position in degrees: elevation above the horizon, azimuth from +x towards +z. */
export interface SunAngles {
  elevation: number;
  azimuth: number;
}

/**
 * Elevation and azimuth (degrees) of the sun towards `direction` (any length): the inverse of
 * sunDirectionFromAngles. Straight up or down, where any azimuth is right, gives azimuth 0.
 * Throws a ParameterError naming `name` for a zero, non-finite or malformed direction.
 */
export function sunAnglesFromDirection(direction: SunDirection, name = 'sunDirection'): SunAngles {
  const vector = direction as Partial<Vector3> | null | undefined;
  const components: readonly unknown[] = Array.isArray(direction) ? direction : [vector?.x, vector?.y, vector?.z];
  if (components.length !== 3 || !components.every((c) => Number.isFinite(c)) || components.every((c) => c === 0)) {
    throw new ParameterError(name, direction, 'a finite, non-zero direction towards the sun: a Vector3 or [x, y, z], y up');
  }
  const [x, y, z] = components as number[];
  const scale = Math.max(Math.abs(x), Math.abs(y), Math.abs(z)); // so that no square overflows
  const degrees = 180 / Math.PI;
  return { elevation: Math.atan2(y / scale, Math.hypot(x / scale, z / scale)) * degrees, azimuth: Math.atan2(z, x) * degrees };
}

/** Unit direction towards a sun at the given elevation and azimuth (degrees), y up. */
export function sunDirectionFromAngles(elevationDeg: number, azimuthDeg: number, target = new Vector3()): Vector3 {
  const elevation = (elevationDeg * Math.PI) / 180;
  const azimuth = (azimuthDeg * Math.PI) / 180;
  return target.set(Math.cos(elevation) * Math.cos(azimuth), Math.sin(elevation), Math.cos(elevation) * Math.sin(azimuth));
}

/**
 * The angles `sun` asks for: its direction's, or its elevation and azimuth, `current` where it
 * gives none. A direction with an angle is an error (`directionName` is what the caller called it).
 */
export function sunAngles(sun: { elevation?: number; azimuth?: number; direction?: SunDirection }, current: SunAngles, directionName: string): SunAngles {
  if (sun.direction === undefined) return { elevation: sun.elevation ?? current.elevation, azimuth: sun.azimuth ?? current.azimuth };
  if (sun.elevation !== undefined || sun.azimuth !== undefined) {
    throw new ParameterError(directionName, sun.direction, 'given without an elevation or azimuth (it sets both)');
  }
  return sunAnglesFromDirection(sun.direction, directionName);
}

/** E_sun, the analytic sky's sun irradiance above the atmosphere (skySunIntensity; its colour is white). */
export const SKY_SUN_INTENSITY = 16;
/** Linear RGB; about sRGB (13, 26, 52): the report's "very dark blue" ocean depth (skyDeepWaterColor). */
export const SKY_DEEP_WATER: readonly [number, number, number] = [0.004, 0.01, 0.035];

const FACE_ORDER = ['px', 'nx', 'py', 'ny', 'pz', 'nz'] as const;

export class SkyEnvironment {
  /** The cube (RGBM, see shaders/sky/rgbm.glsl). A stable uniform object: bind it once. */
  readonly environment: { value: Texture };
  /**
   * The analytic sky's uniforms (shared objects, updated in place: skySunDirection.value is the
   * live sun direction), for materials that include analyticSky.glsl or need the sun.
   */
  readonly skyUniforms: {
    skySunDirection: { value: Vector3 };
    skySunColor: { value: Color };
    skySunIntensity: { value: number };
    skyDeepWaterColor: { value: Color };
    /** The sky's light as a fraction of the day's: 1 with the sun up, falling through twilight (daylight.ts). */
    skyDaylight: { value: number };
    /** The direct sunlight: the fraction of the sun's disk above the horizon times what the clouds let through (daylight.ts). */
    skySunVisibility: { value: number };
    /** The cloud cover, 0 clear … 1 overcast: the overcast sky's weight in the generated sky. */
    skyCloudCover: { value: number };
    /** The overcast sky's zenith luminance per unit of the sun's irradiance (daylight.ts). */
    skyOvercastZenith: { value: number };
    /** The direct sunlight the clouds let through, 1 clear … 0 overcast (daylight.ts). */
    skyCloudSun: { value: number };
  };

  private readonly target: WebGLCubeRenderTarget;
  private readonly cubeCamera: CubeCamera;
  private readonly scene = new Scene();
  private readonly box: Mesh<BoxGeometry, ShaderMaterial>;
  private readonly analyticSky: ShaderMaterial;
  private readonly faceCopy: ShaderMaterial;
  private readonly sun = new Vector3();
  private elevation = 0;
  private azimuth = 0;
  private cloud = 0;
  private loaded: CubeTexture | null = null;
  /** Bumped by every loadFaces, useGeneratedSky and dispose: a load that finishes late is stale. */
  private generation = 0;
  private disposed = false;
  /**
   * (embed work) A restored WebGL context has lost every render target's contents; three.js
   * re-creates its GPU objects lazily, but the generated cube must be drawn again. This listener
   * is added after three.js's own (registered in the WebGLRenderer constructor), so three.js has
   * re-initialised its state when it runs.
   */
  private readonly onContextRestored = (): void => {
    if (!this.disposed) this.render();
  };

  constructor(
    private readonly renderer: WebGLRenderer,
    options: SkyEnvironmentOptions = {},
  ) {
    checkOptionNames(options, SKY_ENVIRONMENT_OPTION_KEYS, 'SkyEnvironment options', { prefix: 'SkyEnvironment ' });
    const defaults = DEFAULT_SKY_ENVIRONMENT;
    const { sunElevation = defaults.sunElevation, sunAzimuth = defaults.sunAzimuth, cloudCover = defaults.cloudCover, resolution = defaults.resolution } = options;
    validateSun(sunElevation, sunAzimuth);
    checkOption(SUN_OPTIONS, 'cloudCover', cloudCover);
    if (!Number.isInteger(resolution) || resolution < 1 || resolution > renderer.capabilities.maxCubemapSize) {
      throw new ParameterError('SkyEnvironment resolution', resolution, `an integer in [1, ${renderer.capabilities.maxCubemapSize}]`);
    }

    this.target = new WebGLCubeRenderTarget(resolution, {
      type: UnsignedByteType,
      format: RGBAFormat,
      magFilter: LinearFilter,
      minFilter: LinearFilter,
      generateMipmaps: false,
      depthBuffer: false,
    });
    this.target.texture.name = 'skyEnvironment';
    this.environment = { value: this.target.texture };
    this.cubeCamera = new CubeCamera(0.1, 10, this.target);

    this.skyUniforms = {
      skySunDirection: { value: this.sun },
      skySunColor: { value: new Color(1, 1, 1) },
      skySunIntensity: { value: SKY_SUN_INTENSITY },
      skyDeepWaterColor: { value: new Color(...SKY_DEEP_WATER) },
      skyDaylight: { value: 1 },
      skySunVisibility: { value: 1 },
      skyCloudCover: { value: 0 },
      skyOvercastZenith: { value: 0 },
      skyCloudSun: { value: 1 },
    };
    const cubeMaterial = (name: string, fragmentShader: string, uniforms: ShaderMaterial['uniforms']) =>
      new ShaderMaterial({
        name,
        glslVersion: GLSL3,
        vertexShader: shaderSource('sky/skyBox.vert'),
        fragmentShader: shaderSource(fragmentShader),
        uniforms,
        side: BackSide,
        depthTest: false,
        depthWrite: false,
      });
    this.analyticSky = cubeMaterial('analyticSky', 'sky/skyBox.frag', this.skyUniforms);
    this.faceCopy = cubeMaterial('skyFaceCopy', 'sky/copyFaces.frag', { tFaces: { value: null } });
    this.box = new Mesh(new BoxGeometry(1, 1, 1), this.analyticSky);
    this.box.frustumCulled = false;
    this.scene.add(this.box);

    this.cloud = cloudCover;
    this.applySun(sunElevation, sunAzimuth);
    // (embed work) Redraw the cube after a context loss; removed in dispose(). An OffscreenCanvas
    // is an EventTarget too, but guard anyway for canvas-like objects without listeners.
    renderer.domElement.addEventListener?.('webglcontextrestored', this.onContextRestored);
  }

  /** Unit direction towards the sun of the generated sky (y up). A copy. */
  get sunDirection(): Vector3 {
    return this.sun.clone();
  }

  get sunElevation(): number {
    return this.elevation;
  }

  get sunAzimuth(): number {
    return this.azimuth;
  }

  /** How much of the sky is cloud, 0 clear … 1 overcast. */
  get cloudCover(): number {
    return this.cloud;
  }

  /**
   * Clouds the generated sky over: 0 a clear sky, 1 overcast (SunOptions.cloudCover), greying it
   * towards the CIE overcast sky and dimming the sun's disk and its light (the glint, the caustics,
   * SunLight). Throws a ParameterError naming cloudCover, keeping the old cover, for a value
   * outside [0, 1]. A loaded face set keeps its own sky; the sun's light still dims.
   */
  setCloudCover(cloudCover: number): void {
    if (this.disposed) throw new DisposedError('SkyEnvironment.setCloudCover', 'SkyEnvironment');
    checkOption(SUN_OPTIONS, 'cloudCover', cloudCover);
    this.cloud = cloudCover;
    this.applySun(this.elevation, this.azimuth);
  }

  /** Whether a loaded face set (rather than the generated sky) is in use. */
  get usingFaces(): boolean {
    return this.loaded !== null;
  }

  /** The loaded face set in use (sRGB images), or null for the generated sky. */
  get faces(): CubeTexture | null {
    return this.loaded;
  }

  /**
   * Moves the sun (degrees; elevation in [-90, 90], azimuth from +x towards +z) and re-renders the
   * generated cube. Throws, keeping the old sun, on invalid values. A loaded face set keeps its own
   * sun: only sunDirection changes.
   */
  setSun(elevationDeg: number, azimuthDeg: number): void {
    if (this.disposed) throw new DisposedError('SkyEnvironment.setSun', 'SkyEnvironment');
    validateSun(elevationDeg, azimuthDeg);
    this.applySun(elevationDeg, azimuthDeg);
  }

  /**
   * Loads six face images (sRGB) and, once all have loaded, uses them as the environment.
   * Rejects, with the generated (or previously loaded) sky still in use, if any face fails to
   * load or decode (404, CORS, not an image), naming the failing URLs; also if a later
   * loadFaces, useGeneratedSky or dispose superseded this call before it finished. It rejects
   * with a ParameterError whose parameter is 'urls'.
   */
  loadFaces(urls: CubeFaceUrls): Promise<void> {
    if (this.disposed) return Promise.reject(new DisposedError('SkyEnvironment.loadFaces', 'SkyEnvironment'));
    const list = FACE_ORDER.map((face) => urls?.[face]);
    const missing = FACE_ORDER.filter((_face, i) => typeof list[i] !== 'string' || list[i] === '');
    if (missing.length > 0) {
      return Promise.reject(failedFaces(urls, `no URL for face ${missing.join(', ')}; the generated sky stays in use`));
    }
    const generation = ++this.generation;

    return new Promise<void>((resolve, reject) => {
      const failed: string[] = [];
      const manager = new LoadingManager();
      manager.onError = (url) => failed.push(url);
      let texture: CubeTexture | null = null;
      // Called once every face has either loaded or failed.
      manager.onLoad = () => {
        if (failed.length > 0 || generation !== this.generation || texture === null) {
          texture?.dispose();
          const kept = this.usingFaces ? 'the previously loaded faces stay' : 'the generated sky stays';
          let message: string;
          if (failed.length > 0) {
            message = `could not load ${failed.join(', ')} (missing, blocked by CORS or not an image); ${kept} in use`;
          } else if (this.disposed) {
            message = `the environment was disposed before ${list.join(', ')} finished loading`;
          } else {
            message = `superseded by a later loadFaces or useGeneratedSky call before ${list.join(', ')} finished loading`;
          }
          reject(failedFaces(urls, message));
          return;
        }
        texture.colorSpace = SRGBColorSpace;
        texture.name = 'skyEnvironmentFaces';
        this.loaded?.dispose();
        this.loaded = texture;
        this.render();
        resolve();
      };
      const loader = new CubeTextureLoader(manager);
      // Failures reach manager.onError, which (unlike the loader's own onError) gets the URL.
      texture = loader.load(list as string[]);
    });
  }

  /** Uses the generated sky again, freeing a loaded face set. */
  useGeneratedSky(): void {
    this.generation++;
    const hadFaces = this.loaded !== null;
    this.loaded?.dispose();
    this.loaded = null;
    if (hadFaces && !this.disposed) this.render();
  }

  dispose(): void {
    this.disposed = true;
    this.useGeneratedSky();
    this.renderer.domElement.removeEventListener?.('webglcontextrestored', this.onContextRestored);
    this.target.dispose();
    this.analyticSky.dispose();
    this.faceCopy.dispose();
    this.box.geometry.dispose();
  }

  private applySun(elevationDeg: number, azimuthDeg: number): void {
    this.elevation = elevationDeg;
    this.azimuth = azimuthDeg;
    sunDirectionFromAngles(elevationDeg, azimuthDeg, this.sun);
    const light = skyLight(elevationDeg, this.cloud);
    this.skyUniforms.skyDaylight.value = light.daylight;
    this.skyUniforms.skySunVisibility.value = light.sunVisibility;
    this.skyUniforms.skyCloudCover.value = this.cloud;
    this.skyUniforms.skyOvercastZenith.value = light.overcastZenith;
    this.skyUniforms.skyCloudSun.value = light.cloudSun;
    if (!this.loaded) this.render();
  }

  /** Draws the cube from the loaded faces if there are any, else from the analytic sky. */
  private render(): void {
    this.faceCopy.uniforms.tFaces.value = this.loaded;
    this.box.material = this.loaded ? this.faceCopy : this.analyticSky;
    const renderer = this.renderer;
    const previousTarget = renderer.getRenderTarget();
    const previousFace = renderer.getActiveCubeFace();
    const previousLevel = renderer.getActiveMipmapLevel();
    const previousXr = renderer.xr.enabled;
    renderer.xr.enabled = false;
    this.cubeCamera.update(renderer, this.scene);
    renderer.xr.enabled = previousXr;
    renderer.setRenderTarget(previousTarget, previousFace, previousLevel);
  }
}

/** Why loadFaces rejects: a ParameterError on its urls, with the whole message. */
function failedFaces(urls: CubeFaceUrls, message: string): ParameterError {
  return new ParameterError('urls', urls, '', `SkyEnvironment.loadFaces: ${message}`);
}

function validateSun(elevationDeg: number, azimuthDeg: number): void {
  checkOption(SUN_OPTIONS, 'sunElevation', elevationDeg);
  checkOption(SUN_OPTIONS, 'sunAzimuth', azimuthDeg);
}
