/**
 * The three.js releases this package supports (which renderer it drives: src/device/deviceFor.ts).
 * What it reaches into beyond three.js's public API is src/device/webgl2/threeInternals.ts.
 *
 * Releases before r180 are refused (checkThreeRelease, from the Ocean), as they draw no sea or a
 * wrong one: r160 to r164 lack what the GPU FFT uses; up to r176 a WebGLArrayRenderTarget ignores
 * its texture options, so the FFT's working layers are 8-bit and the sea a smear; up to r179
 * three.js's logarithmic depth chunks answer to another define (USE_LOGDEPTHBUF), so with
 * logarithmicDepthBuffer the sea's shaders do not compile. Releases after the newest tested one
 * run: three.js ships every few weeks, and a package that refused the next release would break
 * every new install. What could break there is only what the WebGL 2 device reaches into, so its
 * check of three.js's internals (WebGL2Device.unavailableReason) decides whether the GPU FFT may
 * run; without them the path 'auto' (and 'gpu') falls back to JS and says why
 * (ocean.simulation.pathReason, the app's status line).
 */
import { REVISION } from 'three';
import { UnsupportedError } from './parameters/options';

/**
 * The oldest three.js release supported and the newest tested: the browser tests run against the
 * devDependency (the newest tested) and, through scripts/test-three-range.mjs, the oldest and the
 * newest on the registry when it is newer.
 */
export const SUPPORTED_THREE_RELEASES = { oldest: 180, newestTested: 187 } as const;

/** The releases as an npm range, open above: package.json's peerDependencies.three (a unit test compares them). */
export const THREE_PEER_RANGE = `>=0.${SUPPORTED_THREE_RELEASES.oldest}.0`;

/** The releases already told about in this page: the note comes once. */
const notedReleases = new Set<string>();

/**
 * Throws an UnsupportedError naming the release and the range when `revision` (three.js's
 * REVISION: '187', or '188dev' for a build between releases) is older than the oldest supported;
 * for a release newer than the newest tested, logs one console note and returns.
 */
export function checkThreeRelease(revision: string = REVISION): void {
  const release = Number.parseInt(revision, 10);
  const { oldest, newestTested } = SUPPORTED_THREE_RELEASES;
  if (!(release >= oldest)) {
    throw new UnsupportedError('three.js', `three-fft-ocean supports three.js r${oldest} and newer (${THREE_PEER_RANGE}), not r${revision}`);
  }
  if (release > newestTested && !notedReleases.has(revision)) {
    notedReleases.add(revision);
    console.info(`three-fft-ocean: three.js r${revision} is newer than the newest release tested (r${newestTested}); running, with the GPU FFT where three.js's internals still fit it.`);
  }
}

