import { defineConfig, type Plugin } from 'vite';
import { createRequire } from 'node:module';
import { dirname, resolve } from 'node:path';

const root = import.meta.dirname;
/**
 * lil-gui's stylesheet, which the app loads as a file (src/app/panel.ts imports it; the <style>
 * lil-gui would inject breaks under a strict CSP). lil-gui's package.json exports only its
 * scripts, so the file is found next to its main script.
 */
const lilGuiCss = resolve(dirname(createRequire(import.meta.url).resolve('lil-gui')), 'lil-gui.css');

/**
 * Another three.js release for the dev server: THREE_FFT_OCEAN_THREE names its package folder
 * (…/node_modules/three), and `three` and `three/addons/…` (the only forms the pages import)
 * resolve there instead of to the devDependency. scripts/test-three-range.mjs runs browser tests
 * against the oldest supported release this way. Its pre-bundled copy is cached apart, so
 * switching releases never serves a stale bundle.
 */
const otherThree = process.env.THREE_FFT_OCEAN_THREE ? resolve(process.env.THREE_FFT_OCEAN_THREE) : null;
const otherThreeOptions = otherThree
  ? {
      cacheDir: resolve(otherThree, '../.vite'),
      alias: [
        { find: /^three$/, replacement: resolve(otherThree, 'build/three.module.js') },
        { find: /^three\/addons\//, replacement: `${resolve(otherThree, 'examples/jsm')}/` },
      ],
    }
  : { cacheDir: undefined, alias: [] };

/**
 * lil-gui's stylesheet without its icon font. The font is a data: URL, which a strict CSP refuses
 * (font-src falls back to default-src 'self'), and Chromium loads a data: font as soon as it
 * parses the rule, used or not. Its icons (↕ ▾ ▸ ✓) are ordinary characters, drawn here in
 * lil-gui's text font. Fails the build if lil-gui's CSS no longer looks as expected.
 */
function lilGuiWithoutIconFont(): Plugin {
  return {
    name: 'lil-gui-without-icon-font',
    enforce: 'pre',
    transform(code, id) {
      if (id !== lilGuiCss) return null;
      const withoutFont = code.replace(/@font-face\s*{[^}]*font-family:\s*"lil-gui";[^}]*}/, '');
      const restyled = withoutFont.replaceAll('font-family: "lil-gui";', 'font-family: var(--font-family);');
      if (withoutFont === code || restyled === withoutFont) this.error(`${id}: its icon font is no longer where this plugin removes it`);
      return { code: restyled, map: null };
    },
  };
}

/**
 * The library's worker without a source map. A user's bundler copies the worker file as it is (an
 * asset found through new URL(..., import.meta.url)) but not a map beside it, so a
 * `sourceMappingURL` comment in it would name a file missing from their site (a 404 in devtools).
 * The worker is not minified, so devtools show readable code without one. Fails the build if the
 * worker is no longer where this expects it.
 */
function workerWithoutSourceMap(): Plugin {
  const isWorker = (fileName: string) => /^assets\/waveFieldWorker-[^/]*\.js$/.test(fileName);
  return {
    name: 'worker-without-source-map',
    generateBundle: {
      order: 'post',
      handler(_options, bundle) {
        const workers = Object.keys(bundle).filter(isWorker);
        if (workers.length !== 1) this.error(`expected one worker file in the library, found ${workers.length}`);
        for (const fileName of workers) {
          const worker = bundle[fileName];
          if (worker.type !== 'asset' || typeof worker.source !== 'string') this.error(`${fileName} is not a text asset`);
          worker.source = worker.source.replace(/\n\/\/# sourceMappingURL=\S*\s*$/, '\n');
          delete bundle[`${fileName}.map`];
        }
      },
    },
  };
}

/**
 * Two builds from one config (`npm run build` runs both):
 *
 * - `vite build` (the default mode): the app (index.html), the example pages and their gallery
 *   (examples/index.html) into dist/app. (examples/react-three-fiber/ needs React: it is built
 *   in tests/browser/package/package.spec.ts, not here.)
 *   The dev server serves the same pages, plus the pages the browser tests and benchmarks drive,
 *   so tests exercise exactly the modules the app ships.
 * - `vite build --mode lib`: the ES module library from src/index.ts (and the side-effecting
 *   src/embed/register.ts that defines <fft-ocean>, and src/webgpu/index.ts, the Ocean for
 *   WebGPURenderer, `three-fft-ocean/webgpu`) into dist/lib, with three left external
 *   (a peer dependency: the user's bundler or import map provides it). The GLSL files are bundled
 *   as strings (import.meta.glob ?raw in src/shaderSource.ts); the JS-path Web Worker
 *   (src/fft/waveFieldWorker.ts) becomes its own self-contained file next to the library, found
 *   at run time through new URL(..., import.meta.url). Type declarations come from
 *   `tsc -p tsconfig.build.json` into dist/lib/types.
 */
export default defineConfig(({ mode }) => ({
  cacheDir: otherThreeOptions.cacheDir,
  server: { port: 5173, strictPort: true, host: '127.0.0.1' },
  preview: { port: 4173, strictPort: true, host: '127.0.0.1' },
  worker: { format: 'es' },
  ...(mode === 'lib'
    ? {
        publicDir: false,
        plugins: [workerWithoutSourceMap()],
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
              webgpu: resolve(root, 'src/webgpu/index.ts'),
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
        resolve: { alias: [...otherThreeOptions.alias, { find: 'lil-gui/dist/lil-gui.css', replacement: lilGuiCss }] },
        plugins: [lilGuiWithoutIconFont()],
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
              island: resolve(root, 'examples/island.html'),
              shot: resolve(root, 'examples/shot.html'),
              gallery: resolve(root, 'examples/index.html'),
            },
          },
        },
      }),
}));
