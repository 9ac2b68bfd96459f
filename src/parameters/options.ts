/**
 * What every table of options shares (parameters.ts for the simulation, sceneOptions.ts for the
 * sun and the shading): a rule per option, the error that names a bad one, merging checked changes
 * over a base, and the text form options take in URLs, element attributes and the shot CLI.
 */

/**
 * How an option is written in text: a number, one of some words, numbers separated by commas, or a
 * colour (three numbers separated by commas, or a CSS colour such as "#1a6b80").
 */
export type OptionType = 'number' | 'choice' | 'numbers' | 'color';

export interface OptionRule {
  type: OptionType;
  /** Unit for docs and the panel ('' when none). */
  unit: string;
  /** What is allowed, as the error message says it: "<name> must be <allowed>". */
  allowed: string;
  /** Whether a value, as it is stored (after `coerce`), is allowed. */
  check(value: unknown): boolean;
  /**
   * For options given in several forms (colours): the value as it is stored, or undefined when
   * `value` is none of the forms. Without it a value is stored as it is given.
   */
  coerce?(value: unknown): unknown;
  /** For 'choice' options. */
  choices?: readonly string[];
  /** Other names the option is taken under (older spellings); messages suggest its key. */
  aliases?: readonly string[];
}

export type OptionTable<T> = { readonly [K in keyof T]: OptionRule };

export const isNumber = (v: unknown): v is number => typeof v === 'number';
export const between = (low: number, high: number) => (v: unknown) => isNumber(v) && v >= low && v <= high;
/** Angles in degrees: finite, and small enough that reducing them to a turn keeps their precision. */
export const finiteAngle = (v: unknown) => isNumber(v) && Number.isFinite(v) && Math.abs(v) <= 1e6;
export const oneOf = (choices: readonly string[]) => (v: unknown) => typeof v === 'string' && choices.includes(v);
/** An object whose keys name options: not null, an array or a primitive (whose indices or nothing would be taken for names). */
export const isOptionsObject = (v: unknown): v is object => typeof v === 'object' && v !== null && !Array.isArray(v);
/** Linear RGB triples, each channel in [0, max]. */
export const rgb = (max: number) => (v: unknown) => Array.isArray(v) && v.length === 3 && v.every(between(0, max));

/**
 * Thrown for an option outside what is allowed; `parameter` names it (as it was given) and
 * `value` is what it was given. Every error the library throws for a caller's mistake is one.
 */
export class ParameterError extends Error {
  /**
   * @param allowed what is allowed, for the message "<parameter> must be <allowed>; got <value>"
   * @param message the whole message instead, for a mistake that is not a bad value
   */
  constructor(
    readonly parameter: string,
    readonly value: unknown,
    allowed: string,
    message = `${parameter} must be ${allowed}; got ${describeValue(value)}`,
  ) {
    super(message);
    this.name = 'ParameterError';
  }
}

/**
 * Thrown by every method of an object after its dispose() (an Ocean and its getters, a
 * SkyEnvironment, LocalWaves' drop, addPressure and follow); `parameter` names the method.
 */
export class DisposedError extends ParameterError {
  constructor(method: string, owner = 'Ocean') {
    super(method, undefined, '', `${method}: this ${owner} has been disposed (its GPU resources are freed); create a new ${owner}`);
    this.name = 'DisposedError';
  }
}

/**
 * Thrown where this browser, device or three.js release cannot do what was asked (a GPU FFT
 * without the render targets it needs, say); `parameter` names what is missing. The Ocean's 'auto'
 * and 'gpu' paths catch it and fall back to the JS path, saying why (ocean.path.reason).
 */
export class UnsupportedError extends ParameterError {
  constructor(what: string, message: string) {
    super(what, undefined, '', message);
    this.name = 'UnsupportedError';
  }
}

/** Text as messages quote it: in double quotes, cut to its first 40 characters and "…" when longer. */
export function quoteText(text: string): string {
  return `"${text.length > 40 ? `${text.slice(0, 40)}…` : text}"`;
}

/**
 * A value as messages show it: text quoted, lists in brackets, objects (a THREE.Color, a Vector3)
 * by their fields without three's `isColor`-style type flags; one level deep and at most 8 items,
 * so that any object (a cyclic one too) gives a short message.
 */
export function describeValue(value: unknown, nested = false): string {
  if (typeof value === 'string') return quoteText(value);
  if (typeof value === 'function') return 'a function';
  if (typeof value !== 'object' || value === null) return String(value);
  if (nested) return Array.isArray(value) ? '[…]' : '{…}';
  const items = Array.isArray(value)
    ? value.map((item) => describeValue(item, true))
    : Object.entries(value)
        .filter(([key]) => !/^is[A-Z]/.test(key))
        .map(([key, field]) => `${key}: ${describeValue(field, true)}`);
  const shown = items.length > 8 ? [...items.slice(0, 8), '…'] : items;
  return Array.isArray(value) ? `[${shown.join(', ')}]` : `{${shown.join(', ')}}`;
}

/**
 * An option's name as element attributes and CLI flags write it (kebab case): windSpeed is
 * wind-speed. The one conversion of names between the constructor and URL (camel case) and
 * attributes and flags: every shell goes through it (and camelCase back).
 */
export function kebabCase(name: string): string {
  return name.replace(/[A-Z]/g, (c) => `-${c.toLowerCase()}`);
}

/** A kebab-case name back in camel case, as the option tables key it: wind-speed is windSpeed. */
export function camelCase(name: string): string {
  return name.replace(/-([a-z])/g, (_, c: string) => c.toUpperCase());
}

/** Where an option's name leads: the table (group) it is in, its key there, and the name as the table spells it (the key or an alias). */
export interface OptionRoute<G extends string = string> {
  group: G;
  key: string;
  name: string;
}

/**
 * The option router: every option of `tables` (named by group) under each name it is taken by,
 * its key and each alias, written by `spell` (kebabCase for attributes and CLI flags; as they are
 * for the constructor and the URL). A shell looks a name up here and hands the value to the
 * table's rule (parseOptionText, checkOption) with the route's group, key and name.
 */
export function optionRoutes<G extends string>(
  tables: Readonly<Record<G, Readonly<Record<string, OptionRule>>>>,
  spell: (name: string) => string = (name) => name,
): ReadonlyMap<string, OptionRoute<G>> {
  const routes = new Map<string, OptionRoute<G>>();
  for (const group of Object.keys(tables) as G[]) {
    for (const [key, rule] of Object.entries(tables[group])) {
      for (const name of [key, ...(rule.aliases ?? [])]) routes.set(spell(name), { group, key, name });
    }
  }
  return routes;
}

/** The aliases of `table`'s options, each mapped to the key it is another name for. */
export function optionAliases<T>(table: OptionTable<T>): Readonly<Record<string, keyof T & string>> {
  const aliases: Record<string, keyof T & string> = {};
  for (const key of Object.keys(table) as (keyof T & string)[]) for (const alias of table[key].aliases ?? []) aliases[alias] = key;
  return aliases;
}

/** The key of `table` that `name` names (itself, or the key it is an alias of); throws for any other name. */
export function optionKey<T>(table: OptionTable<T>, name: string, value?: unknown): keyof T & string {
  if (Object.hasOwn(table, name)) return name as keyof T & string;
  const aliases = optionAliases(table);
  if (Object.hasOwn(aliases, name)) return aliases[name];
  throw unknownOption(name, value, Object.keys(table), aliases);
}

/**
 * The error for an option name that is not one of `known` (nor of `aliases`): it lists the known
 * names and suggests the nearest, the key rather than the alias when an alias is nearer.
 */
export function unknownOption(
  name: string,
  value: unknown,
  known: readonly string[],
  aliases: Readonly<Record<string, string>> = {},
  prefix = '',
): ParameterError {
  const nearest = nearestName(name, [...known, ...Object.keys(aliases)]);
  const suggestion = Object.hasOwn(aliases, nearest) ? aliases[nearest] : nearest;
  return new ParameterError(`${prefix}${name}`, value, `one of ${known.join(', ')} (did you mean ${suggestion}?)`);
}

/**
 * Checks that `given` is an object whose every key is one of `known` (or of `aliases`): a misspelt
 * option would otherwise be silently ignored. Throws a ParameterError naming `argument` when
 * `given` is not an object of options, or naming the first unknown key (after `prefix`, such as
 * "shape." for an argument of several), with the nearest known name as a suggestion. `allowed`
 * says what the argument must be, for the first error.
 */
export function checkOptionNames(
  given: unknown,
  known: readonly string[],
  argument: string,
  {
    prefix = '',
    aliases = {},
    allowed = `an object of options (${known.join(', ')})`,
  }: { prefix?: string; aliases?: Readonly<Record<string, string>>; allowed?: string } = {},
): asserts given is object {
  if (!isOptionsObject(given)) throw new ParameterError(argument, given, allowed);
  for (const [key, value] of Object.entries(given)) {
    if (!known.includes(key) && !Object.hasOwn(aliases, key)) throw unknownOption(key, value, known, aliases, prefix);
  }
}

/** Levenshtein distance, for "did you mean". */
function editDistance(a: string, b: string): number {
  let previous = Array.from({ length: b.length + 1 }, (_, j) => j);
  for (let i = 1; i <= a.length; i++) {
    const current = [i];
    for (let j = 1; j <= b.length; j++) {
      current[j] = Math.min(previous[j] + 1, current[j - 1] + 1, previous[j - 1] + (a[i - 1] === b[j - 1] ? 0 : 1));
    }
    previous = current;
  }
  return previous[b.length];
}

/** The known name nearest to `name`, case aside (a name that contains it, or it contains, counts as near). */
export function nearestName(name: string, known: readonly string[]): string {
  const lower = name.toLowerCase();
  let best = known[0];
  let bestScore = Infinity;
  for (const candidate of known) {
    const other = candidate.toLowerCase();
    const score = other.includes(lower) || lower.includes(other) ? Math.abs(other.length - lower.length) / 4 : editDistance(lower, other);
    if (score < bestScore) [best, bestScore] = [candidate, score];
  }
  return best;
}

/**
 * The option `name` (a key of `table` or an alias) given `value`: its key and the value as it is
 * stored (coerced, arrays copied). Throws a ParameterError naming `name` unless it is allowed;
 * `shown` is the value the error quotes (by default `value`).
 */
export function checkOption<T>(table: OptionTable<T>, name: string, value: unknown, shown: unknown = value): { key: keyof T & string; value: unknown } {
  const key = optionKey(table, name, shown);
  const rule = table[key];
  const stored = rule.coerce ? rule.coerce(value) : value;
  if (stored === undefined || !rule.check(stored)) throw new ParameterError(name, shown, rule.allowed);
  return { key, value: Array.isArray(stored) ? [...stored] : stored };
}

/**
 * `changes` checked one by one and merged over `base`; throws on the first bad one, and when an
 * option is given under two names. A name whose value is undefined is not given (as an optional
 * TypeScript property), not bad.
 */
export function mergeOptions<T extends object>(table: OptionTable<T>, changes: object, base: Readonly<T>): T {
  const merged: T = { ...base };
  const givenAs = new Map<string, string>();
  for (const [name, value] of Object.entries(changes)) {
    if (value === undefined) continue;
    const option = checkOption(table, name, value);
    const earlier = givenAs.get(option.key);
    if (earlier !== undefined) {
      throw new ParameterError(name, value, '', `${name} and ${earlier} are the same option (${option.key}): give it once`);
    }
    givenAs.set(option.key, name);
    merged[option.key] = option.value as T[typeof option.key];
  }
  return merged;
}

/** A plain decimal or exponent number; Number('') is 0 and Number('0x10') is 16, neither wanted here. */
export function parseDecimal(text: string): number {
  const trimmed = text.trim();
  return /^[+-]?(\d+\.?\d*|\.\d+)(e[+-]?\d+)?$/i.test(trimmed) ? Number(trimmed) : NaN;
}

/**
 * Reads one option (named by its key or an alias) as written in text: numbers as decimals ("deep",
 * "inf" or "infinity" for an infinite one, the depth of deep water), words for choices, lists
 * separated by commas, colours as "r,g,b" (linear) or a CSS colour ("#1a6b80"). Returns the value
 * as it is stored. Throws a ParameterError that names the option and quotes the text (shortened)
 * when it is not allowed.
 */
export function parseOptionText<T>(table: OptionTable<T>, name: string, text: string): unknown {
  const rule = table[optionKey(table, name, text)];
  const numbers = text.split(',').map(parseDecimal);
  let value: unknown;
  if (rule.type === 'choice') value = text.trim();
  else if (rule.type === 'numbers') value = numbers;
  else if (rule.type === 'color') value = numbers.every(Number.isFinite) ? numbers : text.trim();
  else if (/^\s*(deep|inf|infinity)\s*$/i.test(text)) value = Infinity;
  else value = parseDecimal(text);
  return checkOption(table, name, value, text).value;
}

/** An option as parseOptionText reads it back: "deep" for Infinity, lists joined by commas. */
export function formatOptionText(value: unknown): string {
  if (Array.isArray(value)) return value.map((v: number) => String(Number(v.toPrecision(6)))).join(',');
  if (value === Infinity) return 'deep';
  if (typeof value === 'number') return value === 0 ? '0' : String(Number(value.toPrecision(10)));
  return String(value);
}
