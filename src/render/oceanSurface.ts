/**
 * The visible sea: a Mesh of the horizon grid (horizonGrid.ts) with a SeaSurfaceMaterial
 * (seaSurfaceMaterial.ts; OceanMaterial on WebGLRenderer), displaced and shaded from the
 * simulation's field textures, driven only through that interface. Add it to any scene; before each render it
 * places its rings around the rendering camera. The sea is the plane y = 0 of world space (the
 * mesh's own transform is not used). Owns its geometry, the material it is given, scene reflection
 * (SceneReflection, the `reflections: 'scene'` option) and the capture of the scene under it
 * (SceneRefraction, the `refractions: 'scene'` option).
 */
import { Mesh, Vector2, Vector3, type Camera, type Object3D, type Scene, type Texture, type WebGLRenderer } from 'three';
import type { Shore } from '../layers/shore';
import type { WaveLayer } from '../layers/waveLayer';
import { ParameterError } from '../parameters/options';
import { cellsPerRingForViewport, createHorizonGridGeometry, farEdgeDistance, FEWEST_CELLS_PER_RING, MOST_CELLS_PER_RING, RingFrames } from './horizonGrid';
import { addSea, removeSea } from './sceneCapture';
import { SceneReflection, type ReflectionLayers } from './sceneReflection';
import { SceneRefraction } from './sceneRefraction';
import type { OceanMaterial } from './oceanMaterial';
import { backgroundWaterFor, eyeSide, type SeaSurfaceMeshMaterial } from './seaSurfaceMaterial';

/** The fewest cells per ring that can be asked for (OceanSurface.fewestCellsPerRing). */
const FEWEST_CELLS_ALLOWED = 16;

export class OceanSurface<M extends SeaSurfaceMeshMaterial = OceanMaterial> extends Mesh<ReturnType<typeof createHorizonGridGeometry>, M> {
  private cellsPerRing = 0;
  private fewestCells = FEWEST_CELLS_PER_RING;
  private readonly rings = new RingFrames();
  private readonly viewport = new Vector2();
  private readonly cameraPosition = new Vector3();
  /** Where the sky background shows the deep water instead of the sky (BACKGROUND_WATER). */
  readonly backgroundWater = { value: 0 };
  /** The scene as the refraction sees it (the `refractions` shading option), drawn before the sea. */
  readonly refraction = new SceneRefraction();
  /**
   * The objects of this sea that no capture shows (reflection or refraction, of this sea or of
   * another, sceneCapture.ts): the surface, and what its owner adds with hideInCaptures.
   */
  private readonly seaObjects: Object3D[] = [this];
  private readonly reflection = new SceneReflection();

  /**
   * @param material what shades the sea (OceanMaterial on WebGLRenderer); the surface owns it from now on
   * @param waves the layers to draw and the choppiness, asked before every render (they change
   *   when the simulation's parameters do)
   */
  constructor(
    material: M,
    private readonly waves: () => {
      layers: readonly WaveLayer[];
      choppiness: number;
      foam: { value: Texture | null };
      /** The wind, m/s at 10 m: the slopes finer than the layers (seaLighting.ts); 0 when left out. */
      windSpeed?: number;
      /** The way the wind blows, ° from +x towards +z: the foam's streaks (beaufortAppearance.ts); 0 when left out. */
      windDirection?: number;
      /** No crest rises above it and no trough sinks below its negative (m); without it the eye is taken to be above the sea. */
      surfaceBound?: number;
      /** How far below mean sea level the troughs reach, m (SceneReflection.troughDepth); 0 when left out. */
      troughDepth?: number;
      /** The water's height over a point (Ocean.heightAt), asked when the eye is between crest and trough heights. */
      waterHeightAt?: (x: number, z: number) => number;
      /** The seabed the waves feel (shore.ts), prepared for these layers; null or left out: none. */
      shore?: Shore | null;
      /** The layer whose grid carries the foam of hulls under way (LocalWaves, hullFoam.ts), one of `layers`; null or left out: none. */
      hullFoam?: (WaveLayer & { readonly foam: { readonly texture: Texture } }) | null;
    },
  ) {
    super(createHorizonGridGeometry(32), material);
    this.name = 'OceanSurface';
    this.frustumCulled = false; // the vertex shader moves every vertex; the sea is always in view
    this.cellsPerRing = 32;
    this.material.shareUniforms(this.refraction.uniforms);
    this.material.shareUniforms(this.reflection.uniforms);
    addSea(this, this.seaObjects);
  }

  /** Hides `object` (one of this sea's, as its sky background) in every scene capture, as the surface is. */
  hideInCaptures(object: Object3D): void {
    this.seaObjects.push(object);
    addSea(this, this.seaObjects);
  }

  /**
   * The size of the scene's reflection (the option reflections, 'scene') as a fraction of the
   * drawing buffer's, from 0 to 1; 0 shows the sky instead and frees the reflection's render
   * target. The quality levels set it (runtime/adaptiveQuality.ts: 0 at 'lowest').
   * @defaultValue 0.5
   */
  get reflectionScale(): number {
    return this.reflection.scale;
  }

  set reflectionScale(scale: number) {
    if (!(typeof scale === 'number' && scale >= 0 && scale <= 1)) throw new ParameterError('reflectionScale', scale, 'a number from 0 to 1');
    this.reflection.scale = scale;
  }

  /**
   * Which objects the sea reflects (the option reflections, 'scene'): those whose layers meet this
   * mask and the camera's. Change it in place (reflectionLayers.disable(1)). Lights must be on it
   * too to light what is reflected.
   * @defaultValue every layer
   */
  get reflectionLayers(): ReflectionLayers {
    return this.reflection.layers;
  }

  /**
   * The fewest cells on a side of each ring of the grid: the grid follows the drawing buffer's
   * height (about a cell per 10 pixels) down to this many. A power of two from 16 to 128.
   * The quality level 'lowest' sets 16 (runtime/applyQuality.ts): its picture is a few hundred
   * pixels high, and under a software renderer a quarter of the vertices saves a third of its frame.
   * @defaultValue 32
   */
  get fewestCellsPerRing(): number {
    return this.fewestCells;
  }

  set fewestCellsPerRing(cells: number) {
    if (!(Number.isInteger(Math.log2(cells)) && cells >= FEWEST_CELLS_ALLOWED && cells <= MOST_CELLS_PER_RING)) {
      throw new ParameterError('fewestCellsPerRing', cells, `a power of two from ${FEWEST_CELLS_ALLOWED} to ${MOST_CELLS_PER_RING}`);
    }
    this.fewestCells = cells;
  }

  /**
   * Called by three.js before each render of the sea: resizes the grid to the drawing buffer's
   * height if needed, centres the rings under `camera` (placeRings), renders the scene's reflection
   * (sceneReflection.ts) or frees it where the sea reflects only its sky, and, with the refractions
   * option 'scene' and the full shading, draws the scene without the sea for the refraction.
   */
  override onBeforeRender(renderer: WebGLRenderer, scene: Scene, camera: Camera): void {
    this.fitDrawingBuffer(renderer);
    this.placeRings(camera);
    if (this.material.looksIntoScene) this.refraction.capture(renderer, scene, camera);
    else this.refraction.release();
    if (this.material.reflectsScene) this.reflection.render(renderer, scene, camera);
    else this.reflection.freeTarget();
  }

  /**
   * Gives the grid as many cells a ring as `renderer`'s drawing buffer asks for. Called before the
   * render (Ocean.update): three.js takes a mesh's geometry for a draw before its onBeforeRender,
   * so a grid replaced there is drawn only from the next frame, and the frame that replaced it drew
   * the old one (a first frame at 960×540 showed no sea). onBeforeRender calls it too, for a
   * surface drawn without an Ocean's update and for a drawing buffer resized in between.
   */
  fitDrawingBuffer(renderer: WebGLRenderer): void {
    renderer.getDrawingBufferSize(this.viewport);
    const cells = cellsPerRingForViewport(this.viewport.y, this.fewestCells);
    if (cells !== this.cellsPerRing) {
      this.geometry.dispose();
      this.geometry = createHorizonGridGeometry(cells);
      this.cellsPerRing = cells;
    }
  }

  /** Height above the sea of the camera of the last render (0 before the first). */
  get cameraHeight(): number {
    return this.cameraPosition.y;
  }

  /**
   * Distance from a camera `cameraHeight` metres up to the far edge of the surface drawn into
   * `renderer`'s drawing buffer at its current size: the camera's far plane must reach it.
   */
  farEdgeDistanceFor(cameraHeight: number, renderer: WebGLRenderer): number {
    renderer.getDrawingBufferSize(this.viewport);
    return farEdgeDistance(cameraHeight, this.waves().layers, cellsPerRingForViewport(this.viewport.y, this.fewestCells));
  }

  /**
   * Centres the rings under `camera` and tells the reflection how deep the troughs reach (done
   * before every render; public for the geometry test).
   */
  placeRings(camera: Camera): void {
    const position = camera.getWorldPosition(this.cameraPosition);
    const { layers, choppiness, foam, surfaceBound, troughDepth, waterHeightAt, windSpeed, windDirection, shore, hullFoam } = this.waves();
    this.reflection.troughDepth = troughDepth ?? 0;
    this.material.bindLayers(layers, choppiness, foam, windSpeed, windDirection);
    this.material.bindHullFoam(hullFoam ? layers.indexOf(hullFoam) : -1, hullFoam?.foam.texture ?? null);
    this.material.setEye(position.x, position.z);
    this.material.bindShore(shore ?? null, position.x, position.z);
    this.rings.update(position.x, position.z, position.y, layers, this.cellsPerRing);
    this.material.setRings(this.rings, this.cellsPerRing);
    const { side, inWater } = eyeSide(position, surfaceBound, waterHeightAt);
    this.material.setEyeSide(side, inWater);
    this.backgroundWater.value = backgroundWaterFor(side);
  }

  dispose(): void {
    this.geometry.dispose();
    this.material.dispose();
    this.refraction.dispose();
    this.reflection.dispose();
    removeSea(this);
  }
}

