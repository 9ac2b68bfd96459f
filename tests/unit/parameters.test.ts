/**
 * validateParameters: every bad value is refused with a ParameterError that names the parameter,
 * repeats the value and says what is allowed; good changes merge over the base without touching it;
 * combinations are checked (each cascade's band inside its grid, every frequency index in the
 * phase table). parseParameterText / formatParameterText: the text form of URLs, attributes and
 * the CLI.
 */
import { describe, expect, it } from 'vitest';
import { angularFrequency, MAX_FREQUENCY_INDEX } from '../../src/spectrum/dispersion';
import { formatOptionText } from '../../src/parameters/options';
import {
  DEFAULT_PARAMETERS,
  isPowerOfTwo,
  MAX_CASCADES,
  ParameterError,
  parseParameterText,
  SIMULATION_OPTIONS,
  SPECTRUM_MODELS,
  SPREADING_MODELS,
  validateParameters,
  type SimulationParameters,
} from '../../src/parameters/parameters';

/** How ParameterError prints a value: text in double quotes, lists as [a, b], everything else with String. */
function shown(value: unknown): string {
  if (typeof value === 'string') return `"${value}"`;
  return Array.isArray(value) ? `[${value.map(shown).join(', ')}]` : String(value);
}

/** Runs validateParameters and returns the ParameterError it must throw. */
function rejection(changes: Partial<SimulationParameters>, base?: SimulationParameters): ParameterError {
  try {
    validateParameters(changes, base);
  } catch (error) {
    expect(error).toBeInstanceOf(ParameterError);
    return error as ParameterError;
  }
  throw new Error(`validateParameters accepted ${JSON.stringify(changes)}`);
}

/**
 * Each case: the bad change, and fragments the message must contain to say what is allowed.
 * The parameter's name and String(value) are checked for every case.
 */
const BAD_VALUES: [keyof SimulationParameters, unknown, string[]][] = [
  ['resolution', 100, ['power of two', '16', '1024']],
  ['resolution', 255, ['power of two']],
  ['resolution', 8, ['16']],
  ['resolution', 2048, ['1024']],
  ['resolution', 0, ['power of two']],
  ['resolution', -16, ['power of two']],
  ['resolution', 16.5, ['power of two']],
  ['resolution', NaN, ['power of two']],
  ['patchSizes', [0], ['1 to 4 sizes', 'from 1 to 100000']],
  ['patchSizes', [-250], ['from 1 to 100000']],
  ['patchSizes', [NaN], ['from 1 to 100000']],
  ['patchSizes', [Infinity], ['100000']],
  ['patchSizes', [0.5], ['from 1']],
  ['patchSizes', [2e5], ['100000']],
  ['patchSizes', [], ['1 to 4 sizes']],
  ['patchSizes', [10, 20, 40, 80, 160], ['1 to 4 sizes']],
  ['patchSizes', [10, 15], ['at least twice the one before']],
  ['patchSizes', [100, 10], ['ascending']],
  ['patchSizes', [10, '40'], ['sizes in metres']],
  ['patchSizes', 250, ['sizes in metres']],
  ['spectrum', 'phillip', ['one of phillips, pierson-moskowitz, jonswap, tma']],
  ['spectrum', 'JONSWAP', ['one of']],
  ['spreading', 'cos2s', ['one of cos-2s, mitsuyasu, hasselmann, donelan-banner']],
  ['windSpeed', NaN, ['from 0 to 60']],
  ['windSpeed', Infinity, ['from 0 to 60']],
  ['windSpeed', -1, ['from 0 to 60']],
  ['windSpeed', 60.5, ['from 0 to 60']],
  ['windDirection', NaN, ['finite']],
  ['windDirection', Infinity, ['finite']],
  ['windDirection', 1e6 + 1, ['1e6']],
  ['fetch', 0, ['> 0', '100000']],
  ['fetch', -5, ['> 0']],
  ['fetch', 1e5 + 1, ['100000']],
  ['fetch', NaN, ['> 0']],
  ['peakEnhancement', 0.99, ['from 1 to 10']],
  ['peakEnhancement', 10.5, ['from 1 to 10']],
  ['spreadingExponent', -1, ['from 0 to 1000']],
  ['spreadingExponent', 1001, ['from 0 to 1000']],
  ['swellHeight', -0.1, ['from 0 to 30']],
  ['swellHeight', 31, ['from 0 to 30']],
  ['swellPeriod', 0, ['> 0', '40']],
  ['swellPeriod', 41, ['40']],
  ['swellDirection', NaN, ['finite']],
  ['swellElongation', -0.1, ['from 0 to 1']],
  ['swellElongation', 1.1, ['from 0 to 1']],
  ['amplitude', -2e-6, ['from 0 to 1']],
  ['amplitude', NaN, ['from 0 to 1']],
  ['amplitude', 1.5, ['from 0 to 1']],
  ['smallWaveCutoff', -0.1, ['from 0 to 10']],
  ['smallWaveCutoff', 10.5, ['from 0 to 10']],
  ['repeatPeriod', 0, ['> 0']],
  ['repeatPeriod', -200, ['> 0']],
  ['repeatPeriod', Infinity, ['100000']],
  ['repeatPeriod', 1e5 + 1, ['100000']],
  ['depth', 0, ['> 0']],
  ['depth', -10, ['> 0']],
  ['depth', NaN, ['> 0']],
  ['choppiness', -1, ['from 0 to 4']],
  ['choppiness', NaN, ['from 0 to 4']],
  ['choppiness', 4.5, ['from 0 to 4']],
  ['seed', 1.5, ['integer']],
  ['seed', -1, ['integer', '0']],
  ['seed', 2 ** 32, ['4294967295']],
  ['seed', NaN, ['integer']],
  ['resolution', '256', ['power of two']],
  ['seed', null, ['integer']],
];

describe('validateParameters takes an undefined value as not given', () => {
  it('keeps the base value, as for an optional property left out', () => {
    const base = validateParameters({ windSpeed: 17, spectrum: 'tma' });
    expect(validateParameters({ windSpeed: undefined, spectrum: undefined, seed: 9 }, base)).toEqual({ ...base, seed: 9 });
  });
});

describe('validateParameters rejects bad values', () => {
  for (const [parameter, value, allowed] of BAD_VALUES) {
    it(`${parameter} = ${shown(value)}`, () => {
      const error = rejection({ [parameter]: value } as Partial<SimulationParameters>);
      expect(error.name).toBe('ParameterError');
      expect(error.parameter).toBe(parameter);
      expect(Object.is(error.value, value)).toBe(true);
      expect(error.message.startsWith(`${parameter} must be `)).toBe(true);
      expect(error.message).toContain(`got ${shown(value)}`);
      for (const fragment of allowed) expect(error.message).toContain(fragment);
    });
  }

  it('rejects an unknown key, naming it and listing the known ones', () => {
    const error = rejection({ windspeed: 10 } as unknown as Partial<SimulationParameters>);
    expect(error.parameter).toBe('windspeed');
    expect(error.value).toBe(10);
    expect(error.message).toContain('windspeed must be one of');
    for (const key of Object.keys(DEFAULT_PARAMETERS)) expect(error.message).toContain(key);
    expect(error.message).toContain('got 10');
  });

  it('names the first bad parameter when several are bad', () => {
    expect(rejection({ resolution: 100, patchSizes: [-1] }).parameter).toBe('resolution');
    expect(rejection({ patchSizes: [-1], resolution: 100 }).parameter).toBe('patchSizes');
  });
});

describe('validateParameters: the repeat period must keep every frequency index in the phase table', () => {
  /**
   * Largest T (s) for which one cascade of side L keeps the fastest mode's index round(ω·T/2π) ≤
   * MAX_FREQUENCY_INDEX, when T is long enough that the cascade uses T itself (see below). The
   * fastest mode of a single cascade is the grid corner, k = (N/2)·(2π/L)·√2.
   */
  function longestRepeatPeriod(resolution: number, patchSize: number, depth: number): number {
    const kCorner = ((resolution / 2) * 2 * Math.PI * Math.SQRT2) / patchSize;
    return ((MAX_FREQUENCY_INDEX + 0.5) * 2 * Math.PI) / angularFrequency(kCorner, depth);
  }

  const cases: { resolution: number; patchSize: number; depth: number }[] = [
    { resolution: 1024, patchSize: 10, depth: Infinity },
    { resolution: 1024, patchSize: 250, depth: Infinity },
    { resolution: 512, patchSize: 3, depth: 2 },
    { resolution: 16, patchSize: 1, depth: Infinity },
  ];
  for (const { resolution, patchSize, depth } of cases) {
    it(`refuses a repeatPeriod past the limit for one cascade of ${patchSize} m, N = ${resolution}, depth ${depth}`, () => {
      const change = { resolution, patchSizes: [patchSize], depth };
      const limit = longestRepeatPeriod(resolution, patchSize, depth);
      // The cascade uses T itself when T already keeps its slowest mode (the fundamental 2π/L)
      // within 1 % (cascadeBands.ts): π/T ≤ 0.01·ω(2π/L). True for all these limits.
      expect(Math.PI / limit).toBeLessThan(0.01 * angularFrequency((2 * Math.PI) / patchSize, depth));
      // Just inside the limit passes; just past it fails (0.1% either side of the boundary is far
      // more than rounding, which is ~1e-16 relative).
      expect(() => validateParameters({ ...change, repeatPeriod: limit * 0.999 })).not.toThrow();
      const error = rejection({ ...change, repeatPeriod: limit * 1.001 });
      expect(error.parameter).toBe('repeatPeriod');
      expect(error.value).toBe(limit * 1.001);
      expect(error.message).toContain(`got ${limit * 1.001}`);
      expect(error.message).toContain(`resolution ${resolution}`);
      expect(error.message).toContain(`patch ${patchSize} m`);
      // Deep water as the URL writes it, not "Infinity".
      expect(error.message).toContain(depth === Infinity ? 'depth deep ' : `depth ${depth} m`);
      expect(error.message).not.toContain('Infinity');
      expect(error.message).toContain(String(MAX_FREQUENCY_INDEX));
      // The index it reports is the fastest mode's, round(ω·T/2π), computed here independently.
      const kCorner = ((resolution / 2) * 2 * Math.PI * Math.SQRT2) / patchSize;
      const index = Math.round((angularFrequency(kCorner, depth) * limit * 1.001) / (2 * Math.PI));
      expect(error.message).toContain(`would be ${index}`);
    });
  }

  it('checks each cascade with its own repeat period and fastest mode', () => {
    // Cascade c keeps |k| below the edge √(2π/L_{c−1} · πN/L_c) with the next finer cascade (the
    // finest: up to its grid corner) and from the edge with the next coarser one; its period is
    // T·2^j, doubled until π/T_c ≤ 1 % of ω at its slowest mode, max(low edge, 2π/L). The largest
    // index over all cascades must stay ≤ MAX_FREQUENCY_INDEX.
    function largestIndex(p: SimulationParameters): number {
      const L = p.patchSizes;
      const edge = (finer: number) => Math.sqrt(((2 * Math.PI) / L[finer]) * ((Math.PI * p.resolution) / L[finer + 1]));
      let largest = 0;
      L.forEach((size, c) => {
        const low = c === L.length - 1 ? 0 : edge(c);
        const high = c === 0 ? Infinity : edge(c - 1);
        let period = p.repeatPeriod;
        while (Math.PI / period > 0.01 * angularFrequency(Math.max(low, (2 * Math.PI) / size), p.depth)) period *= 2;
        const fastest = Math.min(high, (Math.SQRT2 * Math.PI * p.resolution) / size);
        largest = Math.max(largest, Math.round((angularFrequency(fastest, p.depth) * period) / (2 * Math.PI)));
      });
      return largest;
    }
    let accepted = 0;
    let refused = 0;
    for (const base of [
      { resolution: 256, patchSizes: [13.7, 79.3, 457] },
      { resolution: 1024, patchSizes: [2, 40, 800], depth: 5 },
      { resolution: 64, patchSizes: [1, 5, 25, 125], depth: 0.5 },
    ]) {
      for (let e = 0; e <= 50; e++) {
        const repeatPeriod = 10 ** (e / 10); // 1 s to 100000 s
        const p = { ...DEFAULT_PARAMETERS, ...base, repeatPeriod };
        if (largestIndex(p) <= MAX_FREQUENCY_INDEX) {
          expect(() => validateParameters({ ...base, repeatPeriod }), `T = ${repeatPeriod}`).not.toThrow();
          accepted++;
        } else {
          expect(rejection({ ...base, repeatPeriod }).parameter, `T = ${repeatPeriod}`).toBe('repeatPeriod');
          refused++;
        }
      }
    }
    expect(accepted).toBeGreaterThan(20);
    expect(refused).toBeGreaterThan(20);
  });

  it('checks the merged values: a resolution change can invalidate the base repeat period', () => {
    const base = validateParameters({ resolution: 64, patchSizes: [10], repeatPeriod: 10000 });
    const error = rejection({ resolution: 1024 }, base);
    expect(error.parameter).toBe('repeatPeriod');
    expect(error.value).toBe(10000);
  });
});

describe('validateParameters: each band edge must lie inside both neighbouring grids', () => {
  // The edge between L_c and L_{c+1} is √(2π/L_c · πN/L_{c+1}): above the finer grid's fundamental
  // and below the coarser grid's Nyquist radius exactly while L_{c+1}/L_c ≤ N/2 (cascadeBands.ts).
  for (const resolution of [16, 64, 256, 1024]) {
    it(`accepts neighbours up to N/2 = ${resolution / 2} apart at N = ${resolution}, and refuses more`, () => {
      const limit = resolution / 2;
      expect(() => validateParameters({ resolution, patchSizes: [10, 10 * limit], repeatPeriod: 100 })).not.toThrow();
      const tooFar = [10, 10 * limit * 1.001];
      const error = rejection({ resolution, patchSizes: tooFar, repeatPeriod: 100 });
      expect(error.parameter).toBe('patchSizes');
      expect(error.value).toEqual(tooFar);
      expect(error.message).toContain(`at most ${limit}×`);
      expect(error.message).toContain(`resolution ${resolution}`);
      expect(error.message).toContain(`got [${tooFar.join(', ')}]`);
      // The same for the coarsest pair of four cascades.
      const four = [1, 2, 4, 4 * limit * 1.01];
      expect(rejection({ resolution, patchSizes: four, repeatPeriod: 100 }).parameter).toBe('patchSizes');
    });
  }

  it('accepts a single cascade of any allowed size at any resolution (the finest keeps its grid to the corner)', () => {
    for (const resolution of [16, 64, 1024]) {
      for (const size of [1, 13.7, 1000, 1e5]) {
        expect(() => validateParameters({ resolution, patchSizes: [size], repeatPeriod: 20 }), `N = ${resolution}, L = ${size}`).not.toThrow();
      }
    }
  });

  it('accepts the default cascades at every resolution', () => {
    for (const resolution of [16, 32, 64, 128, 256, 512, 1024]) expect(() => validateParameters({ resolution }), `N = ${resolution}`).not.toThrow();
  });
});

describe('validateParameters merging', () => {
  it('returns the defaults for no changes, as a new object', () => {
    const result = validateParameters({});
    expect(result).toEqual(DEFAULT_PARAMETERS);
    expect(result).not.toBe(DEFAULT_PARAMETERS);
  });

  it('keeps base values for keys not changed and does not mutate base', () => {
    const base: SimulationParameters = {
      spectrum: 'tma',
      windSpeed: 20,
      windDirection: -45,
      fetch: 300,
      peakEnhancement: 2,
      spreading: 'cos-2s',
      spreadingExponent: 30,
      swellHeight: 1.5,
      swellPeriod: 14,
      swellDirection: 100,
      swellElongation: 0.2,
      amplitude: 1e-5,
      smallWaveCutoff: 0,
      depth: 30,
      resolution: 128,
      patchSizes: [20, 100, 500],
      repeatPeriod: 500,
      choppiness: 0.5,
      seed: 99,
      foamAmount: 2,
      foamPersistence: 5,
    };
    const snapshot = structuredClone(base);
    const result = validateParameters({ windSpeed: 5, seed: 3 }, base);
    expect(result).toEqual({ ...snapshot, windSpeed: 5, seed: 3 });
    expect(base).toEqual(snapshot);
    expect(result).not.toBe(base);
    // A refused change leaves base untouched too.
    rejection({ windSpeed: 7, depth: -1 }, base);
    expect(base).toEqual(snapshot);
  });

  it('copies a changed list: changing the caller’s array later does not change the result', () => {
    const sizes = [10, 50, 250];
    const result = validateParameters({ patchSizes: sizes });
    sizes[0] = 20;
    expect(result.patchSizes).toEqual([10, 50, 250]);
  });

  it('accepts the edges of every range', () => {
    const edges: Partial<SimulationParameters>[] = [
      ...SPECTRUM_MODELS.map((spectrum) => ({ spectrum })),
      ...SPREADING_MODELS.map((spreading) => ({ spreading })),
      { resolution: 16 },
      { resolution: 1024 },
      { windSpeed: 0 },
      { windSpeed: 60 },
      { windDirection: -1e6 },
      { windDirection: 1e6 },
      { fetch: 1e-6 },
      { fetch: 1e5 },
      { peakEnhancement: 1 },
      { peakEnhancement: 10 },
      { spreadingExponent: 0 },
      { spreadingExponent: 1000 },
      { swellHeight: 0 },
      { swellHeight: 30 },
      { swellPeriod: 40 },
      { swellDirection: -720.5 },
      { swellElongation: 0 },
      { swellElongation: 1 },
      { amplitude: 0 },
      { amplitude: 1 },
      { smallWaveCutoff: 0 },
      { smallWaveCutoff: 10 },
      { depth: Infinity },
      { depth: 1e-3 },
      { choppiness: 0 },
      { choppiness: 4 },
      { seed: 0 },
      { seed: 4294967295 },
      { patchSizes: [1] },
      { patchSizes: [1e5] },
      { patchSizes: [1, 2, 4, 8] }, // MAX_CASCADES, each exactly twice the one before
      { resolution: 16, patchSizes: [1e5], repeatPeriod: 1e5 },
    ];
    expect(MAX_CASCADES).toBe(4);
    for (const change of edges) expect(validateParameters(change), JSON.stringify(change)).toEqual({ ...DEFAULT_PARAMETERS, ...change });
  });

  it('DEFAULT_PARAMETERS are frozen and themselves valid', () => {
    expect(Object.isFrozen(DEFAULT_PARAMETERS)).toBe(true);
    expect(Object.isFrozen(DEFAULT_PARAMETERS.patchSizes)).toBe(true);
    expect(validateParameters({ ...DEFAULT_PARAMETERS })).toEqual(DEFAULT_PARAMETERS);
  });

  it('has the documented defaults', () => {
    expect(DEFAULT_PARAMETERS).toMatchObject({ spectrum: 'jonswap', windSpeed: 10, patchSizes: [13.7, 79.3, 457], resolution: 256, depth: Infinity });
  });
});

describe('SIMULATION_OPTIONS', () => {
  it('has a rule for every parameter and nothing else, and every default passes its rule', () => {
    expect(Object.keys(SIMULATION_OPTIONS).sort()).toEqual(Object.keys(DEFAULT_PARAMETERS).sort());
    for (const [key, rule] of Object.entries(SIMULATION_OPTIONS)) {
      expect(rule.check(DEFAULT_PARAMETERS[key as keyof SimulationParameters]), key).toBe(true);
      if (rule.type === 'choice') {
        expect(rule.choices, key).toBeDefined();
        for (const choice of rule.choices ?? []) expect(rule.check(choice)).toBe(true);
        expect(rule.allowed).toBe(`one of ${(rule.choices ?? []).join(', ')}`);
      }
    }
    expect(SIMULATION_OPTIONS.spectrum.choices).toEqual(SPECTRUM_MODELS);
    expect(SIMULATION_OPTIONS.spreading.choices).toEqual(SPREADING_MODELS);
    expect(SIMULATION_OPTIONS.patchSizes.type).toBe('numbers');
  });
});

describe('parseParameterText / formatOptionText (the text form)', () => {
  /** The ParameterError parseParameterText must throw. */
  function textRejection(key: keyof SimulationParameters, text: string): ParameterError {
    try {
      parseParameterText(key, text);
    } catch (error) {
      expect(error).toBeInstanceOf(ParameterError);
      return error as ParameterError;
    }
    throw new Error(`parseParameterText accepted ${key} = "${text}"`);
  }

  it('round-trips every default and a changed value of every parameter', () => {
    const changed: SimulationParameters = {
      spectrum: 'pierson-moskowitz',
      windSpeed: 7.25,
      windDirection: -123.456,
      fetch: 0.5,
      peakEnhancement: 4.2,
      spreading: 'donelan-banner',
      spreadingExponent: 17,
      swellHeight: 2.5,
      swellPeriod: 13.3,
      swellDirection: 721,
      swellElongation: 0.75,
      amplitude: 3.3e-7,
      smallWaveCutoff: 0.02,
      depth: 12.5,
      resolution: 512,
      patchSizes: [8, 40.5, 300],
      repeatPeriod: 123.25,
      choppiness: 1.75,
      seed: 4294967295,
      foamAmount: 0.25,
      foamPersistence: 1.5,
    };
    for (const values of [DEFAULT_PARAMETERS, changed]) {
      for (const key of Object.keys(SIMULATION_OPTIONS) as (keyof SimulationParameters)[]) {
        const text = formatOptionText(values[key]);
        expect(parseParameterText(key, text), `${key} = "${text}"`).toEqual(values[key]);
      }
    }
  });

  it('writes and reads deep water as "deep", also Infinity and inf in any case', () => {
    expect(formatOptionText(Infinity)).toBe('deep');
    for (const text of ['deep', 'Deep', ' DEEP ', 'Infinity', 'inf']) expect(parseParameterText('depth', text)).toBe(Infinity);
    expect(parseParameterText('depth', '12.5')).toBe(12.5);
    expect(formatOptionText(12.5)).toBe('12.5');
  });

  it('writes lists comma-separated, "13.7,79.3,457" for the default cascades', () => {
    expect(formatOptionText([13.7, 79.3, 457])).toBe('13.7,79.3,457');
    expect(parseParameterText('patchSizes', '13.7,79.3,457')).toEqual([13.7, 79.3, 457]);
    expect(parseParameterText('patchSizes', ' 10 , 25 ')).toEqual([10, 25]);
    expect(parseParameterText('patchSizes', '250')).toEqual([250]);
  });

  it('writes short decimals: 0, and 0.1 + 0.2 as 0.3', () => {
    expect(formatOptionText(0)).toBe('0');
    expect(formatOptionText(0.1 + 0.2)).toBe('0.3');
    expect(formatOptionText(2e-6)).toBe('0.000002');
    expect(parseParameterText('amplitude', '2e-6')).toBe(2e-6);
    expect(parseParameterText('spectrum', ' tma ')).toBe('tma');
  });

  const BAD_TEXT: [keyof SimulationParameters, string, string][] = [
    ['windSpeed', 'abc', 'from 0 to 60'],
    ['windSpeed', '', 'from 0 to 60'],
    ['windSpeed', '61', 'from 0 to 60'],
    ['amplitude', '0x10', 'from 0 to 1'],
    ['resolution', '100', 'power of two'],
    ['depth', '0', 'written "deep"'],
    ['depth', 'shallow', 'written "deep"'],
    ['seed', '1.5', 'integer'],
    ['patchSizes', '10,15', 'at least twice'],
    ['patchSizes', '10,,40', 'sizes in metres'],
    ['patchSizes', '', 'sizes in metres'],
    ['spectrum', 'gauss', 'one of phillips'],
    ['spreading', '', 'one of cos-2s'],
  ];
  for (const [key, text, allowed] of BAD_TEXT) {
    it(`refuses ${key} = "${text}", naming ${key} and quoting the text`, () => {
      const error = textRejection(key, text);
      expect(error.parameter).toBe(key);
      expect(error.message.startsWith(`${key} must be `)).toBe(true);
      expect(error.message).toContain(allowed);
      expect(error.message).toContain(`got "${text}"`);
    });
  }

  it('shortens a long text in the message', () => {
    const error = textRejection('windSpeed', 'x'.repeat(100));
    expect(error.message).toContain(`got "${'x'.repeat(40)}…"`);
    expect(error.message).not.toContain('x'.repeat(41));
  });

  it('refuses an unknown key', () => {
    expect(textRejection('patchSize' as keyof SimulationParameters, '250').message).toContain('patchSize must be one of spectrum');
  });
});

describe('isPowerOfTwo', () => {
  it('is true exactly for 2^0 … 2^30', () => {
    const powers = new Set(Array.from({ length: 31 }, (_, e) => 2 ** e));
    for (let n = -4; n <= 5000; n++) expect(isPowerOfTwo(n)).toBe(powers.has(n));
    for (const n of powers) expect(isPowerOfTwo(n)).toBe(true);
    for (const n of [0.5, 2.5, NaN, Infinity, -1024]) expect(isPowerOfTwo(n)).toBe(false);
  });
});

describe('edge cases found in review', () => {
  it('rejects keys inherited from Object.prototype with a ParameterError', () => {
    for (const changes of [{ constructor: 1 }, { toString: 'x' }, JSON.parse('{"__proto__": 3}')]) {
      expect(() => validateParameters(changes as never)).toThrow(ParameterError);
      expect(() => validateParameters(changes as never)).toThrow(/must be one of/);
    }
  });
});
