import { defineConfig } from 'vite';
import { resolve } from 'node:path';

const root = import.meta.dirname;

/**
 * Two builds from one config (`npm run build` runs both):
 *
 * - `vite build` (the default mode): the app (index.html) and the example pages into dist/app.
 *   The dev server serves the same pages, plus the pages the browser tests and benchmarks drive,
 *   so tests exercise exactly the modules the app ships.
 * - `vite build --mode lib`: the ES module library from src/index.ts (and the side-effecting
 *   src/embed/register.ts that defines <fft-ocean>) into dist/lib, with three left external
 *   (a peer dependency: the user's bundler or import map provides it). The GLSL files are bundled
 *   as strings (import.meta.glob ?raw in src/shaderSource.ts); the JS-path Web Worker
 *   (src/fft/waveFieldWorker.ts) becomes its own self-contained file next to the library, found
 *   at run time through new URL(..., import.meta.url). Type declarations come from
 *   `tsc -p tsconfig.build.json` into dist/lib/types.
 */
export default defineConfig(({ mode }) => ({
  server: { port: 5173, strictPort: true, host: '127.0.0.1' },
  preview: { port: 4173, strictPort: true, host: '127.0.0.1' },
  worker: { format: 'es' },
  ...(mode === 'lib'
    ? {
        publicDir: false,
        // Relative URLs, so the worker file is found next to the library wherever it is served
        // from (new URL('./assets/…', import.meta.url)), not at the site's root.
        base: './',
        build: {
          target: 'es2022',
          outDir: 'dist/lib',
          emptyOutDir: true, // then tsc writes dist/lib/types (npm run build:lib)
          sourcemap: true,
          minify: false, // readable in users' devtools; their bundler minifies
          copyPublicDir: false,
          lib: {
            entry: {
              'three-fft-ocean': resolve(root, 'src/index.ts'),
              register: resolve(root, 'src/embed/register.ts'),
            },
            formats: ['es' as const],
          },
          rolldownOptions: {
            external: ['three', /^three\//],
            output: { chunkFileNames: 'three-fft-ocean-[hash].js' },
          },
        },
      }
    : {
        build: {
          target: 'es2022',
          outDir: 'dist/app',
          emptyOutDir: true,
          chunkSizeWarningLimit: 1000, // three.js alone is about 600 kB minified
          rolldownOptions: {
            input: {
              app: resolve(root, 'index.html'),
              element: resolve(root, 'examples/element.html'),
              threeScene: resolve(root, 'examples/three-scene.html'),
              shot: resolve(root, 'examples/shot.html'),
            },
          },
        },
      }),
}));
