/**
 * The device factory (src/device/deviceFor.ts): each entry point takes three's renderer it draws
 * with, and a renderer of the other kind is refused with an UnsupportedError that names the entry
 * point to use instead; anything else is refused as not a renderer. Renderers are recognised by
 * three's flags, as three itself does; the real renderers are tried in the browser suites
 * (tests/browser/ocean/ocean.spec.ts, tests/browser/webgpu/webgpu.spec.ts).
 */
import { describe, expect, it } from 'vitest';
import { checkRenderer, createGpuDevice, rendererKind } from '../../src/device/deviceFor';
import { WebGL2Device } from '../../src/device/webgl2/webgl2Device';
import { UnsupportedError } from '../../src/parameters/options';

/** three's flags on its two renderers (WebGPURenderer inherits isRenderer from Renderer). */
const WEBGL = { isWebGLRenderer: true };
const WEBGPU = { isRenderer: true, isWebGPURenderer: true };
const NOT_RENDERERS = [undefined, null, {}, 12, 'webgl', { isWebGLRenderer: 'yes' }];

describe('rendererKind', () => {
  it("tells three's two renderers apart by their flags, and nothing else is one", () => {
    expect(rendererKind(WEBGL)).toBe('WebGLRenderer');
    expect(rendererKind(WEBGPU)).toBe('WebGPURenderer');
    expect(rendererKind({ isRenderer: true })).toBe('WebGPURenderer');
    for (const other of NOT_RENDERERS) expect(rendererKind(other)).toBeNull();
  });
});

describe('checkRenderer', () => {
  it('accepts the renderer each entry point draws with', () => {
    expect(() => checkRenderer(WEBGL, 'three-fft-ocean')).not.toThrow();
    expect(() => checkRenderer(WEBGPU, 'three-fft-ocean/webgpu')).not.toThrow();
  });

  it("refuses the other renderer with an UnsupportedError that names the entry point for it", () => {
    const webgpuToWebGL = () => checkRenderer(WEBGPU, 'three-fft-ocean');
    expect(webgpuToWebGL).toThrow(UnsupportedError);
    expect(webgpuToWebGL).toThrow("renderer: three-fft-ocean's Ocean draws with three.js's WebGLRenderer (import { WebGLRenderer } from 'three'); this is three.js's WebGPURenderer: use the Ocean of three-fft-ocean/webgpu for it");
    const webglToWebGPU = () => checkRenderer(WEBGL, 'three-fft-ocean/webgpu');
    expect(webglToWebGPU).toThrow(UnsupportedError);
    expect(webglToWebGPU).toThrow("renderer: three-fft-ocean/webgpu's Ocean draws with three.js's WebGPURenderer (import { WebGPURenderer } from 'three/webgpu'); this is three.js's WebGLRenderer: use the Ocean of three-fft-ocean for it");
  });

  it('refuses anything else as not a renderer, naming the parameter', () => {
    for (const entry of ['three-fft-ocean', 'three-fft-ocean/webgpu'] as const) {
      for (const other of NOT_RENDERERS) {
        const check = () => checkRenderer(other, entry);
        expect(check).toThrow(UnsupportedError);
        expect(check).toThrow(/^renderer: .*this is not a three.js renderer$/);
      }
    }
  });
});

describe('createGpuDevice', () => {
  it('makes a WebGL2Device for a WebGLRenderer, and refuses the WebGPURenderer and non-renderers as checkRenderer does', () => {
    const device = createGpuDevice(WEBGL);
    expect(device).toBeInstanceOf(WebGL2Device);
    expect(device.renderer).toBe(WEBGL);
    device.dispose();
    expect(() => createGpuDevice(WEBGPU)).toThrow('use the Ocean of three-fft-ocean/webgpu for it');
    expect(() => createGpuDevice(null)).toThrow('this is not a three.js renderer');
  });
});
