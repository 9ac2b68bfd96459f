/**
 * Misspelt option names are errors that suggest the intended one, wherever options are taken:
 * validateParameters, the shading and sun tables, and the Ocean constructor (which checks its
 * option names before it touches the renderer).
 */
import type { WebGLRenderer } from 'three';
import { describe, expect, it } from 'vitest';
import { Ocean } from '../../src/ocean';
import { mergeOptions, nearestName, ParameterError } from '../../src/parameters/options';
import { validateParameters } from '../../src/parameters/parameters';
import { DEFAULT_SHADING, SHADING_OPTIONS } from '../../src/parameters/sceneOptions';

function errorOf(action: () => unknown): ParameterError {
  try {
    action();
  } catch (error) {
    expect(error).toBeInstanceOf(ParameterError);
    return error as ParameterError;
  }
  throw new Error('no error was thrown');
}

describe('nearestName', () => {
  it('finds the intended name for a typo, a case slip and a prefix', () => {
    const known = ['windSpeed', 'windDirection', 'fetch', 'spectrum', 'swellHeight'];
    expect(nearestName('windSped', known)).toBe('windSpeed');
    expect(nearestName('WindSpeed', known)).toBe('windSpeed');
    expect(nearestName('swell', known)).toBe('swellHeight');
    expect(nearestName('fech', known)).toBe('fetch');
  });
});

describe('unknown option names', () => {
  it('validateParameters names the key and suggests the nearest', () => {
    const error = errorOf(() => validateParameters({ windSped: 12 } as never));
    expect(error.parameter).toBe('windSped');
    expect(error.message).toContain('did you mean windSpeed?');
  });

  it('the shading table does too (the British spelling is the option name today)', () => {
    const error = errorOf(() => mergeOptions(SHADING_OPTIONS, { causticColor: [1, 1, 1] } as never, DEFAULT_SHADING));
    expect(error.message).toContain('did you mean causticColour?');
  });

  it('the Ocean constructor rejects a misspelt option before it uses the renderer', () => {
    const error = errorOf(() => new Ocean({} as WebGLRenderer, { windSped: 12 } as never));
    expect(error.parameter).toBe('windSped');
    expect(error.message).toContain('did you mean windSpeed?');
  });
});
