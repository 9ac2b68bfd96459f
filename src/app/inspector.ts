/**
 * The inspector: live tiles of what the course report's figures show, drawn from the real
 * textures into a strip at the bottom of the canvas, with a label and a scale on each —
 * P(k) (Figure 1), h̃0 real and imaginary (Figure 2), the height (Figure 3), the slopes in x and z
 * (Figure 5), the horizontal displacement and the Jacobian.
 *
 * The spectrum tiles read the CPU-side spectrum through DataTextures it owns (rebuilt, with the
 * colour scales, when the spectrum changes); the field tiles bind the simulation's stable field
 * uniforms. dispose() frees the textures, the tiles and the label elements.
 */
import { DataTexture, FloatType, NearestFilter, RedFormat, RepeatWrapping, RGBAFormat, Vector4, type Texture, type WebGLRenderer } from 'three';
import type { Ocean } from '../ocean';
import { signedFrequency, type InitialSpectrum } from '../spectrum/initialSpectrum';
import { FieldView, type FieldViewOptions } from './fieldView';

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
  private readonly phillips = { value: null as DataTexture | null };
  private readonly amplitudes = { value: null as DataTexture | null };
  private readonly viewport = new Vector4();

  constructor(
    private readonly ocean: Ocean,
    container: HTMLElement,
  ) {
    const fields = ocean.simulation.uniforms;
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
      label.style.cssText = 'min-width:0;padding:2px 4px;text-shadow:0 0 3px #000;overflow:hidden;white-space:nowrap;';
      this.labels.appendChild(label);
      return { title, view: new FieldView(texture, { ...options, scale: 1 }), fit, label };
    };
    const metres = (value: number) => `±${value.toPrecision(2)} m`;
    this.tiles = [
      tile('P(k) (log10)', this.phillips, { logarithmic: true, centred: true }, (s) => ({
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
    ];
    container.appendChild(this.labels);
    this.refreshSpectrum();
  }

  /** Size of one square tile in CSS pixels, for a canvas of the given width. */
  static tileSize(canvasWidth: number, count: number): number {
    return Math.floor(canvasWidth / count);
  }

  /** Draws the tiles along the bottom of the current canvas (call after the scene's render). */
  render(renderer: WebGLRenderer): void {
    if (this.ocean.simulation.spectrum !== this.spectrum) this.refreshSpectrum();
    const canvas = renderer.domElement;
    const width = canvas.clientWidth;
    const size = Inspector.tileSize(width, this.tiles.length);
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
    this.labels.style.gridTemplateColumns = `repeat(${this.tiles.length}, ${size}px)`;
  }

  /** Colour scales from the spectrum: ⟨|h̃0|²⟩ = P, so Σ P is the height variance. */
  private scales(spectrum: InitialSpectrum): Scales {
    let variance = 0;
    let slopeVariance = 0;
    let peak = 0;
    const n = spectrum.resolution;
    const energyByRadius = new Float64Array(n); // Σ P over texels at Chebyshev radius r from k = 0
    for (let texel = 0; texel < n * n; texel++) {
      const p = spectrum.phillips[texel];
      const kx = spectrum.waveVectors[4 * texel];
      const kz = spectrum.waveVectors[4 * texel + 1];
      variance += p;
      slopeVariance += p * (kx * kx + kz * kz);
      peak = Math.max(peak, p);
      const radius = Math.max(Math.abs(signedFrequency(texel % n, n)), Math.abs(signedFrequency(Math.floor(texel / n), n)));
      energyByRadius[radius] += p;
    }
    let radius = 0;
    for (let inside = 0; radius < n / 2 && inside < 0.99 * variance; radius++) inside += energyByRadius[radius];
    const zoom = 2 ** Math.max(0, Math.floor(Math.log2(n / 2 / Math.max(radius, 1))));
    // 2.5 standard deviations fill the colour map; a calm sea (all zero) still gets a scale.
    return {
      height: 2.5 * Math.sqrt(variance) || 1,
      slope: 2.5 * Math.sqrt(slopeVariance) || 1,
      amplitude: 2.5 * Math.sqrt(peak / 2) || 1,
      logPeak: peak > 0 ? Math.ceil(Math.log10(peak)) : 0,
      zoom,
    };
  }

  private refreshSpectrum(): void {
    const spectrum = this.ocean.simulation.spectrum as InitialSpectrum;
    this.spectrum = spectrum;
    const n = spectrum.resolution;
    this.phillips.value?.dispose();
    this.amplitudes.value?.dispose();
    this.phillips.value = spectrumTexture(spectrum.phillips, n, RedFormat);
    this.amplitudes.value = spectrumTexture(spectrum.amplitudes, n, RGBAFormat);
    const scales = this.scales(spectrum);
    for (const tile of this.tiles) {
      const { scale, offset, zoom, text } = tile.fit(scales);
      tile.view.setScale(scale, offset ?? 0, zoom);
      tile.label.textContent = `${tile.title} ${text}`;
    }
  }

  dispose(): void {
    for (const { view } of this.tiles) view.dispose();
    this.phillips.value?.dispose();
    this.amplitudes.value?.dispose();
    this.labels.remove();
  }
}

function spectrumTexture(data: Float32Array, n: number, format: typeof RedFormat | typeof RGBAFormat): DataTexture {
  const texture = new DataTexture(data, n, n, format, FloatType);
  texture.wrapS = texture.wrapT = RepeatWrapping; // the centred view wraps half a patch
  texture.magFilter = NearestFilter; // one cell per wave vector, as in the report's figures
  texture.minFilter = NearestFilter;
  texture.needsUpdate = true;
  return texture;
}
