import { expect, test } from '@playwright/test';
import { spawn, spawnSync } from 'node:child_process';
import { mkdtempSync, readdirSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { PNG } from 'pngjs';

// `npm run shot` (scripts/shot.mjs) as a user runs it: a Node process that builds the app if
// needed, starts its own headless Chromium and writes PNG files. No page fixture here.

const root = resolve(import.meta.dirname, '../..');
const script = join(root, 'scripts/shot.mjs');
let dir: string;

test.beforeAll(() => {
  dir = mkdtempSync(join(tmpdir(), 'shot-test-'));
});
test.afterAll(() => {
  rmSync(dir, { recursive: true, force: true });
});

/** Runs the shot command; resolves with its exit code and output. */
function shot(args: string[]): Promise<{ code: number | null; stdout: string; stderr: string }> {
  return new Promise((resolvePromise) => {
    const child = spawn(process.execPath, [script, ...args], { cwd: root });
    let stdout = '';
    let stderr = '';
    child.stdout.on('data', (chunk) => (stdout += chunk));
    child.stderr.on('data', (chunk) => (stderr += chunk));
    child.on('close', (code) => resolvePromise({ code, stdout, stderr }));
  });
}

function brightness(file: string): { width: number; height: number; mean: number; top: number; bottom: number } {
  const png = PNG.sync.read(readFileSync(file));
  const rowMean = (y: number) => {
    let sum = 0;
    for (let x = 0; x < png.width; x++) sum += png.data[4 * (y * png.width + x)] + png.data[4 * (y * png.width + x) + 1] + png.data[4 * (y * png.width + x) + 2];
    return sum / (3 * png.width);
  };
  let sum = 0;
  for (let y = 0; y < png.height; y++) sum += rowMean(y);
  return { width: png.width, height: png.height, mean: sum / png.height, top: rowMean(2), bottom: rowMean(png.height - 3) };
}

test('the same arguments give the same PNG, byte for byte; other arguments another', async () => {
  test.setTimeout(300_000); // may build the app first
  const args = ['--seed', '7', '--time', '12.5', '--wind', '12', '--size', '320x180'];
  const first = await shot([...args, '--out', join(dir, 'a.png')]);
  expect(first.code, first.stderr).toBe(0);
  const second = await shot([...args, '--out', join(dir, 'b.png'), '--no-build']);
  expect(second.code, second.stderr).toBe(0);
  expect(second.stderr).toContain('b.png (320x180, t = 12.5 s)');
  const a = readFileSync(join(dir, 'a.png'));
  expect(a.equals(readFileSync(join(dir, 'b.png')))).toBe(true);

  const picture = brightness(join(dir, 'a.png'));
  expect([picture.width, picture.height]).toEqual([320, 180]);
  expect(picture.top).toBeGreaterThan(120); // sky
  expect(picture.bottom).toBeLessThan(picture.top); // darker sea
  expect(picture.mean).toBeGreaterThan(40);

  const other = await shot(['--seed', '8', '--time', '12.5', '--wind', '12', '--size', '320x180', '--out', join(dir, 'c.png'), '--no-build']);
  expect(other.code, other.stderr).toBe(0);
  expect(a.equals(readFileSync(join(dir, 'c.png')))).toBe(false);
});

test('--frames writes numbered frames at time + i / fps, reporting progress on stderr', async () => {
  test.setTimeout(300_000);
  const out = join(dir, 'frames');
  const result = await shot(['--seed', '3', '--time', '4', '--frames', '3', '--fps', '10', '--size', '160x90', '--out-dir', out]);
  expect(result.code, result.stderr).toBe(0);
  expect(result.stderr).toMatch(/frame 1\/3\nframe 2\/3\nframe 3\/3\n/);
  expect(readdirSync(out).sort()).toEqual(['frame-0000.png', 'frame-0001.png', 'frame-0002.png']);
  const frames = readdirSync(out).sort().map((name) => readFileSync(join(out, name)));
  expect(frames[0].equals(frames[1])).toBe(false); // the sea moved
  expect(frames[1].equals(frames[2])).toBe(false);

  // Frame 2 of that run is the still at t = 4 + 2/10.
  const still = await shot(['--seed', '3', '--time', '4.2', '--size', '160x90', '--out', join(dir, 'still.png'), '--no-build']);
  expect(still.code, still.stderr).toBe(0);
  expect(readFileSync(join(dir, 'still.png')).equals(frames[2])).toBe(true);
});

test('bad arguments fail at once with a clear message', () => {
  const cases: [string[], string][] = [
    [['--size', '1280'], '--size must be <width>x<height>'],
    [['--size', '0x720'], 'the width must be from 1 to 8192'],
    [['--frames', '-3', '--out-dir', 'x'], '--frames must be a whole number of frames, at least 1; got "-3"'],
    [['--frames', '2.5', '--out-dir', 'x'], '--frames must be a whole number'],
    [['--frames', '3'], '--frames needs --out-dir'],
    [['--frames', '3', '--out-dir', 'x', '--fps', '0'], '--fps must be a number of frames per second above 0'],
    [['--seed', 'seven'], '--seed must be an integer'],
    [['--wind', '-1'], '--wind must be a wind speed in m/s from 0 to 100'],
    [['--time', 'later'], '--time must be a finite number of seconds'],
    [['--camera', '1,2,3'], '--camera must be six numbers'],
    [['--out', 'ocean.jpg'], '--out must name a .png file'],
    [['--colour', 'blue'], "Unknown option '--colour'"],
  ];
  for (const [args, message] of cases) {
    const result = spawnSync(process.execPath, [script, ...args], { cwd: root, encoding: 'utf8' });
    expect(result.status, args.join(' ')).toBe(2);
    expect(result.stderr, args.join(' ')).toContain(message);
  }
  const help = spawnSync(process.execPath, [script, '--help'], { cwd: root, encoding: 'utf8' });
  expect(help.status).toBe(0);
  expect(help.stdout).toContain('--frames <n>');
});
