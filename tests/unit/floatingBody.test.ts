/**
 * FloatingBody (src/layers/floatingBody.ts) against Archimedes' principle on flat water, and
 * against a long deep-water wave, which a small box rides up and down with the surface.
 */
import { describe, expect, it } from 'vitest';
import { Quaternion, Vector3 } from 'three';
import { FloatingBody, SEA_WATER_DENSITY } from '../../src/layers/floatingBody';
import { GRAVITY } from '../../src/spectrum/dispersion';

const flat = { heightAt: () => 0 };

describe('FloatingBody', () => {
  it('floats at the Archimedes draft m / (ρ·A), upright, on flat water', () => {
    for (const [mass, size] of [
      [2000, [4, 2, 2]],
      [300, [1, 1, 1]],
      [12000, [10, 3, 4]],
    ] as [number, [number, number, number]][]) {
      const body = new FloatingBody({ mass, size });
      body.position.set(3, 1.5, -7); // dropped from above the water
      for (let frame = 0; frame < 60 * 40; frame++) body.step(1 / 60, flat);
      const draft = -(body.position.y - size[1] / 2);
      const archimedes = mass / (SEA_WATER_DENSITY * size[0] * size[2]);
      expect(body.restingDraft).toBeCloseTo(archimedes, 12);
      expect(Math.abs(draft - archimedes), `${mass} kg, ${size.join('×')} m`).toBeLessThan(1e-4);
      expect(body.orientation.angleTo(new Quaternion())).toBeLessThan(1e-6);
    }
  });

  it('comes back level after a tilt: pitch and roll are damped out', () => {
    const body = new FloatingBody({ mass: 2000, size: [4, 2, 2] });
    body.position.y = 1 - body.restingDraft;
    body.orientation.setFromAxisAngle(new Vector3(1, 0, 1).normalize(), 0.2);
    for (let frame = 0; frame < 60 * 60; frame++) body.step(1 / 60, flat);
    // Level: its up axis is vertical again (a turn about the vertical has no restoring force).
    const up = new Vector3(0, 1, 0).applyQuaternion(body.orientation);
    expect(up.angleTo(new Vector3(0, 1, 0))).toBeLessThan(1e-3);
  });

  it('heaves with a long wave: its height follows the wave’s within 5 %', () => {
    // A 1 m, 100 m deep-water wave, ω = √(g·k) (linear (Airy) wave theory's deep-water dispersion; period 8 s); a 2 m box whose own heave frequency
    // √(ρ·g·A/m) = 6.3 rad/s is far above the wave's 0.79 rad/s, so it follows the surface.
    const amplitude = 1;
    const k = (2 * Math.PI) / 100;
    const omega = Math.sqrt(GRAVITY * k);
    let t = 0;
    const wave = { heightAt: (x: number) => amplitude * Math.cos(k * x - omega * t) };
    const body = new FloatingBody({ mass: 1000, size: [2, 1, 2] });
    body.position.set(10, 0, 0);
    let [low, high] = [Infinity, -Infinity];
    for (let frame = 0; frame < 60 * 80; frame++) {
      t = frame / 60;
      body.step(1 / 60, wave);
      if (t > 40) [low, high] = [Math.min(low, body.position.y), Math.max(high, body.position.y)];
    }
    const heave = (high - low) / 2;
    console.log(`heave amplitude on a 1 m, 100 m wave: ${heave.toFixed(4)} m`);
    expect(Math.abs(heave / amplitude - 1)).toBeLessThan(0.05);
  });

  it('rejects a body that cannot float', () => {
    expect(() => new FloatingBody({ mass: 0, size: [1, 1, 1] })).toThrow(/mass/);
    expect(() => new FloatingBody({ mass: 1, size: [1, -1, 1] })).toThrow(/size/);
  });
});
