import { describe, expect, it } from 'vitest';
import { breakingZone, HULL_SPEED_FROUDE, HullFoam, hullFoamCoverage, KELVIN_WEDGE_TAN } from '../../src/layers/hullFoam';

// The foam a hull under way makes (src/layers/hullFoam.ts), on its own grid, against the laws the
// file cites: the Kelvin wedge (Thomson 1887), the speed through the Froude number, and the
// whitecaps' fading F·e^{−Δt/τ} (foamModel.ts).

const G = 9.81;
const HULL = { length: 8, beam: 2.6 };
const N = 128;
const CELL = 1;
const TAU = 3;

/** A hull from x = 20 m along +x at `speed` m/s for `seconds`, in steps of dt, through the middle row of the grid. */
function run(foam: HullFoam, speed: number, seconds: number, dt: number, from = 20): number {
  let x = from;
  for (let t = 0; t < seconds - 1e-9; t += dt) {
    x += speed * dt;
    foam.fade(dt, TAU);
    foam.stamp(x, 64, 1, 0, HULL.length, HULL.beam, hullFoamCoverage(speed, HULL.length, 1));
  }
  return x;
}

const at = (foam: HullFoam, i: number, j: number) => foam.coverage[j * N + i];

describe('hull foam', () => {
  it("lies in the Kelvin wedge, half-angle arcsin(1/3) = 19.47° (Thomson 1887)", () => {
    expect((Math.atan(KELVIN_WEDGE_TAN) * 180) / Math.PI).toBeCloseTo(19.47, 2);
    // On the centre line inside the hull, at the side behind the bow by s: out to B/2 + s·tan α.
    expect(breakingZone(0, 0, 8, 2.6, 0.01)).toBe(1);
    expect(breakingZone(4 - 6, 1.3 + 6 * KELVIN_WEDGE_TAN - 0.02, 8, 2.6, 0.01)).toBe(1);
    expect(breakingZone(4 - 6, 1.3 + 6 * KELVIN_WEDGE_TAN + 0.02, 8, 2.6, 0.01)).toBe(0);
    // None ahead of the bow, none behind the stern.
    expect(breakingZone(4.02, 0, 8, 2.6, 0.01)).toBe(0);
    expect(breakingZone(-4.02, 0, 8, 2.6, 0.01)).toBe(0);
  });

  it('grows with the speed in proportion to the Froude number, full at the hull speed, none at rest', () => {
    expect(hullFoamCoverage(0, 8, 1)).toBe(0);
    const hullSpeed = HULL_SPEED_FROUDE * Math.sqrt(G * 8); // 3.54 m/s: λ = 2πU²/g = L
    expect((2 * Math.PI * hullSpeed ** 2) / G).toBeCloseTo(8, 2);
    expect(hullFoamCoverage(hullSpeed, 8, 1)).toBeCloseTo(1, 2);
    expect(hullFoamCoverage(hullSpeed / 2, 8, 1)).toBeCloseTo(0.5, 2);
    expect(hullFoamCoverage(3 * hullSpeed, 8, 0.4)).toBeCloseTo(0.4, 6);
  });

  it('leaves a wake behind and along the sides, none ahead, and fades behind as e^(−d/(U·τ))', () => {
    const foam = new HullFoam(N, CELL);
    const speed = 5;
    const bow = run(foam, speed, 12, 1 / 30) + HULL.length / 2;
    const stern = bow - HULL.length;
    for (let j = 0; j < N; j++) {
      for (let i = 0; i < N; i++) {
        const coverage = at(foam, i, j);
        if (coverage < 0.01) continue;
        const behindBow = bow - i;
        // Within a texel (the zone's soft edge) of the wedge from the bow's shoulders, none ahead.
        expect(behindBow).toBeGreaterThan(-CELL);
        expect(Math.abs(j - 64)).toBeLessThanOrEqual(HULL.beam / 2 + Math.max(0, behindBow) * KELVIN_WEDGE_TAN + CELL);
      }
    }
    // Full beside the hull's quarter (Fr = 0.56 > 0.40), just outside its side.
    expect(at(foam, Math.round(stern + 2), 64 + 2)).toBeCloseTo(1, 2);
    // Behind the stern the foam is as old as the time since the stern passed: d/U.
    const behind = (d: number) => at(foam, Math.round(stern - d), 64);
    for (const d of [6, 12, 24]) {
      const age = (stern - Math.round(stern - d)) / speed;
      expect(behind(d)).toBeGreaterThan(0.95 * Math.exp(-age / TAU) - 0.02);
      expect(behind(d)).toBeLessThan(1.05 * Math.exp(-age / TAU) + 0.02);
    }
    expect(Math.max(...Array.from({ length: 20 }, (_, k) => at(foam, Math.ceil(bow) + 1 + k, 64)))).toBe(0);
  });

  it('makes none at rest, and fades by e^(−Δt/τ) after the hull stops', () => {
    const resting = new HullFoam(N, CELL);
    run(resting, 0, 5, 0.1);
    expect(Math.max(...resting.coverage)).toBe(0);
    const foam = new HullFoam(N, CELL);
    const x = run(foam, 4, 6, 0.05);
    const beside = () => at(foam, Math.round(x - 2), 64 + 2);
    const before = beside();
    expect(before).toBeGreaterThan(0.9);
    run(foam, 0, 2, 0.05, x);
    expect(beside() / before).toBeCloseTo(Math.exp(-2 / TAU), 3);
    run(foam, 0, 60, 0.5, x);
    expect(Math.max(...foam.coverage)).toBe(0); // cleared once below what a byte shows
  });

  it('does not depend on the frame rate', () => {
    const [fine, coarse] = [new HullFoam(N, CELL), new HullFoam(N, CELL)];
    run(fine, 5, 6, 1 / 60);
    run(coarse, 5, 6, 1 / 10);
    let largest = 0;
    for (let t = 0; t < N * N; t++) largest = Math.max(largest, Math.abs(fine.coverage[t] - coarse.coverage[t]));
    // A step of 0.5 m moves the zone's soft edge by half a texel: no more than that changes.
    expect(largest).toBeLessThan(0.1);
  });

  it('moves with the grid, by whole texels, and publishes bytes', () => {
    const foam = new HullFoam(N, CELL);
    foam.stamp(60, 64, 1, 0, HULL.length, HULL.beam, 0.8);
    const before = Float32Array.from(foam.coverage);
    foam.shift(3, -2);
    for (const [i, j] of [[50, 64], [57, 62], [60, 66]]) expect(at(foam, i, j)).toBe(before[(j - 2) * N + i + 3]);
    foam.publish();
    expect((foam.texture.image.data as Uint8Array)[64 * N + 57]).toBe(Math.round(at(foam, 57, 64) * 255));
    foam.dispose();
  });
});
