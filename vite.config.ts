import { defineConfig } from 'vite';
import { resolve } from 'node:path';

// The app (index.html) and the pages the browser tests and benchmarks drive are all served by
// the same Vite server, so tests exercise exactly the modules the app ships.
export default defineConfig({
  server: { port: 5173, strictPort: true, host: '127.0.0.1' },
  preview: { port: 4173, strictPort: true, host: '127.0.0.1' },
  build: {
    target: 'es2022',
    rollupOptions: {
      input: { app: resolve(import.meta.dirname, 'index.html') },
    },
  },
});
