/**
 * Hostile input, generated (fast-check, seeded so that CI repeats the same cases and a failure
 * prints its seed and counterexample): the URL parser and the option validators either accept a
 * value and give finite, in-range settings, or reject it with an Error that names the option.
 * Never another exception, never a NaN.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { allFinite, anyText, anyValue } from '../arbitraries';
import { parseState, simulationParameters, URL_KEYS } from '../../src/app/urlState';
import { mergeOptions, ParameterError } from '../../src/parameters/options';
import { DEFAULT_PARAMETERS, SIMULATION_OPTIONS, validateParameters } from '../../src/parameters/parameters';
import { DEFAULT_SHADING, SHADING_OPTIONS } from '../../src/parameters/sceneOptions';

const RUNS = { seed: 20261124, numRuns: 400 };

/** The simulation parameters pass validation, and every number in them is finite. */
function validSimulation(parameters: object): boolean {
  validateParameters(parameters);
  return Object.values(parameters).every((value) => allFinite(value) || value === Infinity);
}

describe('fuzz: the URL parser', () => {
  it('reads any query: every value it keeps is valid and finite, every one it drops is named in a warning', () => {
    const entry = fc.tuple(fc.oneof(fc.constantFrom(...URL_KEYS), fc.string({ maxLength: 12 })), anyText);
    fc.assert(
      fc.property(fc.array(entry, { maxLength: 8 }), (entries) => {
        const query = entries.map(([key, value]) => `${encodeURIComponent(key)}=${encodeURIComponent(value)}`).join('&');
        const { state, warnings } = parseState(query);
        // The simulation parameters the app would build (depth may be Infinity: deep water).
        const parameters = simulationParameters(state);
        expect(validSimulation(parameters)).toBe(true);
        expect(state.cam.every(Number.isFinite)).toBe(true);
        expect(Number.isFinite(state.t) && Number.isFinite(state.timeScale)).toBe(true);
        for (const { parameter, message } of warnings) expect(message).toContain(parameter);
      }),
      RUNS,
    );
  });
});

describe('fuzz: the option validators', () => {
  it('validateParameters: any value for any simulation option is accepted in range, or rejected naming the option', () => {
    const keys = Object.keys(SIMULATION_OPTIONS);
    fc.assert(
      fc.property(fc.constantFrom(...keys), anyValue, (key, value) => {
        try {
          const result = validateParameters({ [key]: value });
          expect(validSimulation(result)).toBe(true);
        } catch (error) {
          expect(error).toBeInstanceOf(ParameterError);
          // The option named may be this one, or one whose bound it moved (repeatPeriod, patchSizes).
          expect((error as ParameterError).message).toMatch(new RegExp(`^(${keys.join('|')})\\b`));
        }
      }),
      RUNS,
    );
  });

  it('the shading options: any value is accepted as a finite colour or number, or rejected naming the option', () => {
    const keys = [...Object.keys(SHADING_OPTIONS), 'scatterColour', 'causticColour', 'windSped'];
    fc.assert(
      fc.property(fc.constantFrom(...keys), anyValue, (key, value) => {
        try {
          const result = mergeOptions(SHADING_OPTIONS, { [key]: value }, DEFAULT_SHADING);
          for (const option of Object.values(result)) expect(allFinite(option)).toBe(true);
        } catch (error) {
          expect(error).toBeInstanceOf(ParameterError);
          expect((error as ParameterError).message.startsWith(key)).toBe(true);
        }
      }),
      RUNS,
    );
  });

  it('a sea built from accepted values holds no NaN anywhere in its parameters, whatever the combination', () => {
    const keys = Object.keys(SIMULATION_OPTIONS);
    fc.assert(
      fc.property(fc.dictionary(fc.constantFrom(...keys), anyValue, { maxKeys: 5 }), (changes) => {
        let parameters: object = DEFAULT_PARAMETERS;
        try {
          parameters = validateParameters(changes);
        } catch (error) {
          expect(error).toBeInstanceOf(ParameterError);
        }
        expect(validSimulation(parameters)).toBe(true);
      }),
      RUNS,
    );
  });
});
