/**
 * Renders a scene into a render target without the sea: what the sea's own shading samples of the
 * scene around it (its reflection, sceneReflection.ts; what lies under it, sceneRefraction.ts). The sea's objects are hidden and the scene's
 * background left out, so the target's alpha is 0 wherever no object was drawn and the sea fills
 * those pixels from its sky instead. Everything the render changes on the renderer and the scene is
 * put back, so it may run inside another render (an object's onBeforeRender).
 */
import { Color, type Camera, type Layers, type Object3D, type Scene, type WebGLRenderer, type WebGLRenderTarget } from 'three';

const savedClearColor = new Color();

/**
 * Renders `scene` from `camera` into `target` (cleared to transparent black, depth 1), drawing only
 * the objects whose layers meet `layers`, with every object of `sea` hidden and no background.
 * Restores the renderer's target, clear colour and alpha, autoClear, XR and shadow-map updates, the
 * scene's background, the camera's layers and the sea's visibility.
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
  const previousFace = renderer.getActiveCubeFace();
  const previousMipmap = renderer.getActiveMipmapLevel();
  renderer.getClearColor(savedClearColor);
  const previousAlpha = renderer.getClearAlpha();
  const previousAutoClear = renderer.autoClear;
  const previousXr = renderer.xr.enabled;
  const previousShadowUpdate = renderer.shadowMap.autoUpdate;
  const previousBackground = scene.background;
  const previousLayers = camera.layers.mask;
  const seaVisible = sea.map((object) => object.visible);
  try {
    for (const object of sea) object.visible = false;
    scene.background = null;
    camera.layers.mask = layers.mask;
    // The camera is placed by the caller: XR would replace it with the headset's. The shadows are
    // the main render's: the same lights, the same maps.
    renderer.xr.enabled = false;
    renderer.shadowMap.autoUpdate = false;
    renderer.setRenderTarget(target);
    renderer.setClearColor(0x000000, 0);
    // A material drawn last may have left depth writes off, and clear() would then keep the old depth.
    renderer.state.buffers.depth.setMask(true);
    renderer.clear(true, true, true);
    renderer.autoClear = false;
    renderer.render(scene, camera);
  } finally {
    renderer.autoClear = previousAutoClear;
    renderer.setClearColor(savedClearColor, previousAlpha);
    renderer.setRenderTarget(previousTarget, previousFace, previousMipmap);
    renderer.xr.enabled = previousXr;
    renderer.shadowMap.autoUpdate = previousShadowUpdate;
    scene.background = previousBackground;
    camera.layers.mask = previousLayers;
    sea.forEach((object, i) => (object.visible = seaVisible[i]));
  }
}
