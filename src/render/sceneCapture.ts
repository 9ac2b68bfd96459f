/**
 * Renders a scene into a render target without the seas: what a sea's own shading samples of the
 * scene around it (its reflection, sceneReflection.ts; what lies under it and, from below, above
 * it, sceneRefraction.ts). Every live sea's objects are hidden in every capture (one list, so
 * that no sea is drawn in another's capture) and the scene's background is left out, so the
 * target's alpha is 0 wherever no object was drawn and the sea fills those pixels from its sky
 * instead. Everything the render changes on the renderer and the scene is put back, so it may run
 * inside another render (an object's onBeforeRender).
 */
import { Box3, Color, type BufferGeometry, type Camera, type ColorRepresentation, type Layers, type Material, type Mesh, type Object3D, type RenderTarget, type Scene, type Vector2, type Vector4, type WebGLRenderTarget } from 'three';

/**
 * What a capture asks of a renderer: three's WebGLRenderer satisfies it, and so does its
 * WebGPURenderer (three-fft-ocean/webgpu's captures, src/webgpu/sceneLightNodes.ts), which has
 * no GL state, extensions or capabilities and says how it stores depth itself.
 */
export interface CaptureRenderer {
  getRenderTarget(): RenderTarget | null;
  getActiveCubeFace(): number;
  getActiveMipmapLevel(): number;
  /** Given what getRenderTarget returned, or a capture's target (a WebGLRenderTarget, which WebGPURenderer draws into as any RenderTarget). */
  setRenderTarget(target: WebGLRenderTarget | null, activeCubeFace?: number, activeMipmapLevel?: number): void;
  getClearColor(target: Color): Color;
  getClearAlpha(): number;
  setClearColor(color: ColorRepresentation, alpha?: number): void;
  clear(color?: boolean, depth?: boolean, stencil?: boolean): unknown;
  render(scene: Object3D, camera: Camera): unknown;
  getDrawingBufferSize(target: Vector2): Vector2;
  autoClear: boolean;
  xr: { enabled: boolean };
  shadowMap: { autoUpdate: boolean };
  /** WebGLRenderer's: its GL state (the depth mask), extensions and capabilities, and its current viewport. */
  state?: { buffers: { depth: { setMask(mask: boolean): void; getReversed?(): boolean } } };
  extensions?: { has(name: string): boolean };
  capabilities?: { logarithmicDepthBuffer: boolean };
  getCurrentViewport?(target: Vector4): Vector4;
  /** WebGPURenderer's: whether its depth buffer is logarithmic or reversed. */
  logarithmicDepthBuffer?: boolean;
  reversedDepthBuffer?: boolean;
}

const savedClearColor = new Color();
/** The seas' objects' visibility during a capture, kept between captures so that none makes an array. */
const seaVisible: boolean[] = [];

/** The objects of every live sea, by owner (OceanSurface): the arrays themselves, which their owners may grow. */
const seas = new Map<object, readonly Object3D[]>();
/** Every sea's objects as one list and one set, made again only when a sea is added, grows or goes (not per render). */
let hidden: { list: readonly Object3D[]; set: ReadonlySet<Object3D> } | null = null;
/** True while a capture renders: a sea drawn in it anyway (one never added) draws no capture of its own. */
let capturing = false;
/** The meshes a capture hid for lying under the water (captureChanges), kept between captures so that none makes an array. */
const underWater: Object3D[] = [];
/** The meshes a capture draws with their stand-ins (captureChanges), and their own geometries meanwhile. */
const stoodIn: Mesh[] = [];
const ownGeometry: BufferGeometry[] = [];
const worldBox = new Box3();
/** The geometries the captures draw in place of their meshes' own (setCaptureStandIn); borrowed, not owned. */
const standIns = new WeakMap<Mesh, BufferGeometry>();

/**
 * Gives `mesh` a geometry that every capture (the sea's reflection and refraction) draws in its
 * place, while the main render keeps the mesh's own; null takes it off. What the sea shows of an
 * object (through metres of water, bent by the waves, in a capture often smaller than the screen)
 * seldom needs every triangle, and a capture's render costs its vertices as the main one does: a
 * coarser copy (the island's sea floor, src/objects/island.ts) saves most of that. The stand-in is
 * the caller's: it stays alive as long as it is set, and the caller disposes it.
 */
export function setCaptureStandIn(mesh: Mesh, geometry: BufferGeometry | null): void {
  if (geometry === null) standIns.delete(mesh);
  else standIns.set(mesh, geometry);
}

/**
 * Adds a sea's objects (`objects`, the array itself) to those every capture hides, or tells that
 * the array of `owner` changed. Undo with removeSea.
 */
export function addSea(owner: object, objects: readonly Object3D[]): void {
  seas.set(owner, objects);
  hidden = null;
}

/** Takes `owner`'s objects off the list every capture hides (its sea is disposed). */
export function removeSea(owner: object): void {
  seas.delete(owner);
  hidden = null;
}

/** Every live sea's objects: what every capture hides. The same object until a sea is added, changed or removed. */
export function hiddenSeaObjects(): { list: readonly Object3D[]; set: ReadonlySet<Object3D> } {
  if (hidden === null) {
    const list = [...seas.values()].flat();
    hidden = { list, set: new Set(list) };
  }
  return hidden;
}

/** Whether a capture is being rendered (a sea drawn in it shows its sky). */
export function isCapturing(): boolean {
  return capturing;
}

/**
 * Whether `scene` holds nothing but the seas' objects (an Ocean, a scene of Oceans): a capture would
 * be transparent everywhere and show nothing, so neither capture is drawn and the shaders take their
 * sky path, which is what they show over a transparent capture.
 */
export function holdsOnlySeas(scene: Object3D): boolean {
  return onlySea(scene, hiddenSeaObjects().set);
}

function onlySea(object: Object3D, sea: ReadonlySet<Object3D>): boolean {
  if (sea.has(object)) return true;
  const group = object.type === 'Object3D' || object.type === 'Scene' || object.type === 'Group';
  if (!group || object.children.length === 0) return false;
  // A loop, not every(): this runs twice a frame and makes no closures.
  for (const child of object.children) if (!onlySea(child, sea)) return false;
  return true;
}

/**
 * What a capture changes in `object`'s visible meshes: into `hide` those that lie wholly under the
 * plane y = `level` (none when it is undefined), into `swap` those with a stand-in
 * (setCaptureStandIn) that are not hidden. Under the plane means that the mesh's own geometry's
 * bounding box, placed in the world, has its top below it; only plain meshes without children
 * whose vertices are where their geometry says (no skinning, instances, morph targets,
 * displacement map or vertex shader of the user's) are judged, and anything else is kept.
 */
export function captureChanges(object: Object3D, level: number | undefined, hide: Object3D[], swap: Mesh[]): void {
  if (!object.visible) return;
  const mesh = object as Mesh;
  if (mesh.isMesh === true) {
    if (level !== undefined && belowLevel(mesh, level)) hide.push(mesh);
    else if (standIns.has(mesh)) swap.push(mesh);
  }
  for (const child of object.children) captureChanges(child, level, hide, swap);
}

function belowLevel(mesh: Mesh, level: number): boolean {
  // A mesh with children is kept: hiding it would hide them, which may reach above the water.
  if (mesh.children.length > 0 || !plainVertices(mesh)) return false;
  const geometry = mesh.geometry;
  if (geometry.boundingBox === null) geometry.computeBoundingBox();
  return worldBox.copy(geometry.boundingBox!).applyMatrix4(mesh.matrixWorld).max.y < level;
}

/** Whether a mesh's vertices are drawn where its geometry's positions put them. */
function plainVertices(mesh: Mesh): boolean {
  const kind = mesh as { isSkinnedMesh?: boolean; isInstancedMesh?: boolean; isBatchedMesh?: boolean };
  if (kind.isSkinnedMesh === true || kind.isInstancedMesh === true || kind.isBatchedMesh === true) return false;
  if (mesh.geometry.morphAttributes.position !== undefined) return false;
  if (!Array.isArray(mesh.material)) return plainMaterial(mesh.material);
  // A loop, not every(): this runs every frame and makes no closures.
  for (const material of mesh.material) if (!plainMaterial(material)) return false;
  return true;
}

/** A material that draws vertices where they are: not the user's own shader, no displacement map. */
function plainMaterial(material: Material): boolean {
  return (material as { isShaderMaterial?: boolean }).isShaderMaterial !== true && ((material as { displacementMap?: unknown }).displacementMap ?? null) === null;
}

/**
 * Renders `scene` from `camera` into `target` (cleared to transparent black, depth 1), drawing only
 * the objects whose layers meet `layers`, with every sea's objects hidden and no background. With
 * a `nearPlaneHeight` (the reflection, whose near plane is the horizontal plane at that height) the
 * meshes that lie wholly under it are hidden too: clipped whole, they would cost their vertices and
 * show nothing (the island's sea floor, most of its triangles). Meshes with a stand-in
 * (setCaptureStandIn) are drawn with it.
 * Restores the renderer's target, clear colour and alpha, autoClear, XR and shadow-map updates, the
 * scene's background, the camera's layers, the seas' visibility and the meshes' own geometries.
 */
export function renderSceneWithoutSea(renderer: CaptureRenderer, scene: Scene, camera: Camera, target: WebGLRenderTarget, layers: Layers, nearPlaneHeight?: number): void {
  const sea = hiddenSeaObjects().list;
  underWater.length = 0;
  stoodIn.length = 0;
  captureChanges(scene, nearPlaneHeight, underWater, stoodIn);
  const previousTarget = renderer.getRenderTarget() as WebGLRenderTarget | null;
  const previousFace = renderer.getActiveCubeFace();
  const previousMipmap = renderer.getActiveMipmapLevel();
  renderer.getClearColor(savedClearColor);
  const previousAlpha = renderer.getClearAlpha();
  const previousAutoClear = renderer.autoClear;
  const previousXr = renderer.xr.enabled;
  const previousShadowUpdate = renderer.shadowMap.autoUpdate;
  const previousBackground = scene.background;
  const previousLayers = camera.layers.mask;
  for (let i = 0; i < sea.length; i++) seaVisible[i] = sea[i].visible;
  capturing = true;
  try {
    for (const object of sea) object.visible = false;
    for (const object of underWater) object.visible = false;
    for (let i = 0; i < stoodIn.length; i++) {
      ownGeometry[i] = stoodIn[i].geometry;
      stoodIn[i].geometry = standIns.get(stoodIn[i])!;
    }
    scene.background = null;
    camera.layers.mask = layers.mask;
    // The camera is placed by the caller: XR would replace it with the headset's. The shadows are
    // the main render's: the same lights, the same maps.
    renderer.xr.enabled = false;
    renderer.shadowMap.autoUpdate = false;
    renderer.setRenderTarget(target);
    renderer.setClearColor(0x000000, 0);
    // A material drawn last may have left depth writes off, and clear() would then keep the old
    // depth (WebGLRenderer; WebGPURenderer's clear turns them on itself).
    renderer.state?.buffers.depth.setMask(true);
    renderer.clear(true, true, true);
    renderer.autoClear = false;
    renderer.render(scene, camera);
  } finally {
    capturing = false;
    renderer.autoClear = previousAutoClear;
    renderer.setClearColor(savedClearColor, previousAlpha);
    renderer.setRenderTarget(previousTarget, previousFace, previousMipmap);
    renderer.xr.enabled = previousXr;
    renderer.shadowMap.autoUpdate = previousShadowUpdate;
    scene.background = previousBackground;
    camera.layers.mask = previousLayers;
    for (let i = 0; i < sea.length; i++) sea[i].visible = seaVisible[i];
    // Only visible meshes were collected.
    for (const object of underWater) object.visible = true;
    // Only those swapped before anything threw.
    for (let i = 0; i < ownGeometry.length; i++) stoodIn[i].geometry = ownGeometry[i];
    ownGeometry.length = 0;
  }
}
