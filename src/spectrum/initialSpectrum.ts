/**
 * The initial wave spectrum h̃0(k) on the simulation grid.
 *
 * Phillips spectrum (Tessendorf 2001, eq. 23, as written in the course report §2.1):
 *   P(k) = A · exp(−1/(k·L)²) / k⁴ · |k̂·ŵ|²,   L = |w|²/g,   P(0) = 0,
 * times exp(−k²·ℓ²) when a small-wave cutoff ℓ > 0 is set (Tessendorf 2001, eq. 24).
 * Initial amplitudes (Tessendorf 2001, eq. 25):
 *   h̃0(k) = (ξr + i·ξi) · √(P(k)/2),  ξr, ξi independent standard normal deviates from the seed.
 *
 * Grid and frequency ordering. The patch of side Lx has N×N samples at x = (n, m)·Lx/N,
 * n, m in [0, N). Its wave vectors are k = 2π·(n', m')/Lx with n', m' in [−N/2, N/2). Texel
 * (column i, row j) holds the frequency n' = i for i < N/2 and n' = i − N for i ≥ N/2 (likewise
 * m' from j): the negative frequencies come after the positive ones, which is the order an FFT
 * expects (the course report §3.1 lost days to this), so h(x) = Σ h̃(k)·e^{ik·x} is one inverse
 * FFT with no reordering and no 1/N² factor. The field at −k lives at texel ((N − i) mod N,
 * (N − j) mod N); at the Nyquist index N/2 that is the texel itself.
 */
import { detCosSinDegrees, detExp } from './deterministicMath';
import { frequencyIndex, GRAVITY } from './dispersion';
import type { SimulationParameters } from '../parameters/parameters';
import { SeededRandom } from './random';

export interface InitialSpectrum {
  resolution: number;
  patchSize: number;
  /** RGBA per texel: (Re h̃0(k), Im h̃0(k), Re h̃0*(−k), Im h̃0*(−k)). */
  amplitudes: Float32Array;
  /**
   * RGBA per texel: (kx, kz, 1/|k|, m). kx and kz are the wavenumbers that derivatives use, with
   * the Nyquist component set to 0: its sign is ambiguous on an even grid, and i·k·h̃ there would
   * make the derivative fields complex. 1/|k| is 0 at k = 0. m is the quantized frequency index
   * (ω = m·2π/T, see dispersion.ts), an exact integer.
   */
  waveVectors: Float32Array;
  /** P(k) per texel, for inspection (the report's Figure 1). */
  phillips: Float32Array;
}

/** The signed frequency n' of texel index i (the FFT ordering described above). */
export function signedFrequency(index: number, resolution: number): number {
  return index < resolution / 2 ? index : index - resolution;
}

/** Unit wind vector (x, z) for a direction in degrees; deterministic. */
export function windUnitVector(directionDegrees: number): [number, number] {
  return detCosSinDegrees(directionDegrees);
}

type PhillipsParameters = Pick<SimulationParameters, 'windSpeed' | 'windDirection' | 'amplitude' | 'smallWaveCutoff'>;

/** P(k) for the wave vector (kx, kz) in rad/m. */
export function phillips(kx: number, kz: number, params: PhillipsParameters): number {
  const k2 = kx * kx + kz * kz;
  if (k2 === 0 || params.windSpeed === 0) return 0; // no mean level; no wind, no waves
  const [wx, wz] = windUnitVector(params.windDirection);
  const largestWave = (params.windSpeed * params.windSpeed) / GRAVITY; // L
  const cosine = (kx * wx + kz * wz) / Math.sqrt(k2);
  const cutoff = params.smallWaveCutoff > 0 ? detExp(-k2 * params.smallWaveCutoff * params.smallWaveCutoff) : 1;
  return ((params.amplitude * detExp(-1 / (k2 * largestWave * largestWave))) / (k2 * k2)) * cosine * cosine * cutoff;
}

export function createInitialSpectrum(params: SimulationParameters): InitialSpectrum {
  const n = params.resolution;
  const dk = (2 * Math.PI) / params.patchSize;
  const random = new SeededRandom(params.seed);
  const h0 = new Float64Array(2 * n * n); // h̃0 per texel, kept in double until packed
  const phillipsValues = new Float32Array(n * n);
  const waveVectors = new Float32Array(4 * n * n);

  for (let j = 0; j < n; j++) {
    const kz = dk * signedFrequency(j, n);
    for (let i = 0; i < n; i++) {
      const kx = dk * signedFrequency(i, n);
      const texel = j * n + i;
      const p = phillips(kx, kz, params);
      const scale = Math.sqrt(p / 2);
      // Both deviates are drawn for every texel, so the sequence does not depend on P.
      h0[2 * texel] = random.nextNormal() * scale;
      h0[2 * texel + 1] = random.nextNormal() * scale;
      phillipsValues[texel] = p;

      const k = Math.sqrt(kx * kx + kz * kz);
      waveVectors[4 * texel] = i === n / 2 ? 0 : kx;
      waveVectors[4 * texel + 1] = j === n / 2 ? 0 : kz;
      waveVectors[4 * texel + 2] = k > 0 ? 1 / k : 0;
      waveVectors[4 * texel + 3] = frequencyIndex(k, params);
    }
  }

  const amplitudes = new Float32Array(4 * n * n);
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      const texel = j * n + i;
      const opposite = ((n - j) % n) * n + ((n - i) % n);
      amplitudes[4 * texel] = h0[2 * texel];
      amplitudes[4 * texel + 1] = h0[2 * texel + 1];
      amplitudes[4 * texel + 2] = h0[2 * opposite];
      amplitudes[4 * texel + 3] = -h0[2 * opposite + 1];
    }
  }
  return { resolution: n, patchSize: params.patchSize, amplitudes, waveVectors, phillips: phillipsValues };
}
