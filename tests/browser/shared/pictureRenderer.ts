import { ACESFilmicToneMapping, PerspectiveCamera, Scene, SRGBColorSpace, WebGLRenderer } from 'three';

/**
 * The renderer, scene and camera of a page that draws pictures of the sea to read back (beaufort,
 * lighting): a canvas in the page kept after each draw (toDataURL), tone-mapped and in sRGB as the
 * app draws, one pixel per canvas pixel; each draw sets the size and the camera.
 */
export function pictureRenderer(): { canvas: HTMLCanvasElement; renderer: WebGLRenderer; scene: Scene; camera: PerspectiveCamera } {
  const canvas = document.createElement('canvas');
  document.body.append(canvas);
  const renderer = new WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true });
  renderer.toneMapping = ACESFilmicToneMapping;
  renderer.outputColorSpace = SRGBColorSpace;
  renderer.setPixelRatio(1);
  return { canvas, renderer, scene: new Scene(), camera: new PerspectiveCamera(50, 1, 0.5, 100_000) };
}
