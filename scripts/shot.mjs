#!/usr/bin/env node
// Renders the ocean to PNG files without a screen, in headless Chromium (WebGL2 through
// SwiftShader when there is no GPU), from the built app's examples/shot.html.
//
//   npm run shot -- --seed 7 --time 12.5 --wind 12 --size 1280x720 --out ocean.png
//   npm run shot -- --seed 7 --frames 120 --fps 30 --out-dir frames/     (frame-0000.png …)
//
// Each frame is drawn at exactly its time (time + i / fps), one at a time, and read back from
// the canvas: the same arguments give the same pixels in the same browser. The app is built
// first (vite build) when dist/app is missing or older than the sources. Run with --help for
// every option.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, readdirSync, statSync, writeFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseArgs } from 'node:util';
import { serveDirectory } from './static-server.mjs';
// Playwright (and ./browser.mjs, which uses it) is imported once the arguments are known to be
// good, so a usage error is reported at once.

const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const APP_DIR = join(ROOT, 'dist', 'app');
const SHOT_PAGE = join(APP_DIR, 'examples', 'shot.html');
/** What the built app is made from: if any is newer than the build, build again. */
const SOURCES = ['src', 'shaders', 'examples', 'public', 'index.html', 'vite.config.ts', 'package.json'];

const HELP = `Usage: npm run shot -- [options]

Renders the ocean headlessly to PNG (one still, or the frames of a video).

Scene
  --seed <int>            random seed of the sea, 0 to 4294967295 (default 1)
  --time <seconds>        time of the (first) frame (default 0)
  --wind <m/s>            wind speed, 0 to 100 (default 12)
  --wind-direction <deg>  direction the wind blows towards (default 30)
  --choppiness <n>        horizontal displacement scale, >= 0 (default 1)
  --resolution <n>        simulation grid, a power of two from 16 to 1024 (default 256)
  --sun-elevation <deg>   -90 to 90 (default 22)
  --sun-azimuth <deg>     (default 40)
  --camera x,y,z,tx,ty,tz camera position and the point it looks at (default: 8 m up, towards the horizon)
  --fov <deg>             vertical field of view, 1 to 179 (default 50)

Output
  --size <W>x<H>          image size in pixels, each 1 to 8192 (default 1280x720)
  --out <file.png>        the still image (default ocean.png)
  --frames <n>            render n frames instead of one still ...
  --fps <n>               ... at this many frames per second of simulated time (default 30)
  --out-dir <dir>         ... into dir/frame-0000.png, frame-0001.png, ...
  --no-build              use dist/app as it is, even if older than the sources
  -h, --help              this text

Encode frames into a video with e.g.: ffmpeg -framerate 30 -i frames/frame-%04d.png -pix_fmt yuv420p ocean.mp4`;

class UsageError extends Error {}

/** Parses and checks the command line; throws UsageError with a message for the user. */
export function parseShotArguments(argv) {
  // parseArgs reads "--time -5" as a missing value followed by an option; negative numbers
  // (times, angles, camera coordinates, and a wrong --frames -3) are values here.
  const args = [];
  for (let i = 0; i < argv.length; i++) {
    if (/^--[a-z-]+$/.test(argv[i]) && i + 1 < argv.length && /^-[\d.]/.test(argv[i + 1])) {
      args.push(`${argv[i]}=${argv[i + 1]}`);
      i++;
    } else {
      args.push(argv[i]);
    }
  }
  let values;
  try {
    ({ values } = parseArgs({
      args,
      strict: true,
      allowPositionals: false,
      options: {
        seed: { type: 'string' },
        time: { type: 'string' },
        wind: { type: 'string' },
        'wind-direction': { type: 'string' },
        choppiness: { type: 'string' },
        resolution: { type: 'string' },
        'sun-elevation': { type: 'string' },
        'sun-azimuth': { type: 'string' },
        camera: { type: 'string' },
        fov: { type: 'string' },
        size: { type: 'string' },
        out: { type: 'string' },
        frames: { type: 'string' },
        fps: { type: 'string' },
        'out-dir': { type: 'string' },
        'no-build': { type: 'boolean' },
        help: { type: 'boolean', short: 'h' },
      },
    }));
  } catch (error) {
    throw new UsageError(error.message);
  }
  if (values.help) return { help: true };

  const number = (name, check, allowed) => {
    const raw = values[name];
    if (raw === undefined) return undefined;
    const value = raw.trim() === '' ? NaN : Number(raw);
    if (!Number.isFinite(value) || !check(value)) throw new UsageError(`--${name} must be ${allowed}; got "${raw}"`);
    return value;
  };
  const scene = {
    seed: number('seed', (v) => Number.isInteger(v) && v >= 0 && v <= 0xffffffff, 'an integer from 0 to 4294967295'),
    wind: number('wind', (v) => v >= 0 && v <= 100, 'a wind speed in m/s from 0 to 100'),
    'wind-direction': number('wind-direction', () => true, 'a number of degrees'),
    choppiness: number('choppiness', (v) => v >= 0, 'a number >= 0'),
    resolution: number(
      'resolution',
      (v) => Number.isInteger(v) && v >= 16 && v <= 1024 && (v & (v - 1)) === 0,
      'a power of two from 16 to 1024',
    ),
    'sun-elevation': number('sun-elevation', (v) => v >= -90 && v <= 90, 'a number of degrees from -90 to 90'),
    'sun-azimuth': number('sun-azimuth', () => true, 'a number of degrees'),
    fov: number('fov', (v) => v >= 1 && v <= 179, 'a number of degrees from 1 to 179'),
  };
  if (values.camera !== undefined) {
    const parts = values.camera.split(',').map((part) => (part.trim() === '' ? NaN : Number(part)));
    if (parts.length !== 6 || !parts.every(Number.isFinite)) {
      throw new UsageError(`--camera must be six numbers x,y,z,targetX,targetY,targetZ; got "${values.camera}"`);
    }
    if (parts[0] === parts[3] && parts[1] === parts[4] && parts[2] === parts[5]) {
      throw new UsageError('--camera: the camera cannot look at its own position');
    }
    scene.camera = parts.join(',');
  }

  const time = number('time', () => true, 'a finite number of seconds') ?? 0;
  let width = 1280;
  let height = 720;
  if (values.size !== undefined) {
    const match = /^(\d+)x(\d+)$/i.exec(values.size.trim());
    if (!match) throw new UsageError(`--size must be <width>x<height> in pixels, e.g. 1280x720; got "${values.size}"`);
    [width, height] = [Number(match[1]), Number(match[2])];
    for (const [name, value] of [['width', width], ['height', height]]) {
      if (value < 1 || value > 8192) throw new UsageError(`--size: the ${name} must be from 1 to 8192 pixels; got ${value}`);
    }
  }

  const video = values.frames !== undefined || values['out-dir'] !== undefined || values.fps !== undefined;
  let frames = 1;
  let fps = 30;
  if (video) {
    if (values.out !== undefined) throw new UsageError('--out is for a single still; with --frames use --out-dir');
    if (values.frames === undefined) throw new UsageError('--out-dir and --fps need --frames <count>');
    frames = number('frames', (v) => Number.isInteger(v) && v >= 1 && v <= 1_000_000, 'a whole number of frames, at least 1');
    fps = number('fps', (v) => v > 0 && v <= 1000, 'a number of frames per second above 0 (at most 1000)') ?? 30;
    if (values['out-dir'] === undefined) throw new UsageError('--frames needs --out-dir <directory> for the frame files');
  } else if (values.out !== undefined && !/\.png$/i.test(values.out)) {
    throw new UsageError(`--out must name a .png file; got "${values.out}"`);
  }
  return {
    help: false,
    scene,
    time,
    width,
    height,
    frames,
    fps,
    video,
    out: resolve(values.out ?? 'ocean.png'),
    outDir: video ? resolve(values['out-dir']) : null,
    build: !values['no-build'],
  };
}

/** Newest modification time (ms) of the files under the given paths (relative to ROOT). */
function newestSource() {
  let newest = 0;
  const visit = (path) => {
    if (!existsSync(path)) return;
    const info = statSync(path);
    if (info.isDirectory()) {
      for (const entry of readdirSync(path)) visit(join(path, entry));
    } else {
      newest = Math.max(newest, info.mtimeMs);
    }
  };
  for (const source of SOURCES) visit(join(ROOT, source));
  return newest;
}

/** Builds the app (vite build) unless dist/app is at least as new as every source file. */
export function ensureBuiltApp({ log = (line) => process.stderr.write(`${line}\n`) } = {}) {
  if (existsSync(SHOT_PAGE) && statSync(SHOT_PAGE).mtimeMs >= newestSource()) return;
  log(existsSync(SHOT_PAGE) ? 'shot: sources changed since the last build; running vite build…' : 'shot: dist/app is missing; running vite build…');
  const vite = join(ROOT, 'node_modules', 'vite', 'bin', 'vite.js');
  const result = spawnSync(process.execPath, [vite, 'build', '--logLevel', 'warn'], { cwd: ROOT, stdio: ['ignore', 2, 2] });
  if (result.status !== 0 || !existsSync(SHOT_PAGE)) throw new Error('vite build failed (see above)');
}

function frameName(index, count) {
  return `frame-${String(index).padStart(Math.max(4, String(count - 1).length), '0')}.png`;
}

async function main() {
  let options;
  try {
    options = parseShotArguments(process.argv.slice(2));
  } catch (error) {
    if (!(error instanceof UsageError)) throw error;
    process.stderr.write(`shot: ${error.message}\nRun with --help for the options.\n`);
    return 2;
  }
  if (options.help) {
    process.stdout.write(`${HELP}\n`);
    return 0;
  }

  const { chromium } = await import('@playwright/test');
  const { BROWSER_ARGS, BROWSER_ENV_VARS, findBrowser } = await import('./browser.mjs');
  const executablePath = findBrowser();
  if (!executablePath) {
    process.stderr.write(
      `shot: no Chromium found. Install one (npm run test:browser does, see scripts/ensure-browser.mjs) or set ${BROWSER_ENV_VARS.join(' or ')}.\n`,
    );
    return 1;
  }
  if (options.build) ensureBuiltApp();
  else if (!existsSync(SHOT_PAGE)) {
    process.stderr.write('shot: dist/app/examples/shot.html is missing; run without --no-build (or npm run build).\n');
    return 1;
  }
  if (options.outDir) mkdirSync(options.outDir, { recursive: true });
  else mkdirSync(dirname(options.out), { recursive: true });

  const server = await serveDirectory(APP_DIR);
  const browser = await chromium.launch({ executablePath, args: BROWSER_ARGS });
  try {
    const page = await browser.newPage({ viewport: { width: 320, height: 180 }, deviceScaleFactor: 1 });
    const pageErrors = [];
    page.on('pageerror', (error) => pageErrors.push(error.message));
    page.on('console', (message) => {
      if (message.type() === 'error') pageErrors.push(message.text());
    });
    const query = new URLSearchParams({ width: String(options.width), height: String(options.height), t: String(options.time) });
    for (const [name, value] of Object.entries(options.scene)) if (value !== undefined) query.set(name, String(value));
    await page.goto(`${server.url}/examples/shot.html?${query}`);
    await page.waitForFunction(() => document.title === 'ready' || document.title.startsWith('error'), null, { timeout: 180_000 });
    const title = await page.title();
    if (title !== 'ready') throw new Error(`the page could not render: ${title.replace(/^error: /, '')}`);
    if (pageErrors.length > 0) throw new Error(`the page reported: ${pageErrors.join(' | ')}`);

    const capture = (t) =>
      page.evaluate(async (time) => {
        await window.renderFrame(time);
        return document.querySelector('canvas').toDataURL('image/png');
      }, t);
    const write = async (t, file) => {
      const dataUrl = await capture(t);
      writeFileSync(file, Buffer.from(dataUrl.slice(dataUrl.indexOf(',') + 1), 'base64'));
    };
    if (!options.video) {
      await write(options.time, options.out);
      process.stderr.write(`shot: wrote ${options.out} (${options.width}x${options.height}, t = ${options.time} s)\n`);
    } else {
      const tty = process.stderr.isTTY;
      for (let i = 0; i < options.frames; i++) {
        await write(options.time + i / options.fps, join(options.outDir, frameName(i, options.frames)));
        const line = `frame ${i + 1}/${options.frames}`;
        process.stderr.write(tty ? `\r${line}` : `${line}\n`);
      }
      if (tty) process.stderr.write('\n');
      process.stderr.write(`shot: wrote ${options.frames} frames to ${options.outDir} (${options.width}x${options.height}, ${options.fps} fps)\n`);
    }
    if (pageErrors.length > 0) throw new Error(`the page reported: ${pageErrors.join(' | ')}`);
    return 0;
  } finally {
    await browser.close();
    await server.close();
  }
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  main().then(
    (code) => process.exit(code),
    (error) => {
      process.stderr.write(`shot: ${error instanceof Error ? error.message : String(error)}\n`);
      process.exit(1);
    },
  );
}
