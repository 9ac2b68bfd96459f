import { describe, expect, it } from 'vitest';
import { CpuWaveFields } from '../../src/fft/cpuWaveFields';
import { DEFAULT_PARAMETERS } from '../../src/parameters/parameters';
import { cascadeSlopes, coxMunkMeanSquareSlope, SLOPE_FILTER_LEVELS } from '../../src/render/seaLighting';
import { QUALITY_LEVELS, QUALITY_STEPS, simulationAtQuality } from '../../src/runtime/adaptiveQuality';
import { createCascadeSpectra } from '../../src/spectrum/initialSpectrum';

/**
 * Cox & Munk (1954), "Measurement of the roughness of the sea surface from photographs of the sun's
 * glitter", J. Opt. Soc. Am. 44: 838–850, clean surface: σ² = 0.003 + 5.12·10⁻³·U, i.e. 0.0542 at
 * 10 m/s and 0.0798 at 15 m/s (their Table / Fig. 14 read at these winds).
 */
describe('coxMunkMeanSquareSlope', () => {
  it('is the clean-surface law, and 0 without wind', () => {
    expect(coxMunkMeanSquareSlope(10)).toBeCloseTo(0.0542, 10);
    expect(coxMunkMeanSquareSlope(15)).toBeCloseTo(0.0798, 10);
    expect(coxMunkMeanSquareSlope(1)).toBeCloseTo(0.00812, 10);
    // No wind, no ripples: a mirror (seaState's meanSquareSlope is 0 there too).
    expect(coxMunkMeanSquareSlope(0)).toBe(0);
  });
});

describe('cascadeSlopes', () => {
  const params = { ...DEFAULT_PARAMETERS, resolution: 64, windSpeed: 12 };
  const spectra = createCascadeSpectra(params);

  it('gives the variance the mip levels of the real slope field average away (E[s²] − E[s]² per block)', () => {
    // The slope fields of each cascade by the JS FFT (what the textures hold), averaged over
    // 2^L × 2^L blocks as generateMipmap does: the variance lost must be the table's. The table is
    // the expectation over time (Σ|h̃0(k)|² + |h̃0(−k)|²); one instant adds the cross terms
    // h̃0(k)·h̃0(−k)·e^{2iωt}, so the fields are taken at several times and their variances averaged.
    for (const spectrum of spectra) {
      const n = spectrum.resolution;
      const fields = new CpuWaveFields(spectrum);
      const slopes = cascadeSlopes(spectrum);
      const times = [0, 1.3, 2.9, 4.1, 7.7, 11.3, 17.9, 23.5];
      const variance = (width: number) => times.reduce((sum, t) => sum + varianceAt(t, width), 0) / times.length;
      const varianceAt = (t: number, width: number) => {
        fields.update(t);
        let sum = 0;
        for (let by = 0; by < n; by += width) {
          for (let bx = 0; bx < n; bx += width) {
            let [sx, sz] = [0, 0];
            for (let y = by; y < by + width; y++) {
              for (let x = bx; x < bx + width; x++) {
                sx += fields.derivatives[4 * (y * n + x)];
                sz += fields.derivatives[4 * (y * n + x) + 1];
              }
            }
            sum += (sx / width / width) ** 2 + (sz / width / width) ** 2;
          }
        }
        return sum / (n / width) ** 2;
      };
      const full = variance(1);
      // Parseval: the field's mean square slope is the spectrum's, up to what the cross terms leave.
      expect(Math.abs(full / slopes.resolved - 1)).toBeLessThan(0.02);
      expect(slopes.filtered[0]).toBe(0);
      for (let level = 1; level <= Math.log2(n); level++) {
        const lost = full - variance(2 ** level);
        expect(Math.abs(lost - slopes.filtered[level]), `patch ${spectrum.patchSize} m, level ${level}`).toBeLessThan(0.02 * slopes.resolved);
      }
      // Past the 1×1 level nothing more is left to filter.
      for (let level = Math.log2(n); level < SLOPE_FILTER_LEVELS; level++) expect(slopes.filtered[level]).toBeCloseTo(slopes.resolved, 6);
    }
  });

  it('resolves less of Cox–Munk on the coarser quality levels, never more than Cox–Munk at 7 and 15 m/s', () => {
    // What the lighting adds (seaLighting.ts) is σ²_CM − resolved: positive where the grid is
    // coarser than the slopes, so the sum is Cox–Munk at every level.
    for (const windSpeed of [7, 15]) {
      const resolved = QUALITY_LEVELS.map((level) => {
        const grid = simulationAtQuality({ ...DEFAULT_PARAMETERS, resolution: 256 }, QUALITY_STEPS[level]);
        return createCascadeSpectra({ ...DEFAULT_PARAMETERS, ...grid, windSpeed }).reduce((sum, s) => sum + cascadeSlopes(s).resolved, 0);
      });
      resolved.slice(1).forEach((value, i) => expect(value).toBeLessThan(resolved[i]));
      expect(resolved[0]).toBeLessThan(coxMunkMeanSquareSlope(windSpeed));
      expect(resolved[0]).toBeGreaterThan(0);
    }
  });
});
