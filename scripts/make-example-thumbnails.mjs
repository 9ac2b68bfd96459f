#!/usr/bin/env node
// The thumbnails of the examples gallery (examples/index.html): each example page served by a
// Vite dev server of its own (port THUMBNAIL_PORT, default 5492), opened in headless Chromium
// (scripts/browser.mjs) at 960×540, screenshot once it has drawn, and stored 320×180 (a 3×3 box
// filter) as examples/thumbnails/<page>.png.
//
//   node scripts/make-example-thumbnails.mjs [name …]
//
// With names (island, three-scene, …) only those pages' thumbnails are made again.
//
// Each picture is checked: a black or flat one fails the run (exit code 1). The react-three-fiber
// example needs React, which this repository does not install: its thumbnail is the picture of
// tests/browser/package/package.spec.ts, which builds it against the packed library
// (UPDATE_THUMBNAILS=1 npx playwright test tests/browser/package/package.spec.ts -g react-three-fiber).
import { mkdirSync, writeFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from '@playwright/test';
import { PNG } from 'pngjs';
import { createServer } from 'vite';
import { BROWSER_ARGS, findBrowser } from './browser.mjs';

const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const OUT_DIR = join(ROOT, 'examples', 'thumbnails');
const PORT = Number(process.env.THUMBNAIL_PORT ?? 5492);
const VIEWPORT = { width: 960, height: 540 };
const SCALE = 3; // → 320×180

/** The pages, with what the picture is of and how to tell that it has been drawn. */
const PAGES = [
  {
    // The first element (the hero) is on screen; the two below it draw only when scrolled to.
    name: 'element',
    path: '/examples/element.html',
    ready: () => customElements.whenDefined('fft-ocean').then(() => document.querySelector('#hero').frameCount >= 3),
  },
  { name: 'three-scene', path: '/examples/three-scene.html?t=6', ready: () => window.example?.frames() > 3 },
  { name: 'island', path: '/examples/island.html?t=6', ready: () => window.islandExample?.frames() > 3 },
  {
    // Drawn a second time at the same t before the picture, as `npm run shot` (scripts/shot.mjs)
    // does: the page's first frame at a drawing-buffer height whose grid differs from the initial
    // one (32 cells a ring; 540 px wants 64) shows no sea, as OceanSurface swaps its geometry in
    // onBeforeRender, after three.js has taken the old one for that draw.
    name: 'shot',
    path: `/examples/shot.html?width=${VIEWPORT.width}&height=${VIEWPORT.height}&time=12.5`,
    ready: () => document.title === 'ready',
    after: () => window.renderFrame(12.5),
  },
];

const chosen = process.argv.slice(2);
const unknown = chosen.filter((name) => !PAGES.some((page) => page.name === name));
if (unknown.length > 0) {
  process.stderr.write(`make-example-thumbnails: no page named ${unknown.join(', ')} (pages: ${PAGES.map((page) => page.name).join(', ')})\n`);
  process.exit(1);
}

const log = (message) => process.stderr.write(`make-example-thumbnails: ${message}\n`);

/** The picture `png` made SCALE times smaller, each pixel the mean of a SCALE×SCALE block. */
function downscale(png) {
  const width = Math.floor(png.width / SCALE);
  const height = Math.floor(png.height / SCALE);
  const out = new PNG({ width, height });
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      for (let c = 0; c < 4; c++) {
        let sum = 0;
        for (let dy = 0; dy < SCALE; dy++) for (let dx = 0; dx < SCALE; dx++) sum += png.data[4 * ((y * SCALE + dy) * png.width + x * SCALE + dx) + c];
        out.data[4 * (y * width + x) + c] = Math.round(sum / (SCALE * SCALE));
      }
    }
  }
  return out;
}

/** Why a picture is no thumbnail (black, or one flat colour), or null. */
function defect(png) {
  let min = 255;
  let max = 0;
  let sum = 0;
  for (let i = 0; i < png.width * png.height; i++) {
    const value = (png.data[4 * i] + png.data[4 * i + 1] + png.data[4 * i + 2]) / 3;
    min = Math.min(min, value);
    max = Math.max(max, value);
    sum += value;
  }
  if (sum / (png.width * png.height) < 20) return 'black';
  if (max - min < 30) return 'one flat colour';
  return null;
}

const executablePath = findBrowser();
if (!executablePath) {
  log('no Chromium found (see scripts/browser.mjs)');
  process.exit(1);
}
const server = await createServer({ root: ROOT, server: { port: PORT, strictPort: true, host: '127.0.0.1' }, logLevel: 'error' });
await server.listen();
const browser = await chromium.launch({ executablePath, args: BROWSER_ARGS });
let failed = false;
try {
  mkdirSync(OUT_DIR, { recursive: true });
  for (const { name, path, ready, after } of PAGES.filter((page) => chosen.length === 0 || chosen.includes(page.name))) {
    const page = await browser.newPage({ viewport: VIEWPORT });
    const errors = [];
    page.on('pageerror', (error) => errors.push(error.message));
    page.on('console', (message) => {
      if (message.type() === 'error' && !message.text().startsWith('Failed to load resource')) errors.push(message.text());
    });
    await page.goto(`http://127.0.0.1:${PORT}${path}`);
    await page.waitForFunction(ready, null, { timeout: 120_000, polling: 250 });
    if (after) await page.evaluate(after);
    const thumbnail = downscale(PNG.sync.read(await page.screenshot()));
    await page.close();
    const problem = errors.length ? `errors on the page: ${errors.join('; ')}` : defect(thumbnail);
    if (problem) {
      log(`${name}: ${problem}`);
      failed = true;
      continue;
    }
    const file = join(OUT_DIR, `${name}.png`);
    writeFileSync(file, PNG.sync.write(thumbnail));
    log(`${name}: ${file}`);
  }
} finally {
  await browser.close();
  await server.close();
}
process.exit(failed ? 1 : 0);
