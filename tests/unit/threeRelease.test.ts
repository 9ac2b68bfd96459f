/**
 * The three.js releases the package claims are the ones it checks at run time and the ones CI
 * tests: package.json's peer range is THREE_PEER_RANGE, the devDependency the browser suite runs is
 * its newest release, and a release outside it gets an UnsupportedError naming it and the range
 * (from the check itself, and from constructing an Ocean, before the renderer is touched).
 */
import { readFileSync } from 'node:fs';
import type { WebGLRenderer } from 'three';
import { afterEach, describe, expect, it, vi } from 'vitest';
import { checkThreeRelease, SUPPORTED_THREE_RELEASES, THREE_PEER_RANGE } from '../../src/fft/threeInternals';
import { UnsupportedError } from '../../src/parameters/options';

const packageJson = JSON.parse(readFileSync(new URL('../../package.json', import.meta.url), 'utf8')) as {
  peerDependencies: Record<string, string>;
  devDependencies: Record<string, string>;
};

describe('the supported three.js releases', () => {
  it('are package.json\'s peer range', () => {
    expect(packageJson.peerDependencies.three).toBe(THREE_PEER_RANGE);
  });

  it('end with the release the browser suite runs (the devDependency)', () => {
    expect(packageJson.devDependencies.three).toMatch(new RegExp(`^0\\.${SUPPORTED_THREE_RELEASES.newest}\\.\\d+$`));
  });
});

describe('checkThreeRelease', () => {
  it('accepts the oldest and the newest supported release and those between', () => {
    for (const revision of ['180', '183', '187']) expect(() => checkThreeRelease(revision)).not.toThrow();
  });

  it('refuses a release outside the range with an UnsupportedError naming it and the range', () => {
    for (const revision of ['160', '176', '179', '188', '188dev', '1000', 'r', '']) {
      const check = () => checkThreeRelease(revision);
      expect(check).toThrow(UnsupportedError);
      expect(check).toThrow(`three-fft-ocean supports three.js r180 to r187 (>=0.180.0 <0.188.0), not r${revision}`);
    }
  });

  it('accepts the three.js these tests run', () => {
    expect(() => checkThreeRelease()).not.toThrow();
  });
});

describe('an Ocean on a three.js outside the range', () => {
  afterEach(() => {
    vi.doUnmock('three');
    vi.resetModules();
  });

  for (const revision of ['179', '188']) {
    it(`throws the UnsupportedError for r${revision} before it touches the renderer`, async () => {
      vi.resetModules();
      vi.doMock('three', async (importOriginal) => ({ ...(await importOriginal<typeof import('three')>()), REVISION: revision }));
      const { Ocean } = await import('../../src/ocean');
      const { UnsupportedError: ErrorOfThisImport } = await import('../../src/parameters/options');
      const construct = () => new Ocean({} as WebGLRenderer);
      expect(construct).toThrow(ErrorOfThisImport);
      expect(construct).toThrow(`not r${revision}`);
    });
  }
});
