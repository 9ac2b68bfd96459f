import { spawnSync } from 'node:child_process';
import { existsSync, readdirSync, statSync } from 'node:fs';
import { join, resolve } from 'node:path';

/** The repository's root. */
const ROOT = resolve(import.meta.dirname, '../../..');
/** What the library is built from: if any is newer than the bundle, build again. */
const SOURCES = ['src', 'shaders', 'vite.config.ts', 'tsconfig.build.json', 'package.json'];
const BUNDLE = join(ROOT, 'dist/lib/three-fft-ocean.js');

/** Newest modification time of the files the library is built from. */
function newestSource(): number {
  let newest = 0;
  const visit = (path: string) => {
    if (!existsSync(path)) return;
    const info = statSync(path);
    if (info.isDirectory()) for (const entry of readdirSync(path)) visit(join(path, entry));
    else newest = Math.max(newest, info.mtimeMs);
  };
  for (const path of SOURCES) visit(join(ROOT, path));
  return newest;
}

/**
 * Builds the library into dist/lib with `npm run build:lib` (vite build --mode lib, which empties
 * dist/lib first, then the tsc declarations), unless the bundle is at least as new as every source
 * file. The specs that test build output (examples, package) share one build a run.
 */
export function ensureBuiltLibrary(): void {
  if (existsSync(BUNDLE) && statSync(BUNDLE).mtimeMs >= newestSource()) return;
  const result = spawnSync('npm', ['run', 'build:lib'], { cwd: ROOT, encoding: 'utf8' });
  if (result.status !== 0) throw new Error(`npm run build:lib failed:\n${result.stdout}\n${result.stderr}`);
}
