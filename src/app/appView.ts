/**
 * How the app draws its scene, shared by the app (app.ts) and `npm run shot` (examples/shot.ts), so
 * that a shot of an app link draws the very pixels the app's canvas shows: the renderer's settings,
 * the camera's lens, the ocean built from an AppState (what happens every frame is the frame loop's,
 * src/runtime/frameLoop.ts, which they share too).
 * No DOM beyond what three.js needs; no side effects on import.
 */
import { ACESFilmicToneMapping, PerspectiveCamera, WebGLRenderer, type WebGLRendererParameters } from 'three';
import { Ocean, type OceanOptions } from '../ocean';
import { ParameterError } from '../parameters/options';
import { QUALITY_LEVELS, QUALITY_STEPS, simulationAtQuality, type QualityStep } from '../runtime/adaptiveQuality';
import { skyboxFaceUrls } from '../render/skyEnvironment';
import { simulationParameters, type AppState } from './urlState';

/**
 * The app's renderer: ACES filmic tone mapping, and a canvas without antialiasing of its own, since
 * that could not be turned off later: the quality level's MSAA is a SceneOutput's
 * (render/sceneOutput.ts). The caller sets pixel ratio and size.
 */
export function createAppRenderer(parameters: WebGLRendererParameters = {}): WebGLRenderer {
  const renderer = new WebGLRenderer({ antialias: false, ...parameters });
  renderer.toneMapping = ACESFilmicToneMapping;
  return renderer;
}

/** The app's camera: 55° vertical field of view, near plane 0.5 m; the frame loop moves the far plane (runtime/farPlane.ts). */
export function createAppCamera(aspect = 1): PerspectiveCamera {
  return new PerspectiveCamera(55, aspect, 0.5, 1e5);
}

/**
 * The quality level a state is drawn at first: its fixed level, or for 'auto' the best (the app
 * then adapts it; `npm run shot` keeps its grid, at pixel ratio 1, so that its pictures are
 * deterministic and of the size asked for).
 */
export function startingQuality(state: Readonly<AppState>): QualityStep {
  return QUALITY_STEPS[state.quality === 'auto' ? QUALITY_LEVELS[0] : state.quality];
}

/**
 * The Ocean options `state` describes (simulation, path, sun, shading), with the grid and cascades
 * of its starting quality level: the WebGL Ocean's (createAppOcean) and, less what it does not draw
 * yet, the WebGPU Ocean's (appWebGPU.ts).
 */
export function appOceanOptions(state: Readonly<AppState>): OceanOptions {
  return {
    ...simulationParameters(state),
    ...simulationAtQuality(state, startingQuality(state)),
    path: state.path,
    sunElevation: state.sunElevation,
    sunAzimuth: state.sunAzimuth,
    cloudCover: state.cloudCover,
    ior: state.ior,
    absorption: state.absorption,
    scatterColor: state.scatterColor,
    causticPower: state.causticPower,
    causticColor: state.causticColor,
    shadingMode: state.mode,
    refractions: state.refractions,
    reflections: state.reflections,
  };
}

/** The ocean `state` describes (appOceanOptions, and wireframe), generated sky. */
export function createAppOcean(renderer: WebGLRenderer, state: Readonly<AppState>, options: Pick<OceanOptions, 'worker'> = {}): Ocean {
  const ocean = new Ocean(renderer, { ...appOceanOptions(state), ...options });
  ocean.surface.material.wireframe = state.wireframe;
  return ocean;
}

/**
 * The origins skybox faces may come from besides the page's own: the space-separated origins of
 * the page's <meta name="fft-ocean-skybox-origins" content="https://cdn.example.com …">. A link
 * someone shares can then not make the app fetch from wherever it names (tracking, or anything
 * the page's own policy would not allow); the page that embeds the app says what it trusts.
 */
export function trustedSkyboxOrigins(page: Document = document): string[] {
  const meta = page.querySelector<HTMLMetaElement>('meta[name="fft-ocean-skybox-origins"]');
  const listed = (meta?.content ?? '').split(/\s+/).filter((origin) => origin !== '');
  return [page.location.origin, ...listed];
}

/**
 * Starts loading the six-face skybox `state.skybox` names (null for 'generated'); until it has
 * loaded, and if it fails, the generated sky stays. A folder on an origin that is not trusted
 * (trustedSkyboxOrigins) is refused, with a ParameterError on 'skybox', before anything is fetched.
 */
export function loadAppSkybox(ocean: Ocean, skybox: string, trustedOrigins = trustedSkyboxOrigins()): Promise<void> | null {
  if (skybox === 'generated') return null;
  const base = skybox.endsWith('/') ? skybox : `${skybox}/`;
  const origin = new URL(base, document.baseURI).origin; // 'null' for data:, blob: or javascript: URLs
  if (!trustedOrigins.includes(origin)) {
    const allowed = `a folder URL on ${trustedOrigins.join(' or ')} (a page allows others with <meta name="fft-ocean-skybox-origins">)`;
    return Promise.reject(new ParameterError('skybox', skybox, allowed));
  }
  return ocean.sky.loadFaces(skyboxFaceUrls(base));
}
