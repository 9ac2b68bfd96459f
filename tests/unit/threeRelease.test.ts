/**
 * The three.js releases the package claims are the ones it checks at run time and the ones CI
 * tests: package.json's peer range is THREE_PEER_RANGE, open above; the devDependency the browser
 * suite runs is the newest tested release; a release older than the range gets an UnsupportedError
 * naming it and the range (from the check itself, and from constructing an Ocean, before the
 * renderer is touched); a newer one runs after one console note. Whether the GPU FFT may run on it
 * is decided by its internals alone (missingThreeInternals). (Which renderer each Ocean takes:
 * deviceFor.test.ts.)
 */
import { readFileSync } from 'node:fs';
import type { WebGLRenderer } from 'three';
import { afterEach, describe, expect, it, vi } from 'vitest';
import { missingThreeInternals } from '../../src/device/webgl2/threeInternals';
import { checkThreeRelease, SUPPORTED_THREE_RELEASES, THREE_PEER_RANGE } from '../../src/threeRelease';
import { UnsupportedError } from '../../src/parameters/options';
import { Ocean } from '../../src/ocean';

const packageJson = JSON.parse(readFileSync(new URL('../../package.json', import.meta.url), 'utf8')) as {
  peerDependencies: Record<string, string>;
  devDependencies: Record<string, string>;
};

describe('the supported three.js releases', () => {
  it("are package.json's peer range, with no upper bound", () => {
    expect(packageJson.peerDependencies.three).toBe(THREE_PEER_RANGE);
    expect(THREE_PEER_RANGE).toBe('>=0.180.0');
  });

  it('name as newest tested the release the browser suite runs (the devDependency)', () => {
    expect(packageJson.devDependencies.three).toMatch(new RegExp(`^0\\.${SUPPORTED_THREE_RELEASES.newestTested}\\.\\d+$`));
  });
});

describe('checkThreeRelease', () => {
  afterEach(() => vi.restoreAllMocks());

  it('accepts the oldest and the newest tested release and those between, silently', () => {
    const info = vi.spyOn(console, 'info').mockImplementation(() => {});
    for (const revision of ['180', '183', '187']) expect(() => checkThreeRelease(revision)).not.toThrow();
    expect(info).not.toHaveBeenCalled();
  });

  it('refuses a release older than the range with an UnsupportedError naming it and the range', () => {
    for (const revision of ['160', '176', '179', '179dev', 'r', '']) {
      const check = () => checkThreeRelease(revision);
      expect(check).toThrow(UnsupportedError);
      expect(check).toThrow(`three-fft-ocean supports three.js r180 and newer (>=0.180.0), not r${revision}`);
    }
  });

  it('runs a release newer than the newest tested, with one console note per release', () => {
    const info = vi.spyOn(console, 'info').mockImplementation(() => {});
    for (const revision of ['188', '188dev', '1000', '188']) expect(() => checkThreeRelease(revision)).not.toThrow();
    expect(info).toHaveBeenCalledTimes(3);
    expect(info.mock.calls[0][0]).toBe(
      "three-fft-ocean: three.js r188 is newer than the newest release tested (r187); running, with the GPU FFT where three.js's internals still fit it.",
    );
  });

  it('accepts the three.js these tests run', () => {
    expect(() => checkThreeRelease()).not.toThrow();
  });
});

describe("three.js's internals the GPU FFT reaches into", () => {
  const complete = () => ({ initRenderTarget() {}, setRenderTargetFramebuffer() {}, properties: { get: () => ({}) } });

  it('are all there: nothing missing', () => {
    expect(missingThreeInternals(complete() as never)).toBeNull();
  });

  for (const gone of ['initRenderTarget', 'setRenderTargetFramebuffer', 'properties'] as const) {
    it(`without ${gone}: the reason names it`, () => {
      const renderer: Record<string, unknown> = complete();
      delete renderer[gone];
      expect(missingThreeInternals(renderer as never)).toContain(`WebGLRenderer.${gone}`);
    });
  }
});

describe('an Ocean on a three.js older than the range', () => {
  afterEach(() => {
    vi.doUnmock('three');
    vi.resetModules();
  });

  it('throws the UnsupportedError for r179 before it touches the renderer', async () => {
    vi.resetModules();
    vi.doMock('three', async (importOriginal) => ({ ...(await importOriginal<typeof import('three')>()), REVISION: '179' }));
    const { Ocean } = await import('../../src/ocean');
    const { UnsupportedError: ErrorOfThisImport } = await import('../../src/parameters/options');
    const construct = () => new Ocean({} as WebGLRenderer);
    expect(construct).toThrow(ErrorOfThisImport);
    expect(construct).toThrow('not r179');
  });
});

describe('an Ocean given a renderer it cannot drive', () => {
  it('throws an UnsupportedError naming the entry point for it, not a TypeError from inside three.js', () => {
    const construct = () => new Ocean({ isRenderer: true, isWebGPURenderer: true } as unknown as WebGLRenderer);
    expect(construct).toThrow(UnsupportedError);
    expect(construct).toThrow("this is three.js's WebGPURenderer: use the Ocean of three-fft-ocean/webgpu for it");
  });
});
