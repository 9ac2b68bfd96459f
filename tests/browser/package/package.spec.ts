import { chromium, expect, test, type Page } from '@playwright/test';
import { execFileSync } from 'node:child_process';
import { copyFileSync, existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, relative, resolve } from 'node:path';
import { PNG } from 'pngjs';
import { serveDirectory } from '../../../scripts/static-server.mjs';
import { ensureBuiltLibrary } from '../shared/builtLibrary';
import { WEBGPU_BROWSER } from '../shared/webgpuBrowser';

// What a new user gets (issue 11, "Done when"): the library packed as npm publishes it (`npm pack`
// of dist/lib as prepack builds it), installed with three into a new project outside the repository,
// the README's Quick start page and main.js copied into it verbatim, built with vite, served as
// plain files and opened in headless Chromium. Its picture must be the app's first view: the same
// camera, renderer settings and sea at the same time give the same pixels. The README's WebGPU
// quick start (three-fft-ocean/webgpu on WebGPURenderer) is built in the same project and must
// draw the sea on both of WebGPURenderer's backends (issue 23).

const repo = resolve(import.meta.dirname, '../../..');
/** The three.js the repository develops against: the one the new project installs. */
const threeVersion: string = JSON.parse(readFileSync(join(repo, 'package.json'), 'utf8')).devDependencies.three;
const SIZE = { width: 480, height: 270 }; // small: SwiftShader draws every pixel on the CPU
/** The simulation time of both pictures, seconds: a whole number of milliseconds, as an app link holds it. */
const FRAME_MS = 2500;

/** The fenced block of README.md that follows `<!-- quick-start: name -->`, as a user would copy it. */
function quickStartFile(readme: string, name: string): string {
  const marker = `<!-- quick-start: ${name} -->`;
  const match = new RegExp(`${marker.replace(/[.*+?^${}()|[\]\\]/g, '\\$&')}\\n\`\`\`\\w*\\n([\\s\\S]*?)\\n\`\`\`\\n`).exec(readme);
  if (!match) throw new Error(`README.md has no fenced block after ${marker}`);
  return `${match[1]}\n`;
}

function run(command: string, args: string[], cwd: string): string {
  return execFileSync(command, args, { cwd, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
}

/** Every file under `dir`, as paths relative to it with '/' separators. */
function listFiles(dir: string): string[] {
  return readdirSync(dir, { recursive: true, encoding: 'utf8' })
    .filter((path) => statSync(join(dir, path)).isFile())
    .map((path) => path.split('\\').join('/'));
}

/**
 * Every `sourceMappingURL=` in the .js files under `dir` whose file is not under `dir` ("file →
 * map" texts). A map a consumer's site does not have is a 404 in their devtools.
 */
function missingSourceMaps(dir: string): string[] {
  const missing: string[] = [];
  for (const file of listFiles(dir).filter((path) => path.endsWith('.js'))) {
    for (const [, url] of readFileSync(join(dir, file), 'utf8').matchAll(/[#@] sourceMappingURL=(\S+)/g)) {
      if (url.startsWith('data:')) continue;
      const map = resolve(dirname(join(dir, file)), url);
      if (relative(dir, map).startsWith('..') || !existsSync(map)) missing.push(`${file} → ${url}`);
    }
  }
  return missing;
}

interface Picture {
  width: number;
  height: number;
  /** RGBA, top row first. */
  data: Uint8Array;
}

async function screenshot(page: Page): Promise<Picture> {
  const png = PNG.sync.read(await page.locator('canvas').first().screenshot());
  return { width: png.width, height: png.height, data: new Uint8Array(png.data) };
}

/** Mean R, G, B of the rows [from, to) of a picture. */
function meanColour({ width, data }: Picture, from: number, to: number): [number, number, number] {
  const sum = [0, 0, 0];
  for (let i = from * width; i < to * width; i++) for (let c = 0; c < 3; c++) sum[c] += data[4 * i + c];
  return sum.map((value) => value / ((to - from) * width)) as [number, number, number];
}

/**
 * Page errors, console errors and failed requests from now on. The browser's own request for
 * /favicon.ico (the quick start page has none, like most new projects) is not the library's.
 */
function watchProblems(page: Page): string[] {
  const problems: string[] = [];
  page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
  page.on('response', (response) => {
    const path = new URL(response.url()).pathname;
    if (response.status() >= 400 && path !== '/favicon.ico') problems.push(`HTTP ${response.status()}: ${path}`);
  });
  page.on('console', (message) => {
    // A failed request's console line has no URL; the response listener names it.
    if (message.type() === 'error' && !message.text().startsWith('Failed to load resource')) problems.push(`console: ${message.text()}`);
  });
  return problems;
}

let workDir: string | undefined;
let packed: string | undefined;
test.afterAll(() => {
  if (workDir) rmSync(workDir, { recursive: true, force: true });
});

/** The folder this file's projects and tarball live in (removed after the tests). */
function work(): string {
  workDir ??= mkdtempSync(join(tmpdir(), 'three-fft-ocean-package-'));
  return workDir;
}

/**
 * The library packed as npm publishes it (only `files` of package.json are in it), once per run.
 * npm's prepack would run `npm run build:lib`; ensureBuiltLibrary runs that very build, unless
 * dist/lib is newer than every source (the examples spec builds it too), and the pack skips the
 * second build.
 */
function tarball(): string {
  if (packed) return packed;
  expect(JSON.parse(readFileSync(join(repo, 'package.json'), 'utf8')).scripts.prepack, 'the build npm pack runs').toBe('npm run build:lib');
  ensureBuiltLibrary();
  run('npm', ['pack', '--silent', '--ignore-scripts', '--pack-destination', work()], repo);
  const name = readdirSync(work()).find((file) => file.endsWith('.tgz'));
  if (!name) throw new Error('npm pack wrote no tarball');
  packed = join(work(), name);
  return packed;
}

/** A new project (folder `name` of the work folder) with `packages` installed: from npm's cache when they are there, else from the registry. */
function newProject(name: string, packages: string[]): string {
  const project = join(work(), name);
  mkdirSync(project);
  writeFileSync(join(project, 'package.json'), JSON.stringify({ name, private: true, type: 'module' }, null, 2));
  const install = ['install', '--no-audit', '--no-fund', '--no-save', ...packages];
  try {
    run('npm', [...install, '--offline'], project); // from npm's cache: no network when all is there
  } catch {
    console.log(`package.spec: ${packages.filter((p) => !p.endsWith('.tgz')).join(', ')} not all in npm's cache; installing from the registry`);
    run('npm', [...install, '--prefer-offline'], project);
  }
  return project;
}

let quickStart: string | undefined;
/** The project the README's quick starts are built in: the tarball and three, installed once for both tests. */
function quickStartProject(): string {
  quickStart ??= newProject('quick-start', [tarball(), `three@${threeVersion}`]);
  return quickStart;
}

test("the packed library in a new vite project: the README's Quick start shows the app's first view", async ({ page, browser }) => {
  test.setTimeout(180_000); // pack (the library built if stale), install, build, two pages: about 60 s here, more on a busy machine
  let project = '';

  await test.step('npm pack', () => {
    expect(tarball(), 'the tarball npm pack wrote').toMatch(/\.tgz$/);
  });

  await test.step('install the tarball and three into a new project', () => {
    project = quickStartProject();
    expect(JSON.parse(readFileSync(join(project, 'node_modules/three/package.json'), 'utf8')).version).toBe(threeVersion);
  });

  // The installed package is the tarball's content: no file in it names a source map it lacks.
  const installed = join(project, 'node_modules/three-fft-ocean');
  expect(listFiles(installed).filter((path) => path.endsWith('.js')).length, 'library files in the tarball').toBeGreaterThan(2);
  expect(missingSourceMaps(installed), 'source maps named in the tarball but not in it').toEqual([]);
  // The README's pictures are in it too, so that they show on the registry's page of the package;
  // and so are the guide's pages (docs/*.md, which the README links to) with their pictures.
  const pictures = (page: string) =>
    [...readFileSync(join(installed, page), 'utf8').matchAll(/!\[[^\]]*\]\(([^)\s]+)\)/g)].map((match) => join(dirname(page), match[1]));
  const readmeImages = pictures('README.md');
  expect(readmeImages.length, 'pictures in the README').toBeGreaterThan(10);
  expect(readmeImages.filter((path) => !existsSync(join(installed, path))), 'README pictures missing from the tarball').toEqual([]);
  const guidePages = readdirSync(join(repo, 'docs')).filter((name) => name.endsWith('.md')).map((name) => `docs/${name}`);
  expect(guidePages.filter((page) => !existsSync(join(installed, page))), 'guide pages missing from the tarball').toEqual([]);
  const guideImages = guidePages.flatMap(pictures);
  expect(guideImages.filter((path) => !existsSync(join(installed, path))), 'guide pictures missing from the tarball').toEqual([]);

  await test.step("build the README's quick start with vite", () => {
    const readme = readFileSync(join(repo, 'README.md'), 'utf8');
    writeFileSync(join(project, 'index.html'), quickStartFile(readme, 'index.html'));
    writeFileSync(join(project, 'main.js'), quickStartFile(readme, 'main.js'));
    run(join(repo, 'node_modules/.bin/vite'), ['build', project, '--logLevel', 'error'], project);
  });
  const site = join(project, 'dist');
  // The user's build copies the library's worker as it is: it must not name a map left behind.
  expect(listFiles(site).some((path) => /waveFieldWorker-.*\.js$/.test(path)), "the library's worker in the build").toBe(true);
  expect(missingSourceMaps(site), "source maps named in the user's build but not in it").toEqual([]);

  const server = await serveDirectory(site);
  try {
    // The quick start's clock is Playwright's, stopped: its animation loop draws one frame, at
    // FRAME_MS (the first time the clock moves), so the time of its picture is known.
    await page.setViewportSize(SIZE);
    await page.clock.install({ time: 0 });
    await page.clock.pauseAt(1000);
    // Count the animation frames that run and remember the time they are given (that of the
    // fake performance.now()); this runs after the clock has replaced requestAnimationFrame.
    await page.addInitScript(() => {
      const state = { frames: 0, lastMs: -1 };
      Object.assign(window, { quickStartFrames: state });
      const original = window.requestAnimationFrame.bind(window);
      window.requestAnimationFrame = (callback) =>
        original((ms) => {
          state.frames++;
          state.lastMs = ms;
          callback(ms);
        });
    });
    const problems = watchProblems(page);
    await page.goto(`${server.url}/`);
    await page.waitForFunction(() => document.querySelector('canvas') !== null);
    // Jump to FRAME_MS: the frame the loop waits for is due, and runs once.
    const now = await page.evaluate(() => performance.now());
    expect(now).toBeLessThan(FRAME_MS);
    await page.clock.fastForward(FRAME_MS - now);
    const frame = await page.evaluate(() => (window as unknown as { quickStartFrames: { frames: number; lastMs: number } }).quickStartFrames);
    expect(frame, 'the frames the quick start drew').toEqual({ frames: 1, lastMs: FRAME_MS });
    const t = frame.lastMs / 1000;
    const quickStart = await screenshot(page);
    expect(problems, 'errors on the quick start page').toEqual([]);

    // The app's first view (the dev server's index.html, all defaults) at the same time, paused.
    const appPage = await browser.newPage({ viewport: SIZE });
    try {
      const appProblems = watchProblems(appPage);
      await appPage.goto(`/?t=${t}&paused=1&quality=high`); // the first view: quality is not yet adapted
      await appPage.waitForFunction(() => window.oceanApp !== undefined);
      // Hide what lies over the canvas (status line, panel) and let two frames draw.
      await appPage.addStyleTag({ content: 'body > :not(#app), #app > :not(canvas) { display: none !important; }' });
      await appPage.evaluate(() => window.oceanApp.capturePixels());
      await appPage.evaluate(() => window.oceanApp.capturePixels());
      const app = await screenshot(appPage);
      expect(appProblems, 'errors on the app page').toEqual([]);

      expect([quickStart.width, quickStart.height]).toEqual([app.width, app.height]);
      const { width, height } = app;
      // A sea under a sky: bright sky at the top, bluer than red, darker water at the bottom.
      const sky = meanColour(quickStart, 0, Math.round(height / 10));
      const sea = meanColour(quickStart, Math.round((height * 3) / 4), height);
      expect(sky[2], 'the sky at the top').toBeGreaterThan(120);
      expect(sea[2], 'the sea is blue').toBeGreaterThan(sea[0] + 10);
      expect(sky[0] + sky[1] + sky[2], 'the sky brighter than the sea').toBeGreaterThan(sea[0] + sea[1] + sea[2] + 30);
      // The same picture: per pixel and channel, the mean difference and how many differ visibly.
      let sum = 0;
      let visible = 0;
      for (let i = 0; i < width * height; i++) {
        let largest = 0;
        for (let c = 0; c < 3; c++) {
          const difference = Math.abs(quickStart.data[4 * i + c] - app.data[4 * i + c]);
          sum += difference;
          largest = Math.max(largest, difference);
        }
        if (largest > 16) visible++;
      }
      console.log(`package.spec: t = ${t} s; mean |difference| ${(sum / (3 * width * height)).toFixed(3)}, pixels off by > 16: ${visible}`);
      expect(sum / (3 * width * height), 'mean difference from the app, per channel').toBeLessThan(1);
      expect(visible / (width * height), 'pixels visibly different from the app').toBeLessThan(0.002); // measured: 23 of 129 600 (0.02 %)
    } finally {
      await appPage.close();
    }
  } finally {
    await server.close();
  }
});

/**
 * Runs in the page before its scripts (page.addInitScript): hands three's WebGPU backend a texture
 * of the canvas's size and format in place of the canvas's own (GPUCanvasContext's configure and
 * getCurrentTexture), and gives the page `readCanvasTexture()`, which copies it back, RGBA rows
 * from the top, or null before the first frame. Headless SwiftShader drops its WebGPU instance
 * once a frame is presented to a canvas (../shared/BROWSER.md; here "Instance dropped in
 * popErrorScope" and a white canvas): so nothing is presented, and what the quick start drew, the
 * whole of WebGPURenderer's output to the canvas with its tone mapping and colour space, is read
 * back from that texture instead, as tests/browser/webgpu reads back its render targets.
 */
function drawCanvasIntoReadableTexture(): void {
  const { GPUTextureUsage, GPUBufferUsage, GPUMapMode } = globalThis as unknown as Record<'GPUTextureUsage' | 'GPUBufferUsage' | 'GPUMapMode', Record<string, number>>;
  let configuration: GPUCanvasConfiguration | null = null;
  let texture: GPUTexture | null = null;
  GPUCanvasContext.prototype.configure = function (given: GPUCanvasConfiguration) {
    configuration = given;
  };
  GPUCanvasContext.prototype.getCurrentTexture = function (this: GPUCanvasContext) {
    if (!configuration) throw new Error('getCurrentTexture before configure');
    const { width, height } = this.canvas;
    if (!texture || texture.width !== width || texture.height !== height) {
      texture?.destroy();
      const usage = (configuration.usage ?? GPUTextureUsage.RENDER_ATTACHMENT) | GPUTextureUsage.COPY_SRC;
      texture = configuration.device.createTexture({ size: [width, height], format: configuration.format, usage });
    }
    return texture;
  };
  const readCanvasTexture = async () => {
    if (!configuration || !texture) return null;
    const { device, format } = configuration;
    const { width, height } = texture;
    const bytesPerRow = Math.ceil((4 * width) / 256) * 256; // copyTextureToBuffer's row alignment
    const buffer = device.createBuffer({ size: bytesPerRow * height, usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ });
    const encoder = device.createCommandEncoder();
    encoder.copyTextureToBuffer({ texture }, { buffer, bytesPerRow }, [width, height]);
    device.queue.submit([encoder.finish()]);
    await buffer.mapAsync(GPUMapMode.READ);
    const bytes = new Uint8Array(buffer.getMappedRange());
    const [r, b] = format === 'bgra8unorm' ? [2, 0] : [0, 2];
    const data: number[] = [];
    for (let row = 0; row < height; row++) {
      for (let i = row * bytesPerRow; i < row * bytesPerRow + 4 * width; i += 4) data.push(bytes[i + r], bytes[i + 1], bytes[i + b], bytes[i + 3]);
    }
    buffer.destroy();
    return { width, height, data };
  };
  Object.assign(window, { readCanvasTexture });
}

/**
 * How much the sea near the camera (the picture's lower half) varies from pixel to pixel: the mean
 * |difference| of the green channel between horizontal neighbours. The JS FFT's worker has not
 * delivered fields for the first frames, which show a flat sea.
 */
function waviness({ width, height, data }: Picture): number {
  let sum = 0;
  for (let y = Math.round(height / 2); y < height; y++) for (let x = 1; x < width; x++) sum += Math.abs(data[4 * (y * width + x) + 1] - data[4 * (y * width + x - 1) + 1]);
  return sum / ((height - Math.round(height / 2)) * (width - 1));
}

/**
 * Opens the quick start's `url` with Playwright's clock stopped, lets its animation loop draw frames
 * from FRAME_MS on, one a poll, until its sea has waves (the worker's fields arrived), and returns
 * that picture as `capture` takes it and the page's problems.
 */
async function drawUntilWaves(page: Page, url: string, capture: () => Promise<Picture | null>): Promise<{ picture: Picture; problems: string[] }> {
  await page.clock.install({ time: 0 });
  await page.clock.pauseAt(1000);
  const problems = watchProblems(page);
  await page.goto(url);
  await page.waitForFunction(() => document.querySelector('canvas') !== null);
  await page.clock.fastForward(FRAME_MS - (await page.evaluate(() => performance.now())));
  let picture: Picture | null = null;
  await expect
    .poll(async () => {
      await page.clock.runFor(17); // one more frame
      picture = await capture();
      return picture ? waviness(picture) : 0;
    }, { timeout: 60_000, message: 'waves on the sea near the camera' })
    .toBeGreaterThan(WAVY);
  return { picture: picture!, problems };
}

/**
 * The waviness (above) a sea with waves exceeds. Measured at 480×270: the quick start's first
 * frame, before the worker's fields, 0.31 (without tone mapping); with waves 3.26 (WebGL2 backend)
 * and 3.31 (WebGPU backend).
 */
const WAVY = 1.5;

test("the packed library's three-fft-ocean/webgpu in the same project: the README's WebGPU quick start draws the sea on WebGPURenderer's two backends", async ({ page }) => {
  test.setTimeout(180_000);
  const project = join(quickStartProject(), 'webgpu'); // the first test's project: its packages, installed once
  await test.step("build the README's WebGPU quick start with vite", () => {
    const readme = readFileSync(join(repo, 'README.md'), 'utf8');
    mkdirSync(project, { recursive: true });
    writeFileSync(join(project, 'index.html'), quickStartFile(readme, 'index.html'));
    writeFileSync(join(project, 'main.js'), quickStartFile(readme, 'webgpu/main.js'));
    run(join(repo, 'node_modules/.bin/vite'), ['build', project, '--logLevel', 'error'], project);
  });
  const server = await serveDirectory(join(project, 'dist'));
  const webgpuBrowser = await chromium.launch(WEBGPU_BROWSER.launchOptions);
  try {
    // WebGL2: the test's own Chromium has no WebGPU adapter (no --enable-unsafe-webgpu), so
    // WebGPURenderer falls back to its WebGL2 backend, the backend forceWebGL: true makes; the canvas is drawn and shown.
    await page.setViewportSize(SIZE);
    const webgl = await drawUntilWaves(page, `${server.url}/`, () => screenshot(page));
    expect(await page.evaluate(() => document.querySelector('canvas')!.getContext('webgl2') !== null), 'a WebGL2 canvas').toBe(true);
    // WebGPU: SwiftShader's adapter, read back from the texture the canvas would present.
    const webgpuPage = await webgpuBrowser.newPage({ viewport: SIZE });
    await webgpuPage.addInitScript(drawCanvasIntoReadableTexture);
    const readBack = () => webgpuPage.evaluate(() => (window as unknown as { readCanvasTexture: () => Promise<{ width: number; height: number; data: number[] } | null> }).readCanvasTexture());
    const webgpu = await drawUntilWaves(webgpuPage, `${server.url}/`, async () => {
      const read = await readBack();
      return read && { ...read, data: new Uint8Array(read.data) };
    });
    const bandMeans: Record<string, [number, number, number][]> = {};
    for (const [backend, { picture, problems }] of Object.entries({ webgl2: webgl, webgpu })) {
      const png = new PNG({ width: picture.width, height: picture.height });
      png.data = Buffer.from(picture.data);
      writeFileSync(test.info().outputPath(`webgpu-quick-start-${backend}.png`), PNG.sync.write(png));
      expect(problems, `errors on the ${backend} page`).toEqual([]);
      expect([picture.width, picture.height], `the ${backend} picture's size`).toEqual([SIZE.width, SIZE.height]);
      const { height } = picture;
      const sky = meanColour(picture, 0, Math.round(height / 10));
      const sea = meanColour(picture, Math.round((height * 3) / 4), height);
      expect(sky[2], `${backend}: the sky at the top`).toBeGreaterThan(120);
      expect(sea[2], `${backend}: the sea is blue`).toBeGreaterThan(sea[0] + 10);
      expect(sky[0] + sky[1] + sky[2], `${backend}: the sky brighter than the sea`).toBeGreaterThan(sea[0] + sea[1] + sea[2] + 30);
      bandMeans[backend] = [sky, sea];
      console.log(`package.spec: WebGPU quick start on ${backend}: sky ${sky.map(Math.round)}, sea ${sea.map(Math.round)}, waviness ${waviness(picture).toFixed(2)}`);
    }
    // The same code on the two backends draws the same sea (a few frames apart: the frame with the worker's first fields).
    for (let band = 0; band < 2; band++) {
      for (let c = 0; c < 3; c++) expect(Math.abs(bandMeans.webgl2[band][c] - bandMeans.webgpu[band][c]), `${band ? 'sea' : 'sky'} colour, channel ${c}, WebGL2 against WebGPU`).toBeLessThan(6);
    }
  } finally {
    await webgpuBrowser.close();
    await server.close();
  }
});

/**
 * The react-three-fiber example (examples/react-three-fiber/) as its users build it: in a new
 * project with React, react-dom, @react-three/fiber, three and the packed library, built by vite
 * with no plugin (its own transform compiles the JSX), served as plain files. The versions: the
 * newest of each whose peer ranges accept one another and three ${threeVersion} (fiber 9 wants
 * React 19, below 19.4). With UPDATE_THUMBNAILS=1 its picture becomes the gallery's thumbnail
 * (examples/thumbnails/react-three-fiber.png, the size of the others).
 */
const R3F_PACKAGES = ['react@19.3.1', 'react-dom@19.3.1', '@react-three/fiber@9.8.2'];

test('the packed library in a new vite project with react-three-fiber: the example draws a sea', async ({ page }) => {
  test.setTimeout(180_000);
  // The guide shows this very file (docs/embedding.md, "With react-three-fiber").
  const source = readFileSync(join(repo, 'examples/react-three-fiber/main.jsx'), 'utf8');
  const guide = readFileSync(join(repo, 'docs/embedding.md'), 'utf8');
  expect(guide, 'the example in docs/embedding.md as it is in examples/react-three-fiber/main.jsx').toContain(
    `<!-- example: examples/react-three-fiber/main.jsx -->\n\`\`\`jsx\n${source}\`\`\`\n`,
  );
  let project = '';
  await test.step('install React, react-three-fiber, three and the tarball into a new project', () => {
    project = newProject('react-three-fiber', [tarball(), `three@${threeVersion}`, ...R3F_PACKAGES]);
  });
  await test.step('build examples/react-three-fiber/ with vite', () => {
    for (const file of ['index.html', 'main.jsx']) copyFileSync(join(repo, 'examples/react-three-fiber', file), join(project, file));
    run(join(repo, 'node_modules/.bin/vite'), ['build', project, '--logLevel', 'error'], project);
  });
  const site = join(project, 'dist');
  const code = listFiles(site).filter((path) => path.endsWith('.js')).map((path) => readFileSync(join(site, path), 'utf8')).join('\n');
  expect(code, 'the ocean built into the page').toContain('horizonDistanceFor');
  expect(missingSourceMaps(site), "source maps named in the build but not in it").toEqual([]);

  const server = await serveDirectory(site);
  try {
    await page.setViewportSize({ width: 320, height: 180 });
    const problems = watchProblems(page);
    await page.goto(`${server.url}/`);
    await page.waitForFunction(() => document.querySelector('canvas') !== null);
    // r3f draws every animation frame; the sea appears once the Ocean is made (in an effect) and drawn.
    let picture = await screenshot(page);
    await expect
      .poll(async () => {
        picture = await screenshot(page);
        return meanColour(picture, 0, Math.round(picture.height / 10))[2];
      }, { timeout: 60_000, message: 'a bright sky at the top' })
      .toBeGreaterThan(120);
    const { height } = picture;
    const sky = meanColour(picture, 0, Math.round(height / 10));
    const sea = meanColour(picture, Math.round((height * 3) / 4), height);
    expect(sea[2], 'the sea is blue').toBeGreaterThan(sea[0] + 10);
    expect(sky[0] + sky[1] + sky[2], 'the sky brighter than the sea').toBeGreaterThan(sea[0] + sea[1] + sea[2] + 30);
    expect(problems, 'errors on the react-three-fiber page').toEqual([]);
    if (process.env.UPDATE_THUMBNAILS) await page.locator('canvas').first().screenshot({ path: join(repo, 'examples/thumbnails/react-three-fiber.png') });
  } finally {
    await server.close();
  }
});
