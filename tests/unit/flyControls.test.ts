import { describe, expect, it } from 'vitest';
import {
  anglesFromDirection,
  bindingFor,
  clampPitch,
  FAST_FACTOR,
  leftVector,
  MAX_PITCH,
  MAX_SPEED,
  MIN_HEIGHT,
  MIN_SPEED,
  NO_INPUT,
  speedAfterWheel,
  step,
  touchMove,
  turn,
  viewDirection,
  wrapYaw,
  type MoveInput,
  type Vec3,
} from '../../src/app/flyControls';

const held = (keys: Partial<MoveInput>): MoveInput => ({ ...NO_INPUT, ...keys });
const cross = (a: Vec3, b: Vec3): Vec3 => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const dot = (a: Vec3, b: Vec3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const close = (a: Vec3, b: Vec3, digits = 12) => a.forEach((value, i) => expect(value).toBeCloseTo(b[i], digits));

describe('view direction v (course report §2.6)', () => {
  it('is (cos φ cos θ, sin θ, sin φ cos θ) and unit length', () => {
    for (const [yaw, pitch] of [
      [0, 0],
      [90, 0],
      [-53.13, -6.84],
      [170, 45],
      [-120, -89],
    ]) {
      const phi = (yaw * Math.PI) / 180;
      const theta = (pitch * Math.PI) / 180;
      const v = viewDirection(yaw, pitch);
      close(v, [Math.cos(phi) * Math.cos(theta), Math.sin(theta), Math.sin(phi) * Math.cos(theta)]);
      expect(Math.hypot(...v)).toBeCloseTo(1, 12);
    }
  });

  it('looks along +x at yaw 0, along −z (three.js default) at yaw −90, up for positive pitch', () => {
    close(viewDirection(0, 0), [1, 0, 0]);
    close(viewDirection(-90, 0), [0, 0, -1]);
    expect(viewDirection(0, 30)[1]).toBeGreaterThan(0);
  });

  it('round-trips through anglesFromDirection', () => {
    const { yaw, pitch } = anglesFromDirection(viewDirection(-53.13, -6.84));
    expect(yaw).toBeCloseTo(-53.13, 10);
    expect(pitch).toBeCloseTo(-6.84, 10);
  });
});

describe('left vector l = u × v', () => {
  it('is the normalised cross product with u = +y, horizontal and perpendicular to v', () => {
    for (const [yaw, pitch] of [
      [0, 0],
      [33, 20],
      [-150, -60],
    ]) {
      const v = viewDirection(yaw, pitch);
      const uv = cross([0, 1, 0], v);
      const length = Math.hypot(...uv);
      close(leftVector(yaw, pitch), [uv[0] / length, uv[1] / length, uv[2] / length]);
      expect(leftVector(yaw, pitch)[1]).toBe(0);
      expect(dot(leftVector(yaw, pitch), v)).toBeCloseTo(0, 12);
    }
  });

  it('points left of the view: looking along −z (three.js default), left is −x', () => {
    close(leftVector(-90, 0), [-1, 0, 0]);
    // Right-handed: v × u points right, so l = u × v = −(v × u) is left.
    close(leftVector(0, 0), [0, 0, -1]);
  });
});

describe('step', () => {
  const start: Vec3 = [10, 20, 30];

  it('moves speed × dt along v for W and against it for S', () => {
    const v = viewDirection(25, -10);
    close(step(start, 25, -10, held({ forward: true }), 8, 0.5), [10 + 4 * v[0], 20 + 4 * v[1], 30 + 4 * v[2]]);
    close(step(start, 25, -10, held({ back: true }), 8, 0.5), [10 - 4 * v[0], 20 - 4 * v[1], 30 - 4 * v[2]]);
  });

  it('moves along l for A and against it for D', () => {
    const l = leftVector(-90, 15);
    close(step(start, -90, 15, held({ left: true }), 2, 1), [10 + 2 * l[0], 20, 30 + 2 * l[2]]);
    close(step(start, -90, 15, held({ right: true }), 2, 1), [10 - 2 * l[0], 20, 30 - 2 * l[2]]);
  });

  it('moves straight up and down for up / down', () => {
    close(step(start, 70, 40, held({ up: true }), 3, 1), [10, 23, 30]);
    close(step(start, 70, 40, held({ down: true }), 3, 1), [10, 17, 30]);
  });

  it('is frame-rate independent: many small steps equal one large one', () => {
    let position = start;
    for (let i = 0; i < 60; i++) position = step(position, 12, 5, held({ forward: true, left: true }), 10, 1 / 60);
    close(position, step(start, 12, 5, held({ forward: true, left: true }), 10, 1), 9);
  });

  it('does not move diagonals faster, and the fast modifier multiplies the speed', () => {
    const diagonal = step([0, 50, 0], 0, 0, held({ forward: true, left: true }), 10, 1);
    expect(Math.hypot(diagonal[0], diagonal[1] - 50, diagonal[2])).toBeCloseTo(10, 12);
    const fast = step([0, 50, 0], 0, 0, held({ forward: true, fast: true }), 10, 1);
    close(fast, [10 * FAST_FACTOR, 50, 0]);
  });

  it('stands still with no key, opposite keys, or dt ≤ 0', () => {
    close(step(start, 0, 0, NO_INPUT, 10, 1), start);
    close(step(start, 0, 0, held({ forward: true, back: true }), 10, 1), start);
    close(step(start, 0, 0, held({ forward: true }), 10, -1), start);
  });

  it('dives under the sea, but not deeper than MIN_HEIGHT (200 m down)', () => {
    expect(step([0, 2, 0], 0, 0, held({ down: true }), 10, 1)[1]).toBeCloseTo(-8, 9);
    expect(step([0, -195, 0], 0, -60, held({ forward: true }), 10, 1)[1]).toBe(MIN_HEIGHT);
    expect(step([0, -195, 0], 0, 0, held({ down: true }), 10, 1)[1]).toBe(MIN_HEIGHT);
  });
});

describe('turning', () => {
  it('mouse right increases yaw (turns right), mouse up increases pitch', () => {
    const { yaw, pitch } = turn(10, 0, 100, -20, 0.1);
    expect(yaw).toBeCloseTo(20, 12);
    expect(pitch).toBeCloseTo(2, 12);
    // Turning right: the new view has a component along the old right vector (−l).
    const l = leftVector(10, 0);
    expect(dot(viewDirection(yaw, 0), l)).toBeLessThan(0);
  });

  it('clamps pitch to ±89° and wraps yaw into (−180, 180]', () => {
    expect(turn(0, 80, 0, -1000).pitch).toBe(MAX_PITCH);
    expect(turn(0, -80, 0, 1000).pitch).toBe(-MAX_PITCH);
    expect(clampPitch(95)).toBe(89);
    expect(wrapYaw(190)).toBeCloseTo(-170, 12);
    expect(wrapYaw(-180)).toBe(180);
    expect(wrapYaw(540)).toBe(180);
    expect(wrapYaw(-45)).toBe(-45);
  });
});

describe('speed, touch and keys', () => {
  it('wheel up speeds up, wheel down slows down, within [MIN_SPEED, MAX_SPEED]', () => {
    expect(speedAfterWheel(20, -100)).toBeCloseTo(24, 12);
    expect(speedAfterWheel(20, 100)).toBeCloseTo(20 / 1.2, 12);
    expect(speedAfterWheel(20, -1e5)).toBe(MAX_SPEED);
    expect(speedAfterWheel(20, 1e5)).toBe(MIN_SPEED);
  });

  it('two-finger drag up moves forward, sideways strafes', () => {
    const v = viewDirection(30, 10);
    close(touchMove([0, 50, 0], 30, 10, 0, -100, 0.1), [10 * v[0], 50 + 10 * v[1], 10 * v[2]]);
    const l = leftVector(30, 10);
    close(touchMove([0, 50, 0], 30, 10, -50, 0, 0.1), [5 * l[0], 50, 5 * l[2]]);
  });

  it('binds physical keys: WASD, arrows, Space/E up, Shift/Q down, F fast', () => {
    expect(['KeyW', 'KeyA', 'KeyS', 'KeyD'].map(bindingFor)).toEqual(['forward', 'left', 'back', 'right']);
    expect(['ArrowUp', 'ArrowLeft', 'ArrowDown', 'ArrowRight'].map(bindingFor)).toEqual(['forward', 'left', 'back', 'right']);
    expect(['Space', 'KeyE', 'ShiftLeft', 'ShiftRight', 'KeyQ', 'KeyF'].map(bindingFor)).toEqual([
      'up',
      'up',
      'down',
      'down',
      'down',
      'fast',
    ]);
    expect(bindingFor('KeyZ')).toBeUndefined();
    expect(bindingFor('toString')).toBeUndefined();
  });
});
