/**
 * heightAt (src/layers/surfaceQuery.ts): the height of the choppy sea surface at a world point,
 * from the sum of the layers' fields (waveLayer.ts: horizontal parts for λ = 1, scaled by the
 * choppiness), over hand-made layers whose fields are written here from a formula.
 *
 * The reference is a single travelling wave, whose choppy surface is a Gerstner (trochoidal)
 * wave: with h = A·cos θ, θ = k·x0 + φ, the λ = 1 displacement is D = −k̂·A·sin θ (Tessendorf 2001,
 * eq. 29), and the surface point over the rest point x0 is (x0 + λ·D(x0), h(x0)). Along k̂ the rest
 * coordinate s0 of the point that lands on s solves s0 − λ·A·sin(|k|s0 + φ) = s, a monotone scalar
 * equation when λ·A·|k| < 1, solved here by bisection; across k̂ nothing moves. The last layer
 * is drawn as cos θ·P(x) + sin θ·P(x + o) (patchBlend.ts): where that layer holds part of the wave,
 * the reference below writes the blended field out and solves for the rest point by fixed-point
 * iteration instead.
 */
import { describe, expect, it } from 'vitest';
import { blendAngle, COPY_OFFSET, patchBlendUniforms } from '../../src/layers/patchBlend';
import { heightAt, normalAt, velocityAt } from '../../src/layers/surfaceQuery';
import { CpuWaveFields } from '../../src/fft/cpuWaveFields';
import { validateParameters } from '../../src/parameters/parameters';
import { GRAVITY } from '../../src/spectrum/dispersion';
import { LONGEST_CARRY, PROVISIONAL_QUERY_RESOLUTION, provisionalQuerySpectrum } from '../../src/layers/cascadeQueryFields';
import { createCascadeSpectra, reducedSpectrum, type InitialSpectrum } from '../../src/spectrum/initialSpectrum';
import type { LayerFrame, LayerQueryFields, WaveLayer } from '../../src/layers/waveLayer';

/** A layer with fixed fields (the same at every t), recording the times it was asked for. */
interface FakeLayer extends WaveLayer {
  readonly times: number[];
}

function fakeLayer(frame: LayerFrame, displacement: Float32Array, derivatives: Float32Array, velocities = new Float32Array(displacement.length)): FakeLayer {
  const times: number[] = [];
  return {
    times,
    textures: { displacement: { value: null }, derivatives: { value: null } },
    frame,
    movesSideways: true,
    update: () => {},
    queryFields: (t: number) => {
      times.push(t);
      return { time: t, resolution: frame.resolution, displacement, derivatives, velocities: () => velocities };
    },
    fieldsOnCpu: () => ({ displacement, derivatives }),
    shownFieldsOnCpu: () => ({ displacement, derivatives }),
    dispose: () => {},
  };
}

/** The wave h = A·cos(k·x + φ − ωt) at t = 0 with its λ = 1 fields. */
interface Wave {
  amplitude: number;
  kx: number;
  kz: number;
  phase: number;
  /** rad/s, for the velocities (0: a wave that does not move). */
  omega?: number;
}

/** `share` of the wave's fields (layout of waveFieldLayout.ts) sampled on a layer's texels. */
function waveLayer(wave: Wave, share: number, frame: LayerFrame): FakeLayer {
  const n = frame.resolution;
  const displacement = new Float32Array(4 * n * n);
  const derivatives = new Float32Array(4 * n * n);
  const velocities = new Float32Array(4 * n * n);
  const { amplitude: a, kx, kz, phase, omega = 0 } = wave;
  const k = Math.hypot(kx, kz);
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      const x = frame.origin[0] + (i * frame.size) / n;
      const z = frame.origin[1] + (j * frame.size) / n;
      const theta = kx * x + kz * z + phase;
      const c = share * a * Math.cos(theta);
      const s = share * a * Math.sin(theta);
      const t = 4 * (j * n + i);
      // (Dx, h, Dz, ∂Dx/∂z) and (∂h/∂x, ∂h/∂z, ∂Dx/∂x, ∂Dz/∂z) for D = −k̂·A·sin θ.
      displacement.set([(-kx / k) * s, c, (-kz / k) * s, ((-kx * kz) / k) * c], t);
      derivatives.set([-kx * s, -kz * s, ((-kx * kx) / k) * c, ((-kz * kz) / k) * c], t);
      // Their time derivatives (θ falls by ω per second): ∂c/∂t = ω·s, ∂s/∂t = −ω·c.
      velocities.set([(kx / k) * omega * c, omega * s, (kz / k) * omega * c, ((-kx * kz) / k) * omega * s], t);
    }
  }
  return fakeLayer(frame, displacement, derivatives, velocities);
}

/**
 * Height at (x, z) of the surface made of `fineShare` of the wave on a plain layer and the rest on a
 * blended last layer of side `lastSize`: h(x0) = A·(f·cos ψ + (1 − f)·(cos θ·cos ψ + sin θ·cos(ψ + k·o))),
 * ψ = k·x0 + φ, θ the blend angle at x0, o the copy's shift; D likewise with sin for cos and −k̂.
 * The rest point x0 with x0 + λ·D(x0) = (x, z) is found by fixed-point iteration.
 */
function blendedHeight(wave: Wave, fineShare: number, lastSize: number, lambda: number, x: number, z: number): number {
  const k = Math.hypot(wave.kx, wave.kz);
  const blend = patchBlendUniforms(lastSize, new Float64Array(12));
  const shift = wave.kx * COPY_OFFSET[0] * lastSize + wave.kz * COPY_OFFSET[1] * lastSize;
  const field = (x0: number, z0: number, f: (angle: number) => number) => {
    const psi = wave.kx * x0 + wave.kz * z0 + wave.phase;
    const theta = blendAngle(blend, x0, z0);
    return wave.amplitude * (fineShare * f(psi) + (1 - fineShare) * (Math.cos(theta) * f(psi) + Math.sin(theta) * f(psi + shift)));
  };
  let [x0, z0] = [x, z];
  for (let step = 0; step < 20_000; step++) {
    const s = field(x0, z0, Math.sin); // D = −k̂·s, so x0 = (x, z) + λ·k̂·s
    [x0, z0] = [x + (lambda * wave.kx * s) / k, z + (lambda * wave.kz * s) / k];
  }
  return field(x0, z0, Math.cos);
}

describe('heightAt over two periodic layers that split one cosine wave', () => {
  // k = 2π·(1, 1)/10 m: periodic on both the 10 m and the 20 m layer. Both have texels of
  // 10/512 = 20/1024 m, where bilinear interpolation of a wave of |k| = 0.89 rad/m errs by at most
  // A·(|k|Δ)²/8 ≈ 1.1e-5 m; near the steepest crests (λ = 3: Jacobian ≥ 0.2) a displacement error
  // moves the rest point by up to 1/0.2 of itself, a height error ≲ 4× as large. Total ≲ 6e-5 m
  // against the 1e-4 m asked for; float32 storage adds ~1e-8.
  const wave: Wave = { amplitude: 0.3, kx: (2 * Math.PI) / 10, kz: (2 * Math.PI) / 10, phase: 0.4 };
  // The fine layer's origin is a whole number of texels off the coarse one's, so the grids share texels.
  const fine = waveLayer(wave, 0.7, { size: 10, origin: [2.5, -7.5], periodic: true, resolution: 512 });
  const coarse = waveLayer(wave, 0.3, { size: 20, origin: [0, 0], periodic: true, resolution: 1024 });
  const layers = [fine, coarse];
  // Points on both sides of the origin, far outside both squares (the layers repeat), on crests,
  // troughs and slopes.
  const points: [number, number][] = [
    [0, 0],
    [1.234, 5.678],
    [-13.37, 2.5],
    [250.1, -999.9],
    [4.3, 4.3],
    ...Array.from({ length: 40 }, (_, i): [number, number] => [-30 + 1.618 * i, 17 - 0.913 * i]),
  ];

  for (const lambda of [0.7, 1.5, 3]) {
    it(`equals the choppy surface’s height within 1e-4 m with choppiness ${lambda}`, () => {
      let worst = 0;
      let moved = 0;
      for (const [x, z] of points) {
        const want = blendedHeight(wave, 0.7, 20, lambda, x, z);
        worst = Math.max(worst, Math.abs(heightAt(layers, lambda, 12.5, x, z) - want));
        // The choppy height differs from the plain cosine at (x, z): the test sees the displacement.
        moved = Math.max(moved, Math.abs(want - wave.amplitude * Math.cos(wave.kx * x + wave.kz * z + wave.phase)));
      }
      expect(worst).toBeLessThan(1e-4);
      expect(moved).toBeGreaterThan(0.05);
    });
  }

  it('with choppiness 0 is the blended field at the point itself, not the plain sum', () => {
    let blendShows = 0;
    for (const [x, z] of points) {
      const want = blendedHeight(wave, 0.7, 20, 0, x, z);
      expect(Math.abs(heightAt(layers, 0, 0, x, z) - want)).toBeLessThan(1e-4);
      blendShows = Math.max(blendShows, Math.abs(want - wave.amplitude * Math.cos(wave.kx * x + wave.kz * z + wave.phase)));
    }
    // The copies differ from the plain wave by a good part of the coarse layer's 0.09 m.
    expect(blendShows).toBeGreaterThan(0.03);
  });

  for (const lambda of [0, 1.5]) {
    it(`normalAt is the normal of the choppy surface’s height field with choppiness ${lambda}`, () => {
      // The graph y = H(x, z) has the upward normal (−∂H/∂x, 1, −∂H/∂z)/|…|; H here is the
      // reference above, differentiated by central differences over 1 mm (error ~1e-7); bilinear
      // interpolation of the slopes errs by ~A·|k|·(|k|Δ)²/8 ≈ 1e-5.
      const tolerance = 1e-4;
      const e = 1e-3;
      let tilted = 0;
      for (const [x, z] of points) {
        const h = (px: number, pz: number) => blendedHeight(wave, 0.7, 20, lambda, px, pz);
        const [gx, gz] = [(h(x + e, z) - h(x - e, z)) / (2 * e), (h(x, z + e) - h(x, z - e)) / (2 * e)];
        const length = Math.hypot(gx, 1, gz);
        const got = normalAt(layers, lambda, 12.5, x, z, { x: 0, y: 0, z: 0 });
        expect(Math.abs(got.x + gx / length), `x at (${x}, ${z})`).toBeLessThan(tolerance);
        expect(Math.abs(got.y - 1 / length), `y at (${x}, ${z})`).toBeLessThan(tolerance);
        expect(Math.abs(got.z + gz / length), `z at (${x}, ${z})`).toBeLessThan(tolerance);
        tilted = Math.max(tilted, Math.hypot(got.x, got.z));
      }
      expect(tilted).toBeGreaterThan(0.1); // the slopes are really there (A·|k| = 0.27)
    });
  }

  it('asks every layer for its fields at the time it was given', () => {
    fine.times.length = 0;
    coarse.times.length = 0;
    heightAt(layers, 1, 42.25, 1, 2);
    expect(fine.times.length).toBeGreaterThan(0);
    expect(new Set([...fine.times, ...coarse.times])).toEqual(new Set([42.25]));
  });
});

describe('heightAt with a non-periodic layer', () => {
  // A 10 m square at (100, 200) that raises the water by 0.25 m and moves nothing sideways.
  const n = 32;
  const displacement = new Float32Array(4 * n * n);
  for (let t = 0; t < n * n; t++) displacement[4 * t + 1] = 0.25;
  const patch = fakeLayer({ size: 10, origin: [100, 200], periodic: false, resolution: n }, displacement, new Float32Array(4 * n * n));
  const wave: Wave = { amplitude: 0.2, kx: (2 * Math.PI) / 16, kz: 0, phase: 1 };
  const background = waveLayer(wave, 1, { size: 16, origin: [0, 0], periodic: true, resolution: 256 });

  it('contributes nothing outside its square, and its fields inside', () => {
    for (const lambda of [0, 1.2]) {
      // At least λ·A = 0.24 m inside its texels' span [100, 109.69]: the choppy background moves
      // the rest point by up to that (see below).
      const inside: [number, number][] = [
        [100.3, 200.3],
        [104.2, 203.7],
        [109.4, 209.4],
      ];
      // Left of, right of, below, above, diagonal to the square, and where a periodic copy would be.
      // (Along x at least λ·A = 0.24 m away: the choppy background moves the rest point of a
      // surface point by up to that, and it is the rest point that the patch is sampled at.)
      const outside: [number, number][] = [
        [99.5, 205],
        [110.5, 205],
        [105, 210.01],
        [105, 199.9],
        [105, 210.5],
        [90, 190],
        [115, 215],
        [95, 195],
        [5, 5],
      ];
      for (const [x, z] of inside) {
        const difference = heightAt([background, patch], lambda, 0, x, z) - heightAt([background], lambda, 0, x, z);
        expect(Math.abs(difference - 0.25), `inside at (${x}, ${z}), λ = ${lambda}`).toBeLessThan(1e-7);
      }
      for (const [x, z] of outside) {
        const difference = heightAt([background, patch], lambda, 0, x, z) - heightAt([background], lambda, 0, x, z);
        expect(difference, `outside at (${x}, ${z}), λ = ${lambda}`).toBe(0);
      }
    }
  });

  it('alone, is the still water level 0 outside its square', () => {
    expect(heightAt([patch], 1, 0, 0, 0)).toBe(0);
    expect(heightAt([patch], 1, 0, 120, 200)).toBe(0);
    expect(Math.abs(heightAt([patch], 1, 0, 105, 205) - 0.25)).toBeLessThan(1e-7);
  });
});

/**
 * Where the surface particle of rest point (x0, z0) is at time t: x0 + (λ·Dx, h, λ·Dz), the fields
 * sampled bilinearly with REPEAT as the GPU does, the last layer as cos θ·P(x) + sin θ·P(x + o).
 */
function particleAt(layers: readonly WaveLayer[], lambda: number, t: number, x0: number, z0: number): number[] {
  const sum = [0, 0, 0];
  layers.forEach((layer, i) => {
    const { size, resolution: n } = layer.frame;
    const { displacement } = layer.queryFields(t);
    const sample = (u: number, v: number, c: number) => {
      const [i0, j0] = [Math.floor(u), Math.floor(v)];
      const at = (a: number, b: number) => displacement[4 * ((((b % n) + n) % n) * n + (((a % n) + n) % n)) + c];
      const [fu, fv] = [u - i0, v - j0];
      return (1 - fv) * ((1 - fu) * at(i0, j0) + fu * at(i0 + 1, j0)) + fv * ((1 - fu) * at(i0, j0 + 1) + fu * at(i0 + 1, j0 + 1));
    };
    const [u, v] = [(x0 / size) * n, (z0 / size) * n];
    const last = i === layers.length - 1;
    const theta = last ? blendAngle(patchBlendUniforms(size, new Float64Array(12)), x0, z0) : 0;
    for (let c = 0; c < 3; c++) {
      sum[c] += last ? Math.cos(theta) * sample(u, v, c) + Math.sin(theta) * sample(u + COPY_OFFSET[0] * n, v + COPY_OFFSET[1] * n, c) : sample(u, v, c);
    }
  });
  return [x0 + lambda * sum[0], sum[1], z0 + lambda * sum[2]];
}

/**
 * The JS path's fields of the cascades of `parameters`, as a layer each, each from its spectrum or
 * from `copyOf` it; with `lag` (s) each layer answers a query at t with its fields for t − lag, as
 * a worker's fields a frame old (cascadeQueryFields.ts).
 */
function realSeaLayers(parameters: ReturnType<typeof validateParameters>, lag = 0, copyOf = (spectrum: InitialSpectrum) => spectrum): WaveLayer[] {
  return createCascadeSpectra(parameters).map((cascadeSpectrum) => {
    const spectrum = copyOf(cascadeSpectrum);
    const fields = new CpuWaveFields(spectrum);
    let shown: LayerQueryFields | null = null;
    return {
      textures: { displacement: { value: null }, derivatives: { value: null } },
      frame: { size: spectrum.patchSize, origin: [0, 0], periodic: true, resolution: spectrum.resolution },
      movesSideways: true,
      update: () => {},
      queryFields: (t: number) => {
        if (shown?.time !== t - lag) {
          fields.update(t - lag);
          shown = fields.forQueries(t - lag);
        }
        return shown;
      },
      fieldsOnCpu: (t: number) => {
        fields.update(t);
        return fields;
      },
      shownFieldsOnCpu: () => null,
      dispose: () => {},
    };
  });
}

describe('heightAt over a real sea', () => {
  it('gives the height of the surface particle that lies over the point (within 10 µm, storm, λ = 1.2)', () => {
    // Particles picked by their rest points x0 lie at P(x0) = x0 + (λ·Dx, h, λ·Dz)(x0) (the
    // definition of the choppy surface, Tessendorf 2001 eq. 29): heightAt over P(x0) must find x0
    // again, where the height is h(x0). Newton's steps stop within ~10 µm of x0 (surfaceQuery.ts).
    const parameters = validateParameters({ resolution: 256, windSpeed: 20, seed: 11, choppiness: 1.2 });
    const layers = realSeaLayers(parameters);
    const t = 12.5;
    let worst = 0;
    let heights = 0;
    for (let p = 0; p < 200; p++) {
      const [x0, z0] = [(p % 20) * 6.1 - 61, Math.floor(p / 20) * 7.3 - 36];
      const [px, height, pz] = particleAt(layers, parameters.choppiness, t, x0, z0);
      worst = Math.max(worst, Math.abs(heightAt(layers, parameters.choppiness, t, px, pz) - height));
      heights += Math.abs(height);
    }
    console.log(`heightAt over 200 particles of a 20 m/s sea: worst ${(worst * 1e6).toFixed(2)} µm off (mean |h| ${(heights / 200).toFixed(2)} m)`);
    expect(heights / 200).toBeGreaterThan(0.5); // a real storm sea (m)
    expect(worst).toBeLessThan(1e-5);
  });
});

describe('heightAt from fields of an earlier time, carried by their velocities', () => {
  it('is within 1 % of the RMS height of the answer from fields of the time asked, up to 40 ms late (LONGEST_CARRY); without the carry 10 times more', () => {
    // D(t) ≈ D(t0) + (t − t0)·∂D/∂t: the error of the first-order step is ½·Δt²·∂²D/∂t², for one
    // Airy wave ½·Δt²·ω²·a (Dean & Dalrymple 1991, §4.4): it grows with Δt², fastest for the short
    // waves. 1 % of the RMS height is what heightAt holds against the drawn surface (ocean.spec.ts).
    const parameters = validateParameters({ resolution: 64, windSpeed: 12, seed: 5, choppiness: 1.2 });
    const exact = realSeaLayers(parameters);
    const t = 41.5;
    const points = Array.from({ length: 100 }, (_, p) => [(p % 10) * 17.3 - 80, Math.floor(p / 10) * 13.9 - 60]);
    const heights = points.map(([x, z]) => heightAt(exact, parameters.choppiness, t, x, z));
    const rms = Math.sqrt(heights.reduce((sum, h) => sum + h * h, 0) / heights.length);
    const worstError = (query: (x: number, z: number) => number) => Math.max(...points.map(([x, z], p) => Math.abs(query(x, z) - heights[p])));
    const carried: Record<number, number> = {};
    for (const lag of [0.016, 0.033, LONGEST_CARRY, 0.1]) {
      const late = realSeaLayers(parameters, lag);
      carried[lag] = worstError((x, z) => heightAt(late, parameters.choppiness, t, x, z));
    }
    const notCarried = worstError((x, z) => heightAt(exact, parameters.choppiness, t - 0.016, x, z));
    console.log(`heightAt from late fields: worst error / RMS height (${rms.toFixed(3)} m) by lag (s) ${JSON.stringify(Object.fromEntries(Object.entries(carried).map(([lag, e]) => [lag, +(e / rms).toFixed(5)])))}; 16 ms late, not carried: ${(notCarried / rms).toFixed(4)}`);
    expect(rms).toBeGreaterThan(0.3); // a real sea (m): Hs ≈ 4·RMS ≈ 2 m at 12 m/s
    expect(carried[LONGEST_CARRY]).toBeLessThan(0.01 * rms);
    expect(carried[0.1]).toBeGreaterThan(0.01 * rms); // why the carry stops at LONGEST_CARRY
    expect(carried[0.033]).toBeGreaterThan(2 * carried[0.016]); // it grows with the lag (about as Δt²)
    expect(notCarried).toBeGreaterThan(10 * carried[0.016]);
  });
});

describe('heightAt from the provisional copies the queries read until a worker answers (provisionalQuerySpectrum)', () => {
  it('is within 1 % of the RMS height of the exact answers, between the texels too, over a 14 m/s sea; 64² copies of every cascade were off by 40 % of it', () => {
    // The surface is drawn from the cascades' textures, interpolated between texels; the queries
    // interpolate their copies the same way. Exact at their texels, coarser copies of the coarse
    // cascades are not between them, where a coarse cascade's shortest waves (about 27 rings,
    // cascadeBands.ts) have 2.4 texels each on a 64² grid.
    const parameters = validateParameters({ resolution: 256, windSpeed: 14, windDirection: 50, seed: 5 });
    const spectra = createCascadeSpectra(parameters);
    const copies = spectra.map(provisionalQuerySpectrum);
    expect(copies.map((copy) => copy.resolution)).toEqual([PROVISIONAL_QUERY_RESOLUTION, 256, 256]); // the finest first
    expect(copies.slice(1)).toEqual(spectra.slice(1)); // the coarse cascades keep theirs
    const t = 7.25;
    const points = Array.from({ length: 400 }, (_, p) => [Math.sin(p * 12.9898) * 300, Math.cos(p * 78.233) * 300]);
    const answers = (layers: WaveLayer[]) => points.map(([x, z]) => heightAt(layers, parameters.choppiness, t, x, z));
    const exact = answers(realSeaLayers(parameters));
    const rms = Math.sqrt(exact.reduce((sum, h) => sum + h * h, 0) / exact.length);
    const worstError = (heights: number[]) => Math.max(...heights.map((h, p) => Math.abs(h - exact[p])));
    const provisional = worstError(answers(realSeaLayers(parameters, 0, provisionalQuerySpectrum)));
    const allOn64 = worstError(answers(realSeaLayers(parameters, 0, (spectrum) => reducedSpectrum(spectrum, 64))));
    console.log(`provisional copies over a 14 m/s sea (RMS height ${rms.toFixed(3)} m): worst ${(provisional * 100).toFixed(2)} cm off; every cascade on 64²: ${(allOn64 * 100).toFixed(1)} cm`);
    expect(rms).toBeGreaterThan(0.5);
    expect(provisional).toBeLessThan(0.01 * rms); // heightAt's tolerance against the drawn surface (ocean.spec.ts)
    expect(allOn64).toBeGreaterThan(0.1 * rms);
  });
});

describe('velocityAt', () => {
  it('on one deep-water wave: the surface particles go round circles at speed A·ω (Airy; within 2 %)', () => {
    // Linear (Airy) theory: at the surface of a deep-water wave of amplitude A and frequency ω the
    // particles move on circles of radius A at speed A·ω (Dean & Dalrymple 1991, "Water Wave
    // Mechanics for Engineers and Scientists", §4.4, the orbital velocities u = A·ω·cos θ,
    // w = A·ω·sin θ at z = 0). With choppiness 1 the surface is that trochoid.
    const k = (2 * Math.PI) / 40;
    const wave: Wave = { amplitude: 1.5, kx: 0.6 * k, kz: 0.8 * k, phase: 0.3, omega: Math.sqrt(GRAVITY * k) };
    const layers = [waveLayer(wave, 1, { size: 80, origin: [0, 0], periodic: true, resolution: 256 }), waveLayer(wave, 0, { size: 400, origin: [0, 0], periodic: true, resolution: 64 })];
    const out = { x: 0, y: 0, z: 0 };
    let worst = 0;
    for (let x = 0; x < 40; x += 3.1) {
      velocityAt(layers, 1, 0, x, 7, out);
      worst = Math.max(worst, Math.abs(Math.hypot(out.x, out.y, out.z) / (wave.amplitude * wave.omega!) - 1));
    }
    console.log(`velocityAt, one Airy wave: speed within ${(100 * worst).toFixed(3)} % of A·ω`);
    expect(worst).toBeLessThan(0.02);
  });

  it('is the time derivative of the displacement of the same surface particle, over a real three-cascade sea (within 2 %)', () => {
    // The JS path's fields of the default cascades, as a layer each; the particle at the rest point
    // x0 is at P(x0, t) = x0 + (λ·Dx, h, λ·Dz)(x0, t): its velocity by central difference over ±2 ms.
    const parameters = validateParameters({ resolution: 64, windSpeed: 12, seed: 5, choppiness: 1.2 });
    const layers = realSeaLayers(parameters);
    const lambda = parameters.choppiness;
    const t = 37.25;
    const h = 2e-3;
    const out = { x: 0, y: 0, z: 0 };
    let worst = 0;
    let speeds = 0;
    // Particles picked by their rest points x0: each is at P(x0, t) = x0 + (λ·Dx, h, λ·Dz)(x0, t),
    // over which velocityAt is asked (it finds x0 again by Newton's method).
    for (const [x0, z0] of [[3.2, -7.1], [41.5, 12.25], [-120.3, 66.6], [250.75, -310.5], [9.9, 9.9]]) {
      const [px, , pz] = particleAt(layers, lambda, t, x0, z0);
      velocityAt(layers, lambda, t, px, pz, out);
      const before = particleAt(layers, lambda, t - h, x0, z0);
      const after = particleAt(layers, lambda, t + h, x0, z0);
      const expected = [0, 1, 2].map((c) => (after[c] - before[c]) / (2 * h));
      const speed = Math.hypot(...expected);
      speeds += speed;
      worst = Math.max(worst, Math.hypot(out.x - expected[0], out.y - expected[1], out.z - expected[2]) / speed);
    }
    console.log(`velocityAt against dP/dt of the particle: worst ${(100 * worst).toFixed(3)} % of its speed (mean speed ${(speeds / 5).toFixed(2)} m/s)`);
    expect(speeds / 5).toBeGreaterThan(0.3); // the particles move (m/s)
    expect(worst).toBeLessThan(0.02);
  });
});
