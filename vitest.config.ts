import { defineConfig } from 'vitest/config';

// Node unit tests only; the GPU is tested in real Chromium by Playwright (tests/browser).
export default defineConfig({
  test: {
    include: ['tests/unit/**/*.test.ts'],
    environment: 'node',
    // No test races a clock: the default 5 s failed CPU-bound tests (the FFTs against a naive DFT)
    // on this 2-core machine under load. The limit only stops a test that hangs.
    testTimeout: 120_000,
  },
});
