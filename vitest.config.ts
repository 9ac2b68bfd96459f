import { defineConfig } from 'vitest/config';

// Node unit tests only; the GPU is tested in real Chromium by Playwright (tests/browser).
export default defineConfig({
  test: {
    include: ['tests/unit/**/*.test.ts'],
    environment: 'node',
    // No test races a clock: the default 5 s failed CPU-bound tests (the FFTs against a naive DFT)
    // on this 2-core machine under load. The limit only stops a test that hangs.
    testTimeout: 120_000,
    // Two files at once on two cores (the default is one fewer than the cores): back to back on this
    // machine, under load, 1 worker against 2 took 170 s / 116 s, 82 s / 61 s and 123 s / 76 s.
    maxWorkers: 2,
  },
});
