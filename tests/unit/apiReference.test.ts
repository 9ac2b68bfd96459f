/**
 * The API reference in docs/api/ is generated from the TSDoc of the package's public entries
 * (typedoc.json). This test generates it again into a temporary folder, with the same command as
 * `npm run docs:api`, and fails when a committed file differs or is missing or extra, naming it:
 * after changing the public API or its TSDoc, run `npm run docs:api` and commit docs/api/.
 * TypeDoc's warnings are errors (typedoc.json), so a broken {@link} fails here too.
 */
import { execFile } from 'node:child_process';
import { mkdtempSync, readdirSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, relative, sep } from 'node:path';
import { fileURLToPath } from 'node:url';
import { promisify } from 'node:util';
import { afterAll, describe, expect, it } from 'vitest';

const root = fileURLToPath(new URL('../../', import.meta.url));
const committed = join(root, 'docs', 'api');
const typedocCli = join(root, 'node_modules', 'typedoc', 'bin', 'typedoc');

/** Every file under `dir`, as paths relative to it with forward slashes, sorted. */
function filesUnder(dir: string): string[] {
  return readdirSync(dir, { recursive: true, withFileTypes: true })
    .filter((entry) => entry.isFile())
    .map((entry) => relative(dir, join(entry.parentPath, entry.name)).split(sep).join('/'))
    .sort();
}

/** Where two texts first differ, as "line n: expected … / generated …". */
function firstDifference(expected: string, actual: string): string {
  const a = expected.split('\n');
  const b = actual.split('\n');
  for (let i = 0; i < Math.max(a.length, b.length); i++) {
    if (a[i] !== b[i]) return `line ${i + 1}:\n  committed: ${JSON.stringify(a[i])}\n  generated: ${JSON.stringify(b[i])}`;
  }
  return 'same lines';
}

describe('API reference (docs/api/)', () => {
  const out = mkdtempSync(join(tmpdir(), 'three-fft-ocean-api-'));
  afterAll(() => rmSync(out, { recursive: true, force: true }));

  it(
    'is what TypeDoc makes of src/ now (else: npm run docs:api)',
    async () => {
      try {
        await promisify(execFile)(process.execPath, [typedocCli, '--out', out, '--logLevel', 'Warn'], { cwd: root });
      } catch (error) {
        const { stdout = '', stderr = '' } = error as { stdout?: string; stderr?: string };
        throw new Error(`TypeDoc failed (warnings are errors; see typedoc.json):\n${stdout}${stderr}`);
      }

      const expected = filesUnder(committed);
      const generated = filesUnder(out);
      const missing = generated.filter((file) => !expected.includes(file));
      const extra = expected.filter((file) => !generated.includes(file));
      const differing = generated
        .filter((file) => expected.includes(file))
        .flatMap((file) => {
          const was = readFileSync(join(committed, file), 'utf8');
          const now = readFileSync(join(out, file), 'utf8');
          return was === now ? [] : [`docs/api/${file}, ${firstDifference(was, now)}`];
        });

      const problems = [
        ...missing.map((file) => `docs/api/${file} is missing (TypeDoc writes it)`),
        ...extra.map((file) => `docs/api/${file} is extra (TypeDoc no longer writes it)`),
        ...differing.map((difference) => `differs: ${difference}`),
      ];
      expect(problems, 'docs/api/ is stale: run `npm run docs:api` and commit it').toEqual([]);
      expect(generated.length).toBeGreaterThan(0);
    },
    // Only stops a hang (vitest.config.ts): TypeDoc compiles and checks all of src/, which took
    // 65 s at load 18 on this 2-core machine, past the default 120 s on a busier or slower one.
    300_000,
  );
});
