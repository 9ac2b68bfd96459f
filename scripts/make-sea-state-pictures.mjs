#!/usr/bin/env node
// `npm run make-sea-states`: the sea-state pictures and table of docs/sea-states.md, and the feature
// pictures of the README and the guide.
//
// For every named preset (SEA_PRESETS) and for every Beaufort force 0–12 (beaufortPreset), renders
// one picture with the shot CLI (scripts/shot.mjs) into
// docs/sea-states/<name>.png, and computes Hs and Tp with seaState. The presets, seaState and the
// parameter names come from the TypeScript sources themselves (loaded with Vite's ssrLoadModule,
// as the bench does, bench/lib/servers.mjs), so no formula or default is copied here. It writes the Markdown table to
// docs/sea-states/table.md (links relative to that folder) and prints the same Markdown with links
// relative to docs/, ready for docs/sea-states.md.
//
// Every picture: 320x180 (small, so that the eighteen stay light in the repository), seed 7, t = 12.5 s, the app's default lens and sun. The camera is the
// app's default one (12 m up, cam=0,12,0,-53.13,-6.84) except for storm-type seas (Hs > 6 m), which
// all get STORM_CAM: with Hs > 6 m the highest crests (about 1.1·Hs in a few hundred waves) reach
// eye level at 12 m and the nearest crest hides the sea behind it; at force 12 (Hs ≈ 16 m) the
// eye would sometimes be under water. 25 m is above the highest crest expected at force 12, and
// looking 10° down keeps the near waves and the horizon in the same picture.
//
// The app is built once (if it is older than its sources) and every shot runs with --no-build;
// SHOT_CONCURRENCY shots run at a time (SwiftShader is slow, about 20 s a picture). Each picture
// is checked: a black, blank or flat-coloured sea fails the run (exit code 1). The shot's truecolour
// PNG is then stored as a 256-colour one (median cut, a few Lloyd steps, no dithering): about
// 0.17 MB at 960x540, a tenth of that at 320x180.
//
// The feature pictures (FEATURES: whitecaps in a storm, a boat and its wake, …) are app links
// rendered with the shot CLI's --query into docs/features/<file>, checked and stored the same way.
// The first of them is the README's picture: what `npm start` shows first (the app with no URL
// parameters, at t = 0), kept as the shot wrote it (truecolour), so that it is exactly that view;
// tests/browser/shot/shot.spec.ts renders it again and compares. --features-only renders only the
// feature pictures, --sea-states-only only the sea states and their table.
import { spawn } from 'node:child_process';
import { mkdirSync, readFileSync, statSync, writeFileSync } from 'node:fs';
import { availableParallelism } from 'node:os';
import { dirname, join, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { crc32, deflateSync } from 'node:zlib';
import { PNG } from 'pngjs';
import { createServer } from 'vite';
import { ensureBuiltApp } from './shot.mjs';

const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const OUT_DIR = join(ROOT, 'docs', 'sea-states');
const FEATURES_DIR = join(ROOT, 'docs', 'features');
/** The README's picture, in FEATURES_DIR (tests/browser/shot/shot.spec.ts knows this name too). */
const FIRST_VIEW_FILE = 'first-view.png';
/** The feature pictures of the README and the guide: app links (what the app's "copy link" gives), paused at their t. */
const FEATURES = [
  { name: "the app's first view", file: FIRST_VIEW_FILE, query: 'paused=1', truecolour: true },
  { name: 'whitecaps in a storm', file: 'whitecaps.png', query: 'windSpeed=20&seed=7&paused=1&t=30&cam=0,25,0,-53.13,-12' },
  { name: 'a boat and its wake', file: 'wake.png', query: 'windSpeed=4&seed=7&boat=1&paused=1&t=40&cam=0,30,0,-20,-30' },
  { name: 'under water', file: 'underwater.png', query: 'windSpeed=6&seed=7&paused=1&t=12.5&cam=0,-4,0,-150,45' },
];
const SHOT = join(ROOT, 'scripts', 'shot.mjs');

const BEAUFORT_FORCES = Array.from({ length: 13 }, (_, force) => force);
/** The sea-state pictures' size; the feature pictures are FEATURE_SIZE. */
const SIZE = '320x180';
const FEATURE_SIZE = '960x540';
const SEED = 7;
const TIME = 12.5;
/** The app's default camera (src/app/urlState.ts): x, y, z in m, yaw and pitch in degrees. */
const DEFAULT_CAM = '0,12,0,-53.13,-6.84';
/** Storm-type seas: 25 m up, same heading as the default, 10° down (see the top of this file). */
const STORM_CAM = '0,25,0,-53.13,-10';
/** Seas with a significant wave height above this (m) are storm-type. */
const STORM_HS = 6;
const SHOT_CONCURRENCY = Math.max(1, Math.min(3, availableParallelism()));

const started = performance.now();
const log = (message) => process.stderr.write(`make-sea-states: ${message}\n`);

/** The sea states to show: [name, file stem, parameters]. */
async function loadSeaStates() {
  const server = await createServer({
    root: ROOT,
    server: { middlewareMode: true, watch: null },
    appType: 'custom',
    logLevel: 'silent',
    optimizeDeps: { noDiscovery: true },
  });
  try {
    const { SEA_PRESETS, beaufortPreset, presetCloudCover } = await server.ssrLoadModule('/src/spectrum/presets.ts');
    const { seaState } = await server.ssrLoadModule('/src/spectrum/seaState.ts');
    const states = [
      ...Object.entries(SEA_PRESETS),
      ...BEAUFORT_FORCES.map((force) => [`Beaufort ${force}`, beaufortPreset(force)]),
    ];
    return states.map(([name, parameters]) => ({
      name,
      file: `${name.toLowerCase().replace(/\s+/g, '-')}.png`,
      parameters,
      cloudCover: presetCloudCover(parameters),
      ...seaState(parameters),
    }));
  } finally {
    await server.close();
  }
}

/** A parameter value as the shot CLI reads it (the app's URL form). */
function optionText(value) {
  if (Array.isArray(value)) return value.map(optionText).join(',');
  if (value === Infinity) return 'deep';
  return String(value);
}

/** The shot CLI's arguments for one sea state: every parameter of the preset, in kebab-case. */
function shotArguments(state) {
  if (state.query) return ['--query', state.query, '--size', FEATURE_SIZE, '--out', join(FEATURES_DIR, state.file), '--no-build'];
  const args = [];
  for (const [key, value] of Object.entries(state.parameters)) {
    args.push(`--${key.replace(/[A-Z]/g, (c) => `-${c.toLowerCase()}`)}`, optionText(value));
  }
  // The sky the preset goes with (overcast from force 8), as the app's preset menu sets it.
  args.push('--cloud-cover', String(state.cloudCover));
  args.push('--seed', String(SEED), '--time', String(TIME), '--size', SIZE, '--cam', state.cam);
  args.push('--out', join(OUT_DIR, state.file), '--no-build');
  return args;
}

function runShot(state) {
  return new Promise((resolvePromise, reject) => {
    const child = spawn(process.execPath, [SHOT, ...shotArguments(state)], { cwd: ROOT, stdio: ['ignore', 'ignore', 'pipe'] });
    let stderr = '';
    child.stderr.on('data', (chunk) => (stderr += chunk));
    child.on('error', reject);
    child.on('close', (code) => {
      if (code === 0) resolvePromise();
      else reject(new Error(`shot for ${state.name} exited with ${code}:\n${stderr.trim()}`));
    });
  });
}

/** Colours of the stored pictures. */
const PALETTE_SIZE = 256;

/**
 * A palette of `size` colours for the RGBA pixels `data`: median cut of the colours' histogram (5 bits
 * a channel; the box with the largest spread × √pixels is split at its median along that channel),
 * then Lloyd steps (each bin's colour goes to its nearest palette colour, which moves to their mean).
 */
function palette(data, size) {
  const bins = new Map(); // 15-bit colour → [pixels, Σr, Σg, Σb]
  for (let i = 0; i < data.length; i += 4) {
    const key = ((data[i] >> 3) << 10) | ((data[i + 1] >> 3) << 5) | (data[i + 2] >> 3);
    const bin = bins.get(key);
    if (bin) {
      bin[0]++;
      bin[1] += data[i];
      bin[2] += data[i + 1];
      bin[3] += data[i + 2];
    } else {
      bins.set(key, [1, data[i], data[i + 1], data[i + 2]]);
    }
  }
  const entries = [...bins.values()];
  const mean = (box) => {
    const n = box.reduce((sum, bin) => sum + bin[0], 0);
    return [1, 2, 3].map((c) => box.reduce((sum, bin) => sum + bin[c], 0) / n);
  };
  const boxes = [entries];
  while (boxes.length < size) {
    let best = -1;
    let bestScore = 0;
    let bestChannel = 1;
    boxes.forEach((box, index) => {
      if (box.length < 2) return;
      const pixels = box.reduce((sum, bin) => sum + bin[0], 0);
      for (let c = 1; c <= 3; c++) {
        let low = Infinity;
        let high = -Infinity;
        for (const bin of box) {
          low = Math.min(low, bin[c] / bin[0]);
          high = Math.max(high, bin[c] / bin[0]);
        }
        const score = (high - low) * Math.sqrt(pixels);
        if (score > bestScore) [best, bestScore, bestChannel] = [index, score, c];
      }
    });
    if (best < 0) break;
    const box = boxes[best].sort((a, b) => a[bestChannel] / a[0] - b[bestChannel] / b[0]);
    const half = box.reduce((sum, bin) => sum + bin[0], 0) / 2;
    let cut = 1;
    for (let pixels = box[0][0]; cut < box.length - 1 && pixels < half; cut++) pixels += box[cut][0];
    boxes.splice(best, 1, box.slice(0, cut), box.slice(cut));
  }
  let colours = boxes.map(mean);
  for (let step = 0; step < 4; step++) {
    const sums = colours.map(() => [0, 0, 0, 0]);
    for (const bin of entries) {
      const sum = sums[nearest(colours, bin[1] / bin[0], bin[2] / bin[0], bin[3] / bin[0])];
      for (let c = 0; c < 4; c++) sum[c] += bin[c];
    }
    colours = colours.map((colour, i) => (sums[i][0] > 0 ? [sums[i][1] / sums[i][0], sums[i][2] / sums[i][0], sums[i][3] / sums[i][0]] : colour));
  }
  return colours.map((colour) => colour.map(Math.round));
}

/** Index of the colour nearest to (r, g, b) in `colours`. */
function nearest(colours, r, g, b) {
  let best = 0;
  let bestDistance = Infinity;
  for (let i = 0; i < colours.length; i++) {
    const [cr, cg, cb] = colours[i];
    const distance = (cr - r) ** 2 + (cg - g) ** 2 + (cb - b) ** 2;
    if (distance < bestDistance) [best, bestDistance] = [i, distance];
  }
  return best;
}

/** An 8-bit indexed-colour PNG of the RGBA picture `png` (alpha dropped: the canvas is opaque). */
function indexedPng({ width, height, data }) {
  const colours = palette(data, PALETTE_SIZE);
  const indexOf = new Map();
  const rows = Buffer.alloc((width + 1) * height); // each row: filter type 0, then the indices
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const i = 4 * (y * width + x);
      const key = (data[i] << 16) | (data[i + 1] << 8) | data[i + 2];
      let index = indexOf.get(key);
      if (index === undefined) indexOf.set(key, (index = nearest(colours, data[i], data[i + 1], data[i + 2])));
      rows[y * (width + 1) + 1 + x] = index;
    }
  }
  const chunk = (type, body) => {
    const head = Buffer.alloc(8);
    head.writeUInt32BE(body.length, 0);
    head.write(type, 4, 'latin1');
    const crc = Buffer.alloc(4);
    crc.writeUInt32BE(crc32(Buffer.concat([head.subarray(4), body])), 0);
    return Buffer.concat([head, body, crc]);
  };
  const header = Buffer.alloc(13);
  header.writeUInt32BE(width, 0);
  header.writeUInt32BE(height, 4);
  header.set([8, 3, 0, 0, 0], 8); // 8 bits, indexed colour, deflate, adaptive filtering, no interlace
  return Buffer.concat([
    Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]),
    chunk('IHDR', header),
    chunk('PLTE', Buffer.from(colours.flat())),
    chunk('IDAT', deflateSync(rows, { level: 9 })),
    chunk('IEND', Buffer.alloc(0)),
  ]);
}

/**
 * Mean and standard deviation of the luma (0–255) of the picture's lower half, where the sea is:
 * a black, blank or single-coloured sea is a failed picture.
 */
function seaLuma(png) {
  let sum = 0;
  let sumSquares = 0;
  let count = 0;
  for (let y = Math.floor(png.height / 2); y < png.height; y++) {
    for (let x = 0; x < png.width; x++) {
      const i = 4 * (y * png.width + x);
      const luma = 0.2126 * png.data[i] + 0.7152 * png.data[i + 1] + 0.0722 * png.data[i + 2];
      sum += luma;
      sumSquares += luma * luma;
      count++;
    }
  }
  const mean = sum / count;
  return { mean, deviation: Math.sqrt(Math.max(0, sumSquares / count - mean * mean)) };
}

/** Runs task(item) for every item, at most `limit` at a time. */
async function eachLimited(items, limit, task) {
  let next = 0;
  const worker = async () => {
    while (next < items.length) await task(items[next++]);
  };
  await Promise.all(Array.from({ length: Math.min(limit, items.length) }, worker));
}

const fixed = (value, digits) => value.toFixed(digits);

/** The Markdown table and picture grid, with picture links starting with `prefix`. */
function markdown(states, prefix) {
  const lines = [
    '| sea state | spectrum | wind U10 (m/s) | fetch (km) | depth (m) | swell | patch sizes (m) | Hs (m) | Tp (s) |',
    '|---|---|--:|--:|--:|---|---|--:|--:|',
  ];
  for (const { name, parameters: p, significantWaveHeight, peakPeriod } of states) {
    const swell = p.swellHeight > 0 ? `${p.swellHeight} m, ${p.swellPeriod} s, towards ${p.swellDirection}°` : '–';
    const depth = p.depth === Infinity ? 'deep' : String(p.depth);
    const cells = [name, p.spectrum, p.windSpeed, p.fetch, depth, swell, p.patchSizes.join(', '), fixed(significantWaveHeight, 2), fixed(peakPeriod, 1)];
    lines.push(`| ${cells.join(' | ')} |`);
  }
  lines.push('');
  const storms = states.filter((state) => state.cam === STORM_CAM).map((state) => state.name);
  lines.push(
    `Pictures: ${SIZE.replace('x', '×')}, seed 7, t = 12.5 s, the app's camera (cam=${DEFAULT_CAM}); the storm-type seas ` +
      `(Hs > ${STORM_HS} m: ${storms.join(', ')}) from 25 m up, looking 10° down (cam=${STORM_CAM}).`,
  );
  lines.push('');
  const columns = 3;
  lines.push(`|${' |'.repeat(columns)}`, `|${':-:|'.repeat(columns)}`);
  for (let i = 0; i < states.length; i += columns) {
    const row = states.slice(i, i + columns).map(
      (state) => `![${state.name}](${prefix}${state.file})<br>${state.name}: Hs ${fixed(state.significantWaveHeight, 1)} m, Tp ${fixed(state.peakPeriod, 1)} s`,
    );
    while (row.length < columns) row.push(' ');
    lines.push(`| ${row.join(' | ')} |`);
  }
  return `${lines.join('\n')}\n`;
}

async function main() {
  mkdirSync(OUT_DIR, { recursive: true });
  mkdirSync(FEATURES_DIR, { recursive: true });
  ensureBuiltApp({ log });
  log('loading the presets and seaState through Vite (ssrLoadModule)');
  const states = await loadSeaStates();
  for (const state of states) state.cam = state.significantWaveHeight > STORM_HS ? STORM_CAM : DEFAULT_CAM;

  const only = process.argv.includes('--features-only') ? FEATURES : process.argv.includes('--sea-states-only') ? states : [...states, ...FEATURES];
  log(`rendering ${only.length} pictures, ${SHOT_CONCURRENCY} at a time`);
  const failures = [];
  await eachLimited(only, SHOT_CONCURRENCY, async (state) => {
    const shotStarted = performance.now();
    await runShot(state);
    const file = join(state.query ? FEATURES_DIR : OUT_DIR, state.file);
    const png = PNG.sync.read(readFileSync(file));
    const { mean, deviation } = seaLuma(png);
    if (!state.truecolour) writeFileSync(file, indexedPng(png));
    const seconds = ((performance.now() - shotStarted) / 1000).toFixed(0);
    log(`${relative(ROOT, file)}: ${(statSync(file).size / 1024).toFixed(0)} KiB, sea luma ${mean.toFixed(0)} ± ${deviation.toFixed(1)}, ${seconds} s`);
    if (mean < 8 || deviation < 1) failures.push(`${state.name}: the sea is black or flat (luma ${mean.toFixed(1)} ± ${deviation.toFixed(2)})`);
  });

  if (only === FEATURES) {
    if (failures.length > 0) throw new Error(`bad pictures:\n  ${failures.join('\n  ')}`);
    return;
  }
  const header = '<!-- Made by `npm run make-sea-states` (scripts/make-sea-state-pictures.mjs); do not edit. -->\n\n';
  writeFileSync(join(OUT_DIR, 'table.md'), header + markdown(states, ''));
  process.stdout.write(markdown(states, 'sea-states/')); // for docs/sea-states.md
  const total = states.reduce((sum, state) => sum + statSync(join(OUT_DIR, state.file)).size, 0);
  log(`wrote ${relative(ROOT, join(OUT_DIR, 'table.md'))}; pictures ${(total / 1024 / 1024).toFixed(2)} MiB; ${((performance.now() - started) / 1000).toFixed(0)} s`);
  if (failures.length > 0) throw new Error(`bad pictures:\n  ${failures.join('\n  ')}`);
}

main().catch((error) => {
  process.stderr.write(`make-sea-states: ${error instanceof Error ? error.message : String(error)}\n`);
  process.exit(1);
});
