/** The canvas's pixels right after a frame's render, for the browser tests (oceanApp.capturePixels). */
import type { WebGLRenderer } from 'three';

export interface Pixels {
  width: number;
  height: number;
  /** RGBA, bottom row first. */
  data: Uint8Array;
}

export class PixelCapture {
  private pending: ((pixels: Pixels) => void)[] = [];

  /** The canvas's pixels right after the next frame's render. */
  request(): Promise<Pixels> {
    return new Promise((resolve) => this.pending.push(resolve));
  }

  /** Called right after a frame's render: reads the canvas if anyone asked. */
  afterRender(renderer: WebGLRenderer): void {
    if (this.pending.length === 0) return;
    const pixels = readCanvas(renderer);
    for (const resolve of this.pending) resolve(pixels);
    this.pending = [];
  }
}

function readCanvas(renderer: WebGLRenderer): Pixels {
  const gl = renderer.getContext();
  renderer.setRenderTarget(null);
  const width = gl.drawingBufferWidth;
  const height = gl.drawingBufferHeight;
  const data = new Uint8Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, data);
  return { width, height, data };
}
