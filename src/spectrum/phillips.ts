/**
 * The course report's spectrum, the Phillips spectrum (Tessendorf 2001, eq. 23, as written in the
 * report §2.1):
 *   P(k) = A · exp(−1/(k·L)²) / k⁴ · |k̂·ŵ|²,   L = |w|²/g,   P(0) = 0,
 * times exp(−k²·ℓ²) when a small-wave cutoff ℓ > 0 is set (Tessendorf 2001, eq. 24). It has no
 * unit: h̃0 = (ξr + i·ξi)·√(P/2) on a patch, so A sets the heights for one patch size
 * (seaState.ts turns it into a wave-number spectrum for the largest cascade's patch).
 */
import type { SimulationParameters } from '../parameters/parameters';
import { detCosSinDegrees, detExp } from './deterministicMath';
import { GRAVITY } from './dispersion';

/** Unit wind vector (x, z) for a direction in degrees; deterministic. */
export function windUnitVector(directionDegrees: number): [number, number] {
  return detCosSinDegrees(directionDegrees);
}

export type PhillipsParameters = Pick<SimulationParameters, 'windSpeed' | 'windDirection' | 'amplitude' | 'smallWaveCutoff'>;

/** P(k) for the wave vector (kx, kz) in rad/m. */
export function phillips(kx: number, kz: number, params: PhillipsParameters): number {
  const k2 = kx * kx + kz * kz;
  const largestWave = (params.windSpeed * params.windSpeed) / GRAVITY; // L
  // No mean level; no wind, no waves. Below k·L = 1e-3, exp(−1/(kL)²) = exp(−1e6) is exactly 0 in
  // double, and k⁴ could underflow to 0 as well (0/0).
  if (params.windSpeed === 0 || k2 * largestWave * largestWave < 1e-6) return 0;
  const [wx, wz] = windUnitVector(params.windDirection);
  const cosine = (kx * wx + kz * wz) / Math.sqrt(k2);
  const cutoff = params.smallWaveCutoff > 0 ? detExp(-k2 * params.smallWaveCutoff * params.smallWaveCutoff) : 1;
  return ((params.amplitude * detExp(-1 / (k2 * largestWave * largestWave))) / (k2 * k2)) * cosine * cosine * cutoff;
}
