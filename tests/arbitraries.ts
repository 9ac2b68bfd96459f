/**
 * Hostile input for the property-based tests, shared by the Node fuzz tests (tests/unit/fuzz.test.ts)
 * and the in-browser ones (tests/browser/robustness/robustness.ts), so both throw the same values at
 * the library.
 */
import fc from 'fast-check';

/** Numbers as hostile as they come: huge, tiny, negative, NaN, ±Infinity, −0, and ordinary ones. */
export const anyNumber = fc.oneof(fc.double(), fc.constantFrom(NaN, Infinity, -Infinity, -0, 1e308, -1e308, 5e-324, 1e-300, 1e21, 1e39), fc.integer());
/** Text a URL or an attribute may hold: numbers written oddly, words, lists, nothing, control characters. */
export const anyText = fc.oneof(
  fc.string(),
  anyNumber.map(String),
  fc.array(anyNumber, { maxLength: 5 }).map((values) => values.join(',')),
  fc.constantFrom('', ' ', 'deep', 'abc', '1e999', '-0', '0x10', '1,2,3', '#1a6b80', 'javascript:alert(1)', '<script>', '%00', '1_000'),
);
/** An array of thousands of one number: too long for any option, and long to print. */
export const hugeArray = fc.tuple(fc.integer({ min: 1000, max: 20_000 }), anyNumber).map(([length, value]) => new Array<number>(length).fill(value));
/**
 * Any value a caller may pass: numbers, text, short and huge arrays, objects with any keys (a
 * vector's x, y, z among them), null, undefined.
 */
export const anyValue = fc.oneof(
  anyNumber,
  anyText,
  fc.array(anyNumber, { maxLength: 5 }),
  hugeArray,
  fc.object({ maxDepth: 1, maxKeys: 4 }),
  fc.record({ x: anyNumber, y: anyNumber, z: anyNumber }),
  fc.constantFrom(null, undefined, true, {}, [] as number[]),
);

/**
 * Every number in `value` is finite: a number, an array or typed array of them (nested too), or a
 * three.js vector, colour or matrix (through its toArray()). Anything else holds no number.
 */
export function allFinite(value: unknown): boolean {
  if (typeof value === 'number') return Number.isFinite(value);
  if (Array.isArray(value)) return value.every(allFinite);
  if (value instanceof Float32Array || value instanceof Float64Array) return value.every(Number.isFinite);
  const vector = value as { toArray?: unknown } | null;
  if (typeof vector?.toArray === 'function') return allFinite((vector as { toArray(): unknown }).toArray());
  return true;
}
