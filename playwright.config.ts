import { defineConfig } from '@playwright/test';
import { BROWSER_ARGS, findBrowser } from './scripts/browser.mjs';

// Real headless Chromium with WebGL2 (SwiftShader on machines without a GPU), against the Vite
// dev server, so the tests run the same modules the app serves. TEST_PORT lets two runs on one
// machine use their own servers.
const port = Number(process.env.TEST_PORT ?? 5173);

export default defineConfig({
  testDir: 'tests/browser',
  timeout: 120_000,
  expect: { timeout: 30_000 },
  fullyParallel: false,
  workers: 1, // two cores, and SwiftShader uses both for one page
  // Each file's time at the end (fileTimesReporter.ts), then the list reporter's summary as the last line.
  reporter: [['./tests/browser/shared/fileTimesReporter.ts'], ['list']],
  outputDir: port === 5173 ? 'test-results' : `test-results-${port}`,
  retries: 0,
  use: {
    baseURL: `http://127.0.0.1:${port}`,
    launchOptions: { executablePath: findBrowser() ?? undefined, args: BROWSER_ARGS },
  },
  webServer: {
    command: `npx vite --port ${port} --strictPort --host 127.0.0.1`,
    url: `http://127.0.0.1:${port}/`,
    // A server already running serves the devDependency three.js: a run against another release
    // (scripts/test-three-range.mjs) starts its own.
    reuseExistingServer: !process.env.CI && !process.env.THREE_FFT_OCEAN_THREE,
    timeout: 60_000,
  },
});
