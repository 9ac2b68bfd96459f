/**
 * Test page for the embeddable parts: <fft-ocean> (registered as on any page) and the Ocean
 * object on a renderer of the test's own, with pixel and memory probes for the Playwright tests
 * (embed.spec.ts, lifecycle.spec.ts).
 */
import { BoxGeometry, Mesh, MeshBasicMaterial, PerspectiveCamera, RenderTarget, Scene, SRGBColorSpace, WebGLRenderer } from 'three';
import '../../../src/embed/register';
import { defineFftOceanElement, FftOceanElement } from '../../../src/embed/fftOceanElement';
import { Ocean } from '../../../src/index';

/** Brightness statistics of what `el` draws now (drawn synchronously, read back at once). */
function pixels(el: FftOceanElement, grid = 16): { width: number; height: number; mean: number; spread: number; samples: number[] } {
  if (!el.renderFrame()) throw new Error('the element has nothing to draw into');
  const gl = el.renderer!.getContext();
  const width = gl.drawingBufferWidth;
  const height = gl.drawingBufferHeight;
  const data = new Uint8Array(4 * width * height);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, data);
  // Mean RGB of each cell of a grid × grid partition: a coarse, alignment-tolerant fingerprint.
  const samples: number[] = [];
  for (let gy = 0; gy < grid; gy++) {
    for (let gx = 0; gx < grid; gx++) {
      let sum = 0;
      let count = 0;
      for (let y = Math.floor((gy * height) / grid); y < Math.floor(((gy + 1) * height) / grid); y++) {
        for (let x = Math.floor((gx * width) / grid); x < Math.floor(((gx + 1) * width) / grid); x++) {
          const i = 4 * (y * width + x);
          sum += data[i] + data[i + 1] + data[i + 2];
          count += 3;
        }
      }
      samples.push(sum / count);
    }
  }
  const mean = samples.reduce((a, b) => a + b, 0) / samples.length;
  const spread = Math.sqrt(samples.reduce((a, b) => a + (b - mean) ** 2, 0) / samples.length);
  return { width, height, mean, spread, samples };
}

/** Resolves after `count` animation frames. */
function frames(count: number): Promise<void> {
  return new Promise((resolve) => {
    const step = () => (--count <= 0 ? resolve() : requestAnimationFrame(step));
    requestAnimationFrame(step);
  });
}

/**
 * Creates `<fft-ocean>` with these attributes inside `parent` (default #box), at the fixed quality
 * level high unless they give one: 'auto' would lower the render scale, grid and cascades within
 * seconds under SwiftShader, and the tests compare pictures and fields over longer.
 */
function create(attributes: Record<string, string> = {}, parent: Element = document.querySelector('#box')!): FftOceanElement {
  const el = document.createElement('fft-ocean');
  for (const [name, value] of Object.entries({ quality: 'high', ...attributes })) el.setAttribute(name, value);
  parent.append(el);
  return el;
}

/** Waits until `el` has drawn at least `count` frames (or rejects after `timeout` ms). */
async function drawn(el: FftOceanElement, count = 1, timeout = 20_000): Promise<void> {
  const start = performance.now();
  while (el.frameCount < count) {
    if (performance.now() - start > timeout) throw new Error(`only ${el.frameCount} frames drawn in ${timeout} ms`);
    await frames(1);
  }
}

/**
 * Sets the page back as it loaded, for the next test of a spec file that shares it: no element
 * (each one removed frees its renderer and context), nothing else a test added to the body, the
 * page scrolled to its top.
 */
async function reset(): Promise<void> {
  for (const child of [...document.body.children]) if (child.id !== 'box' && child.tagName !== 'SCRIPT') child.remove();
  document.querySelector('#box')!.replaceChildren();
  scrollTo(0, 0);
  await frames(2); // the removed elements have freed what they held (a microtask after removal)
}

const harness = { Ocean, FftOceanElement, WebGLRenderer, Scene, PerspectiveCamera, Mesh, BoxGeometry, MeshBasicMaterial, RenderTarget, SRGBColorSpace, defineFftOceanElement, pixels, frames, create, drawn, reset };

declare global {
  interface Window {
    embed: typeof harness;
  }
}
window.embed = harness;
document.title = 'ready';
