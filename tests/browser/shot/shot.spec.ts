import { expect, test, type Page } from '@playwright/test';
import { spawn, spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readdirSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { PNG } from 'pngjs';
import { ensureBuiltApp } from '../../../scripts/shot.mjs';
import { serveDirectory } from '../../../scripts/static-server.mjs';

// `npm run shot` (scripts/shot.mjs) as a user runs it: a Node process that builds the app if
// needed, starts its own headless Chromium and writes PNG files. The tests that compare a shot
// with the app itself (on the dev server, as app.spec.ts drives it) use the page fixture; so do
// the tests of many scene options, which give the shot page (examples/shot.html, built and served
// as the CLI serves it) the CLI's arguments as the CLI passes them (its own parseShotArguments and pageQuery)
// in one browser, rather than a Chromium launched per case, and so do the stills the other tests
// compare with (a frame of --frames, the README's picture): the page reads every scene option
// and writes every message (shot.mjs checks only its own options), and the process around it
// (exit codes, the PNG file) is tested through the CLI by the other tests.

const root = resolve(import.meta.dirname, '../../..');
const script = join(root, 'scripts/shot.mjs');
let dir: string;
/** The built app, served as the CLI serves it: one bundle loads faster than the dev server's modules. */
let builtApp: Awaited<ReturnType<typeof serveDirectory>>;

test.beforeAll(async () => {
  test.setTimeout(300_000); // may build the app first
  dir = mkdtempSync(join(tmpdir(), 'shot-test-'));
  ensureBuiltApp();
  builtApp = await serveDirectory(join(root, 'dist/app'));
});
test.afterAll(async () => {
  rmSync(dir, { recursive: true, force: true });
  await builtApp.close();
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

/**
 * The CLI's still of an app link at a size, run once for this file: the tests that need the same
 * link's shot share it (each run launches a Chromium and compiles the sea's shaders again).
 */
const linkShots = new Map<string, Promise<{ code: number | null; stderr: string; file: string }>>();
function shotOfLink(link: string, size: { width: number; height: number }) {
  const key = `${link} ${size.width}x${size.height}`;
  let result = linkShots.get(key);
  if (!result) {
    const file = join(dir, `link-${linkShots.size}.png`);
    result = shot(['--query', link, '--size', `${size.width}x${size.height}`, '--out', file]).then(({ code, stderr }) => ({ code, stderr, file }));
    linkShots.set(key, result);
  }
  return result;
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

test('the same arguments give the same PNG, byte for byte', async () => {
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
  // Other arguments give another PNG through the CLI: the buoys test below (the shots of a link
  // with and without buoys=1 differ in over 100 pixels); another seed another picture: the scene
  // options test (its page, given what the CLI gives it).
});

test('--frames writes numbered frames at time + i / fps, reporting progress on stderr', async ({ page }) => {
  test.setTimeout(300_000);
  const out = join(dir, 'frames');
  // Without foam: a frame sequence steps the foam from frame to frame, while a still warms it up
  // from nothing (src/layers/foamModel.ts), so only the waves are the same in frame 2 and the still.
  const noFoam = ['--foam-amount', '0'];
  const result = await shot(['--seed', '3', '--time', '4', '--frames', '3', '--fps', '10', '--size', '160x90', '--out-dir', out, ...noFoam]);
  expect(result.code, result.stderr).toBe(0);
  expect(result.stderr).toMatch(/frame 1\/3\nframe 2\/3\nframe 3\/3\n/);
  expect(readdirSync(out).sort()).toEqual(['frame-0000.png', 'frame-0001.png', 'frame-0002.png']);
  const frames = readdirSync(out).sort().map((name) => readFileSync(join(out, name)));
  expect(frames[0].equals(frames[1])).toBe(false); // the sea moved
  expect(frames[1].equals(frames[2])).toBe(false);

  // Frame 2 of that run is the still at t = 4 + 2/10: the PNG the CLI writes for it, made by its
  // page (a still through the CLI itself: the first test; the same pixels: the link tests).
  const still = await shotPicture(page, ['--seed', '3', '--time', '4.2', '--size', '160x90', ...noFoam]);
  expect(still.equals(frames[2])).toBe(true);
});

test('bad arguments fail at once with a clear message', async () => {
  const cases: [string[], string][] = [
    [['--size', '1280'], '--size must be <width>x<height>'],
    [['--size', '0x720'], 'the width must be from 1 to 8192'],
    [['--frames', '-3', '--out-dir', 'x'], '--frames must be a whole number of frames, at least 1; got "-3"'],
    [['--frames', '2.5', '--out-dir', 'x'], '--frames must be a whole number'],
    [['--frames', '3'], '--frames needs --out-dir'],
    [['--frames', '3', '--out-dir', 'x', '--fps', '0'], '--fps must be a number of frames per second above 0'],
    [['--time', 'later'], '--time must be a finite number of seconds'],
    [['--time'], '--time needs a value'],
    [['--camera', '1,2,3'], '--camera must be six numbers'],
    [['--out', 'ocean.jpg'], '--out must name a .png file'],
    [['ocean.png'], 'unexpected argument "ocean.png"'],
    [['--query', 'seed=3', '--time', '2', '--wind-speed', '5'], '--query is the whole scene of an app link: put --time, --wind-speed into it'],
  ];
  // Each is the CLI's own parsing's UsageError, which the CLI turns into exit code 2 and its message
  // by one branch (scripts/shot.mjs main), whatever the mistake: the first case through the CLI
  // proves it; a process per further case started Node again for the same proof.
  const { parseShotArguments, UsageError } = await shotCli();
  for (const [args, message] of cases) {
    expect(() => parseShotArguments(args), args.join(' ')).toThrow(UsageError);
    expect(() => parseShotArguments(args), args.join(' ')).toThrow(message);
  }
  const [args, message] = cases[0];
  const result = spawnSync(process.execPath, [script, ...args], { cwd: root, encoding: 'utf8' });
  expect(result.status, args.join(' ')).toBe(2);
  expect(result.stderr, args.join(' ')).toContain(`shot: ${message}`);
});

test('--help lists the CLI\'s options and, from the option tables, every scene option with its default', () => {
  test.setTimeout(300_000); // the page writes the scene part: may build the app first
  const help = spawnSync(process.execPath, [script, '--help'], { cwd: root, encoding: 'utf8' });
  expect(help.status, help.stderr).toBe(0);
  expect(help.stdout).toContain('--frames <n>');
  expect(help.stdout).toContain('--query "<query>"');
  expect(help.stdout).toContain('--wind is --wind-speed');
  expect(help.stdout).toMatch(
    /\n {2}--scatter-color <#rrggbb\|r,g,b> +a colour: a THREE\.Color,[\s\S]*?\(default 0,0\.035,0\.06\);\s+--scatter-colour\s+is\s+--scatter-color/,
  );
  for (const name of ['spectrum', 'fetch', 'patch-sizes', 'depth', 'swell-height', 'shading-mode', 'absorption', 'path', 'skybox', 'boat', 'buoys', 'scene', 'quality']) {
    expect(help.stdout).toMatch(new RegExp(`\\n  --${name} `));
  }
  expect(help.stdout).toMatch(/has no use for[\s\S]*\n {2}--target-fps +the frame rate[\s\S]*\n {2}--time-scale /);
  expect(help.stdout).toMatch(/--sun-elevation <deg> +a number of degrees from -90 to 90 \(default 30\)/);
  expect(help.stdout).toMatch(/--wind-speed <m\/s> +a speed in m\/s from 0 to 60 \(default 10\)/);
  expect(help.stdout).toContain('(default 13.7,79.3,457)');
});

/** Raw RGBA of a PNG (a file, or its bytes), top row first. */
function rgba(png: string | Buffer): { width: number; height: number; data: Buffer } {
  const { width, height, data } = PNG.sync.read(typeof png === 'string' ? readFileSync(png) : png);
  return { width, height, data };
}

/** The CLI's own argument parsing and the query it gives its page (scripts/shot.mjs). */
interface ShotCli {
  parseShotArguments(argv: string[]): object;
  pageQuery(options: object): URLSearchParams;
  UsageError: new () => Error;
}
const shotCli = () => import('../../../scripts/shot.mjs') as unknown as Promise<ShotCli>;

/**
 * Opens the built shot page with the query the CLI gives it for `args`, as the CLI opens it (a
 * 320×180 viewport), and waits until it is done: its title 'ready' or 'error: …'.
 */
async function openShotPage(page: Page, args: string[]): Promise<{ title: string; error?: string; kind?: string }> {
  const { parseShotArguments, pageQuery } = await shotCli();
  await page.setViewportSize({ width: 320, height: 180 });
  await page.goto(`${builtApp.url}/examples/shot.html?${pageQuery(parseShotArguments(args))}`);
  await page.waitForFunction(() => document.title === 'ready' || document.title.startsWith('error'));
  return page.evaluate(() => ({ title: document.title, error: window.shotError, kind: window.shotErrorKind }));
}

/** The PNG the CLI writes for `args` (a still): its page's frame at the first time, as scripts/shot.mjs reads it. */
async function shotPicture(page: Page, args: string[]): Promise<Buffer> {
  const { title, error } = await openShotPage(page, args);
  expect(title, error).toBe('ready');
  const dataUrl = await page.evaluate(async () => {
    await window.renderFrame(window.shotStart!.t);
    return document.querySelector('canvas')!.toDataURL('image/png');
  });
  return Buffer.from(dataUrl.slice(dataUrl.indexOf(',') + 1), 'base64');
}

test('every scene option reaches the picture: seed, spectrum, depth, fetch, patch sizes, colours, shading mode; --wind is --wind-speed', async ({ page }) => {
  test.setTimeout(300_000);
  const base = ['--seed', '4', '--time', '3', '--size', '160x90'];
  const run = (args: string[]) => shotPicture(page, [...base, ...args]);
  const old = await run(['--wind', '12']);
  // Another seed, another sea.
  expect((await shotPicture(page, ['--seed', '5', '--time', '3', '--size', '160x90', '--wind', '12'])).equals(old)).toBe(false);
  // The old name and the new one, with the default spectrum written out, give the same bytes.
  expect((await run(['--wind-speed', '12', '--spectrum', 'jonswap'])).equals(old)).toBe(true);
  expect((await run(['--wind-speed', '12', '--spectrum', 'phillips'])).equals(old)).toBe(false);
  const shallow = await run(['--wind-speed', '12', '--spectrum', 'tma', '--depth', '4', '--fetch', '300', '--patch-sizes', '10,50,250']);
  expect(shallow.equals(old)).toBe(false);
  expect((await run(['--wind-speed', '12', '--absorption', '0.05,0.05,0.05', '--sun-elevation', '-5'])).equals(old)).toBe(false);
  // A colour as CSS changes the picture; the default caustic colour under its British name does not.
  expect((await run(['--wind-speed', '12', '--scatter-color', '#1a6b80'])).equals(old)).toBe(false);
  expect((await run(['--wind-speed', '12', '--caustic-colour', '0.12,0.12,0.12'])).equals(old)).toBe(true);

  // The height mode (the report's Figure 3) shades the sea in greys: the lower half, all sea, is grey
  // but for the odd pixel where a folding crest leaves a sub-pixel gap onto the sky (the known fold
  // holes of issue "A package three.js users adopt"; 2 of 7200 pixels here): at most 1 in 1000.
  const { width, height, data } = rgba(await run(['--wind-speed', '12', '--shading-mode', 'height']));
  expect([width, height]).toEqual([160, 90]);
  let colourful = 0;
  for (let y = Math.ceil(height / 2); y < height; y++) {
    for (let x = 0; x < width; x++) {
      const i = 4 * (y * width + x);
      if (Math.max(data[i], data[i + 1], data[i + 2]) - Math.min(data[i], data[i + 1], data[i + 2]) > 2) colourful++;
    }
  }
  expect(colourful).toBeLessThanOrEqual((width * height) / 2 / 1000);
  const full = rgba(old).data;
  const i = 4 * ((height - 3) * width + width / 2);
  expect(full[i + 2] - full[i]).toBeGreaterThan(10); // the same sea shaded in full is blue
});

test('a bad value or an unknown option comes back from the page: exit code 2, naming the option', async ({ page }) => {
  test.setTimeout(300_000); // may build the app first
  const cases: [string[], string][] = [
    [['--wind-sped', '12'], 'unknown option --wind-sped; did you mean --wind-speed?'],
    [['--sun-elevaton', '10'], 'did you mean --sun-elevation?'],
    [['--szie', '320x180'], 'did you mean --size?'],
    [['--seed', 'seven'], '--seed must be an integer from 0 to 4294967295; got "seven"'],
    [['--wind', '-1'], '--wind must be a speed in m/s from 0 to 60; got "-1"'],
    [['--spectrum', 'pm'], '--spectrum must be one of phillips, pierson-moskowitz, jonswap, tma; got "pm"'],
    [['--shading-mode', 'glossy'], '--shading-mode must be one of full, fresnel'],
    [['--patch-sizes', '100,50'], '--patch-sizes must be 1 to 4 sizes in metres'],
    [['--absorption', '0.4,0.1'], '--absorption must be three numbers'],
    [['--scatter-color', 'seaweed'], '--scatter-color must be a colour: a THREE.Color, a hex number'],
    [['--scater-colour', '#fff'], 'unknown option --scater-colour; did you mean --scatter-color?'],
    [['--path', 'cuda'], `--path must be 'auto', 'gpu' or 'js'; got "cuda"`],
    [['--wind', '5', '--wind-speed', '6'], '--wind-speed is given twice (also as --wind)'],
    [['--query', 'windSpeed=99&cam=1,2'], 'windSpeed must be a speed in m/s from 0 to 60; got "99"; cam must be five numbers'],
    [['--query', 'wind=5'], 'wind: unknown URL parameter'],
    [['--buoy'], 'unknown option --buoy; did you mean --buoys?'],
    [['--quality', 'ultra'], '--quality must be one of auto, high, medium, low, lowest; got "ultra"'],
    // The app's settings a shot has no use for are refused, saying why, not silently dropped.
    [['--target-fps', '60'], "--target-fps is an app setting a shot has no use for: the frame rate quality 'auto' adapts to"],
    [['--time-scale', '2'], '--time-scale is an app setting a shot has no use for: a shot draws the times asked for'],
    [['--paused'], '--paused is an app setting a shot has no use for'],
    [['--t', '3'], '--t is an app setting a shot has no use for: the time of a shot is --time <seconds>'],
  ];
  // Every message from the page, given what the CLI gives it, each of kind 'usage'. The CLI turns
  // any message of that kind into exit code 2 and the message word for word, by one branch
  // (scripts/shot.mjs withShotPage), whatever the kind of mistake: one case through the CLI proves
  // it (exit code 2, the message, no file), each further one launched a Chromium for the same proof.
  const throughCli = new Set(['--wind-sped']);
  for (const [args, message] of cases) {
    const error = await openShotPage(page, [...args, '--size', '16x16']);
    expect(error.kind, `${args.join(' ')}: ${error.title}`).toBe('usage');
    expect(error.error, args.join(' ')).toContain(message);
    if (!throughCli.delete(args[0])) continue;
    const result = await shot([...args, '--size', '16x16', '--out', join(dir, 'never.png')]);
    expect(result.code, `${args.join(' ')}: ${result.stderr}`).toBe(2);
    expect(result.stderr, args.join(' ')).toContain(`shot: ${error.error}\n`); // the page's message, word for word
  }
  expect(throughCli.size).toBe(0);
  expect(existsSync(join(dir, 'never.png'))).toBe(false);
});

/**
 * The app's canvas (on the test server, as app.spec.ts drives it) for a link's query, right after
 * a render, as RGBA top row first like a PNG; the app must read the link without a warning.
 */
async function appCanvas(page: Page, query: string, size: { width: number; height: number }): Promise<{ width: number; height: number; data: Buffer }> {
  await page.setViewportSize(size);
  await page.goto(`/?${query}`);
  await page.waitForFunction(() => window.oceanApp !== undefined);
  const appPixels = await page.evaluate(async () => {
    for (let i = 0; i < 3; i++) await new Promise((resolve) => requestAnimationFrame(resolve));
    const { width, height, data } = await window.oceanApp.capturePixels();
    let text = '';
    for (let i = 0; i < data.length; i += 8192) text += String.fromCharCode(...data.subarray(i, i + 8192));
    return { width, height, base64: btoa(text) };
  });
  const warnings = await page.locator('.notice.warning').count();
  expect(warnings).toBe(0); // the link is one the app reads without complaint
  const { width, height } = appPixels;
  // readPixels gives the bottom row first.
  const bottomFirst = Buffer.from(appPixels.base64, 'base64');
  const data = Buffer.alloc(bottomFirst.length);
  for (let y = 0; y < height; y++) bottomFirst.copy(data, 4 * y * width, 4 * (height - 1 - y) * width, 4 * (height - y) * width);
  return { width, height, data };
}

/** The largest difference of any channel at pixel i (a byte offset) between two RGBA pictures. */
function pixelDifference(a: Buffer, b: Buffer, i: number): number {
  let difference = 0;
  for (let c = 0; c < 4; c++) difference = Math.max(difference, Math.abs(a[i + c] - b[i + c]));
  return difference;
}

/** An app link, its shot compared with the app with and without buoys=1. */
const LINK =
  'windSpeed=14&windDirection=50&seed=5&sunElevation=18&sunAzimuth=70&absorption=0.3,0.06,0.03&scatterColour=%23103040&quality=high&paused=1&t=7.25&cam=3,9,-4,20,-8';

test('a link from the app and its shot agree pixel for pixel', async ({ page }) => {
  test.setTimeout(300_000);
  const size = { width: 320, height: 180 };
  const query = LINK;
  const app = await appCanvas(page, query, size);
  expect([app.width, app.height]).toEqual([size.width, size.height]);

  // The shot of the same link (as copied: the whole address works too).
  const result = await shotOfLink(`http://127.0.0.1/?${query}`, size);
  expect(result.code, result.stderr).toBe(0);
  expect(result.stderr).toContain('t = 7.25 s');
  const { width, height, data } = rgba(result.file);
  expect([width, height]).toEqual([size.width, size.height]);

  let differing = 0;
  let largest = 0;
  for (let i = 0; i < data.length; i += 4) {
    const difference = pixelDifference(app.data, data, i);
    if (difference > 0) differing++;
    largest = Math.max(largest, difference);
  }
  expect({ differing, largest }).toEqual({ differing: 0, largest: 0 });
  // Not vacuous: the shot of another link is another picture (the next test: buoys=1 added to
  // this link changes over 100 pixels of its shot, where the app draws them), and the app puts
  // its camera where the link's cam says (app.spec.ts: URL → scene).
});

test('a link with buoys=1: the shot draws the app\'s buoys where the app does; all else the same pixels', async ({ page }) => {
  test.setTimeout(300_000);
  const size = { width: 320, height: 180 };
  const withBuoys = LINK.replace('&quality', '&buoys=1&quality');
  expect(withBuoys).not.toBe(LINK);
  const app = await appCanvas(page, withBuoys, size);
  const pictures: Record<string, Buffer> = {};
  // Without buoys: the link of the test above, whose shot that test may have made already.
  for (const [name, link] of [['buoys', withBuoys], ['none', `http://127.0.0.1/?${LINK}`]]) {
    const result = await shotOfLink(link, size);
    expect(result.code, result.stderr).toBe(0);
    pictures[name] = rgba(result.file).data;
  }
  // The buoys of a picture: its pixels that differ from the same sea without them (before, the
  // shot dropped buoys=1 and drew none).
  const { width, height } = size;
  const buoyPixels = (picture: Buffer) => Array.from({ length: width * height }, (_, p) => pixelDifference(picture, pictures.none, 4 * p) > 0);
  const [inApp, inShot] = [buoyPixels(app.data), buoyPixels(pictures.buoys)];
  const count = (mask: boolean[]) => mask.filter(Boolean).length;
  /** How far (px, in x or y, up to 9) the pixel p is from the nearest pixel set in `mask`. */
  const distanceTo = (mask: boolean[], p: number) => {
    const [x, y] = [p % width, Math.floor(p / width)];
    for (let r = 0; r < 9; r++) {
      for (let v = Math.max(0, y - r); v <= Math.min(height - 1, y + r); v++) {
        for (let u = Math.max(0, x - r); u <= Math.min(width - 1, x + r); u++) if (mask[v * width + u]) return r;
      }
    }
    return 9;
  };
  let differingElsewhere = 0;
  let differingAtBuoys = 0;
  let farthest = 0; // from a buoy pixel of one picture to the nearest of the other
  for (let p = 0; p < width * height; p++) {
    if (inApp[p]) farthest = Math.max(farthest, distanceTo(inShot, p));
    if (inShot[p]) farthest = Math.max(farthest, distanceTo(inApp, p));
    if (pixelDifference(app.data, pictures.buoys, 4 * p) === 0) continue;
    if (Math.min(distanceTo(inApp, p), distanceTo(inShot, p)) <= 2) differingAtBuoys++;
    else differingElsewhere++;
  }
  console.log(
    `buoys: ${count(inApp)} pixels in the app, ${count(inShot)} in the shot, each within ${farthest} px of the other's; ` +
      `${differingAtBuoys} pixels differ at the buoys, ${differingElsewhere} elsewhere`,
  );
  expect(count(inShot)).toBeGreaterThan(100); // five floats and masts, the nearest 25 m ahead
  // Away from the buoys (2 px around them in either picture) the pictures are the same pixels.
  expect(differingElsewhere).toBe(0);
  // The app sets its buoys down on the queries' provisional copy (its workers' fields come later:
  // fftCascade.ts), the shot on the exact surface: within millimetres of each other (before the
  // provisional copy kept the coarse cascades' grids, 64² copies put them up to 12 cm apart, and
  // 70 pixels here differed). The same buoys in the same places.
  expect(Math.abs(count(inApp) - count(inShot))).toBeLessThanOrEqual(0.02 * count(inShot));
  expect(farthest).toBeLessThanOrEqual(1);
  expect(differingAtBuoys).toBeLessThan(10);
});

test("the README's picture is what npm start shows first: the app's defaults at t = 0, rendered again, match it", async ({ page }) => {
  test.setTimeout(300_000);
  const readmePicture = 'docs/features/first-view.png'; // FIRST_VIEW_FILE of scripts/make-sea-state-pictures.mjs
  expect(readFileSync(join(root, 'README.md'), 'utf8')).toContain(`](${readmePicture})`);
  const committed = rgba(join(root, readmePicture));
  // The app with no URL parameters starts at t = 0; paused, it stays on that first view. The PNG
  // the CLI writes for it, made by its page (the CLI around it: the first tests).
  const fresh = rgba(await shotPicture(page, ['--query', 'paused=1', '--size', `${committed.width}x${committed.height}`]));
  expect(await page.evaluate(() => window.shotStart!.t)).toBe(0);
  expect([fresh.width, fresh.height]).toEqual([committed.width, committed.height]);
  // As the screenshot baselines: rasterization may differ a little between Chromium builds.
  let differing = 0;
  for (let i = 0; i < fresh.data.length; i += 4) {
    const difference = Math.max(...[0, 1, 2].map((c) => Math.abs(fresh.data[i + c] - committed.data[i + c])));
    if (difference > 24) differing++;
  }
  console.log(`README picture against a fresh first view: ${differing} of ${fresh.width * fresh.height} pixels differ by more than 24 levels`);
  expect(differing / (fresh.width * fresh.height)).toBeLessThan(0.01);
});

