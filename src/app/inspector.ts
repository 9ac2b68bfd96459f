/**
 * The inspector: live tiles of what the course report's figures show, drawn from the real
 * textures into a strip at the bottom of the canvas, with a label and a scale on each —
 * P(k) (Figure 1), h̃0 real and imaginary (Figure 2), the height (Figure 3), the slopes in x and z
 * (Figure 5), the horizontal displacement, the Jacobian and the whitecap foam — and, last, a plot
 * of the sea state's frequency spectrum S(ω) with Hs and Tp (spectrumPlot.ts).
 *
 * The tiles show one wave layer (an FFT cascade, `cascade`, the largest by default). The spectrum
 * tiles read its CPU-side spectrum through DataTextures the inspector owns (rebuilt, with the
 * colour scales, when the spectrum changes); the field tiles show the layer's textures through
 * uniform objects of the inspector's, pointed at the layer's current textures before each draw.
 * dispose() frees the textures, the tiles and the label elements.
 */
import { DataTexture, FloatType, NearestFilter, RedFormat, RepeatWrapping, RGBAFormat, Vector4, type Texture, type WebGLRenderer } from 'three';
import type { Ocean } from '../ocean';
import { signedFrequency, type InitialSpectrum } from '../spectrum/initialSpectrum';
import { FieldView, type FieldViewOptions } from './fieldView';
import { SpectrumPlot } from './spectrumPlot';

interface Scales {
  height: number;
  slope: number;
  amplitude: number;
  logPeak: number;
  /** Magnification of the spectrum tiles so that 99% of Σ P lies inside them. */
  zoom: number;
}

export interface InspectorTile {
  title: string;
  view: FieldView;
  /** The tile's colour scale and its label for the current spectrum. */
  fit(scales: Scales): { scale: number; offset?: number; zoom?: number; text: string };
  label: HTMLElement;
}

export class Inspector {
  readonly tiles: InspectorTile[];
  private readonly labels: HTMLElement;
  private spectrum: InitialSpectrum | null = null;
  /** Which cascade the tiles show, 0 the finest; clamped to the layers there are. */
  cascade = Infinity;
  private readonly density = { value: null as DataTexture | null };
  private readonly fields = { tDisplacement: { value: null as Texture | null }, tDerivatives: { value: null as Texture | null } };
  private readonly amplitudes = { value: null as DataTexture | null };
  private readonly foam = { value: null as Texture | null };
  private readonly viewport = new Vector4();
  private readonly plot = new SpectrumPlot();

  constructor(
    private readonly ocean: Ocean,
    container: HTMLElement,
  ) {
    const fields = this.fields;
    this.labels = document.createElement('div');
    this.labels.className = 'inspector-labels';
    this.labels.style.cssText =
      'position:absolute;left:0;right:0;bottom:0;pointer-events:none;display:grid;font:11px system-ui,sans-serif;color:#fff;';
    const tile = (
      title: string,
      texture: { value: Texture | null },
      options: Omit<FieldViewOptions, 'scale'>,
      fit: InspectorTile['fit'],
    ): InspectorTile => {
      const label = document.createElement('div');
      // A dark band under the text: readable over white foam or a pale tile.
      label.style.cssText = 'align-self:start;min-width:0;padding:2px 4px;background:rgba(0,0,0,0.6);overflow:hidden;white-space:nowrap;';
      this.labels.appendChild(label);
      return { title, view: new FieldView(texture, { ...options, scale: 1 }), fit, label };
    };
    const metres = (value: number) => `±${value.toPrecision(2)} m`;
    this.tiles = [
      tile('Ψ(k) (log10)', this.density, { logarithmic: true, centred: true }, (s) => ({
        scale: 3,
        offset: s.logPeak - 3,
        zoom: s.zoom,
        text: `10^${s.logPeak - 6}…10^${s.logPeak} ×${s.zoom}`,
      })),
      tile('Re h̃0(k)', this.amplitudes, { channel: 0, diverging: true, centred: true }, (s) => ({
        scale: s.amplitude,
        zoom: s.zoom,
        text: metres(s.amplitude),
      })),
      tile('Im h̃0(k)', this.amplitudes, { channel: 1, diverging: true, centred: true }, (s) => ({
        scale: s.amplitude,
        zoom: s.zoom,
        text: metres(s.amplitude),
      })),
      tile('height h', fields.tDisplacement, { channel: 1 }, (s) => ({ scale: s.height, text: metres(s.height) })),
      tile('∂h/∂x', fields.tDerivatives, { channel: 0, diverging: true }, (s) => ({ scale: s.slope, text: `±${s.slope.toPrecision(2)}` })),
      tile('∂h/∂z', fields.tDerivatives, { channel: 1, diverging: true }, (s) => ({ scale: s.slope, text: `±${s.slope.toPrecision(2)}` })),
      tile('Dx', fields.tDisplacement, { channel: 0, diverging: true }, (s) => ({ scale: s.height, text: metres(s.height) })),
      tile('Dz', fields.tDisplacement, { channel: 2, diverging: true }, (s) => ({ scale: s.height, text: metres(s.height) })),
      tile('Jacobian', fields.tDerivatives, { diverging: true, jacobian: fields.tDisplacement }, () => ({
        scale: 1,
        offset: 1,
        text: '0…2 (blue < 1)',
      })),
      // The foam lies over the largest patch (whitecapFoam.ts), whichever cascade the others show.
      tile('foam, largest patch', this.foam, { channel: 0 }, () => ({ scale: 0.5, offset: 0.5, text: '0…100 % covered' })),
    ];
    this.labels.appendChild(this.plot.canvas);
    container.appendChild(this.labels);
    this.refreshSpectrum();
  }

  /** Squares along the bottom: the tiles and the spectrum plot. */
  static readonly CELL_COUNT = 11;

  /** Size of one square cell in CSS pixels, for a canvas of the given width. */
  static tileSize(canvasWidth: number): number {
    return Math.floor(canvasWidth / Inspector.CELL_COUNT);
  }

  /** Draws the tiles along the bottom of the current canvas (call after the scene's render). */
  render(renderer: WebGLRenderer): void {
    const layer = this.shownLayer();
    if (layer.spectrum !== this.spectrum) this.refreshSpectrum();
    this.fields.tDisplacement.value = layer.textures.displacement.value;
    this.fields.tDerivatives.value = layer.textures.derivatives.value;
    this.foam.value = this.ocean.simulation.foam.texture.value;
    const canvas = renderer.domElement;
    const width = canvas.clientWidth;
    const size = Inspector.tileSize(width);
    renderer.getViewport(this.viewport);
    const autoClear = renderer.autoClear;
    renderer.autoClear = false;
    renderer.setScissorTest(true);
    this.tiles.forEach(({ view }, index) => {
      renderer.setViewport(index * size, 0, size, size);
      renderer.setScissor(index * size, 0, size, size);
      view.render(renderer);
    });
    renderer.setScissorTest(false);
    renderer.setViewport(this.viewport);
    renderer.autoClear = autoClear;
    this.labels.style.height = `${size}px`;
    this.labels.style.gridTemplateColumns = `repeat(${Inspector.CELL_COUNT}, ${size}px)`;
    this.plot.draw(this.ocean.parameters, size);
  }

  /** Shows the next cascade (after the last, the first). */
  nextCascade(): void {
    this.cascade = (this.shownCascade + 1) % this.ocean.simulation.cascades.length;
  }

  /** Index of the cascade the tiles show. */
  get shownCascade(): number {
    return Math.min(this.ocean.simulation.cascades.length - 1, Math.max(0, Math.floor(this.cascade)));
  }

  private shownLayer() {
    return this.ocean.simulation.cascades[this.shownCascade];
  }

  /** Colour scales from the spectrum: ⟨|h̃0|²⟩ = p = Ψ·Δk²/2 (initialSpectrum.ts), so Σ 2p is the height variance. */
  private scales(spectrum: InitialSpectrum): Scales {
    const dk = (2 * Math.PI) / spectrum.patchSize;
    let variance = 0;
    let slopeVariance = 0;
    let peak = 0;
    let densityPeak = 0;
    const n = spectrum.resolution;
    const energyByRadius = new Float64Array(n); // Σ 2p over texels at Chebyshev radius r from k = 0
    for (let texel = 0; texel < n * n; texel++) {
      const p = (spectrum.density[texel] * dk * dk) / 2;
      const kx = spectrum.waveVectors[4 * texel];
      const kz = spectrum.waveVectors[4 * texel + 1];
      variance += 2 * p;
      slopeVariance += 2 * p * (kx * kx + kz * kz);
      peak = Math.max(peak, p);
      densityPeak = Math.max(densityPeak, spectrum.density[texel]);
      const radius = Math.max(Math.abs(signedFrequency(texel % n, n)), Math.abs(signedFrequency(Math.floor(texel / n), n)));
      energyByRadius[radius] += 2 * p;
    }
    let radius = 0;
    for (let inside = 0; radius < n / 2 && inside < 0.99 * variance; radius++) inside += energyByRadius[radius];
    const zoom = 2 ** Math.max(0, Math.floor(Math.log2(n / 2 / Math.max(radius, 1))));
    // 2.5 standard deviations fill the colour map; a calm sea (all zero) still gets a scale.
    return {
      height: 2.5 * Math.sqrt(variance) || 1,
      slope: 2.5 * Math.sqrt(slopeVariance) || 1,
      amplitude: 2.5 * Math.sqrt(energeticMean(spectrum, dk, peak / 100) / 2) || 1,
      logPeak: densityPeak > 0 ? Math.ceil(Math.log10(densityPeak)) : 0,
      zoom,
    };
  }

  private refreshSpectrum(): void {
    const spectrum = this.shownLayer().spectrum;
    this.spectrum = spectrum;
    const n = spectrum.resolution;
    this.density.value?.dispose();
    this.amplitudes.value?.dispose();
    this.density.value = spectrumTexture(spectrum.density, n, RedFormat);
    this.amplitudes.value = spectrumTexture(spectrum.amplitudes, n, RGBAFormat);
    const scales = this.scales(spectrum);
    for (const tile of this.tiles) {
      const { scale, offset, zoom, text } = tile.fit(scales);
      tile.view.setScale(scale, offset ?? 0, zoom);
      tile.label.textContent = `${tile.title} ${text}`;
    }
    const first = this.tiles[0].label;
    first.textContent = `${spectrum.patchSize} m (C: next) · ${first.textContent}`;
  }

  dispose(): void {
    for (const { view } of this.tiles) view.dispose();
    this.density.value?.dispose();
    this.amplitudes.value?.dispose();
    this.labels.remove();
  }
}

/**
 * Mean of p = ⟨|h̃0|²⟩ over the modes where p > threshold: the amplitude tiles are scaled to the
 * modes that carry the sea (scaled to the single largest one, nearly all of them showed blank).
 */
function energeticMean(spectrum: InitialSpectrum, dk: number, threshold: number): number {
  let sum = 0;
  let count = 0;
  for (const density of spectrum.density) {
    const p = (density * dk * dk) / 2;
    if (p > threshold) {
      sum += p;
      count++;
    }
  }
  return count > 0 ? sum / count : 0;
}

function spectrumTexture(data: Float32Array, n: number, format: typeof RedFormat | typeof RGBAFormat): DataTexture {
  const texture = new DataTexture(data, n, n, format, FloatType);
  texture.wrapS = texture.wrapT = RepeatWrapping; // the centred view wraps half a patch
  texture.magFilter = NearestFilter; // one cell per wave vector, as in the report's figures
  texture.minFilter = NearestFilter;
  texture.needsUpdate = true;
  return texture;
}
