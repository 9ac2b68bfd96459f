/**
 * Draws a scene without its sea, for the sea's own shading to look up what lies behind or under
 * the water (sceneRefraction.ts). The renderer is left as it was found.
 */
import { Color, type Camera, type Layers, type Object3D, type Scene, type WebGLRenderer, type WebGLRenderTarget } from 'three';

const savedClearColor = new Color();

/**
 * Renders `scene` from `camera` into `target`, cleared to transparent black, with the objects of
 * `sea` hidden, no scene.background and only the objects in `layers`. Restores the renderer's
 * render target, clear colour and alpha, shadow-map updates, XR, the scene's background, the camera's layers and the sea's
 * visibility afterwards; safe inside an object's onBeforeRender (three.js renders are re-entrant,
 * as its Reflector's are).
 */
export function renderSceneWithoutSea(
  renderer: WebGLRenderer,
  scene: Scene,
  camera: Camera,
  target: WebGLRenderTarget,
  sea: readonly Object3D[],
  layers: Layers,
): void {
  const previousTarget = renderer.getRenderTarget();
  renderer.getClearColor(savedClearColor);
  const previousAlpha = renderer.getClearAlpha();
  const previousBackground = scene.background;
  const previousMask = camera.layers.mask;
  const wasVisible = sea.map((object) => object.visible);
  // As three.js's Reflector does: the shadows of this frame are drawn already, and XR would render
  // the capture once per eye into the headset.
  const shadowsUpdated = renderer.shadowMap.autoUpdate;
  const xrEnabled = renderer.xr.enabled;
  try {
    renderer.shadowMap.autoUpdate = false;
    renderer.xr.enabled = false;
    for (const object of sea) object.visible = false;
    scene.background = null;
    camera.layers.mask = layers.mask;
    renderer.setRenderTarget(target);
    renderer.setClearColor(0x000000, 0);
    renderer.clear(true, true, false);
    renderer.render(scene, camera);
  } finally {
    renderer.shadowMap.autoUpdate = shadowsUpdated;
    renderer.xr.enabled = xrEnabled;
    sea.forEach((object, i) => (object.visible = wasVisible[i]));
    scene.background = previousBackground;
    camera.layers.mask = previousMask;
    renderer.setClearColor(savedClearColor, previousAlpha);
    renderer.setRenderTarget(previousTarget);
  }
}
