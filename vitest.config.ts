import { defineConfig } from 'vitest/config';

// Node unit tests only; the GPU is tested in real Chromium by Playwright (tests/browser).
export default defineConfig({
  test: {
    include: ['tests/unit/**/*.test.ts'],
    environment: 'node',
  },
});
