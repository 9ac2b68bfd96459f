/**
 * Misspelt option names are errors that suggest the intended one, wherever options are taken:
 * validateParameters, the shading and sun tables, the Ocean constructor (which checks its option
 * names before it touches the renderer), and every other exported constructor and method that
 * takes options. The British spellings of the colours are aliases
 * of the American names; colours come in the forms three.js users pass. Messages quote what was
 * given, shortened.
 */
import { Color, ColorManagement, type WebGLRenderer } from 'three';
import { describe, expect, it, vi } from 'vitest';
import { Ocean } from '../../src/ocean';
import { FloatingBody } from '../../src/layers/floatingBody';
import { LocalWaves } from '../../src/layers/localWaves';
import { OceanSimulation } from '../../src/layers/oceanSimulation';
import { SkyEnvironment } from '../../src/render/skyEnvironment';
import { camelCase, kebabCase, mergeOptions, nearestName, optionRoutes, ParameterError, parseOptionText, quoteText } from '../../src/parameters/options';
import { RUN_OPTIONS } from '../../src/parameters/runOptions';
import { PATH_PREFERENCES, PATH_PREFERENCES_TEXT } from '../../src/layers/oceanSimulation';
import { validateParameters } from '../../src/parameters/parameters';
import { colorToLinear, DEFAULT_SHADING, SHADING_OPTIONS, type Rgb } from '../../src/parameters/sceneOptions';

function errorOf(action: () => unknown): ParameterError {
  try {
    action();
  } catch (error) {
    expect(error).toBeInstanceOf(ParameterError);
    return error as ParameterError;
  }
  throw new Error('no error was thrown');
}


/** A stand-in the Ocean only asks what kind of renderer it is: these checks come before it is used. */
const UNTOUCHED_WEBGL_RENDERER = { isWebGLRenderer: true } as unknown as WebGLRenderer;
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

  it('the shading table does too, suggesting the American spelling', () => {
    const error = errorOf(() => mergeOptions(SHADING_OPTIONS, { causticColr: [1, 1, 1] } as never, DEFAULT_SHADING));
    expect(error.parameter).toBe('causticColr');
    expect(error.message).toContain('did you mean causticColor?');
    // Nearer the British alias than the key: still the key is suggested.
    expect(errorOf(() => mergeOptions(SHADING_OPTIONS, { scatterColours: 0 } as never, DEFAULT_SHADING)).message).toContain(
      'did you mean scatterColor?',
    );
  });

  it('the Ocean constructor rejects a misspelt option before it uses the renderer', () => {
    const error = errorOf(() => new Ocean(UNTOUCHED_WEBGL_RENDERER, { windSped: 12 } as never));
    expect(error.parameter).toBe('windSped');
    expect(error.message).toContain('did you mean windSpeed?');
    expect(errorOf(() => new Ocean(UNTOUCHED_WEBGL_RENDERER, { scatterColur: 0 } as never)).message).toContain('did you mean scatterColor?');
  });

  it('the Ocean constructor rejects options that are not an object of them, naming them (before: a TypeError, or a string\'s indices taken for names)', () => {
    for (const options of [null, 'windSpeed', [12], 12]) {
      const error = errorOf(() => new Ocean(UNTOUCHED_WEBGL_RENDERER, options as never));
      expect(error.parameter).toBe('options');
      expect(error.message.startsWith('options must be an object of options, such as { windSpeed: 12 }; got ')).toBe(true);
    }
  });
});

describe('unknown option names in every other constructor and method that takes options', () => {
  // A fake renderer: each check must come before the renderer is used (the JS local waves ask only
  // for the float-filtering extension).
  const renderer = { extensions: { has: () => true } } as unknown as WebGLRenderer;
  const localWaves = () => new LocalWaves(renderer, Infinity, false, { resolution: 16 });
  const hull = { length: 8, beam: 2.6, draft: 0.6 };
  const pose = { x: 0, z: 0, heading: 0 };
  const cases: [string, () => unknown, string, string][] = [
    ['new OceanSimulation(renderer, parameters, options)', () => new OceanSimulation(renderer, {}, { pth: 'js' } as never), 'pth', 'path'],
    ['OceanSimulation\'s localWaves option', () => new OceanSimulation(renderer, {}, { localWaves: { cellSise: 2 } } as never), 'localWaves.cellSise', 'cellSize'],
    ['new SkyEnvironment(renderer, options)', () => new SkyEnvironment(renderer, { sunElevaton: 10 } as never), 'SkyEnvironment sunElevaton', 'sunElevation'],
    ['new FloatingBody(options)', () => new FloatingBody({ mass: 100, size: [1, 1, 1], dampng: 0.1 } as never), 'FloatingBody dampng', 'damping'],
    ['new LocalWaves(renderer, depth, useGpu, options)', () => new LocalWaves(renderer, Infinity, false, { resolutoin: 64 } as never), 'localWaves.resolutoin', 'resolution'],
    ['LocalWaves.drop(x, z, options)', () => localWaves().drop(0, 0, { radus: 2 } as never), 'drop radus', 'radius'],
    ['LocalWaves.addPressure(shape, pose)', () => localWaves().addPressure({ ...hull, lenght: 9 } as never, pose), 'hull lenght', 'length'],
    ['LocalWaves.addPressure(shape, pose)\'s pose', () => localWaves().addPressure(hull, { ...pose, headng: 1 } as never), 'hull pose headng', 'heading'],
  ];
  for (const [entry, action, parameter, suggestion] of cases) {
    it(`${entry} names the misspelt key and suggests the nearest`, () => {
      const error = errorOf(action);
      expect(error.parameter).toBe(parameter);
      expect(error.message).toContain(`(did you mean ${suggestion}?)`);
    });
  }

  it('options that are not an object of them are a ParameterError naming the argument (before: a TypeError, or nothing)', () => {
    const named: [() => unknown, string][] = [
      [() => new OceanSimulation(renderer, {}, null as never), 'OceanSimulation options'],
      [() => new SkyEnvironment(renderer, 'sunElevation' as never), 'SkyEnvironment options'],
      [() => new FloatingBody(null as never), 'FloatingBody options'],
      [() => localWaves().drop(0, 0, [1] as never), 'drop options'],
      [() => localWaves().addPressure(8 as never, pose), 'hull shape'],
      [() => localWaves().addPressure(hull, null as never), 'hull pose'],
    ];
    for (const [action, parameter] of named) expect(errorOf(action).parameter).toBe(parameter);
  });
});

describe('the British spellings are aliases', () => {
  it('causticColour and scatterColour set causticColor and scatterColor', () => {
    const merged = mergeOptions(SHADING_OPTIONS, { causticColour: [0.5, 0.25, 1], scatterColour: [0, 0.1, 0.2] }, DEFAULT_SHADING);
    expect(merged.causticColor).toEqual([0.5, 0.25, 1]);
    expect(merged.scatterColor).toEqual([0, 0.1, 0.2]);
    expect(Object.keys(merged)).toEqual(Object.keys(DEFAULT_SHADING));
  });

  it('an option given under both names is an error naming both', () => {
    const error = errorOf(() => mergeOptions(SHADING_OPTIONS, { causticColor: 0xffffff, causticColour: 0 }, DEFAULT_SHADING));
    expect(error.parameter).toBe('causticColour');
    expect(error.message).toBe('causticColour and causticColor are the same option (causticColor): give it once');
  });

  it('text under an alias is read as the option (URLs, attributes, the CLI)', () => {
    expect(parseOptionText(SHADING_OPTIONS, 'scatterColour', '0,0.5,1')).toEqual([0, 0.5, 1]);
  });
});

describe('colours', () => {
  const teal = new Color(0x1a6b80);
  const linearTeal: Rgb = [teal.r, teal.g, teal.b];

  it('a hex number, a CSS string and a THREE.Color are sRGB as authored, made linear as new Color() does', () => {
    expect(ColorManagement.enabled).toBe(true);
    // 0x1a → (26/255) in sRGB is about 0.0103 linear: converted, not 0.102.
    expect(linearTeal[0]).toBeCloseTo(0.0103, 4);
    for (const input of [0x1a6b80, '#1a6b80', '#1A6B80', 'rgb(26, 107, 128)', teal]) {
      const rgb = colorToLinear(input)!;
      for (let i = 0; i < 3; i++) expect(rgb[i], String(input)).toBeCloseTo(linearTeal[i], 12);
    }
    expect(colorToLinear('white')).toEqual([1, 1, 1]);
    expect(colorToLinear(0)).toEqual([0, 0, 0]);
  });

  it('an [r, g, b] array is linear already and taken as it is', () => {
    expect(colorToLinear([0.0, 0.035, 0.06])).toEqual([0.0, 0.035, 0.06]);
  });

  it('is undefined for anything that is not a colour, and three.js warns of none (the ParameterError names the option)', () => {
    const warn = vi.spyOn(console, 'warn').mockImplementation(() => {});
    try {
      for (const bad of ['#12345', '#zz', 'tealish', ' red', '!', '', 'rgb(1, 2)', 'RGB(1, 2, 3)', 'colour(1)', 0x1000000, -1, 1.5, NaN, {}, [1, 2], [1, 2, 3, 4], null, undefined, true]) {
        expect(colorToLinear(bad), String(bad)).toBeUndefined();
      }
      expect(warn.mock.calls).toEqual([]);
    } finally {
      warn.mockRestore();
    }
    expect(colorToLinear('TEAL')).toEqual(colorToLinear('teal'));
  });

  it('every form is accepted by the shading options and stored as linear RGB', () => {
    for (const input of [0x1a6b80, '#1a6b80', teal]) {
      const merged = mergeOptions(SHADING_OPTIONS, { scatterColor: input, causticColor: input }, DEFAULT_SHADING);
      expect(merged.scatterColor).toEqual(colorToLinear(input));
      expect(merged.causticColor).toEqual(colorToLinear(input));
    }
  });

  it('a bad colour throws a ParameterError naming the option and quoting the value', () => {
    const cases: [unknown, string][] = [
      ['#12345', 'got "#12345"'],
      ['not a colour', 'got "not a colour"'],
      [0x1000000, 'got 16777216'],
      [[1, 2], 'got [1, 2]'],
      [[0, -0.1, 0], 'got [0, -0.1, 0]'],
      [new Color(-1, 0, 0), 'got {r: -1, g: 0, b: 0}'],
      [{ r: 1 }, 'got {r: 1}'],
    ];
    for (const [value, quoted] of cases) {
      const error = errorOf(() => mergeOptions(SHADING_OPTIONS, { causticColor: value }, DEFAULT_SHADING));
      expect(error.parameter).toBe('causticColor');
      expect(error.message.startsWith('causticColor must be a colour: a THREE.Color, a hex number')).toBe(true);
      expect(error.message).toContain(quoted);
    }
  });

  it('as text: "#rrggbb", any CSS colour, or linear "r,g,b"; a bad one is quoted as written', () => {
    expect(parseOptionText(SHADING_OPTIONS, 'causticColor', '#1a6b80')).toEqual(colorToLinear(0x1a6b80));
    expect(parseOptionText(SHADING_OPTIONS, 'causticColor', ' rgb(26, 107, 128) ')).toEqual(colorToLinear(0x1a6b80));
    expect(parseOptionText(SHADING_OPTIONS, 'causticColor', '0.1, 0.2,0.3')).toEqual([0.1, 0.2, 0.3]);
    for (const text of ['1,2', '0.1,x,0.3', '#1a6b8', 'nocolour']) {
      const error = errorOf(() => parseOptionText(SHADING_OPTIONS, 'causticColor', text));
      expect(error.message).toContain(`got "${text}"`);
    }
  });
});

describe('messages show any value briefly', () => {
  it('objects one level deep and lists of at most 8 items, so a cyclic or huge value gives a short message', () => {
    const cyclic: Record<string, unknown> = { r: 1, list: [1, 2] };
    cyclic.self = cyclic;
    const shown = (value: unknown) => errorOf(() => mergeOptions(SHADING_OPTIONS, { causticColor: value }, DEFAULT_SHADING)).message.split('; got ')[1];
    expect(shown(cyclic)).toBe('{r: 1, list: […], self: {…}}');
    expect(shown(Array.from({ length: 1000 }, (_, i) => i))).toBe('[0, 1, 2, 3, 4, 5, 6, 7, …]');
    expect(shown(() => 1)).toBe('a function');
    expect(shown(['#1a6b80', null])).toBe('["#1a6b80", null]');
  });
});

describe('quoteText', () => {
  it('quotes text, cutting it after 40 characters', () => {
    expect(quoteText('abc')).toBe('"abc"');
    expect(quoteText('x'.repeat(40))).toBe(`"${'x'.repeat(40)}"`);
    expect(quoteText('x'.repeat(41))).toBe(`"${'x'.repeat(40)}…"`);
  });
});

describe('the names shells write options by, and the one list of paths', () => {
  it('converts between camel case and kebab case, both ways', () => {
    expect(kebabCase('windSpeed')).toBe('wind-speed');
    expect(kebabCase('scatterColour')).toBe('scatter-colour');
    expect(kebabCase('ior')).toBe('ior');
    for (const name of ['windSpeed', 'patchSizes', 'sunElevation', 'timeScale', 'ior']) expect(camelCase(kebabCase(name))).toBe(name);
  });

  it('routes every key and alias of the tables, as a shell spells them, to its table and key', () => {
    const routes = optionRoutes({ shading: SHADING_OPTIONS, run: RUN_OPTIONS }, kebabCase);
    expect(routes.get('scatter-color')).toEqual({ group: 'shading', key: 'scatterColor', name: 'scatterColor' });
    expect(routes.get('scatter-colour')).toEqual({ group: 'shading', key: 'scatterColor', name: 'scatterColour' });
    expect(routes.get('time-scale')).toEqual({ group: 'run', key: 'timeScale', name: 'timeScale' });
    expect(optionRoutes({ run: RUN_OPTIONS }).get('timeScale')?.key).toBe('timeScale');
  });

  it('lists the paths once, and says them in messages from that list', () => {
    expect(PATH_PREFERENCES).toEqual(['auto', 'gpu', 'js']);
    expect(PATH_PREFERENCES_TEXT).toBe("'auto', 'gpu' or 'js'");
    expect(() => parseOptionText(RUN_OPTIONS, 'path', 'webgpu')).toThrow(`path must be 'auto', 'gpu' or 'js'; got "webgpu"`);
  });

  it("the renderer is 'webgl' or 'webgpu', and a bad one is named with both", () => {
    expect(parseOptionText(RUN_OPTIONS, 'renderer', 'webgpu')).toBe('webgpu');
    expect(parseOptionText(RUN_OPTIONS, 'renderer', ' webgl ')).toBe('webgl');
    expect(() => parseOptionText(RUN_OPTIONS, 'renderer', 'vulkan')).toThrow(`renderer must be 'webgl' or 'webgpu'; got "vulkan"`);
  });

  it('time runs at most 1000 times as fast, either way', () => {
    expect(parseOptionText(RUN_OPTIONS, 'timeScale', '-1000')).toBe(-1000);
    expect(() => parseOptionText(RUN_OPTIONS, 'timeScale', '1001')).toThrow(ParameterError);
    expect(() => parseOptionText(RUN_OPTIONS, 'timeScale', 'NaN')).toThrow(ParameterError);
  });
});
