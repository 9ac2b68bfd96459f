/**
 * The inspector's plot of the sea state: the frequency spectrum S(ω) (seaState.ts) on log–log
 * axes, the peak ωp and the significant wave height Hs = 4√m0 written on it, and the band of ω each
 * FFT cascade simulates shaded beneath (cascadeBands.ts), so one sees which cascade holds which
 * waves. A 2D canvas of its own, redrawn when the parameters change.
 */
import type { SimulationParameters } from '../parameters/parameters';
import { cascadeBands } from '../spectrum/cascadeBands';
import { angularFrequency } from '../spectrum/dispersion';
import { frequencySpectrum, spectralMoments } from '../spectrum/seaState';

const CASCADE_COLOURS = ['#4aa3ff33', '#ffb34733', '#7dd87d33', '#e07de033'];
const SAMPLES = 160;

export class SpectrumPlot {
  readonly canvas = document.createElement('canvas');
  private drawn: { parameters: Readonly<SimulationParameters>; size: number } | null = null;

  constructor() {
    this.canvas.className = 'spectrum-plot';
    this.canvas.style.cssText = 'width:100%;height:100%;display:block;background:#0b1722;';
  }

  /** Draws S(ω) for these parameters at `size` CSS pixels square, unless that is what it shows already. */
  draw(parameters: Readonly<SimulationParameters>, size: number): void {
    if (this.drawn?.parameters === parameters && this.drawn.size === size) return;
    this.drawn = { parameters, size };
    const scale = window.devicePixelRatio || 1;
    this.canvas.width = Math.max(1, Math.round(size * scale));
    this.canvas.height = Math.max(1, Math.round(size * scale));
    const context = this.canvas.getContext('2d');
    if (!context) return;
    context.setTransform(scale, 0, 0, scale, 0, 0);
    context.clearRect(0, 0, size, size);
    const largestPatch = parameters.patchSizes[parameters.patchSizes.length - 1];
    const { m0, peakFrequency } = spectralMoments(parameters, largestPatch);
    context.font = '11px system-ui, sans-serif';
    context.fillStyle = '#fff';
    if (!(m0 > 0 && peakFrequency > 0)) {
      context.fillText('S(ω): no waves', 6, 16);
      return;
    }
    // ω from a quarter of the peak to 16 times it, S over four decades below its largest value.
    const low = Math.log(peakFrequency / 4);
    const high = Math.log(peakFrequency * 16);
    const values = Array.from({ length: SAMPLES }, (_, i) => frequencySpectrum(Math.exp(low + ((high - low) * i) / (SAMPLES - 1)), parameters, largestPatch));
    const top = Math.log10(Math.max(...values)) + 0.2;
    const bottom = top - 4.2;
    const x = (logOmega: number) => ((logOmega - low) / (high - low)) * size;
    const y = (s: number) => size - ((Math.log10(Math.max(s, 1e-300)) - bottom) / (top - bottom)) * size;

    cascadeBands(parameters.patchSizes, parameters.resolution).forEach((band, cascade) => {
      const from = band.low > 0 ? Math.log(angularFrequency(band.low, parameters.depth)) : low;
      const to = band.high < Infinity ? Math.log(angularFrequency(band.high, parameters.depth)) : high;
      context.fillStyle = CASCADE_COLOURS[cascade % CASCADE_COLOURS.length];
      context.fillRect(x(from), 0, x(to) - x(from), size);
    });
    context.strokeStyle = '#9fd3ff';
    context.lineWidth = 1.5;
    context.beginPath();
    values.forEach((s, i) => context[i === 0 ? 'moveTo' : 'lineTo'](x(low + ((high - low) * i) / (SAMPLES - 1)), y(s)));
    context.stroke();
    context.strokeStyle = '#ffffff88';
    context.setLineDash([3, 3]);
    context.beginPath();
    context.moveTo(x(Math.log(peakFrequency)), 0);
    context.lineTo(x(Math.log(peakFrequency)), size);
    context.stroke();
    context.setLineDash([]);
    context.fillStyle = '#fff';
    context.fillText('S(ω)', 4, 13);
    context.fillText(`Hs ${(4 * Math.sqrt(m0)).toFixed(2)} m`, 4, size - 18);
    context.fillText(`Tp ${((2 * Math.PI) / peakFrequency).toFixed(1)} s`, 4, size - 5);
  }
}
