/**
 * Whitecap foam: where the sea surface folds or nearly folds, foam is made; it stays with the
 * water and fades with a persistence time.
 *
 * Foam F is the fraction of the surface covered, in [0, 1], kept per texel of the largest cascade's
 * patch (whitecapFoam.ts says why there). It obeys
 *     dF/dt = R(U10)·C(J) − F/τ,   clamped to [0, 1],
 * stepped exactly for C constant over the step (so the result does not depend on the frame rate,
 * up to how finely the steps sample C):
 *     F ← F·e^{−Δt/τ} + R·τ·C·(1 − e^{−Δt/τ}).
 *   J     the Jacobian of the total choppy map x ↦ x + λ·D(x), over all cascades (Tessendorf 2001
 *         §4.6: J < 1 where the surface is squeezed, J < 0 where it folds over itself):
 *         J = (1 + λ·ΣDx,x)(1 + λ·ΣDz,z) − (λ·ΣDx,z)²;
 *   C(J)  how near the surface is to folding: 0 above J_START, 1 at or below J_FULL, linear between;
 *   R     the foam made per second at C = 1;
 *   τ     the persistence: whitecap foam decays over seconds (Callaghan et al. 2012, "Observed
 *         variation in the decay time of oceanic whitecap foam", J. Geophys. Res. 117: e-folding
 *         times of a few seconds).
 * The simulated Jacobian says WHERE foam is made; the sea's statistics say HOW MUCH. Averaged over
 * the surface and over time, the equation (without the clamp) has the steady state
 *     E[F] = R·τ·E[C(J)],
 * whatever the correlations of J in time and space (the mean of a linear filter's output is its
 * gain times the mean input). calibrateFoam() chooses J_START, J_FULL and R·τ per sea so that E[F]
 * is the observed whitecap fraction of Monahan & O'Muircheartaigh (1980),
 *     W(U10) = 3.84·10⁻⁶·U10^3.41,
 * with E[C(J)] computed from the Jacobian's statistics under a Gaussian model of the wave field
 * (jacobianCovariance: the displacement gradients ΣDx,x, ΣDz,z, ΣDx,z are linear in the Gaussian
 * amplitudes h̃0, so jointly Gaussian with a covariance that the cascades' own modes give). The
 * amount then does not depend on the grid N, the number of cascades or their patch sizes: a coarse
 * grid that resolves fewer slopes gets a threshold J_START nearer 1, a fine one a lower one.
 * J_START is the quantile of J at probability FOAM_ACTIVE_FRACTION·W, J_FULL the one at a quarter
 * of that: foam is made on twice the area it covers, the crests that are squeezed most. These two
 * shares are choices of look, not physics: they set how dense the foam is where it is (R·τ comes
 * out near 1, so the densest patches are nearly white and F ≤ 1 seldom clips), not how much there
 * is, which the calibration fixes.
 * No crest breaks below Beaufort force 3 (WMO: at force 2 "crests have a glassy appearance and do
 * not break"; at force 3 "crests begin to break"), that is at winds up to 3.3 m/s, the top of force
 * 2: there R = 0.
 * shaders/foam/whitecapFoam.frag is the same model on the GPU.
 */
import { detExp, detPow } from '../spectrum/deterministicMath';
import type { InitialSpectrum } from '../spectrum/initialSpectrum';
import type { LayerFieldsOnCpu } from './waveLayer';

/** J_START is the quantile of J at FOAM_ACTIVE_FRACTION·W: foam is made on that share of the surface. */
export const FOAM_ACTIVE_FRACTION = 2;
/** J_FULL is the quantile of J at FOAM_FULL_SHARE of J_START's probability. */
export const FOAM_FULL_SHARE = 0.25;
/** Wind speed at 10 m up to which no crest breaks, m/s (the top of Beaufort force 2). */
export const FOAM_ONSET_WIND = 3.3;

/**
 * After a jump in time (the first update, time going back, or a step longer than the warm-up
 * window), the foam is rebuilt from nothing over WARM_UP_WINDOW persistence times in WARM_UP_STEPS
 * equal steps, so that the foam at time t depends only on t and the parameters (stills and frame
 * sequences are reproducible). Foam older than 3τ keeps e⁻³ = 5 % of its coverage.
 */
export const WARM_UP_WINDOW = 3;
export const WARM_UP_STEPS = 12;

/** One step of the foam: to `time`, `dt` seconds long. */
export interface FoamStepTime {
  time: number;
  dt: number;
}

/**
 * How to bring the foam from the time of its last update to t: a step of dt in (0, WARM_UP_WINDOW·τ]
 * goes on from the foam there is; any other change (the first update, NaN before it; time going
 * back; a longer jump) clears it and warms it up over the window before t. No change: no steps.
 */
export function foamSchedule(lastTime: number, t: number, persistence: number): { clear: boolean; steps: FoamStepTime[] } {
  const dt = t - lastTime;
  const window = WARM_UP_WINDOW * persistence;
  if (dt === 0) return { clear: false, steps: [] };
  if (dt > 0 && dt <= window) return { clear: false, steps: [{ time: t, dt }] };
  const step = window / WARM_UP_STEPS;
  return { clear: true, steps: Array.from({ length: WARM_UP_STEPS }, (_, k) => ({ time: t - (WARM_UP_STEPS - 1 - k) * step, dt: step })) };
}

/**
 * Monahan & O'Muircheartaigh (1980), "Optimal power-law description of oceanic whitecap coverage
 * dependence on wind speed", J. Phys. Oceanogr. 10: 2094–2099, eq. 5: the fraction of the sea
 * surface covered by whitecaps, W = 3.84·10⁻⁶·U10^3.41 (U10 in m/s); 0 up to the onset wind.
 */
export function whitecapFraction(windSpeed: number): number {
  return windSpeed > FOAM_ONSET_WIND ? 3.84e-6 * detPow(windSpeed, 3.41) : 0;
}

/** C(J): 0 where the surface is not squeezed enough to break (J ≥ start), 1 where J ≤ full. */
export function foldingDegree(jacobian: number, start: number, full: number): number {
  return Math.min(1, Math.max(0, (start - jacobian) / (start - full)));
}

/**
 * The covariance of the Jacobian's terms (a, b, c) = (ΣDx,x, ΣDz,z, ΣDx,z) over the surface and over
 * time, m⁰. With h = Σ h̃(k,t)·e^{ik·x} and D = −i·(k/|k|)·h (Tessendorf 2001, eq. 29), each term is
 * Σ g(k)·h̃(k,t)·e^{ik·x} with g = kx²/|k|, kz²/|k|, kx·kz/|k|, real and even in k; over x (Parseval)
 * and t (the cross terms e^{±2iωt} average out) E[|h̃(k,t)|²] = |h̃0(k)|² + |h̃0(−k)|², so
 *     Cov(f, g) = Σ_k f(k)·g(k)·(|h̃0(k)|² + |h̃0(−k)|²)
 * over every mode every cascade keeps: the statistics of the sea as simulated, whatever its grid.
 */
export interface JacobianCovariance {
  aa: number;
  bb: number;
  cc: number;
  ab: number;
  ac: number;
  bc: number;
}

/** JacobianCovariance of the cascades' initial spectra (initialSpectrum.ts' amplitudes and waveVectors). */
export function jacobianCovariance(spectra: readonly Pick<InitialSpectrum, 'amplitudes' | 'waveVectors'>[]): JacobianCovariance {
  const sum: JacobianCovariance = { aa: 0, bb: 0, cc: 0, ab: 0, ac: 0, bc: 0 };
  for (const { amplitudes, waveVectors } of spectra) {
    for (let at = 0; at < amplitudes.length; at += 4) {
      const power = amplitudes[at] ** 2 + amplitudes[at + 1] ** 2 + amplitudes[at + 2] ** 2 + amplitudes[at + 3] ** 2;
      if (power === 0) continue;
      const kx = waveVectors[at];
      const kz = waveVectors[at + 1];
      const inverseK = waveVectors[at + 2];
      const a = kx * kx * inverseK;
      const b = kz * kz * inverseK;
      const c = kx * kz * inverseK;
      sum.aa += a * a * power;
      sum.bb += b * b * power;
      sum.cc += c * c * power;
      sum.ab += a * b * power;
      sum.ac += a * c * power;
      sum.bc += b * c * power;
    }
  }
  return sum;
}

/** What the foam model needs of a sea besides its Jacobian: see the header. */
export interface FoamCalibration {
  /** J_START: no foam is made where J ≥ it. */
  jacobianStart: number;
  /** J_FULL: foam is made at the full rate where J ≤ it. */
  jacobianFull: number;
  /** R·τ, the coverage that C = 1 held for long makes (R = this/τ); 0: no foam. */
  foamPerFolding: number;
}

/** No foam at all. */
export const NO_FOAM: Readonly<FoamCalibration> = Object.freeze({ jacobianStart: 0, jacobianFull: -1, foamPerFolding: 0 });

/**
 * erfc(x), Press et al., "Numerical Recipes" (2nd ed. 1992), §6.2, erfcc: Chebyshev fit with
 * fractional error below 1.2·10⁻⁷ everywhere.
 */
export function erfc(x: number): number {
  const z = Math.abs(x);
  const t = 1 / (1 + 0.5 * z);
  const r =
    t *
    detExp(
      -z * z - 1.26551223 +
        t * (1.00002368 + t * (0.37409196 + t * (0.09678418 + t * (-0.18628806 + t * (0.27886807 + t * (-1.13520398 + t * (1.48851587 + t * (-0.82215223 + t * 0.17087277)))))))),
    );
  return x >= 0 ? r : 2 - r;
}

/** The standard normal upper tail Q(x) = P(Z > x) and density φ(x). */
const upperTail = (x: number) => 0.5 * erfc(x / Math.SQRT2);
const density = (x: number) => detExp(-0.5 * x * x) / Math.sqrt(2 * Math.PI);

/**
 * The Gaussian model of J = (1 + λa)(1 + λb) − λ²c²: (a, b, c) = L·z with z standard normal and L
 * the Cholesky factor of the covariance. Given z1, z2, the product P = (1 + λa)(1 + λb) is fixed
 * and c is normal with mean μ = L31·z1 + L32·z2 and deviation s = L33, so P(J < j) and E[C(J)]
 * have closed forms in c; the outer integral over z1, z2 is the trapezoid rule on [−7, 7]² in
 * steps of 0.25 (the Gaussian's tails beyond hold 3e-12; for smooth integrands the rule converges
 * spectrally, Trefethen & Weideman 2014, SIAM Review 56: 385–458).
 */
class JacobianModel {
  private readonly products: Float64Array;
  private readonly means: Float64Array;
  private readonly weights: Float64Array;
  private readonly deviation: number;

  constructor(
    covariance: JacobianCovariance,
    private readonly choppiness: number,
  ) {
    const { aa, bb, cc, ab, ac, bc } = covariance;
    // A tiny ridge keeps the factor defined for a degenerate sea (all waves along one axis).
    const ridge = 1e-9 * (aa + bb + cc);
    const l11 = Math.sqrt(aa + ridge);
    const l21 = ab / l11;
    const l22 = Math.sqrt(Math.max(0, bb + ridge - l21 * l21));
    const l31 = ac / l11;
    const l32 = (bc - l31 * l21) / l22;
    this.deviation = Math.sqrt(Math.max(ridge, cc + ridge - l31 * l31 - l32 * l32));
    const step = 0.25;
    const count = 2 * 28 + 1;
    this.products = new Float64Array(count * count);
    this.means = new Float64Array(count * count);
    this.weights = new Float64Array(count * count);
    let total = 0;
    for (let i = 0; i < count; i++) {
      const z1 = -8 + i * step;
      for (let j = 0; j < count; j++) {
        const z2 = -7 + j * step;
        const at = i * count + j;
        const a = l11 * z1;
        const b = l21 * z1 + l22 * z2;
        this.products[at] = (1 + choppiness * a) * (1 + choppiness * b);
        this.means[at] = l31 * z1 + l32 * z2;
        this.weights[at] = density(z1) * density(z2);
        total += this.weights[at];
      }
    }
    for (let at = 0; at < this.weights.length; at++) this.weights[at] /= total;
  }

  /** P(J < j). */
  probabilityBelow(j: number): number {
    let sum = 0;
    for (let at = 0; at < this.weights.length; at++) {
      sum += this.weights[at] * this.tail(this.products[at], this.means[at], j);
    }
    return sum;
  }

  /** E[C(J)] for C = clamp((start − J)/(start − full), 0, 1). */
  meanFolding(start: number, full: number): number {
    const scale = (this.choppiness * this.choppiness) / (start - full);
    let sum = 0;
    for (let at = 0; at < this.weights.length; at++) {
      const [product, mean] = [this.products[at], this.means[at]];
      const lambda2 = this.choppiness * this.choppiness;
      sum += this.weights[at] * scale * (this.excess(mean, (product - start) / lambda2) - this.excess(mean, (product - full) / lambda2));
    }
    return sum;
  }

  /** P(P − λ²c² < j) = P(c² > (P − j)/λ²) for c ~ N(μ, s²). */
  private tail(product: number, mean: number, j: number): number {
    const v = (product - j) / (this.choppiness * this.choppiness);
    if (v <= 0) return 1;
    const r = Math.sqrt(v);
    const s = this.deviation;
    return upperTail((r - mean) / s) + upperTail((r + mean) / s);
  }

  /**
   * E[(c² − v)⁺] for c ~ N(μ, s²): v ≤ 0 gives μ² + s² − v; otherwise, with r = √v, α = (r − μ)/s,
   * β = (r + μ)/s, and E[c²·1{c > r}] = (μ² + s²)·Q(α) + s·(μ + r)·φ(α) (and its mirror),
   *     E[(c² − v)⁺] = (μ² + s² − v)·(Q(α) + Q(β)) + s·((r + μ)·φ(α) + (r − μ)·φ(β)).
   */
  private excess(mean: number, v: number): number {
    const s = this.deviation;
    const second = mean * mean + s * s;
    if (v <= 0) return second - v;
    const r = Math.sqrt(v);
    const alpha = (r - mean) / s;
    const beta = (r + mean) / s;
    return Math.max(0, (second - v) * (upperTail(alpha) + upperTail(beta)) + s * ((r + mean) * density(alpha) + (r - mean) * density(beta)));
  }

  /**
   * The j with P(J < j) = probability, to 1e-4 of it: the Illinois variant of regula falsi
   * (Dowell & Jarratt 1971, BIT 11: 168–174) on P(J < j) − probability, increasing in j, from the
   * bracket [−1 − 40σ, 1 + 40σ].
   */
  quantile(probability: number, spread: number): number {
    let [low, high] = [-1 - 40 * spread, 1 + 40 * spread];
    let [fLow, fHigh] = [this.probabilityBelow(low) - probability, this.probabilityBelow(high) - probability];
    let side = 0;
    for (let step = 0; step < 60 && fHigh - fLow > 0; step++) {
      const j = (low * fHigh - high * fLow) / (fHigh - fLow);
      const f = this.probabilityBelow(j) - probability;
      if (Math.abs(f) <= 1e-4 * probability) return j;
      if (f < 0) {
        [low, fLow] = [j, f];
        if (side === -1) fHigh /= 2;
        side = -1;
      } else {
        [high, fHigh] = [j, f];
        if (side === 1) fLow /= 2;
        side = 1;
      }
    }
    return (low + high) / 2;
  }
}

/**
 * J_START, J_FULL and R·τ for a sea whose Jacobian terms have this covariance, at this choppiness
 * and wind: E[F] = R·τ·E[C(J)] = W(U10) (see the header). No foam up to the onset wind, without
 * choppiness or without slopes (J ≡ 1 never folds).
 */
export function calibrateFoam(covariance: JacobianCovariance, choppiness: number, windSpeed: number): FoamCalibration {
  const target = whitecapFraction(windSpeed);
  const spread = choppiness * Math.sqrt(covariance.aa + covariance.bb);
  if (!(target > 0) || !(spread > 1e-6)) return { ...NO_FOAM };
  const model = new JacobianModel(covariance, choppiness);
  // P(J < 1) is near ½ for a gentle sea: the active area is capped below it.
  const active = Math.min(0.4, FOAM_ACTIVE_FRACTION * target);
  const jacobianStart = model.quantile(active, spread);
  const jacobianFull = model.quantile(FOAM_FULL_SHARE * active, spread);
  const folding = model.meanFolding(jacobianStart, jacobianFull);
  return { jacobianStart, jacobianFull, foamPerFolding: folding > 0 ? target / folding : 0 };
}

/** R, foam made per second at C = 1, 1/s: `amount` times the calibrated R·τ over τ. */
export function foamCreationRate(calibration: FoamCalibration, amount: number, persistence: number): number {
  return (amount * calibration.foamPerFolding) / persistence;
}

/** The coefficients of one step: F ← F·decay + gain·C. */
export function foamStep(creationRate: number, persistence: number, dt: number): { decay: number; gain: number } {
  const decay = Math.exp(-dt / persistence);
  return { decay, gain: creationRate * persistence * (1 - decay) };
}

/** What a foam field samples: a cascade's CPU fields and where they lie. */
export interface CascadeOnCpu {
  fields: LayerFieldsOnCpu;
  size: number;
  resolution: number;
}

/**
 * Which texel of a cascade (side `size`, `resolution` texels) is nearest to each foam texel's
 * point i·foamSize/foamResolution, along one axis. Float32 arithmetic, as the GPU computes it
 * (shaders/foam/whitecapFoam.frag): both paths pick the same texels.
 */
export function nearestTexels(foamSize: number, foamResolution: number, size: number, resolution: number): Int32Array {
  const scale = Math.fround((foamSize * resolution) / (foamResolution * size));
  const texels = new Int32Array(foamResolution);
  for (let i = 0; i < foamResolution; i++) {
    texels[i] = Math.floor(Math.fround(Math.fround(i * scale) + 0.5)) % resolution;
  }
  return texels;
}

/**
 * The foam field on the CPU (the JS path, and the oracle the GPU pass is tested against): one
 * coverage per texel of a square of side `size` at the world origin, `resolution` texels a side,
 * texel (i, j) at (i, j)·size/resolution as the fields are.
 */
export class CpuFoamField {
  readonly coverage: Float32Array;
  private readonly jacobianTerms: Float32Array;
  /** nearestTexels for each cascade's size and resolution, made once. */
  private readonly texelTables = new Map<string, Int32Array>();

  constructor(
    readonly size: number,
    readonly resolution: number,
  ) {
    this.coverage = new Float32Array(resolution * resolution);
    this.jacobianTerms = new Float32Array(3 * resolution * resolution);
  }

  /** Forgets all foam. */
  clear(): void {
    this.coverage.fill(0);
  }

  /** One step of dt seconds with the cascades' fields at the step's end. */
  step(cascades: readonly CascadeOnCpu[], choppiness: number, calibration: FoamCalibration, creationRate: number, persistence: number, dt: number): void {
    const m = this.resolution;
    const terms = this.jacobianTerms; // Σ (Dx,x, Dz,z, Dx,z) per foam texel
    terms.fill(0);
    for (const { fields, size, resolution: n } of cascades) {
      const key = `${size} ${n}`;
      let texels = this.texelTables.get(key);
      if (!texels) this.texelTables.set(key, (texels = nearestTexels(this.size, m, size, n)));
      for (let j = 0; j < m; j++) {
        const row = texels[j] * n;
        for (let i = 0; i < m; i++) {
          const source = 4 * (row + texels[i]);
          const target = 3 * (j * m + i);
          terms[target] += fields.derivatives[source + 2];
          terms[target + 1] += fields.derivatives[source + 3];
          terms[target + 2] += fields.displacement[source + 3];
        }
      }
    }
    const { decay, gain } = foamStep(creationRate, persistence, dt);
    const coverage = this.coverage;
    const { jacobianStart: start, jacobianFull: full } = calibration;
    for (let texel = 0; texel < m * m; texel++) {
      const jacobian =
        (1 + choppiness * terms[3 * texel]) * (1 + choppiness * terms[3 * texel + 1]) - (choppiness * terms[3 * texel + 2]) ** 2;
      coverage[texel] = Math.min(1, coverage[texel] * decay + gain * foldingDegree(jacobian, start, full));
    }
  }
}
