/**
 * What every table of options shares (parameters.ts for the simulation, sceneOptions.ts for the
 * sun and the shading): a rule per option, the error that names a bad one, merging checked changes
 * over a base, and the text form options take in URLs, element attributes and the shot CLI.
 */

/** How an option is written in text: a number, one of some words, or numbers separated by commas. */
export type OptionType = 'number' | 'choice' | 'numbers';

export interface OptionRule {
  type: OptionType;
  /** Unit for docs and the panel ('' when none). */
  unit: string;
  /** What is allowed, as the error message says it: "<name> must be <allowed>". */
  allowed: string;
  check(value: unknown): boolean;
  /** For 'choice' options. */
  choices?: readonly string[];
}

export type OptionTable<T> = { readonly [K in keyof T]: OptionRule };

export const isNumber = (v: unknown): v is number => typeof v === 'number';
export const between = (low: number, high: number) => (v: unknown) => isNumber(v) && v >= low && v <= high;
/** Angles in degrees: finite, and small enough that reducing them to a turn keeps their precision. */
export const finiteAngle = (v: unknown) => isNumber(v) && Number.isFinite(v) && Math.abs(v) <= 1e6;
export const oneOf = (choices: readonly string[]) => (v: unknown) => typeof v === 'string' && choices.includes(v);
/** Linear RGB triples, each channel in [0, max]. */
export const rgb = (max: number) => (v: unknown) => Array.isArray(v) && v.length === 3 && v.every(between(0, max));

/** Thrown for an option outside what is allowed; `parameter` names it. */
export class ParameterError extends Error {
  constructor(
    readonly parameter: string,
    readonly value: unknown,
    allowed: string,
  ) {
    super(`${parameter} must be ${allowed}; got ${describeValue(value)}`);
    this.name = 'ParameterError';
  }
}

function describeValue(value: unknown): string {
  return Array.isArray(value) ? `[${value.map(String).join(', ')}]` : String(value);
}

function ruleOf<T>(table: OptionTable<T>, key: string, value: unknown): OptionRule {
  if (!Object.hasOwn(table, key)) throw unknownOption(key, value, Object.keys(table));
  return table[key as keyof T];
}

/** The error for an option name that is not one of `known`: it lists them and suggests the nearest. */
export function unknownOption(name: string, value: unknown, known: readonly string[]): ParameterError {
  return new ParameterError(name, value, `one of ${known.join(', ')} (did you mean ${nearestName(name, known)}?)`);
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

/** Throws a ParameterError naming `key` unless `value` is allowed for it. */
export function checkOption<T>(table: OptionTable<T>, key: string, value: unknown): void {
  const rule = ruleOf(table, key, value);
  if (!rule.check(value)) throw new ParameterError(key, value, rule.allowed);
}

/**
 * `changes` checked one by one and merged over `base` (arrays copied); throws on the first bad one.
 * A key whose value is undefined is not given (as an optional TypeScript property), not bad.
 */
export function mergeOptions<T extends object>(table: OptionTable<T>, changes: Partial<T>, base: Readonly<T>): T {
  const merged = { ...base };
  for (const [key, value] of Object.entries(changes)) {
    if (value === undefined) continue;
    checkOption(table, key, value);
    (merged as Record<string, unknown>)[key] = Array.isArray(value) ? [...value] : value;
  }
  return merged;
}

/** A plain decimal or exponent number; Number('') is 0 and Number('0x10') is 16, neither wanted here. */
export function parseDecimal(text: string): number {
  const trimmed = text.trim();
  return /^[+-]?(\d+\.?\d*|\.\d+)(e[+-]?\d+)?$/i.test(trimmed) ? Number(trimmed) : NaN;
}

/**
 * Reads one option as written in text: numbers as decimals ("deep", "inf" or "infinity" for an
 * infinite one, the depth of deep water), words for choices, lists separated by commas. Throws a
 * ParameterError that names the option and quotes the text (shortened) when it is not allowed.
 */
export function parseOptionText<T>(table: OptionTable<T>, key: string, text: string): unknown {
  const rule = ruleOf(table, key, text);
  const quoted = `"${text.length > 40 ? `${text.slice(0, 40)}…` : text}"`;
  let value: unknown;
  if (rule.type === 'choice') value = text.trim();
  else if (rule.type === 'numbers') value = text.split(',').map(parseDecimal);
  else if (/^\s*(deep|inf|infinity)\s*$/i.test(text)) value = Infinity;
  else value = parseDecimal(text);
  if (!rule.check(value)) throw new ParameterError(key, quoted, rule.allowed);
  return value;
}

/** An option as parseOptionText reads it back: "deep" for Infinity, lists joined by commas. */
export function formatOptionText(value: unknown): string {
  if (Array.isArray(value)) return value.map((v: number) => String(Number(v.toPrecision(6)))).join(',');
  if (value === Infinity) return 'deep';
  if (typeof value === 'number') return value === 0 ? '0' : String(Number(value.toPrecision(10)));
  return String(value);
}
