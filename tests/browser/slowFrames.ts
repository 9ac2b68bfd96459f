import type { Page } from '@playwright/test';

/**
 * Makes every frame of the page 250 ms slower (a busy main thread, as on a slow machine) for about
 * 1.5 s and measures how far simulated time moved meanwhile: the app's (`'app'`) or the first
 * <fft-ocean>'s (`'element'`). Both times are read at each frame's requestAnimationFrame
 * timestamp, the one the page's clock sees too, so the measurement holds whichever callback of a
 * frame runs first.
 */
export function slowFrames(page: Page, source: 'app' | 'element'): Promise<{ simulated: number; real: number }> {
  return page.evaluate(async (source) => {
    const simulatedTime = () => (source === 'app' ? window.oceanApp.state.t : document.querySelector('fft-ocean')!.time);
    const samples: [number, number][] = [];
    await new Promise<void>((resolve) => {
      const frame = (now: number) => {
        const end = performance.now() + 250;
        while (performance.now() < end) {
          // busy
        }
        samples.push([now, simulatedTime()]);
        if (samples.length < 2 || now - samples[1][0] < 1500) requestAnimationFrame(frame);
        else resolve();
      };
      requestAnimationFrame(frame);
    });
    // From the second sample: the interval before the first frame was not a slow one.
    const [first, last] = [samples[1], samples[samples.length - 1]];
    return { simulated: last[1] - first[1], real: (last[0] - first[0]) / 1000 };
  }, source);
}
