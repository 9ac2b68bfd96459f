/**
 * The paths the repository names must exist, so that a reader who follows one finds the file.
 *
 * 1. Every repository path in a comment of the code (src/, shaders/, scripts/, bench/, tests/,
 *    examples/) and anywhere in a Markdown page (README.md, docs/): a token that starts with one of
 *    the top folders (src/, tests/, shaders/, docs/, scripts/, bench/, examples/, public/). With a
 *    file extension it must be a file, with a trailing slash a folder, otherwise either. Source
 *    files named without a folder (`fftCascade.ts`) must exist somewhere in those folders.
 *    The one allowance: a token that is clearly a pattern, with a placeholder (`<name>`, `*` or
 *    `…`: `docs/sea-states/<name>.png`, `docs/*.md`), names a folder and what lies in it; the
 *    folder before the first placeholder must exist (so `src/sim/…` fails: there is no src/sim).
 *    CHANGELOG.md is not read: it is history, and may name files that have since been removed or
 *    renamed.
 * 2. Every page of the guide (docs/*.md) is linked from README.md, and every relative link and
 *    picture in README.md and docs/*.md resolves to a file, and its #anchor, if it has one, to a
 *    heading of that page.
 */
import { existsSync, readdirSync, readFileSync, statSync } from 'node:fs';
import { basename, dirname, extname, join, relative, resolve } from 'node:path';
import { describe, expect, it } from 'vitest';

const root = resolve(import.meta.dirname, '../..');
const TOP_FOLDERS = ['src', 'tests', 'shaders', 'docs', 'scripts', 'bench', 'examples', 'public'];
const CODE_FOLDERS = ['src', 'shaders', 'scripts', 'bench', 'tests', 'examples'];
const CODE_EXTENSIONS = new Set(['.ts', '.mts', '.mjs', '.js', '.glsl', '.frag', '.vert', '.css', '.html']);
/** Folders under the code folders that hold no sources of ours (generated output, baselines). */
const SKIPPED = new Set(['node_modules', 'dist', 'screenshots.spec.ts-snapshots']);

/** Every file under `dir` (relative to the repository root), skipping SKIPPED folders. */
function filesUnder(dir: string): string[] {
  const out: string[] = [];
  for (const entry of readdirSync(join(root, dir), { withFileTypes: true })) {
    const path = `${dir}/${entry.name}`;
    if (entry.isDirectory()) {
      if (!SKIPPED.has(entry.name)) out.push(...filesUnder(path));
    } else out.push(path);
  }
  return out;
}

const codeFiles = CODE_FOLDERS.flatMap(filesUnder).filter((path) => CODE_EXTENSIONS.has(extname(path)));
const guidePages = readdirSync(join(root, 'docs'))
  .filter((name) => name.endsWith('.md'))
  .map((name) => `docs/${name}`);
const markdownPages = ['README.md', ...filesUnder('docs').filter((path) => path.endsWith('.md'))];
/** Every file's name in the code folders and docs, for names given without a folder. */
const knownNames = new Set([...codeFiles, ...filesUnder('docs'), ...filesUnder('public')].map((path) => basename(path)));

/** The comments of a source file: `// …`, `/* … *\/` and `<!-- … -->`, joined by newlines. */
function comments(text: string, path: string): string {
  const found: string[] = [];
  const pattern = path.endsWith('.css') ? /\/\*[\s\S]*?\*\//g : /\/\*[\s\S]*?\*\/|<!--[\s\S]*?-->|(?<![:'"`\\])\/\/[^\n]*/g;
  for (const match of text.matchAll(pattern)) found.push(match[0]);
  return found.join('\n');
}

/** The repository paths a text names, as written (trailing sentence punctuation removed). */
function rootedPaths(text: string): string[] {
  const pattern = new RegExp(`(?<![\\w./@-])(?:${TOP_FOLDERS.join('|')})/[\\w./<>*…-]*`, 'g');
  return [...text.matchAll(pattern)].map((match) => match[0].replace(/[.,:;]+$/, ''));
}

/** Source files named without a folder (`fftCascade.ts`, `foam.glsl`). */
function bareSourceNames(text: string): string[] {
  const pattern = /(?<![\w./@<-])[A-Za-z][\w-]*(?:\.spec|\.test|\.d)?\.(?:ts|mts|mjs|glsl|frag|vert)\b(?![\w/(])/g;
  return [...text.matchAll(pattern)].map((match) => match[0]);
}

/** What is wrong with one rooted path, or null. */
function problem(path: string): string | null {
  const placeholder = path.search(/[<>*…]/);
  if (placeholder >= 0) {
    const folder = path.slice(0, path.lastIndexOf('/', placeholder) + 1);
    return existsSync(join(root, folder)) && statSync(join(root, folder)).isDirectory() ? null : `a pattern in ${folder}, which is no folder`;
  }
  const full = join(root, path);
  if (path.endsWith('/')) return existsSync(full) && statSync(full).isDirectory() ? null : 'no such folder';
  if (extname(path) !== '') return existsSync(full) && statSync(full).isFile() ? null : 'no such file';
  return existsSync(full) ? null : 'no such file or folder';
}

/** "file: path (what is wrong)" for every bad path named in `text` of `file`. */
function badPaths(file: string, text: string): string[] {
  const bad: string[] = [];
  for (const path of rootedPaths(text)) {
    const why = problem(path);
    if (why) bad.push(`${file}: ${path} (${why})`);
  }
  for (const name of bareSourceNames(text)) if (!knownNames.has(name)) bad.push(`${file}: ${name} (no file of that name)`);
  return bad;
}

describe('paths named in the repository', () => {
  it('finds the files it reads (a check of the test itself)', () => {
    expect(codeFiles).toContain('src/ocean.ts');
    expect(codeFiles).toContain('shaders/surface/ocean.frag');
    expect(markdownPages).toContain('docs/sea-states/table.md');
    expect(rootedPaths('see src/ocean.ts, and tests/browser/<feature>/.')).toEqual(['src/ocean.ts', 'tests/browser/<feature>/']);
    expect(badPaths('x', '// src/nothing/here.ts and tests/missing/ and gone.ts')).toHaveLength(3);
    expect(badPaths('x', 'docs/sea-states/<name>.png, docs/*.md and src/layers/… are patterns in real folders')).toEqual([]);
    expect(badPaths('x', 'src/sim/… and src/sim/<file>.ts')).toHaveLength(2);
  });

  it('in code comments exist', () => {
    // This file names wrong paths on purpose (above, to check the check), so it is left out.
    const scanned = codeFiles.filter((file) => file !== 'tests/unit/paths.test.ts');
    const bad = scanned.flatMap((file) => badPaths(file, comments(readFileSync(join(root, file), 'utf8'), file)));
    expect(bad).toEqual([]);
  });

  it('in the Markdown pages exist (not CHANGELOG.md: history may name removed files)', () => {
    const bad = markdownPages.flatMap((file) => badPaths(file, readFileSync(join(root, file), 'utf8')));
    expect(bad).toEqual([]);
  });
});

/** A heading's anchor as GitHub and npm make it: lower case, punctuation dropped, spaces to '-'. */
function slug(heading: string): string {
  return heading
    .trim()
    .toLowerCase()
    .replace(/[^\p{L}\p{N} _-]/gu, '')
    .replace(/ /g, '-');
}

/** The anchors of a Markdown page's headings (outside fenced code). */
function anchors(text: string): Set<string> {
  const withoutCode = text.replace(/^```[\s\S]*?^```/gm, '');
  return new Set([...withoutCode.matchAll(/^#{1,6} +(.+)$/gm)].map((match) => slug(match[1])));
}

/** The relative link targets of a Markdown page (links and pictures, outside fenced code). */
function relativeLinks(text: string): string[] {
  const withoutCode = text.replace(/^```[\s\S]*?^```/gm, '').replace(/`[^`\n]*`/g, '');
  return [...withoutCode.matchAll(/\]\(([^)\s]+)\)/g)].map((match) => match[1]).filter((target) => !/^[a-z]+:/i.test(target));
}

describe('the guide', () => {
  it('has every page linked from the README', () => {
    expect(guidePages.length).toBeGreaterThan(0);
    const readme = readFileSync(join(root, 'README.md'), 'utf8');
    const linked = new Set(relativeLinks(readme).map((target) => target.split('#')[0]));
    expect(guidePages.filter((page) => !linked.has(page))).toEqual([]);
  });

  it('has every relative link and picture of README.md and docs/*.md resolve, anchors included', () => {
    expect(slug('The `<fft-ocean>` element')).toBe('the-fft-ocean-element');
    const bad: string[] = [];
    for (const page of ['README.md', ...guidePages]) {
      const text = readFileSync(join(root, page), 'utf8');
      for (const target of relativeLinks(text)) {
        const [path, anchor] = target.split('#');
        const file = path === '' ? page : relative(root, resolve(root, dirname(page), path));
        if (!existsSync(join(root, file)) || file.startsWith('..')) {
          bad.push(`${page}: ${target} (no such file)`);
          continue;
        }
        if (anchor !== undefined && file.endsWith('.md') && !anchors(readFileSync(join(root, file), 'utf8')).has(anchor)) {
          bad.push(`${page}: ${target} (no heading #${anchor} in ${file})`);
        }
      }
    }
    expect(bad).toEqual([]);
  });
});
