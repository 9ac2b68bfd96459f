// The bench's servers: Vite (the sources for Node, the pages for Chromium), a static server for a
// comparison checkout, and the free ports they listen on.
import { readFile } from 'node:fs/promises';
import { createServer as createHttpServer } from 'node:http';
import { createServer as createNetServer } from 'node:net';
import { extname, resolve, sep } from 'node:path';
import { createServer } from 'vite';

/** Vite without a port, to load the TypeScript sources into Node (ssrLoadModule). */
export function createModuleServer() {
  return createServer({
    server: { middlewareMode: true, watch: null },
    appType: 'custom',
    logLevel: 'silent',
    optimizeDeps: { noDiscovery: true },
  });
}

/** Vite serving the repository (the bench pages and the app) on 127.0.0.1:port, once listen() is called. */
export function createPageServer(port) {
  return createServer({
    logLevel: 'silent',
    optimizeDeps: { noDiscovery: true }, // no dependency discovery, so no reload mid-benchmark
    server: {
      port,
      strictPort: true,
      host: '127.0.0.1',
      // No file watcher and no HMR: an edit anywhere in the tree must not reload the page mid-run.
      watch: null,
      hmr: false,
      // Cross-origin isolation gives performance.now() 5 µs resolution instead of 100 µs.
      headers: { 'Cross-Origin-Opener-Policy': 'same-origin', 'Cross-Origin-Embedder-Policy': 'require-corp' },
    },
  });
}

/** The first port from `first` on that 127.0.0.1 lets us listen on. */
export async function freePort(first) {
  for (let port = first; port < first + 50; port++) {
    const free = await new Promise((resolve) => {
      const probe = createNetServer();
      probe.once('error', () => resolve(false));
      probe.listen(port, '127.0.0.1', () => probe.close(() => resolve(true)));
    });
    if (free) return port;
  }
  throw new Error(`no free port in ${first}-${first + 49}`);
}

const STATIC_TYPES = { '.html': 'text/html', '.js': 'text/javascript', '.css': 'text/css', '.png': 'image/png', '.jpg': 'image/jpeg', '.json': 'application/json' };

/**
 * A static file server for `root` on 127.0.0.1:port (GET and HEAD, nothing outside root), with the
 * same cross-origin isolation headers as the app's Vite server, so both pages get the same timer
 * resolution. Resolves to the server once it listens.
 */
export async function serveStatic(root, port) {
  const server = createHttpServer(async (request, response) => {
    if (request.method !== 'GET' && request.method !== 'HEAD') {
      response.writeHead(405).end();
      return;
    }
    let path;
    try {
      path = decodeURIComponent(new URL(request.url ?? '/', 'http://127.0.0.1').pathname);
    } catch {
      response.writeHead(400).end();
      return;
    }
    const file = resolve(root, `.${path.endsWith('/') ? `${path}index.html` : path}`);
    if (!file.startsWith(root + sep)) {
      response.writeHead(403).end();
      return;
    }
    try {
      const body = await readFile(file);
      response.writeHead(200, {
        'Content-Type': STATIC_TYPES[extname(file).toLowerCase()] ?? 'application/octet-stream',
        'Cross-Origin-Opener-Policy': 'same-origin',
        'Cross-Origin-Embedder-Policy': 'require-corp',
        'Cache-Control': 'no-store',
      });
      response.end(request.method === 'HEAD' ? undefined : body);
    } catch {
      response.writeHead(404).end();
    }
  });
  await new Promise((resolveListen, reject) => {
    server.once('error', reject);
    server.listen(port, '127.0.0.1', resolveListen);
  });
  return server;
}
