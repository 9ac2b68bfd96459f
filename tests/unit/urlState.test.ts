import { describe, expect, it } from 'vitest';
import { MIN_HEIGHT } from '../../src/app/flyControls';
import { DEFAULT_PARAMETERS, SIMULATION_OPTIONS } from '../../src/parameters/parameters';
import { colorToLinear } from '../../src/parameters/sceneOptions';
import {
  assignState,
  DEFAULT_STATE,
  defaultState,
  parseState,
  parseValue,
  roundTime,
  serializeState,
  urlRounded,
  URL_KEYS,
  type AppState,
} from '../../src/app/urlState';

function changed(): AppState {
  return {
    ...defaultState(),
    spectrum: 'tma',
    windSpeed: 7.5,
    windDirection: -45,
    fetch: 250,
    peakEnhancement: 2.5,
    spreading: 'cos-2s',
    spreadingExponent: 24,
    swellHeight: 1.5,
    swellPeriod: 14,
    swellDirection: -20,
    swellElongation: 0.3,
    amplitude: 9e-7,
    patchSizes: [20, 120, 600],
    resolution: 128,
    choppiness: 1.25,
    smallWaveCutoff: 0.05,
    depth: 35,
    repeatPeriod: 120,
    seed: 4294967295,
    foamAmount: 2.5,
    foamPersistence: 6,
    sunElevation: 12.5,
    sunAzimuth: -100,
    cloudCover: 0.6,
    ior: 1.34,
    causticPower: 64,
    causticColor: [0.2, 0.25, 0.3],
    absorption: [0.5, 0.1, 0.05],
    scatterColor: [0, 0.04, 0.07],
    mode: 'height',
    refractions: 'sky',
    reflections: 'sky',
    wireframe: true,
    inspector: true,
    buoys: true,
    boat: true,
    scene: 'island',
    renderer: 'webgpu',
    path: 'js',
    quality: 'low',
    targetFps: 20,
    timeScale: 0.5,
    paused: true,
    t: 12.345,
    cam: [100.5, 7.25, -30.125, 170, -20.5],
    skybox: '/skybox/clear-afternoon/',
  };
}

describe('serializeState / parseState', () => {
  it('round-trips every value', () => {
    const state = changed();
    const query = serializeState(state);
    const { state: parsed, warnings } = parseState(query);
    expect(warnings).toEqual([]);
    expect(parsed).toEqual(state);
    expect(serializeState(parsed)).toBe(query);
  });

  it('names every panel parameter and the app values in the query', () => {
    const query = new URLSearchParams(serializeState(changed()));
    expect([...query.keys()]).toEqual(URL_KEYS);
    expect(query.get('depth')).toBe('35');
    expect(query.get('patchSizes')).toBe('20,120,600');
    expect(query.get('spectrum')).toBe('tma');
    expect(query.get('mode')).toBe('height');
    expect(query.get('paused')).toBe('1');
    expect(query.get('cam')).toBe('100.5,7.25,-30.125,170,-20.5');
    expect(query.get('absorption')).toBe('0.5,0.1,0.05');
  });

  it('writes only t and cam for the default state, and reads the defaults back', () => {
    const query = serializeState(DEFAULT_STATE);
    expect(query).toBe('t=0&cam=0,12,0,-53.13,-6.84');
    expect(parseState(query)).toEqual({ state: defaultState(), warnings: [] });
    expect(parseState('')).toEqual({ state: defaultState(), warnings: [] });
    expect(parseState('?')).toEqual({ state: defaultState(), warnings: [] });
  });

  it('has every simulation option as a URL key, first, in the table’s order', () => {
    const keys = Object.keys(SIMULATION_OPTIONS);
    expect(URL_KEYS.slice(0, keys.length)).toEqual(keys);
  });

  it('writes patch sizes as "13.7,79.3,457" and reads them back', () => {
    expect(serializeState({ ...defaultState(), patchSizes: [10, 60, 350] })).toContain('patchSizes=10,60,350&');
    expect(parseState('patchSizes=13.7,79.3,457')).toEqual({ state: defaultState(), warnings: [] });
    const { state, warnings } = parseState('patchSizes=5,40');
    expect(warnings).toEqual([]);
    expect(state.patchSizes).toEqual([5, 40]);
  });

  it('warns that an old link’s patchSize is unknown and keeps the default cascades', () => {
    const { state, warnings } = parseState('patchSize=250');
    expect(warnings).toEqual([{ parameter: 'patchSize', message: expect.stringContaining('unknown') }]);
    expect(state).toEqual(defaultState());
  });

  it('writes deep water as depth=deep and reads deep / Infinity', () => {
    expect(serializeState({ ...defaultState(), depth: 35 })).toContain('depth=35');
    expect(parseState('depth=deep').state.depth).toBe(Infinity);
    expect(parseState('depth=Infinity').state.depth).toBe(Infinity);
    expect(parseState('depth=12.5').state.depth).toBe(12.5);
  });

  it('reads colours as linear r,g,b or as CSS (sRGB), and the British spellings as aliases', () => {
    const teal = colorToLinear(0x1a6b80);
    expect(parseState('causticColor=%231a6b80&scatterColor=rgb(26,107,128)')).toEqual({
      state: { ...defaultState(), causticColor: teal, scatterColor: teal },
      warnings: [],
    });
    const old = parseState('causticColour=0.5,0.5,0.5&scatterColour=0,0.1,0.2');
    expect(old).toEqual({ state: { ...defaultState(), causticColor: [0.5, 0.5, 0.5], scatterColor: [0, 0.1, 0.2] }, warnings: [] });
    // Written back under the American names, as linear r,g,b.
    expect(serializeState(old.state)).toBe('causticColor=0.5,0.5,0.5&scatterColor=0,0.1,0.2&t=0&cam=0,12,0,-53.13,-6.84');
  });

  it('reads flags as 1/0 and true/false', () => {
    expect(parseState('paused=1&wireframe=true&inspector=0').state).toMatchObject({ paused: true, wireframe: true, inspector: false });
  });

  it('clamps the camera depth and pitch the way the controls do', () => {
    expect(parseState('cam=1,-5,2,370,120').state.cam).toEqual([1, -5, 2, 10, 89]); // diving is allowed
    expect(parseState('cam=1,-500,2,0,0').state.cam).toEqual([1, MIN_HEIGHT, 2, 0, 0]);
  });

  it('stores t to the millisecond, so roundTime(t) round-trips exactly', () => {
    const t = roundTime(1234.56789);
    expect(t).toBe(1234.568);
    expect(parseState(serializeState({ ...defaultState(), t })).state.t).toBe(t);
  });
});

describe('invalid values', () => {
  const cases: [string, string][] = [
    ['windSpeed', 'abc'],
    ['windSpeed', '150'],
    ['windSpeed', '61'],
    ['windSpeed', ''],
    ['spectrum', 'gauss'],
    ['spreading', 'cos2s'],
    ['fetch', '0'],
    ['swellElongation', '2'],
    ['resolution', '100'],
    ['resolution', '2048'],
    ['patchSizes', '-3'],
    ['patchSizes', '10,15'],
    ['patchSizes', '10,abc'],
    ['patchSizes', ''],
    ['patchSizes', '1,2,4,8,16'],
    ['amplitude', '0x10'],
    ['depth', '0'],
    ['depth', 'shallow'],
    ['seed', '1.5'],
    ['sunElevation', '100'],
    ['ior', '0.9'],
    ['causticPower', '0'],
    ['causticColor', '1,2'],
    ['causticColor', '#12345'],
    ['absorption', '1,-1,1'],
    ['scatterColor', 'reddish'],
    ['mode', 'shiny'],
    ['path', 'webgpu'],
    ['wireframe', 'maybe'],
    ['timeScale', '-1001'],
    ['timeScale', '1e308'],
    ['paused', '2'],
    ['t', 'NaN'],
    ['cam', '1,2,3'],
    ['cam', '1,2,3,4,x'],
  ];
  for (const [name, value] of cases) {
    it(`${name}=${value} warns naming ${name} and keeps the default`, () => {
      const { state, warnings } = parseState(`${name}=${encodeURIComponent(value)}&windDirection=10`);
      expect(warnings).toHaveLength(1);
      expect(warnings[0].parameter).toBe(name);
      expect(warnings[0].message.startsWith(name)).toBe(true);
      expect(warnings[0].message).toContain('default');
      expect(state).toEqual({ ...defaultState(), windDirection: 10 });
    });
  }

  it('quotes a bad value as written, its first 40 characters', () => {
    const { warnings } = parseState(`windSpeed=${'9'.repeat(30)}abcdefghijklmnop&timeScale=${'x'.repeat(50)}`);
    expect(warnings.map((w) => w.message)).toEqual([
      expect.stringContaining(`got "${'9'.repeat(30)}abcdefghij…"`),
      expect.stringContaining(`got "${'x'.repeat(40)}…"`),
    ]);
    expect(parseState('windSpeed=abc').warnings[0].message).toContain('got "abc"');
  });

  it('says deep water as the URL writes it, "deep"', () => {
    const { warnings } = parseState('resolution=1024&patchSizes=10&repeatPeriod=9000');
    expect(warnings[0].message).toContain('at depth deep');
    expect(parseState('depth=-1').warnings[0].message).toContain('using the default deep');
    // (The rule itself says how code writes it: 'or Infinity (written "deep")'.)
    for (const { message } of [...warnings, ...parseState('depth=-1').warnings]) expect(message).not.toMatch(/(depth|default) Infinity/);
  });

  it('keeps the good values next to a bad one', () => {
    const { state, warnings } = parseState('windSpeed=abc&seed=9&mode=height');
    expect(warnings.map((w) => w.parameter)).toEqual(['windSpeed']);
    expect(state.windSpeed).toBe(DEFAULT_PARAMETERS.windSpeed);
    expect(state.seed).toBe(9);
    expect(state.mode).toBe('height');
  });

  it('reads scene=island, and warns of an unknown scene and keeps the open sea', () => {
    expect(parseState('scene=island').state.scene).toBe('island');
    const { state, warnings } = parseState('scene=volcano&seed=9');
    expect(warnings).toEqual([{ parameter: 'scene', message: 'scene must be "sea" or "island"; got "volcano" — using the default sea' }]);
    expect(state.scene).toBe('sea');
    expect(state.seed).toBe(9);
  });

  it('warns about unknown parameters and ignores them', () => {
    const { state, warnings } = parseState('windspeed=5');
    expect(warnings).toEqual([{ parameter: 'windspeed', message: expect.stringContaining('unknown') }]);
    expect(state).toEqual(defaultState());
  });

  it('resets the parameter a combination check names (repeatPeriod too long for N and patch size)', () => {
    // N = 1024 on a 10 m patch repeats at most every ~6160 s; each value alone is fine.
    const { state, warnings } = parseState('resolution=1024&patchSizes=10&repeatPeriod=9000');
    expect(warnings.map((w) => w.parameter)).toEqual(['repeatPeriod']);
    expect(warnings[0].message).toContain('using the default 200');
    expect(state).toMatchObject({ resolution: 1024, patchSizes: [10], repeatPeriod: DEFAULT_PARAMETERS.repeatPeriod });
  });

  it('resets patch sizes whose neighbours are too far apart for the resolution', () => {
    // At N = 64 neighbours may differ by at most N/2 = 32×; each value alone is fine.
    const { state, warnings } = parseState('resolution=64&patchSizes=1,100');
    expect(warnings.map((w) => w.parameter)).toEqual(['patchSizes']);
    expect(warnings[0].message).toContain('using the default 13.7,79.3,457');
    expect(state).toMatchObject({ resolution: 64, patchSizes: DEFAULT_PARAMETERS.patchSizes });
  });

  it('parseValue explains what is allowed', () => {
    expect(parseValue('resolution', '100')).toEqual({ error: expect.stringMatching(/^resolution must be a power of two/) });
    expect(parseValue('mode', 'x')).toEqual({ error: expect.stringContaining('full, fresnel') });
  });
});

describe('helpers', () => {
  it('urlRounded gives the value a reload would give', () => {
    expect(urlRounded('windSpeed', 0.1 + 0.2)).toBe(0.3);
    expect(urlRounded('cam', [1.23456, 2, 3, 4.00049, 5])).toEqual([1.235, 2, 3, 4, 5]);
    expect(urlRounded('mode', 'height')).toBe('height');
  });

  it('assignState writes arrays in place', () => {
    const state = defaultState();
    const absorption = state.absorption;
    assignState(state, { absorption: [1, 2, 3], windSpeed: 5 });
    expect(state.absorption).toBe(absorption);
    expect(absorption).toEqual([1, 2, 3]);
    expect(state.windSpeed).toBe(5);
  });

  it('defaultState is a fresh copy', () => {
    const a = defaultState();
    a.absorption[0] = 99;
    expect(DEFAULT_STATE.absorption[0]).toBe(0.45);
    expect(defaultState().absorption[0]).toBe(0.45);
  });
});
