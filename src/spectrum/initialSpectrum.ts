/**
 * The initial wave spectra h̃0(k) of the FFT cascades.
 *
 * Initial amplitudes (Tessendorf 2001, eq. 25, in physical units):
 *   h̃0(k) = (ξr + i·ξi) · √(Ψ̄(−k)·Δk² / 4),   Δk = 2π/L,
 * ξr, ξi independent standard normal deviates from the seed, Ψ the wave-number spectrum (m⁴, the
 * variance of waves travelling towards k̂ per unit area of the k plane: seaState.ts). Why −k:
 * Tessendorf's evolution h̃0(k)·e^{iωt}·e^{ik·x} is a wave travelling towards −k (its phase is
 * constant where k·x = −ωt), so the waves that travel towards k̂ are h̃0(−k)'s. Ψ̄ is Ψ averaged
 * over the part of the mode's cell in the cascade's band (cellMean below): Ψ itself well inside the
 * band. Why /4: then E|h̃0(k)|² = Ψ̄(−k)·Δk²/2, and the field h = Σ h̃(k, t)·e^{ik·x} with
 * h̃(k,t) = h̃0(k)e^{iωt} + h̃0*(−k)e^{−iωt} has variance Σ E|h̃0(k)|² + E|h̃0(−k)|² = Σ Ψ̄(k)·Δk²,
 * the spectrum's m0 (each band's ∫Ψ d²k, exactly up to quadrature). For the
 * report's Phillips spectrum, seaState.ts makes Ψ = 2·P·(L₀/2π)² with L₀ the largest patch, so that
 * one cascade of side L₀ gets exactly the report's h̃0 = (ξr + i·ξi)·√(P/2).
 * Each cascade keeps only the modes whose cells reach into its band (cascadeBands.ts): the others are 0.
 *
 * Grid and frequency ordering. The patch of side Lx has N×N samples at x = (n, m)·Lx/N,
 * n, m in [0, N). Its wave vectors are k = 2π·(n', m')/Lx with n', m' in [−N/2, N/2). Texel
 * (column i, row j) holds the frequency n' = i for i < N/2 and n' = i − N for i ≥ N/2 (likewise
 * m' from j): the negative frequencies come after the positive ones, which is the order an FFT
 * expects (the course report §3.1 lost days to this), so h(x) = Σ h̃(k)·e^{ik·x} is one inverse
 * FFT with no reordering and no 1/N² factor. The field at −k lives at texel ((N − i) mod N,
 * (N − j) mod N); at the Nyquist index N/2 that is the texel itself.
 */
import type { SimulationParameters } from '../parameters/parameters';
import { cascadeBands, cascadeRepeatPeriod, cellInBand, EDGE_CELL_SPLIT, edgeCellPoints, type CascadeBand } from './cascadeBands';
import { frequencyIndex } from './dispersion';
import { SeededRandom } from './random';
import { fixedWaveNumberSpectrum } from './seaState';

/** One cascade's initial spectrum. */
export interface InitialSpectrum {
  resolution: number;
  patchSize: number;
  /** The cascade's own repeat period T_c, s (cascadeBands.ts); ω = m·2π/T_c. */
  repeatPeriod: number;
  /** The modes it keeps (cascadeBands.ts). */
  band: CascadeBand;
  /** RGBA per texel: (Re h̃0(k), Im h̃0(k), Re h̃0*(−k), Im h̃0*(−k)). */
  amplitudes: Float32Array;
  /**
   * RGBA per texel: (kx, kz, 1/|k|, m). kx and kz are the wavenumbers that derivatives use, with
   * the Nyquist component set to 0: its sign is ambiguous on an even grid, and i·k·h̃ there would
   * make the derivative fields complex. 1/|k| is 0 at k = 0. m is the quantized frequency index
   * (ω = m·2π/T_c, see dispersion.ts), an exact integer; 0 outside the band.
   */
  waveVectors: Float32Array;
  /** Ψ̄(k) per texel in m⁴ (Ψ(k) inside the band, 0 outside; cellMean), for inspection (the report's Figure 1). */
  density: Float32Array;
}

/** Ψ(kx, kz) in m⁴: the variance of waves travelling towards k̂ per unit area of the k plane. */
export type WaveNumberSpectrum = (kx: number, kz: number) => number;

/** Ψ of the sea state the parameters describe (seaState.ts); Phillips' A refers to the largest patch. */
export function seaStateSpectrum(params: SimulationParameters): WaveNumberSpectrum {
  const largestPatch = params.patchSizes[params.patchSizes.length - 1];
  return fixedWaveNumberSpectrum(params, largestPatch);
}

/** The signed frequency n' of texel index i (the FFT ordering described above). */
export function signedFrequency(index: number, resolution: number): number {
  return index < resolution / 2 ? index : index - resolution;
}

/**
 * The largest |i| or |j| of the texels (column i, row j) whose amplitudes are not all zero, i and j
 * signed (≤ N/2): a cascade keeps a disc or ring of modes (cascadeBands.ts), and both FFT paths
 * skip what holds only the frequencies beyond it (BatchedInverseFft2D's inputBand, the GPU path's
 * x passes).
 */
export function largestFrequency({ resolution: n, amplitudes }: Pick<InitialSpectrum, 'resolution' | 'amplitudes'>): number {
  let largest = 0;
  for (let texel = 0; texel < n * n; texel++) {
    const at = 4 * texel;
    if (amplitudes[at] === 0 && amplitudes[at + 1] === 0 && amplitudes[at + 2] === 0 && amplitudes[at + 3] === 0) continue;
    const i = texel % n;
    const j = (texel - i) / n;
    largest = Math.max(largest, Math.min(i, n - i), Math.min(j, n - j));
  }
  return largest;
}

/**
 * The initial spectra of every cascade (params.patchSizes, finest first), drawn from one seeded
 * generator, largest patch first: a single cascade gets the same deviates as before cascades
 * existed, so a seed keeps its sea.
 */
export function createCascadeSpectra(params: SimulationParameters, spectrum = seaStateSpectrum(params)): InitialSpectrum[] {
  const random = new SeededRandom(params.seed);
  const largestFirst = cascadeBands(params.patchSizes, params.resolution).reverse();
  return largestFirst.map((band) => createInitialSpectrum(band, params, spectrum, random)).reverse();
}

/** What makes a cascade's spectrum: createCascadeSpectrum(params, cascade). */
export interface SpectrumOrigin {
  params: SimulationParameters;
  cascade: number;
}

/**
 * Cascade `cascade` (an index into params.patchSizes, 0 the finest) of createCascadeSpectra(params),
 * bit for bit, without computing the others: the deviates of the larger ones are drawn and dropped
 * (every texel draws two, whatever its Ψ). With `resolution` below params.resolution it is
 * reducedSpectrum(that cascade, resolution), bit for bit, computing only the modes kept. A query
 * worker builds its copy with it (fieldWorker.ts), so the main thread sends parameters rather than
 * megabytes of spectrum.
 */
export function createCascadeSpectrum(params: SimulationParameters, cascade: number, resolution = params.resolution): InitialSpectrum {
  const random = new SeededRandom(params.seed);
  const bands = cascadeBands(params.patchSizes, params.resolution);
  const draws = 2 * params.resolution ** 2;
  for (let larger = bands.length - 1; larger > cascade; larger--) {
    for (let draw = 0; draw < draws; draw++) random.nextNormal();
  }
  return createInitialSpectrum(bands[cascade], params, seaStateSpectrum(params), random, resolution);
}

/**
 * Ψ̄ of mode (n, m): ∫Ψ d²k over the part of its cell (cascadeBands.ts, cellInBand) in the band,
 * divided by the cell's area Δk², so that Ψ̄·Δk² is the variance the mode carries; null for a mode
 * whose cell lies outside the band. A discrete mode stands for the waves of its whole cell: it
 * carries the variance of its bin, the spectral density integrated over it (the discrete variance
 * spectrum of Mobley, Ocean Optics Web Book, "Spectra to Surfaces: 2D", 2021). From that integral
 * rather than from Ψ at the mode, each band's lattice sum is the band's ∫Ψ d²k however few lattice
 * points lie near its edge: a band edge 2.35 fundamentals out (N = 64, patches 5.8× apart) leaves
 * 21 lattice points inside where the disc holds only 17.4 cells, and with Ψ ∝ k⁻⁴ the finer band
 * lost a fifth of its variance. Cells wholly inside take the midpoint rule, Ψ at the centre; a
 * cell the edge crosses, the midpoint rule on its EDGE_CELL_SPLIT² sub-cells in the band.
 */
function cellMean(band: CascadeBand, spectrum: WaveNumberSpectrum, n: number, m: number, resolution: number): number | null {
  const overlap = cellInBand(band, n, m);
  // A cell the edge crosses on the Nyquist row or column is left out: the sign of its wave vector
  // is ambiguous there (InitialSpectrum.waveVectors). Only a coarser band's upper edge at the
  // largest patch ratio, N/2, reaches that far.
  if (overlap === 'none' || (overlap === 'part' && Math.max(Math.abs(n), Math.abs(m)) >= resolution / 2)) return null;
  const dk = (2 * Math.PI) / band.patchSize;
  if (overlap === 'whole') return spectrum(dk * n, dk * m);
  const points = edgeCellPoints(band, n, m);
  if (points.length === 0) return null;
  let sum = 0;
  for (const [x, y] of points) sum += spectrum(dk * x, dk * y);
  return sum / EDGE_CELL_SPLIT ** 2;
}

/**
 * One cascade's h̃0, drawing 2·N² deviates from `random` in texel order. With `size` below N, only
 * the texels of reducedSpectrum(·, size) are computed and kept, on that grid.
 */
function createInitialSpectrum(
  band: CascadeBand,
  params: SimulationParameters,
  spectrum: WaveNumberSpectrum,
  random: SeededRandom,
  size = params.resolution,
): InitialSpectrum {
  const n = params.resolution;
  const dk = (2 * Math.PI) / band.patchSize;
  const repeatPeriod = cascadeRepeatPeriod(band, params);
  // Where grid index i (a row or column) goes on the kept grid, or −1 if dropped.
  const place = Int32Array.from({ length: n }, (_, i) => {
    const f = signedFrequency(i, n);
    return size === n ? i : Math.abs(f) < size / 2 ? (f + size) % size : -1;
  });
  const kept = (i: number, j: number) => place[i] >= 0 && place[j] >= 0;
  const h0 = new Float64Array(2 * size * size); // h̃0 per texel, kept in double until packed
  const density = new Float32Array(size * size);
  const waveVectors = new Float32Array(4 * size * size);

  // Ψ̄ over the band first: h̃0(k) needs Ψ̄(−k), which is then the opposite texel's, evaluated once.
  const psi = new Float64Array(size * size);
  const inBand = new Uint8Array(size * size);
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      if (!kept(i, j)) continue;
      const cell = cellMean(band, spectrum, signedFrequency(i, n), signedFrequency(j, n), n);
      psi[place[j] * size + place[i]] = cell ?? 0;
      inBand[place[j] * size + place[i]] = cell === null ? 0 : 1;
    }
  }
  for (let j = 0; j < n; j++) {
    const kz = dk * signedFrequency(j, n);
    for (let i = 0; i < n; i++) {
      if (!kept(i, j)) {
        // Both deviates are drawn for every texel, so the sequence does not depend on Ψ or size.
        random.nextNormal();
        random.nextNormal();
        continue;
      }
      const kx = dk * signedFrequency(i, n);
      const texel = place[j] * size + place[i];
      const k = Math.sqrt(kx * kx + kz * kz);
      // The opposite texel is at exactly (−kx, −kz) off the rows and columns 0 and N/2 (there a 0
      // would become −0, or −N/2 stay −N/2); where its Ψ̄ is 0 it may be outside the band: ask.
      const opposite = ((size - place[j]) % size) * size + ((size - place[i]) % size);
      const mirrored = i % (n / 2) !== 0 && j % (n / 2) !== 0 && psi[opposite] !== 0;
      const psiOpposite = mirrored ? psi[opposite] : (cellMean(band, spectrum, -signedFrequency(i, n), -signedFrequency(j, n), n) ?? 0);
      const scale = inBand[texel] ? Math.sqrt((psiOpposite * dk * dk) / 4) : 0;
      h0[2 * texel] = random.nextNormal() * scale;
      h0[2 * texel + 1] = random.nextNormal() * scale;
      density[texel] = psi[texel];

      waveVectors[4 * texel] = i === n / 2 ? 0 : kx;
      waveVectors[4 * texel + 1] = j === n / 2 ? 0 : kz;
      waveVectors[4 * texel + 2] = k > 0 ? 1 / k : 0;
      waveVectors[4 * texel + 3] = inBand[texel] ? frequencyIndex(k, { depth: params.depth, repeatPeriod }) : 0;
    }
  }

  const amplitudes = new Float32Array(4 * size * size);
  for (let j = 0; j < size; j++) {
    for (let i = 0; i < size; i++) {
      if (size < n && (i === size / 2 || j === size / 2)) continue; // dropped: stays 0 (not −0)
      const texel = j * size + i;
      const opposite = ((size - j) % size) * size + ((size - i) % size);
      amplitudes[4 * texel] = h0[2 * texel];
      amplitudes[4 * texel + 1] = h0[2 * texel + 1];
      amplitudes[4 * texel + 2] = h0[2 * opposite];
      amplitudes[4 * texel + 3] = -h0[2 * opposite + 1];
    }
  }
  return { resolution: size, patchSize: band.patchSize, repeatPeriod, band, amplitudes, waveVectors, density };
}

/**
 * The same cascade on a coarser grid of `resolution` texels a side (a power of two below the
 * spectrum's): the modes whose signed frequencies both lie strictly inside ±resolution/2, with the
 * same amplitudes, wave vectors and frequencies. The rest are dropped: the shortest waves, and the
 * coarser grid's Nyquist row and column (whose sign is ambiguous there). Its fields are the
 * cascade's without those waves, at every (N/resolution)-th texel. For the queries' CPU copy
 * (fftCascade.ts): the band of every cascade but the finest ends well inside such a grid
 * (cascadeBands.ts), so it loses nothing; the finest loses its shortest ripples.
 */
export function reducedSpectrum(spectrum: InitialSpectrum, resolution: number): InitialSpectrum {
  const n = spectrum.resolution;
  const amplitudes = new Float32Array(4 * resolution * resolution);
  const waveVectors = new Float32Array(4 * resolution * resolution);
  const density = new Float32Array(resolution * resolution);
  for (let j = 0; j < resolution; j++) {
    for (let i = 0; i < resolution; i++) {
      if (i === resolution / 2 || j === resolution / 2) continue;
      const texel = j * resolution + i;
      const from = ((signedFrequency(j, resolution) + n) % n) * n + ((signedFrequency(i, resolution) + n) % n);
      // Element by element: a subarray per texel would cost more than the copy (each cascade
      // builds one of these on the main thread for the queries, cascadeQueryFields.ts).
      for (let c = 0; c < 4; c++) {
        amplitudes[4 * texel + c] = spectrum.amplitudes[4 * from + c];
        waveVectors[4 * texel + c] = spectrum.waveVectors[4 * from + c];
      }
      density[texel] = spectrum.density[from];
    }
  }
  const { patchSize, repeatPeriod, band } = spectrum;
  return { resolution, patchSize, repeatPeriod, band, amplitudes, waveVectors, density };
}
