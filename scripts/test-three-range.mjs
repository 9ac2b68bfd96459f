/**
 * The last step of `npm test`: the browser tests tagged @three-range (the GPU FFT against the JS
 * one, geometry and shading read back from the GPU, the screenshots) against the oldest three.js
 * release package.json's peerDependencies.three admits. The rest of the suite runs the newest, the
 * devDependency. This installs the release from the registry into .three-releases/<version>
 * (recorded nowhere else) and has Playwright start a dev server that serves it in place of the
 * devDependency (THREE_FFT_OCEAN_THREE, read in vite.config.ts).
 *
 * `node scripts/test-three-range.mjs <version>` runs the same tests against another release, to try
 * one before moving the range (widen SUPPORTED_THREE_RELEASES in src/fft/threeInternals.ts first,
 * or the Ocean refuses it).
 */
import { spawnSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';

const root = resolve(import.meta.dirname, '..');
const readVersion = (folder, field) => JSON.parse(readFileSync(resolve(folder, 'package.json'), 'utf8'))[field];

const peerRange = readVersion(root, 'peerDependencies').three;
const oldest = /^>=(0\.\d+\.0) <0\.\d+\.0$/.exec(peerRange)?.[1];
if (oldest === undefined) throw new Error(`package.json: peerDependencies.three is "${peerRange}", not ">=0.A.0 <0.B.0"`);
const version = process.argv[2] ?? oldest;

const prefix = resolve(root, '.three-releases', version);
run('npm', ['install', '--no-save', '--no-package-lock', '--no-audit', '--no-fund', '--prefix', prefix, `three@${version}`]);
const three = resolve(prefix, 'node_modules/three');
const installed = readVersion(three, 'version');
if (installed !== version) throw new Error(`${three} holds three ${installed}, not ${version}`);

console.log(`Browser tests tagged @three-range against three ${version}`);
run('npx', ['playwright', 'test', '--grep', '@three-range', '--output', `test-results-three-${version}`], { ...process.env, THREE_FFT_OCEAN_THREE: three });

function run(command, args, env = process.env) {
  const { status, error } = spawnSync(command, args, { cwd: root, env, stdio: 'inherit' });
  if (error) throw error;
  if (status !== 0) process.exit(status ?? 1);
}
