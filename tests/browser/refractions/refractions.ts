/**
 * Test page for the scene seen through the water (refractions: 'scene', src/render/sceneRefraction.ts):
 * an Ocean over calm water under a sky of one known colour, a white plate under it at a chosen
 * depth, and (for the pictures) a box piercing the surface and rocks on a bed. Draws onto the
 * canvas, without tone mapping in linear RGB for the measurements, and reads pixels back.
 */
import {
  BoxGeometry,
  Color,
  DirectionalLight,
  HemisphereLight,
  IcosahedronGeometry,
  LinearSRGBColorSpace,
  Mesh,
  MeshBasicMaterial,
  MeshStandardMaterial,
  NoToneMapping,
  PerspectiveCamera,
  PlaneGeometry,
  Scene,
  SRGBColorSpace,
  Vector3,
  WebGLRenderer,
  type Material,
} from 'three';
import { Ocean, type OceanOptions } from '../../../src/ocean';
import { ParameterError } from '../../../src/parameters/options';

export type Vec3 = [number, number, number];

export interface SetupOptions {
  /** The Ocean's options (calm water, no caustics are the test's choice). */
  ocean: OceanOptions;
  /** The sky's one colour, an sRGB grey level 0..255 of its six faces; none: the generated sky. */
  skyGrey?: number;
  /** 'linear': linear RGB without tone mapping (measurements); 'display': sRGB, ACES (pictures). */
  output: 'linear' | 'display';
  /**
   * 'plate': a white plate (MeshBasicMaterial); 'box': a dark grey 2 m cube half under the water
   * at (0, 0, −6); 'sunk': a red 2 m cube under the water, its top 0.5 m down, at (0, −1.5, −6);
   * 'raised': a red 1 m cube above the water, centred at (3, 1.5, 0); 'showcase': a lit reef, a
   * box through the surface; 'none': the sea alone.
   */
  content: 'plate' | 'box' | 'sunk' | 'raised' | 'showcase' | 'none';
  width: number;
  height: number;
  camera: { position: Vec3; lookAt: Vec3; fov: number };
}

let renderer: WebGLRenderer | null = null;
let ocean: Ocean | null = null;
const scene = new Scene();
const camera = new PerspectiveCamera();
const plate = new Mesh(new PlaneGeometry(60, 60), new MeshBasicMaterial({ color: 0xffffff, toneMapped: false }));
plate.rotation.x = -Math.PI / 2;
const box = new Mesh(new BoxGeometry(2, 2, 2), new MeshBasicMaterial({ color: new Color(0.1, 0.1, 0.1), toneMapped: false }));
box.position.set(0, 0, -6);
const sunk = new Mesh(new BoxGeometry(2, 2, 2), new MeshBasicMaterial({ color: new Color(1, 0, 0), toneMapped: false }));
sunk.position.set(0, -1.5, -6);
const raised = new Mesh(new BoxGeometry(1, 1, 1), new MeshBasicMaterial({ color: new Color(1, 0, 0), toneMapped: false }));
raised.position.set(3, 1.5, 0);

/** A one-colour image as a data URL (the sky's faces). */
function greyImage(level: number): string {
  const canvas = document.createElement('canvas');
  canvas.width = canvas.height = 4;
  const context = canvas.getContext('2d')!;
  context.fillStyle = `rgb(${level}, ${level}, ${level})`;
  context.fillRect(0, 0, 4, 4);
  return canvas.toDataURL('image/png');
}

function showcase(): void {
  scene.add(new HemisphereLight(0xbfd8ff, 0x404030, 1.2));
  const sun = new DirectionalLight(0xffffff, 2.5);
  sun.position.set(-20, 30, 30);
  scene.add(sun);
  const sand = new Mesh(new PlaneGeometry(80, 80), new MeshStandardMaterial({ color: 0xd8c49a, roughness: 1 }));
  sand.rotation.x = -Math.PI / 2;
  sand.position.y = -2.5;
  scene.add(sand);
  const rock = new MeshStandardMaterial({ color: 0x8a6f58, roughness: 0.9, flatShading: true });
  const coral = new MeshStandardMaterial({ color: 0xd0563c, roughness: 0.8, flatShading: true });
  [
    [-3, -2.2, -9, 1.4, rock],
    [1.5, -1.9, -11, 1.1, coral],
    [4, -2.3, -7, 0.9, rock],
    [-1, -2.0, -6, 0.7, coral],
  ].forEach(([x, y, z, r, material]) => {
    const stone = new Mesh(new IcosahedronGeometry(r as number, 1), material as Material);
    stone.position.set(x as number, y as number, z as number);
    scene.add(stone);
  });
  const box = new Mesh(new BoxGeometry(2.5, 2, 2.5), new MeshStandardMaterial({ color: 0xc03a2b, roughness: 0.6 }));
  box.position.set(2.5, 0.1, -14);
  box.rotation.y = 0.5;
  scene.add(box);
}

async function setup(options: SetupOptions): Promise<void> {
  renderer?.dispose();
  renderer?.domElement.remove();
  ocean?.dispose();
  scene.clear();
  renderer = new WebGLRenderer();
  renderer.setPixelRatio(1);
  renderer.setSize(options.width, options.height);
  document.body.append(renderer.domElement);
  renderer.outputColorSpace = options.output === 'linear' ? LinearSRGBColorSpace : SRGBColorSpace;
  renderer.toneMapping = options.output === 'linear' ? NoToneMapping : renderer.toneMapping;
  scene.background = new Color(0xff00ff); // the capture must not show it
  ocean = new Ocean(renderer, { ...options.ocean, worker: false });
  scene.add(ocean);
  if (options.skyGrey !== undefined) {
    const url = greyImage(options.skyGrey);
    await ocean.sky.loadFaces({ px: url, nx: url, py: url, ny: url, pz: url, nz: url });
  }
  if (options.content === 'plate') scene.add(plate);
  else if (options.content === 'box') scene.add(box);
  else if (options.content === 'sunk') scene.add(sunk);
  else if (options.content === 'raised') scene.add(raised);
  else if (options.content === 'showcase') showcase();
  camera.fov = options.camera.fov;
  camera.aspect = options.width / options.height;
  camera.near = 0.1;
  camera.far = 1e5;
  camera.position.fromArray(options.camera.position);
  camera.lookAt(new Vector3(...options.camera.lookAt));
  camera.updateProjectionMatrix();
  camera.updateMatrixWorld();
}

/**
 * Draws a frame (the plate at `plateDepth` metres under the sea) and reads the canvas at `pixels`
 * ([x, y] from the bottom left), in the output's values 0..1; with each, the direction of the ray
 * from the eye through that pixel's centre.
 */
function draw(plateDepth: number, pixels: [number, number][]): { colours: Vec3[]; rays: Vec3[]; eye: Vec3; captured: boolean } {
  plate.position.y = -plateDepth;
  ocean!.update(1, camera);
  renderer!.render(scene, camera);
  const gl = renderer!.getContext();
  const { width, height } = renderer!.domElement;
  const colours = pixels.map(([x, y]) => {
    const texel = new Uint8Array(4);
    gl.readPixels(x, y, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, texel);
    return [texel[0] / 255, texel[1] / 255, texel[2] / 255] as Vec3;
  });
  const rays = pixels.map(([x, y]) => {
    const point = new Vector3(((x + 0.5) / width) * 2 - 1, ((y + 0.5) / height) * 2 - 1, 0.5).unproject(camera);
    return point.sub(camera.position).normalize().toArray() as Vec3;
  });
  return { colours, rays, eye: camera.position.toArray() as Vec3, captured: ocean!.surface.refraction.renderTarget !== null };
}

/** setShading's error for `changes` (its parameter and message), or null if it took them; and the refractions in force. */
function setShading(changes: Record<string, unknown>): { error: { parameter: string; message: string } | null; refractions: string } {
  let error = null;
  try {
    ocean!.setShading(changes);
  } catch (caught) {
    if (!(caught instanceof ParameterError)) throw caught;
    error = { parameter: caught.parameter, message: caught.message };
  }
  return { error, refractions: ocean!.shading.refractions };
}

/** The constructor's error for `options`, or null. */
function construct(options: Record<string, unknown>): { parameter: string; message: string } | null {
  const own = new WebGLRenderer();
  try {
    new Ocean(own, options as OceanOptions).dispose();
    return null;
  } catch (caught) {
    if (!(caught instanceof ParameterError)) throw caught;
    return { parameter: caught.parameter, message: caught.message };
  } finally {
    own.dispose();
  }
}

/** The pixel [x, y] (from the bottom left) where the world point `point` is drawn. */
function pixelOf(point: Vec3): [number, number] {
  const ndc = new Vector3(...point).project(camera);
  const { width, height } = renderer!.domElement;
  return [Math.floor(((ndc.x + 1) / 2) * width), Math.floor(((ndc.y + 1) / 2) * height)];
}

/** The whole canvas (RGBA rows from the bottom, base64) after a frame at time t, and whether the refraction drew its capture. */
function picture(t: number): { pixels: string; captured: boolean } {
  ocean!.update(t, camera);
  renderer!.render(scene, camera);
  const gl = renderer!.getContext();
  const { width, height } = renderer!.domElement;
  const data = new Uint8Array(4 * width * height);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, data);
  let text = '';
  for (let i = 0; i < data.length; i += 0x8000) text += String.fromCharCode(...data.subarray(i, i + 0x8000));
  return { pixels: btoa(text), captured: ocean!.surface.refraction.uniforms.sceneCaptured.value };
}

/** An object on layer 1, which neither the camera nor the captures draw: a scene that holds more than seas, but whose captures are empty. */
const unseen = new Mesh(new BoxGeometry(1, 1, 1), new MeshBasicMaterial({ color: 0xff0000 }));
unseen.layers.set(1);
unseen.position.set(0, 1, -5);

/** Puts the unseen object in the scene, or takes it out. */
function withUnseenObject(present: boolean): void {
  if (present) scene.add(unseen);
  else scene.remove(unseen);
}

/**
 * The picture at time t with a second Ocean in the scene (or without, `second` false), the second
 * drawn only on layer 1, which the camera leaves out and the first sea's refraction capture takes
 * (its layers 0 and 1): whatever of the second sea a capture shows changes the first sea's picture.
 */
function withSecondSea(second: boolean, t: number): { pixels: string; captured: boolean } {
  const own = ocean!;
  own.surface.refraction.layers = { mask: 0b11 };
  const other = second ? new Ocean(renderer!, { windSpeed: 6, resolution: 32, seed: 9, localWaves: false, worker: false }) : null;
  try {
    if (other !== null) {
      other.traverse((object) => object.layers.set(1));
      scene.add(other);
      other.update(t, camera);
    }
    return picture(t);
  } finally {
    own.surface.refraction.layers = null;
    if (other !== null) {
      scene.remove(other);
      other.dispose();
    }
  }
}

const harness = { setup, draw, setShading, construct, pixelOf, picture, withUnseenObject, withSecondSea };
declare global {
  interface Window {
    refractionHarness: typeof harness;
  }
}
window.refractionHarness = harness;
document.title = 'ready';
