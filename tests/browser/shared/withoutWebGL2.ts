import type { Page } from '@playwright/test';

/**
 * Makes the page's browser offer no WebGL2: getContext('webgl2') returns null, as on old devices or
 * with hardware acceleration off. Only the context's absence is simulated; nothing else is.
 */
export async function withoutWebGL2(page: Page): Promise<void> {
  await page.addInitScript(() => {
    const original = HTMLCanvasElement.prototype.getContext;
    HTMLCanvasElement.prototype.getContext = function (this: HTMLCanvasElement, type: string, ...rest: unknown[]) {
      if (type === 'webgl2') return null;
      return (original as (...args: unknown[]) => unknown).call(this, type, ...rest);
    } as typeof original;
  });
}
