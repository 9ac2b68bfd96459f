import { BROWSER_ARGS, findBrowser } from '../../../scripts/browser.mjs';

/**
 * The Chromium of the spec files that need WebGPU: SwiftShader's WebGPU adapter, which Chromium
 * gives localhost pages with --enable-unsafe-webgpu. Pass this one object to `test.use`:
 * Playwright tells worker options apart by the object given, so the files that give this same one
 * run in one worker on one Chromium, where each file's own copy made a new worker and launched
 * Chromium again.
 */
export const WEBGPU_BROWSER = { launchOptions: { executablePath: findBrowser() ?? undefined, args: [...BROWSER_ARGS, '--enable-unsafe-webgpu'] } };
