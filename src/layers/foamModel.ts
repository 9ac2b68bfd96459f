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
 *   R     the foam made per second at C = 1, FOAM_RATE, or none below Beaufort force 3 (WMO: at
 *         force 2 "crests have a glassy appearance and do not break"; at force 3 "crests begin to
 *         break"), that is at winds up to 3.3 m/s, the top of force 2. The wind needs no other
 *         term: a stronger wind raises the spectrum's slopes over more octaves, so the surface folds
 *         more often. FOAM_RATE and J_START, J_FULL were set once so that the default sea
 *         (JONSWAP, 100 km fetch, cascades 13.7/79.3/457 m at N = 256) covers about what Monahan &
 *         O'Muircheartaigh (1980) give, W = 3.84·10⁻⁶·U10^3.41 (0.99 % at 10 m/s);
 *         tests/unit/whitecapFoam.test.ts measures the coverage at winds from 4 to 20 m/s against it.
 *   τ     the persistence: whitecap foam decays over seconds (Callaghan et al. 2012, "Observed
 *         variation in the decay time of oceanic whitecap foam", J. Geophys. Res. 117: e-folding
 *         times of a few seconds).
 * shaders/foam/whitecapFoam.frag is the same model on the GPU.
 */
import type { LayerFieldsOnCpu } from './waveLayer';

/** Jacobian above which no foam is made. */
export const FOAM_J_START = 0.535;
/** Jacobian at or below which foam is made at the full rate: where the surface folds over itself. */
export const FOAM_J_FULL = 0;
/** Foam made per second at C = 1, 1/s. */
export const FOAM_RATE = 300;
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

/** R(U10): foam made per second where the surface folds (C = 1), 1/s; 0 up to the onset wind. */
export function foamCreationRate(windSpeed: number): number {
  return windSpeed > FOAM_ONSET_WIND ? FOAM_RATE : 0;
}

/** C(J): 0 where the surface is not squeezed enough to break, 1 where it folds. */
export function foldingDegree(jacobian: number): number {
  return Math.min(1, Math.max(0, (FOAM_J_START - jacobian) / (FOAM_J_START - FOAM_J_FULL)));
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
  step(cascades: readonly CascadeOnCpu[], choppiness: number, creationRate: number, persistence: number, dt: number): void {
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
    for (let texel = 0; texel < m * m; texel++) {
      const jacobian =
        (1 + choppiness * terms[3 * texel]) * (1 + choppiness * terms[3 * texel + 1]) - (choppiness * terms[3 * texel + 2]) ** 2;
      coverage[texel] = Math.min(1, coverage[texel] * decay + gain * foldingDegree(jacobian));
    }
  }
}
