#!/usr/bin/env node
// Renders the ocean to PNG files without a screen, in headless Chromium (WebGL2 through
// SwiftShader when there is no GPU), from the built app's examples/shot.html.
//
//   npm run shot -- --seed 7 --time 12.5 --wind-speed 12 --size 1280x720 --out ocean.png
//   npm run shot -- --spectrum tma --depth 8 --patch-sizes 13.7,79.3,457 --shading-mode fresnel
//   npm run shot -- --seed 7 --frames 120 --fps 30 --out-dir frames/     (frame-0000.png …)
//   npm run shot -- --size 1280x720 --query "windSpeed=14&paused=1&t=3.2&cam=0,12,0,-53.13,-6.84"
//
// This script checks only its own options (--size, --out, --frames, --fps, --out-dir, --time,
// --camera, --fov, --query, --no-build, --help). Every other --option (the sea, the sun, the
// shading, --path, --skybox …) goes to the page as it was written: examples/shot.ts reads it with
// the same tables the app uses (src/parameters/), so there is no second copy of any rule here, and
// a bad or unknown one comes back as the page's 'error: …' title (exit code 2). --help asks the
// page for that list too. --query renders an app link's scene as the app does (the same parseState,
// camera, time, shading, sky, renderer and lens): the PNG is the app's canvas at that size.
//
// Each frame is drawn at exactly its time (time + i / fps; from a link, t + i × timeScale / fps),
// one at a time, and read back from the canvas: the same arguments give the same pixels in the
// same browser. The app is built first (vite build) when dist/app is missing or older than the
// sources. Exit codes: 0 done, 1 failure (no browser, build or WebGL trouble), 2 usage error.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, readdirSync, statSync, writeFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { serveDirectory } from './static-server.mjs';
// Playwright (and ./browser.mjs, which uses it) is imported once the arguments are known to be
// good, so a usage error is reported at once.

const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const APP_DIR = join(ROOT, 'dist', 'app');
const SHOT_PAGE = join(APP_DIR, 'examples', 'shot.html');
/** What the built app is made from: if any is newer than the build, build again. */
const SOURCES = ['src', 'shaders', 'examples', 'public', 'index.html', 'vite.config.ts', 'package.json'];

/** This script's own options: they take a value. */
const OWN_OPTIONS = ['size', 'out', 'frames', 'fps', 'out-dir', 'time', 'camera', 'fov', 'query'];
/** This script's own options that take none. */
const OWN_FLAGS = ['no-build', 'help'];

const HELP = `Usage: npm run shot -- [options]

Renders the ocean headlessly to PNG (one still, or the frames of a video), drawn as the app draws it.

Picture
  --time <seconds>        time of the (first) frame (default 0)
  --camera x,y,z,tx,ty,tz camera position and the point it looks at (default: the app's camera,
                          see --cam below)
  --fov <deg>             vertical field of view, 1 to 179 (default the app's, 55)
  --query "<query>"       the scene of an app link: what follows "?" in the app's address (or the
                          whole link), e.g. --query "windSpeed=14&paused=1&t=3.2&cam=0,12,0,-53,-7".
                          The PNG is what the app's canvas shows at the same --size (its camera, t,
                          shading, sky); not together with --time, --camera, --fov or scene options.
                          A link the app would warn about is an error here.

Output
  --size <W>x<H>          image size in pixels, each 1 to 8192 (default 1280x720)
  --out <file.png>        the still image (default ocean.png)
  --frames <n>            render n frames instead of one still ...
  --fps <n>               ... at this many frames per second of simulated time (default 30)
  --out-dir <dir>         ... into dir/frame-0000.png, frame-0001.png, ...
  --no-build              use dist/app as it is, even if older than the sources
  -h, --help              this text

Scene options (--<name> <value>, or --<name>=<value>) are the app's URL parameters in kebab-case,
read by the page with the library's own rules; their defaults are the app's. Older names still
work: --wind is --wind-speed.`;

const HELP_END = `
Encode frames into a video with e.g.: ffmpeg -framerate 30 -i frames/frame-%04d.png -pix_fmt yuv420p ocean.mp4
Exit codes: 0 done, 1 failure (no browser, the build, WebGL), 2 usage error (a bad or unknown option).`;

export class UsageError extends Error {}

/**
 * Splits the command line into this script's options and the scene options for the page (kept
 * in order, as written); checks this script's own. Throws UsageError with a message for the user.
 */
export function parseShotArguments(argv) {
  const values = {};
  const scene = [];
  for (let i = 0; i < argv.length; i++) {
    const arg = argv[i];
    if (arg === '-h') {
      values.help = true;
      continue;
    }
    const match = /^--([^=]+)(?:=([\s\S]*))?$/.exec(arg);
    if (!match) throw new UsageError(`unexpected argument "${arg}": options start with --`);
    const name = match[1];
    let value = match[2];
    if (OWN_FLAGS.includes(name)) {
      if (value !== undefined) throw new UsageError(`--${name} takes no value`);
      values[name] = true;
      continue;
    }
    // The next word is the value unless it is another option. Negative numbers ("--time -5",
    // "--sun-elevation -10") are values.
    if (value === undefined && i + 1 < argv.length && !argv[i + 1].startsWith('--') && argv[i + 1] !== '-h') value = argv[++i];
    if (OWN_OPTIONS.includes(name)) {
      if (value === undefined) throw new UsageError(`--${name} needs a value`);
      if (Object.hasOwn(values, name)) throw new UsageError(`--${name} is given twice`);
      values[name] = value;
    } else {
      // A flag of the page's (--wireframe) may come without a value: '' then.
      scene.push([name, value ?? '']);
    }
  }
  if (values.help) return { help: true, build: !values['no-build'] };

  const number = (name, check, allowed) => {
    const raw = values[name];
    if (raw === undefined) return undefined;
    const value = raw.trim() === '' ? NaN : Number(raw);
    if (!Number.isFinite(value) || !check(value)) throw new UsageError(`--${name} must be ${allowed}; got "${raw}"`);
    return value;
  };
  const fov = number('fov', (v) => v >= 1 && v <= 179, 'a number of degrees from 1 to 179');
  let camera;
  if (values.camera !== undefined) {
    const parts = values.camera.split(',').map((part) => (part.trim() === '' ? NaN : Number(part)));
    if (parts.length !== 6 || !parts.every(Number.isFinite)) {
      throw new UsageError(`--camera must be six numbers x,y,z,targetX,targetY,targetZ; got "${values.camera}"`);
    }
    if (parts[0] === parts[3] && parts[1] === parts[4] && parts[2] === parts[5]) {
      throw new UsageError('--camera: the camera cannot look at its own position');
    }
    camera = parts.join(',');
  }
  const time = number('time', () => true, 'a finite number of seconds');

  let query;
  if (values.query !== undefined) {
    const clash = ['time', 'camera', 'fov'].filter((name) => values[name] !== undefined).map((name) => `--${name}`);
    clash.push(...scene.map(([name]) => `--${name}`));
    if (clash.length > 0) {
      throw new UsageError(`--query is the whole scene of an app link: put ${clash.join(', ')} into it instead (as the app's URL names them: t=, cam=, windSpeed=, …)`);
    }
    // A whole link, or just its query (with or without "?"); the #fragment is not part of it.
    query = values.query.replace(/#[\s\S]*$/, '');
    if (query.includes('?')) query = query.slice(query.indexOf('?') + 1);
  }

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
    query,
    camera,
    fov,
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

/** The page's query for `options`: the size, this script's scene settings, and the scene options as written. */
export function pageQuery(options) {
  const query = new URLSearchParams({ width: String(options.width), height: String(options.height) });
  if (options.query !== undefined) {
    query.set('query', options.query);
  } else {
    if (options.time !== undefined) query.set('time', String(options.time));
    if (options.camera !== undefined) query.set('camera', options.camera);
    if (options.fov !== undefined) query.set('fov', String(options.fov));
    for (const [name, value] of options.scene) query.append(`--${name}`, value);
  }
  query.set('cli', [...OWN_OPTIONS, ...OWN_FLAGS].join(','));
  return query;
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

/** A failure that is not the user's (no browser, the build): exit code 1. */
class ShotFailure extends Error {}

/**
 * Opens the built app's shot page with `query` in headless Chromium, waits until its title says
 * it is done ('ready', 'help' or 'error: …'), and calls use(page, pageErrors). A page error of
 * kind 'usage' (a bad or unknown option, a bad query) throws UsageError, any other ShotFailure.
 */
async function withShotPage({ build }, query, use) {
  const { chromium } = await import('@playwright/test');
  const { BROWSER_ARGS, BROWSER_ENV_VARS, findBrowser } = await import('./browser.mjs');
  const executablePath = findBrowser();
  if (!executablePath) {
    throw new ShotFailure(`no Chromium found. Install one (npm run test:browser does, see scripts/ensure-browser.mjs) or set ${BROWSER_ENV_VARS.join(' or ')}.`);
  }
  if (build) ensureBuiltApp();
  else if (!existsSync(SHOT_PAGE)) throw new ShotFailure('dist/app/examples/shot.html is missing; run without --no-build (or npm run build).');

  const server = await serveDirectory(APP_DIR);
  const browser = await chromium.launch({ executablePath, args: BROWSER_ARGS });
  try {
    // The canvas has its own size (--size, at pixel ratio 1); a small viewport is cheaper to composite.
    const page = await browser.newPage({ viewport: { width: 320, height: 180 }, deviceScaleFactor: 1 });
    const pageErrors = [];
    page.on('pageerror', (error) => pageErrors.push(error.message));
    page.on('console', (message) => {
      if (message.type() === 'error') pageErrors.push(message.text());
    });
    // Not waiting for 'load': the page builds the sea before it, which on a busy machine takes longer
    // than goto's 30 s; the title says when it is done (below, with its own time limit).
    await page.goto(`${server.url}/examples/shot.html?${query}`, { waitUntil: 'commit' });
    await page.waitForFunction(() => ['ready', 'help'].includes(document.title) || document.title.startsWith('error'), null, { timeout: 180_000 });
    const title = await page.title();
    if (title.startsWith('error')) {
      const { kind, message } = await page.evaluate(() => ({ kind: window.shotErrorKind, message: window.shotError }));
      if (kind === 'usage') throw new UsageError(message);
      throw new ShotFailure(`the page could not render: ${message ?? title.replace(/^error: /, '')}`);
    }
    if (pageErrors.length > 0) throw new ShotFailure(`the page reported: ${pageErrors.join(' | ')}`);
    return await use(page, pageErrors);
  } finally {
    await browser.close();
    await server.close();
  }
}

/** The scene options' part of --help, which the page writes from the option tables. */
function sceneHelp(build) {
  return withShotPage({ build }, new URLSearchParams({ help: '1' }), (page) => page.evaluate(() => window.shotHelp));
}

async function render(options) {
  if (options.outDir) mkdirSync(options.outDir, { recursive: true });
  else mkdirSync(dirname(options.out), { recursive: true });
  await withShotPage(options, pageQuery(options), async (page, pageErrors) => {
    const capture = (t) =>
      page.evaluate(async (time) => {
        await window.renderFrame(time);
        return document.querySelector('canvas').toDataURL('image/png');
      }, t);
    const write = async (t, file) => {
      const dataUrl = await capture(t);
      writeFileSync(file, Buffer.from(dataUrl.slice(dataUrl.indexOf(',') + 1), 'base64'));
    };
    // The first frame's time and how fast time runs: --time, or a link's t and timeScale.
    const start = await page.evaluate(() => window.shotStart);
    if (!options.video) {
      await write(start.t, options.out);
      process.stderr.write(`shot: wrote ${options.out} (${options.width}x${options.height}, t = ${start.t} s)\n`);
    } else {
      const tty = process.stderr.isTTY;
      for (let i = 0; i < options.frames; i++) {
        await write(start.t + (i * start.timeScale) / options.fps, join(options.outDir, frameName(i, options.frames)));
        const line = `frame ${i + 1}/${options.frames}`;
        process.stderr.write(tty ? `\r${line}` : `${line}\n`);
      }
      if (tty) process.stderr.write('\n');
      process.stderr.write(`shot: wrote ${options.frames} frames to ${options.outDir} (${options.width}x${options.height}, ${options.fps} fps)\n`);
    }
    if (pageErrors.length > 0) throw new ShotFailure(`the page reported: ${pageErrors.join(' | ')}`);
  });
}

async function main() {
  try {
    const options = parseShotArguments(process.argv.slice(2));
    if (options.help) {
      process.stdout.write(`${HELP}\n\n`);
      try {
        process.stdout.write(`${await sceneHelp(options.build)}\n`);
      } catch (error) {
        process.stdout.write(
          `(The scene options could not be listed: ${error.message}\n They are the keys of SIMULATION_OPTIONS, SUN_OPTIONS and SHADING_OPTIONS in src/parameters/, in kebab-case.)\n`,
        );
      }
      process.stdout.write(`${HELP_END}\n`);
      return 0;
    }
    await render(options);
    return 0;
  } catch (error) {
    if (error instanceof UsageError) {
      process.stderr.write(`shot: ${error.message}\nRun with --help for the options.\n`);
      return 2;
    }
    if (error instanceof ShotFailure) {
      process.stderr.write(`shot: ${error.message}\n`);
      return 1;
    }
    throw error;
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
