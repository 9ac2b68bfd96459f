/**
 * FloatingBody (src/layers/floatingBody.ts) against Archimedes' principle on flat water, and
 * against a long deep-water wave, which a small box rides up and down with the surface.
 */
import { describe, expect, it } from 'vitest';
import { Quaternion, Vector3, type WebGLRenderer } from 'three';
import { FloatingBody, SEA_WATER_DENSITY } from '../../src/layers/floatingBody';
import { LocalWaves } from '../../src/layers/localWaves';
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

});

describe('FloatingBody input', () => {
  it('names the parameter that is not a finite positive number, and what is allowed', () => {
    const good = { mass: 300, size: [1, 1, 1] as [number, number, number] };
    for (const [options, named] of [
      [{ ...good, mass: NaN }, /FloatingBody mass must be a finite number of kilograms > 0; got NaN/],
      [{ ...good, mass: -1 }, /FloatingBody mass/],
      [{ ...good, size: [1, NaN, 1] }, /FloatingBody size must be \[length, height, width\]/],
      [{ ...good, size: [1, 1] }, /FloatingBody size/],
      [{ ...good, samples: 2.5 }, /FloatingBody samples must be a whole number from 1 to 64/],
      [{ ...good, damping: Infinity }, /FloatingBody damping/],
      [{ ...good, density: 0 }, /FloatingBody density/],
    ] as const) {
      expect(() => new FloatingBody(options as never)).toThrow(named);
    }
  });

  it('refuses a NaN position or time step, naming it, and keeps its last good state', () => {
    const body = new FloatingBody({ mass: 300, size: [1, 1, 1] });
    body.settle(flat);
    const before = body.position.clone();
    body.position.x = NaN;
    expect(() => body.step(1 / 60, flat)).toThrow(/FloatingBody.step: position must be finite x, y, z \(m\); got \[NaN, /);
    body.position.x = before.x;
    expect(() => body.step(NaN, flat)).toThrow(/FloatingBody.step\(dt\) must be a finite time step ≥ 0 \(s\); got NaN/);
    expect(() => body.step(-1, flat)).toThrow(/FloatingBody.step\(dt\)/);
    expect(body.position.equals(before)).toBe(true);
  });
});

describe('FloatingBody pressing on local waves', () => {
  /** Stands in for ocean.localWaves: records the hull it is given and each pose. */
  function recordingWater() {
    const record = { shapes: [] as { length: number; beam: number; draft: number }[], poses: [] as number[][], removed: 0 };
    const water = {
      heightAt: () => 0,
      addPressure: (shape: { length: number; beam: number; draft: number }, pose: { x: number; z: number; heading: number }) => {
        record.shapes.push({ ...shape });
        record.poses.push([pose.x, pose.z, pose.heading, shape.draft]);
        return {
          setPose: (x: number, z: number, heading: number, draft = NaN) => void record.poses.push([x, z, heading, draft]),
          remove: () => void record.removed++,
        };
      },
    };
    return { water, record };
  }

  it('puts its footprint on the water as deep as it floats, follows it, turns with it, and comes off', () => {
    const { water, record } = recordingWater();
    const body = new FloatingBody({ mass: 2000, size: [4, 2, 2] });
    body.position.set(5, 0, -3);
    body.pressOn(water);
    expect(record.shapes).toEqual([{ length: 4, beam: 2, draft: body.restingDraft }]);
    body.settle(flat);
    let [x, z, heading, draft] = record.poses.at(-1)!;
    expect([x, z, heading]).toEqual([5, -3, 0]);
    expect(draft).toBeCloseTo(body.restingDraft, 12); // settled at the Archimedes draft
    // Moved and turned a quarter round the vertical (its +x axis to +z): the patch follows.
    body.position.x = 9;
    body.orientation.setFromAxisAngle(new Vector3(0, 1, 0), -Math.PI / 2);
    body.step(1 / 60, flat);
    [x, z, heading, draft] = record.poses.at(-1)!;
    expect([x, z]).toEqual([9, -3]);
    expect(heading).toBeCloseTo(Math.PI / 2, 9);
    expect(draft).toBeGreaterThan(0);
    // Lifted clear of the water it presses nothing.
    body.position.y = 5;
    body.step(0, flat);
    expect(record.poses.at(-1)![3]).toBe(0);
    body.pressOn(null);
    expect(record.removed).toBe(1);
  });
});

describe('FloatingBody pressing on real local waves (the JS solver)', () => {
  /**
   * A crate of 1 t, 2 × 1 × 2 m, let go 0.3 m above its resting draft on still water, for 20 s at
   * 60 fps: its heave (the distance of its bottom from where it rests), and the largest height
   * of the local waves 15 m away at the end.
   */
  function heave(pressing: boolean): { largestSwing: number; lastSwing: number; ringsAway: number } {
    // Only the renderer's float-filtering extension is asked on the JS path.
    const renderer = { extensions: { has: () => true } } as unknown as WebGLRenderer;
    const waves = new LocalWaves(renderer, Infinity, false, { resolution: 64, cellSize: 1 });
    const water = { heightAt: (x: number, z: number) => waves.heightAt(x, z) };
    // No damping of its own: what takes its energy is the waves, or nothing.
    const body = new FloatingBody({ mass: 1000, size: [2, 1, 2], samples: 3, damping: 0 });
    body.settle(water);
    if (pressing) body.pressOn(waves);
    body.position.y += 0.3;
    let t = 0;
    waves.update(t, 0);
    const swings: number[] = [];
    for (let frame = 1; frame <= 60 * 20; frame++) {
      t = frame / 60;
      waves.update(t, 1 / 60);
      body.step(1 / 60, water);
      swings.push(Math.abs(body.position.y - (0.5 - body.restingDraft)));
    }
    let ringsAway = 0;
    for (let a = 0; a < 2 * Math.PI; a += 0.1) ringsAway = Math.max(ringsAway, Math.abs(waves.heightAt(15 * Math.cos(a), 15 * Math.sin(a))));
    waves.dispose();
    return { largestSwing: Math.max(...swings), lastSwing: Math.max(...swings.slice(-120)), ringsAway };
  }

  it('stays stable, and its heave radiates rings that carry its energy away (radiation damping)', () => {
    // A heaving body loses energy to the waves it makes (radiation damping: Newman 1977, Marine
    // Hydrodynamics §6.16). Without damping of its own, pressing, its heave must never grow
    // (pressing against the whole surface it did: see floatingBody.ts) and must shrink as the rings
    // carry energy away, where alone it swings on undiminished. (The 1 m grid resolves waves of
    // 2 m and more, longer than the crate's 1 s heave makes, 1.6 m: it radiates less than a real
    // crate would.)
    const alone = heave(false);
    const pressing = heave(true);
    console.log(`heave after 18 s: ${(pressing.lastSwing * 100).toFixed(2)} cm pressing, ${(alone.lastSwing * 100).toFixed(2)} cm alone; rings 15 m away ${(pressing.ringsAway * 100).toFixed(2)} cm`);
    expect(pressing.largestSwing).toBeLessThan(0.3 + 1e-3);
    expect(alone.lastSwing).toBeGreaterThan(0.29);
    expect(pressing.lastSwing).toBeLessThan(0.8 * alone.lastSwing);
    expect(pressing.ringsAway).toBeGreaterThan(5e-4); // m
    expect(alone.ringsAway).toBe(0);
  });
});
