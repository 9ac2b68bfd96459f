// Chromium for the browser groups: the launch beside a Vite server of the pages, the shared bench
// page, and helpers for pages (a ready page, a step with a timeout, frame intervals).
import { chromium } from '@playwright/test';
import { BROWSER_ARGS, findBrowser } from '../../scripts/browser.mjs';
import { emit, log } from './output.mjs';
import { createPageServer, freePort } from './servers.mjs';

/** `promise`, or a rejection naming `what` once it has taken more than `ms`. */
export function withTimeout(promise, ms, what) {
  let timer;
  const timeout = new Promise((_, reject) => {
    timer = setTimeout(() => reject(new Error(`${what} took more than ${ms / 1000} s`)), ms);
  });
  return Promise.race([promise, timeout]).finally(() => clearTimeout(timer));
}

/**
 * In the page: the real time between `count` successive frames (requestAnimationFrame
 * timestamps, ms), what users see. Shared by the app and the comparison so both are timed alike.
 */
export async function frameIntervals(count) {
  const frame = () => new Promise((resolve) => requestAnimationFrame(resolve));
  const samples = [];
  let last = await frame();
  for (let i = 0; i < count; i++) {
    const now = await frame();
    samples.push(now - last);
    last = now;
  }
  return samples;
}

/** Opens bench/pages/<file> of the Vite server on `port` in `page`, and waits until it is ready. */
export async function openReady(page, port, file) {
  await page.goto(`http://127.0.0.1:${port}/bench/pages/${file}`);
  await page.waitForFunction(() => document.title === 'ready', null, { timeout: 60_000 });
}

/**
 * Starts Vite on the first free port from `firstPort` and Chromium, opens the bench page (bench.html)
 * and prints the `browser` row (what the page's WebGL2 supports), then runs
 * `body({ browser, page, server, port, info })` and closes both. Throws without RGBA32F render targets.
 */
export async function withBenchBrowser(firstPort, body) {
  const executablePath = findBrowser();
  if (!executablePath) throw new Error('no Chromium found (see scripts/browser.mjs; set CHROMIUM_PATH)');
  const port = await freePort(firstPort);
  log(`starting Vite on http://127.0.0.1:${port}/`);
  const server = await createPageServer(port);
  let browser;
  try {
    await server.listen();
    log(`launching ${executablePath}`);
    browser = await chromium.launch({ executablePath, args: BROWSER_ARGS });
    const page = await browser.newPage();
    page.on('pageerror', (error) => log(`page error: ${error.message}`));
    page.on('response', (response) => {
      if (response.status() >= 400) log(`HTTP ${response.status()} for ${response.url()}`);
    });
    page.on('console', (message) => {
      if (message.type() === 'error' || message.type() === 'warning') log(`page ${message.type()}: ${message.text()}`);
    });
    await openReady(page, port, 'bench.html');
    const info = await page.evaluate(() => window.bench.info());
    emit({ bench: 'browser', ...info });
    if (info.supportedPrecision !== 'float32') throw new Error(`no RGBA32F render targets (supported: ${info.supportedPrecision})`);
    if (!info.timerQuery) log('EXT_disjoint_timer_query_webgl2 is missing: only readpixels-sync GPU rows');
    await body({ browser, page, server, port, info });
  } finally {
    await browser?.close().catch(() => {});
    await server.close().catch(() => {});
  }
}
