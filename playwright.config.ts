import { defineConfig } from '@playwright/test';
import { BROWSER_ARGS, findBrowser } from './scripts/browser.mjs';

// Real headless Chromium with WebGL2 (SwiftShader on machines without a GPU), against the Vite
// dev server, so the tests run the same modules the app serves.
export default defineConfig({
  testDir: 'tests/browser',
  timeout: 120_000,
  expect: { timeout: 30_000 },
  fullyParallel: false,
  workers: 1, // two cores, and SwiftShader uses both for one page
  reporter: 'list',
  retries: 0,
  use: {
    baseURL: 'http://127.0.0.1:5173',
    launchOptions: { executablePath: findBrowser() ?? undefined, args: BROWSER_ARGS },
  },
  webServer: {
    command: 'npx vite --port 5173 --strictPort --host 127.0.0.1',
    url: 'http://127.0.0.1:5173/',
    reuseExistingServer: !process.env.CI,
    timeout: 60_000,
  },
});
