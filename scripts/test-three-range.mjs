/**
 * The last step of `npm test`: the browser tests tagged @three-range (the GPU FFT against the JS
 * one, geometry and shading read back from the GPU, the screenshots) against the other three.js
 * releases the peer range admits. The rest of the suite runs the devDependency (the newest tested
 * release). Here run:
 *   - the oldest release, the lower end of package.json's peerDependencies.three;
 *   - the newest release on the registry (`npm view three version`) when it is newer than the
 *     devDependency: the range is open above, so a user installing today gets that one.
 * Each is installed from the registry into .three-releases/<version> (recorded nowhere else), and
 * Playwright starts a dev server that serves it in place of the devDependency
 * (THREE_FFT_OCEAN_THREE, read in vite.config.ts).
 *
 * `node scripts/test-three-range.mjs <version>` runs the same tests against that release alone.
 */
import { spawnSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';

const root = resolve(import.meta.dirname, '..');
const readPackage = (folder) => JSON.parse(readFileSync(resolve(folder, 'package.json'), 'utf8'));

const ownPackage = readPackage(root);
const peerRange = ownPackage.peerDependencies.three;
const oldest = /^>=(0\.\d+\.0)$/.exec(peerRange)?.[1];
if (oldest === undefined) throw new Error(`package.json: peerDependencies.three is "${peerRange}", not ">=0.A.0"`);
const tested = ownPackage.devDependencies.three;

const releases = process.argv[2] ? [process.argv[2]] : [oldest, ...newerOnRegistry()];
for (const version of releases) testAgainst(version);

/** The registry's newest three.js, when it is newer than the devDependency (else nothing). */
function newerOnRegistry() {
  const { stdout, status } = spawnSync('npm', ['view', 'three', 'version'], { cwd: root, encoding: 'utf8' });
  if (status !== 0) throw new Error('npm view three version failed: the newest release on the registry is unknown');
  const newest = stdout.trim();
  // Versions compared part by part as numbers ('0.187.1' > '0.187.0', '0.190.0' > '0.187.0').
  if (newest.localeCompare(tested, 'en', { numeric: true }) > 0) return [newest];
  console.log(`The newest three.js on the registry is ${newest}, the devDependency the suite already ran (${tested}).`);
  return [];
}

function testAgainst(version) {
  const prefix = resolve(root, '.three-releases', version);
  run('npm', ['install', '--no-save', '--no-package-lock', '--no-audit', '--no-fund', '--prefix', prefix, `three@${version}`]);
  const three = resolve(prefix, 'node_modules/three');
  const installed = readPackage(three).version;
  if (installed !== version) throw new Error(`${three} holds three ${installed}, not ${version}`);
  console.log(`Browser tests tagged @three-range against three ${version}`);
  run('npx', ['playwright', 'test', '--grep', '@three-range', '--output', `test-results-three-${version}`], { ...process.env, THREE_FFT_OCEAN_THREE: three });
}

function run(command, args, env = process.env) {
  const { status, error } = spawnSync(command, args, { cwd: root, env, stdio: 'inherit' });
  if (error) throw error;
  if (status !== 0) process.exit(status ?? 1);
}
