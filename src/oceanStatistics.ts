/**
 * The Oceans' statistics of their sea (src/ocean.ts documents them for users; the WebGPU Ocean,
 * src/webgpu/ocean.ts, shares them): the height's RMS
 * from the spectra, the sea state from the spectrum's moments, and the repeat period; each computed
 * once per set of spectra or parameters, since render loops ask for them every frame.
 */
import type { SeaStateSummary } from './ocean';
import type { SimulationParameters } from './parameters/parameters';
import type { InitialSpectrum } from './spectrum/initialSpectrum';
import { spectralMoments } from './spectrum/seaState';
import { seaRepeatPeriod } from './spectrum/cascadeBands';

/** What the statistics read of a sea: its cascades' spectra and its parameters (an OceanSimulation, or the WebGPU Ocean's own). */
export interface StatisticsSource {
  readonly cascades: readonly { readonly spectrum: InitialSpectrum }[];
  readonly parameters: Readonly<SimulationParameters>;
}

export class SeaStatistics {
  private rms: { spectra: readonly InitialSpectrum[]; value: number } | null = null;
  private summary: { parameters: Readonly<SimulationParameters>; value: SeaStateSummary } | null = null;
  private period: { parameters: Readonly<SimulationParameters>; value: number } | null = null;

  /** @param simulation the sea's simulation (asked each time: the Ocean makes it after this) */
  constructor(private readonly simulation: () => StatisticsSource) {}

  /**
   * RMS of the height over time (m): by Parseval the mean of h² over a patch is Σ|h̃(k, t)|², whose
   * average over the repeat period is Σ(|h̃0(k)|² + |h̃0(−k)|²) (the cross terms oscillate); the
   * cascades hold disjoint bands, so their variances add.
   */
  get heightRms(): number {
    const cascades = this.simulation().cascades;
    if (this.rms?.spectra.length !== cascades.length || this.rms.spectra.some((spectrum, i) => spectrum !== cascades[i].spectrum)) {
      let sum = 0;
      for (const { spectrum } of cascades) for (const a of spectrum.amplitudes) sum += a * a;
      this.rms = { spectra: cascades.map((cascade) => cascade.spectrum), value: Math.sqrt(sum) };
    }
    return this.rms.value;
  }

  /** Hs = 4√m0 (m) and the peak period (s; 0 without waves), from the moments of the spectrum (seaState.ts). */
  get seaState(): SeaStateSummary {
    const parameters = this.simulation().parameters;
    if (this.summary?.parameters !== parameters) {
      const { m0, peakFrequency } = spectralMoments(parameters, parameters.patchSizes[parameters.patchSizes.length - 1]);
      const value = { significantWaveHeight: 4 * Math.sqrt(m0), peakPeriod: peakFrequency > 0 ? (2 * Math.PI) / peakFrequency : 0 };
      this.summary = { parameters, value };
    }
    return this.summary.value;
  }

  /** Seconds after which every cascade's waves are where they were (cascadeBands.ts). */
  get repeatPeriod(): number {
    const parameters = this.simulation().parameters;
    if (this.period?.parameters !== parameters) this.period = { parameters, value: seaRepeatPeriod(parameters) };
    return this.period.value;
  }
}
