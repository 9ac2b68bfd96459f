/**
 * The whitecap foam's coverage (src/layers/foamModel.ts, JS path) against Monahan &
 * O'Muircheartaigh's law on every preset and at winds from 4 to 25 m/s, and its independence of the
 * grid: N, the number of cascades and their patch sizes (the quality levels').
 */
import { describe, expect, it } from 'vitest';
import type { SimulationParameters } from '../../src/parameters/parameters';
import { beaufortPreset, SEA_PRESETS } from '../../src/spectrum/presets';
import { mean, seaWithFoam } from './seaWithFoam';

/**
 * Monahan & O'Muircheartaigh (1980), "Optimal power-law description of oceanic whitecap coverage
 * dependence on wind speed", J. Phys. Oceanogr. 10:2094–2099, eq. 5: whitecap fraction W(U10),
 * written out here apart from the model's whitecapFraction.
 */
const monahan = (windSpeed: number) => 3.84e-6 * windSpeed ** 3.41;

/**
 * Mean coverage over `seconds` after a warm-up to t = 20 s, sampled every 0.4 s with steps of 0.1 s
 * (the JS foam, as whitecapFoam.ts advances it).
 */
function measuredCoverage(parameters: Partial<SimulationParameters>, seconds = 2): number {
  const sea = seaWithFoam(parameters);
  sea.advance(20);
  let [sum, samples] = [0, 0];
  for (let k = 1; k <= Math.round(seconds / 0.1); k++) {
    sea.advance(20 + k * 0.1);
    if (k % 4 === 0) [sum, samples] = [sum + mean(sea.foam.coverage), samples + 1];
  }
  return sum / samples;
}

/** Rows of a Markdown table. */
const table = (head: string[], rows: (string | number)[][]) =>
  [`| ${head.join(' | ')} |`, `|${head.map(() => '---').join('|')}|`, ...rows.map((r) => `| ${r.join(' | ')} |`)].join('\n');
const percent = (w: number) => (100 * w).toPrecision(3);

describe('whitecap coverage against Monahan & O’Muircheartaigh (1980)', () => {
  it('is within a factor of 2 of W = 3.84e-6·U10^3.41 on every preset (N = 64)', () => {
    const seas: [string, Partial<SimulationParameters>][] = [
      ...Object.entries(SEA_PRESETS),
      ...[3, 4, 5, 6, 7, 8, 9, 10, 11, 12].map((force): [string, Partial<SimulationParameters>] => [`Beaufort ${force}`, beaufortPreset(force)]),
    ];
    const rows = seas.map(([name, preset]) => {
      const windSpeed = preset.windSpeed!;
      const coverage = measuredCoverage({ ...preset, resolution: 64 }, 4);
      return { name, windSpeed, cascades: preset.patchSizes!.length, coverage, monahan: monahan(windSpeed) };
    });
    console.log(
      table(
        ['preset', 'U10 (m/s)', 'cascades', 'measured W (%)', 'Monahan W (%)', 'ratio'],
        rows.map((r) => [r.name, r.windSpeed, r.cascades, percent(r.coverage), percent(r.monahan), r.windSpeed > 3.3 ? (r.coverage / r.monahan).toFixed(2) : '– (onset: none)']),
      ),
    );
    for (const row of rows) {
      // Force 2 and below (the calm preset, 3 m/s): none, by the onset rule (WMO: crests do not break).
      if (row.windSpeed <= 3.3) expect(row.coverage, row.name).toBe(0);
      else {
        expect(row.coverage / row.monahan, row.name).toBeGreaterThan(0.5);
        expect(row.coverage / row.monahan, row.name).toBeLessThan(2);
      }
    }
  });

  it('is within a factor of 2 of W from 4 to 25 m/s on the default sea, and grows with the wind', () => {
    const rows = [4, 6, 8, 10, 12, 15, 20, 25].map((windSpeed) => {
      const coverage = measuredCoverage({ windSpeed, resolution: 128 }, 4);
      return { windSpeed, coverage, monahan: monahan(windSpeed), ratio: coverage / monahan(windSpeed) };
    });
    console.log(table(['U10 (m/s)', 'measured W (%)', 'Monahan W (%)', 'ratio'], rows.map((r) => [r.windSpeed, percent(r.coverage), percent(r.monahan), r.ratio.toFixed(2)])));
    for (const row of rows) {
      expect(row.ratio, `U10 = ${row.windSpeed} m/s`).toBeGreaterThan(0.5);
      expect(row.ratio, `U10 = ${row.windSpeed} m/s`).toBeLessThan(2);
    }
    rows.slice(1).forEach((row, i) => expect(row.coverage).toBeGreaterThan(rows[i].coverage));
  });

  it('is the same within ±20 % at every quality level’s grid and patch layout (12 m/s, seed 5)', () => {
    // The grids of src/runtime/adaptiveQuality.ts' QUALITY_STEPS (simulationAtQuality: N at most
    // the level's, the largest maxCascades patches), and two layouts more: N = 512, and 4 cascades.
    const defaults = [13.7, 79.3, 457];
    const layouts: [string, Partial<SimulationParameters>, number][] = [
      ['high (N 256, 3 cascades)', { resolution: 256, patchSizes: defaults }, 2],
      ['N 512, 3 cascades', { resolution: 512, patchSizes: defaults }, 1.2],
      ['4 cascades (2.37 m added), N 256', { resolution: 256, patchSizes: [2.37, ...defaults] }, 2],
      ['medium (N 128, 3 cascades)', { resolution: 128, patchSizes: defaults }, 4],
      ['low (N 64, 2 cascades)', { resolution: 64, patchSizes: defaults.slice(1) }, 20],
      ['lowest (N 32, 2 cascades)', { resolution: 32, patchSizes: defaults.slice(1) }, 40],
    ];
    const rows = layouts.map(([name, grid, seconds]) => ({ name, coverage: measuredCoverage({ windSpeed: 12, seed: 5, ...grid }, seconds) }));
    const high = rows[0].coverage;
    console.log(table(['grid', 'measured W (%)', 'Monahan W (%)', '÷ high'], rows.map((r) => [r.name, percent(r.coverage), percent(monahan(12)), (r.coverage / high).toFixed(2)])));
    for (const row of rows) expect(Math.abs(row.coverage / high - 1), row.name).toBeLessThan(0.2);
  });

});
