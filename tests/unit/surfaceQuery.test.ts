/**
 * heightAt (src/layers/surfaceQuery.ts): the height of the choppy sea surface at a world point,
 * from the sum of the layers' fields (waveLayer.ts: horizontal parts for λ = 1, scaled by the
 * choppiness), over hand-made layers whose fields are written here from a formula.
 *
 * The reference is a single travelling wave, whose choppy surface is a Gerstner (trochoidal)
 * wave: with h = A·cos θ, θ = k·x0 + φ, the λ = 1 displacement is D = −k̂·A·sin θ (Tessendorf 2001,
 * eq. 29), and the surface point over the rest point x0 is (x0 + λ·D(x0), h(x0)). Along k̂ the rest
 * coordinate s0 of the point that lands on s solves s0 − λ·A·sin(|k|s0 + φ) = s, a monotone scalar
 * equation when λ·A·|k| < 1. Periodic layers are sampled through the slow surface warp w
 * (surfaceWarp.ts), so the reference solves x0 + λ·D(x0 + w(x0)) = x instead.
 */
import { describe, expect, it } from 'vitest';
import { heightAt } from '../../src/layers/surfaceQuery';
import { surfaceWarp, WARP_MAX_STRAIN } from '../../src/layers/surfaceWarp';
import type { LayerFrame, WaveLayer } from '../../src/layers/waveLayer';

/** A layer with fixed fields (the same at every t), recording the times it was asked for. */
interface FakeLayer extends WaveLayer {
  readonly times: number[];
}

function fakeLayer(frame: LayerFrame, displacement: Float32Array, derivatives: Float32Array): FakeLayer {
  const times: number[] = [];
  return {
    times,
    textures: { displacement: { value: null }, derivatives: { value: null } },
    frame,
    update: () => {},
    fieldsOnCpu: (t: number) => {
      times.push(t);
      return { displacement, derivatives };
    },
    dispose: () => {},
  };
}

/** The wave h = A·cos(k·x + φ) with its λ = 1 fields. */
interface Wave {
  amplitude: number;
  kx: number;
  kz: number;
  phase: number;
}

/** `share` of the wave's fields (layout of waveFieldLayout.ts) sampled on a layer's texels. */
function waveLayer(wave: Wave, share: number, frame: LayerFrame): FakeLayer {
  const n = frame.resolution;
  const displacement = new Float32Array(4 * n * n);
  const derivatives = new Float32Array(4 * n * n);
  const { amplitude: a, kx, kz, phase } = wave;
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
    }
  }
  return fakeLayer(frame, displacement, derivatives);
}

/** w(x, z), the surface warp the periodic layers are sampled through (surfaceWarp.ts). */
function warp(x: number, z: number): [number, number] {
  return surfaceWarp(x, z, [0, 0]);
}

/**
 * Height of the Gerstner surface of `wave` with choppiness λ at the world point (x, z), the layers
 * sampled through the warp: the rest point x0 with x0 + λ·D(x0 + w(x0)) = (x, z), found here by
 * plain fixed-point iteration (a contraction: λ·A·|k|·(1 + WARP_MAX_STRAIN) < 1), independent of
 * heightAt's Newton steps; the height is H(x0 + w(x0)).
 */
function gerstnerHeight(wave: Wave, lambda: number, x: number, z: number): number {
  const k = Math.hypot(wave.kx, wave.kz);
  const a = wave.amplitude;
  expect(lambda * a * k * (1 + WARP_MAX_STRAIN)).toBeLessThan(1); // no folds: one rest point per surface point
  let [x0, z0] = [x, z];
  for (let step = 0; step < 20_000; step++) {
    const [wx, wz] = warp(x0, z0);
    const s = a * Math.sin(wave.kx * (x0 + wx) + wave.kz * (z0 + wz) + wave.phase);
    // D = −k̂·A·sin θ, so x0 = (x, z) − λ·D = (x, z) + λ·k̂·A·sin θ.
    [x0, z0] = [x + (lambda * wave.kx * s) / k, z + (lambda * wave.kz * s) / k];
  }
  const [wx, wz] = warp(x0, z0);
  return a * Math.cos(wave.kx * (x0 + wx) + wave.kz * (z0 + wz) + wave.phase);
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
    it(`equals the Gerstner wave’s height within 1e-4 m with choppiness ${lambda}`, () => {
      let worst = 0;
      let moved = 0;
      for (const [x, z] of points) {
        const want = gerstnerHeight(wave, lambda, x, z);
        worst = Math.max(worst, Math.abs(heightAt(layers, lambda, 12.5, x, z) - want));
        // The choppy height differs from the plain cosine at (x, z): the test sees the displacement.
        const [wx, wz] = warp(x, z);
        moved = Math.max(moved, Math.abs(want - wave.amplitude * Math.cos(wave.kx * (x + wx) + wave.kz * (z + wz) + wave.phase)));
      }
      expect(worst).toBeLessThan(1e-4);
      expect(moved).toBeGreaterThan(0.05);
    });
  }

  it('with choppiness 0 is the plain sum of the layers’ heights', () => {
    // At points whose warped position lies on both grids' texels, bilinear interpolation returns
    // the texels themselves: the sum of the two float32 values (1e-9 for the rounding of the
    // texel coordinates and of the point found by iteration).
    for (const [i, j] of [
      [0, 0],
      [17, 300],
      [511, 5],
      [-40, 1000],
    ]) {
      const [targetX, targetZ] = [(i * 10) / 512, (j * 10) / 512];
      // The point (x, z) with (x, z) + w(x, z) on that texel.
      let [x, z] = [targetX, targetZ];
      for (let step = 0; step < 100; step++) {
        const [wx, wz] = warp(x, z);
        [x, z] = [targetX - wx, targetZ - wz];
      }
      const texel = (layer: FakeLayer, x0: number, z0: number) => {
        const { size, origin, resolution: n } = layer.frame;
        const u = (((Math.round(((x0 - origin[0]) / size) * n) % n) + n) % n) as number;
        const v = (((Math.round(((z0 - origin[1]) / size) * n) % n) + n) % n) as number;
        return layer.fieldsOnCpu(0).displacement[4 * (v * n + u) + 1];
      };
      const sum = texel(fine, targetX, targetZ) + texel(coarse, targetX, targetZ);
      expect(Math.abs(heightAt(layers, 0, 0, x, z) - sum)).toBeLessThan(1e-9);
    }
    // Anywhere: the cosine at the warped point, within the interpolation error.
    for (const [x, z] of points) {
      const [wx, wz] = warp(x, z);
      const want = wave.amplitude * Math.cos(wave.kx * (x + wx) + wave.kz * (z + wz) + wave.phase);
      expect(Math.abs(heightAt(layers, 0, 0, x, z) - want)).toBeLessThan(1e-4);
    }
  });

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
      // At least λ·A = 0.24 m inside its texels' span [100, 109.69] (see below).
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
