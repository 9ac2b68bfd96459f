// Where the Chromium for tests, benchmarks and `npm run shot` is, and the flags that give it
// WebGL2 through SwiftShader on a machine without a GPU (measured in ../shared/BROWSER.md).
import { existsSync } from 'node:fs';
import { chromium } from '@playwright/test';

/** Environment variables that may name a Chromium binary, in order of precedence. */
export const BROWSER_ENV_VARS = ['CHROMIUM_PATH', 'PLAYWRIGHT_CHROMIUM_EXECUTABLE_PATH'];
const SYSTEM_PATHS = ['/usr/lib/chromium/chromium', '/usr/bin/chromium', '/usr/bin/chromium-browser'];

/**
 * The Chromium to use: the path in an environment variable if set, else Playwright's own
 * Chromium if installed, else Debian's. Returns null when there is none.
 */
export function findBrowser() {
  for (const name of BROWSER_ENV_VARS) {
    const path = process.env[name];
    if (path) return existsSync(path) ? path : null;
  }
  try {
    const own = chromium.executablePath();
    if (own && existsSync(own)) return own;
  } catch {
    // Playwright has no browser of its own installed.
  }
  return SYSTEM_PATHS.find((path) => existsSync(path)) ?? null;
}

/** Launch flags: SwiftShader WebGL2 (with timer queries), and no background network traffic. */
export const BROWSER_ARGS = [
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
  '--ignore-gpu-blocklist',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--disable-quic',
  '--no-first-run',
];
