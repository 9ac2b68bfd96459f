/**
 * The option tables of the guide's embedding page (docs/embedding.md, "Options") come from the one
 * source of truth: the option tables (rules, units, what is allowed), the defaults, and the TSDoc of
 * the option interfaces (what each option means and its @defaultValue). This test builds the tables
 * and fails when the page's differ; `npm run docs` (UPDATE_DOCS=1) writes them. It also checks every @defaultValue against the default in force, so
 * that the typed API docs cannot drift either.
 */
import { readFileSync, writeFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { ELEMENT_DEFAULTS, FFT_OCEAN_ATTRIBUTES } from '../../src/embed/elementAttributes';
import { kebabCase, type OptionRule } from '../../src/parameters/options';
import { DEFAULT_PARAMETERS, SIMULATION_OPTIONS } from '../../src/parameters/parameters';
import { DEFAULT_SHADING, DEFAULT_SUN, SHADING_OPTIONS, SUN_OPTIONS } from '../../src/parameters/sceneOptions';
// From the package's entry point, as a user reads them.
import { DEFAULT_SIMULATION_OPTIONS, DEFAULT_SKY_ENVIRONMENT } from '../../src/index';

const root = new URL('../../', import.meta.url);
const source = (path: string) => readFileSync(new URL(path, root), 'utf8');

/** What the TSDoc of one member of an interface says: its text, and its @defaultValue as written. */
interface MemberDoc {
  text: string;
  defaultValue: string | null;
  /** What follows the @defaultValue literal ('where Worker exists'), or ''. */
  defaultNote: string;
}

/** The text of `interface name` in the TypeScript source `text`, from its name to its closing brace. */
function interfaceBody(text: string, name: string): string {
  const start = text.search(new RegExp(`interface ${name}\\b[^{]*\\{`));
  if (start < 0) throw new Error(`no interface ${name}`);
  let depth = 0;
  let end = text.indexOf('{', start);
  for (; end < text.length; end++) {
    if (text[end] === '{') depth++;
    if (text[end] === '}' && --depth === 0) break;
  }
  return text.slice(start, end);
}

/** The TSDoc of every member of `interface name` in the TypeScript source `text`. */
function interfaceDocs(text: string, name: string): Map<string, MemberDoc> {
  const body = interfaceBody(text, name);
  const docs = new Map<string, MemberDoc>();
  for (const [, comment, member] of body.matchAll(/\/\*\*([\s\S]*?)\*\/\s*(\w+)\??:/g)) {
    const flat = comment
      .split('\n')
      .map((line) => line.replace(/^\s*\*\s?/, '').trim())
      .join(' ')
      .trim();
    const at = flat.indexOf('@defaultValue');
    if (at < 0) {
      docs.set(member, { text: flat, defaultValue: null, defaultNote: '' });
      continue;
    }
    const after = flat.slice(at + '@defaultValue'.length).trim();
    const literal = /^(\[[^\]]*\]|'[^']*'|[^\s:,]+)/.exec(after)![1];
    const rest = after.slice(literal.length).replace(/^[:,]?\s*/, '');
    docs.set(member, { text: flat.slice(0, at).trim(), defaultValue: literal, defaultNote: rest });
  }
  return docs;
}

/** A default as the docs write it: 'text', [1, 2], Infinity, true. */
function literal(value: unknown): string {
  if (typeof value === 'string') return `'${value}'`;
  if (Array.isArray(value)) return `[${value.map((v) => literal(v)).join(', ')}]`;
  return String(value);
}

/** The value a @defaultValue literal writes (the forms `literal` gives). */
function valueOf(text: string): unknown {
  if (text.startsWith("'")) return text.slice(1, -1);
  if (text.startsWith('[')) return text.slice(1, -1).split(',').map((part) => valueOf(part.trim()));
  if (text === 'true' || text === 'false') return text === 'true';
  return Number(text);
}


const cell = (text: string) => text.replace(/\|/g, '\\|');

interface TableSource {
  title: string;
  rules: Readonly<Record<string, OptionRule>>;
  defaults: Readonly<Record<string, unknown>>;
  docs: Map<string, MemberDoc>;
}

const simulationSource = source('src/parameters/parameters.ts');
const sceneSource = source('src/parameters/sceneOptions.ts');
const TABLES: TableSource[] = [
  { title: 'simulation (`setParameters`)', rules: SIMULATION_OPTIONS, defaults: DEFAULT_PARAMETERS, docs: interfaceDocs(simulationSource, 'SimulationParameters') },
  { title: 'sun (`setSun`)', rules: SUN_OPTIONS, defaults: DEFAULT_SUN, docs: interfaceDocs(sceneSource, 'SunOptions') },
  { title: 'shading (`setShading`)', rules: SHADING_OPTIONS, defaults: DEFAULT_SHADING, docs: interfaceDocs(sceneSource, 'ShadingOptions') },
];
const constructorDocs = new Map([
  ...interfaceDocs(source('src/ocean.ts'), 'OceanOptions'),
  ...interfaceDocs(source('src/layers/oceanSimulation.ts'), 'SimulationOptions'),
]);
const elementDocs = interfaceDocs(source('src/embed/elementAttributes.ts'), 'ElementSettings');

/** The page's generated part: the option tables. */
function optionTables(): string {
  const lines: string[] = [];
  for (const { title, rules, defaults, docs } of TABLES) {
    lines.push(`**${title}**`, '', '| option | attribute | default | unit | allowed | what it is |', '|:--|:--|:--|:--|:--|:--|');
    for (const [key, rule] of Object.entries(rules)) {
      const names = [key, ...(rule.aliases ?? [])];
      lines.push(
        `| ${names.map((n) => `\`${n}\``).join(', ')} | ${names.map((n) => `\`${kebabCase(n)}\``).join(', ')} | \`${literal(defaults[key])}\` | ${rule.unit || '–'} | ${cell(rule.allowed)} | ${cell(docs.get(key)!.text)} |`,
      );
    }
    lines.push('');
  }
  lines.push('**constructor only** (`new Ocean(renderer, options)`; `path` also by `ocean.setPath`)', '', '| option | default | what it is |', '|:--|:--|:--|');
  for (const key of ['sunDirection', 'path', 'worker', 'localWaves']) {
    const doc = constructorDocs.get(key)!;
    const value = doc.defaultValue === null ? '–' : `\`${doc.defaultValue}\` ${doc.defaultNote}`.trim();
    lines.push(`| \`${key}\` | ${cell(value)} | ${cell(doc.text)} |`);
  }
  lines.push('', '**`<fft-ocean>` only** (beside the options above, in kebab case)', '', '| attribute | default | what it is |', '|:--|:--|:--|');
  for (const [key, value] of Object.entries(ELEMENT_DEFAULTS)) lines.push(`| \`${kebabCase(key)}\` | \`${literal(value)}\` | ${cell(elementDocs.get(key)!.text)} |`);
  return lines.join('\n');
}

const BEGIN = '<!-- option tables: generated from the source by `npm run docs`, checked by tests/unit/optionTables.test.ts -->';
/** The page that holds the option tables, relative to the repository root. */
const PAGE = 'docs/embedding.md';
const END = '<!-- end of option tables -->';

describe(`the option tables of ${PAGE}`, () => {
  it('are the tables the source gives (npm run docs writes them)', () => {
    const page = source(PAGE);
    const begin = page.indexOf(BEGIN);
    const end = page.indexOf(END);
    expect(begin, `${PAGE} has the option tables’ first marker`).toBeGreaterThan(0);
    expect(end, `${PAGE} has the option tables’ end marker after the first`).toBeGreaterThan(begin);
    const written = page.slice(begin + BEGIN.length, end).trim();
    const generated = optionTables();
    if (process.env.UPDATE_DOCS === '1' && written !== generated) {
      writeFileSync(new URL(PAGE, root), `${page.slice(0, begin + BEGIN.length)}\n\n${generated}\n\n${page.slice(end)}`);
      return;
    }
    expect(written).toBe(generated);
  });

  it('name every attribute of <fft-ocean>', () => {
    const page = source(PAGE);
    const tables = page.slice(page.indexOf(BEGIN), page.indexOf(END));
    for (const attribute of FFT_OCEAN_ATTRIBUTES) expect(tables, attribute).toContain(`\`${attribute}\``);
  });
});

describe('the TSDoc of every option', () => {
  it('gives a @defaultValue equal to the default in force', () => {
    const checked: string[] = [];
    const sources = [
      ...TABLES.map(({ defaults, docs }) => ({ defaults, docs })),
      { defaults: ELEMENT_DEFAULTS as unknown as Record<string, unknown>, docs: elementDocs },
    ];
    for (const { defaults, docs } of sources) {
      for (const [key, value] of Object.entries(defaults)) {
        const doc = docs.get(key);
        expect(doc?.defaultValue, `${key} has a @defaultValue`).toBeTruthy();
        expect(valueOf(doc!.defaultValue!), key).toEqual(value);
        checked.push(key);
      }
    }
    // The Ocean's own sun options repeat the sun table's: the same defaults.
    for (const [key, value] of Object.entries(DEFAULT_SUN)) expect(valueOf(constructorDocs.get(key)!.defaultValue!), `OceanOptions.${key}`).toEqual(value);
    expect(checked.length).toBe(Object.keys(DEFAULT_PARAMETERS).length + Object.keys(DEFAULT_SUN).length + Object.keys(DEFAULT_SHADING).length + Object.keys(ELEMENT_DEFAULTS).length);
  });
  it('of the other options objects gives a @defaultValue for every optional member, equal to the default in force where one is defined', () => {
    const simulationOptions = source('src/layers/oceanSimulation.ts');
    const skySource = source('src/render/skyEnvironment.ts');
    const compared: [string, Map<string, MemberDoc>, Readonly<Record<string, unknown>>][] = [
      ['SimulationOptions', interfaceDocs(simulationOptions, 'SimulationOptions'), DEFAULT_SIMULATION_OPTIONS],
      ['SkyEnvironmentOptions', interfaceDocs(skySource, 'SkyEnvironmentOptions'), DEFAULT_SKY_ENVIRONMENT],
      [
        'ShadingChanges',
        interfaceDocs(sceneSource, 'ShadingChanges'),
        // The colours in any form, and their British aliases: the shading's defaults.
        { scatterColor: DEFAULT_SHADING.scatterColor, causticColor: DEFAULT_SHADING.causticColor, scatterColour: DEFAULT_SHADING.scatterColor, causticColour: DEFAULT_SHADING.causticColor },
      ],
    ];
    for (const [name, docs, defaults] of compared) {
      expect([...docs.keys()].sort(), `${name}'s members`).toEqual(Object.keys(defaults).sort());
      for (const [key, value] of Object.entries(defaults)) expect(valueOf(docs.get(key)!.defaultValue ?? 'none'), `${name}.${key}`).toEqual(value);
    }
    // Where the default is the state in force or the absence of a value: said in words, present.
    const described: [string, string][] = [
      ['src/ocean.ts', 'OceanOptions'],
      ['src/ocean.ts', 'SunPosition'],
      ['src/layers/localWaves.ts', 'LocalWavesOptions'],
      ['src/layers/localWaves.ts', 'DropOptions'],
      ['src/layers/floatingBody.ts', 'FloatingBodyOptions'],
    ];
    for (const [path, name] of described) {
      const text = source(path);
      const docs = interfaceDocs(text, name);
      const optional = [...interfaceBody(text, name).matchAll(/^\s*(\w+)\?:/gm)].map((match) => match[1]);
      expect(optional.length, `${name} has optional members`).toBeGreaterThan(0);
      for (const member of optional) expect(docs.get(member)?.defaultValue, `${name}.${member} has a @defaultValue`).toBeTruthy();
    }
  });
});
