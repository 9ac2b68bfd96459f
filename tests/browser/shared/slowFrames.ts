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

/**
 * Makes every frame of the page 250 ms slower, as slowFrames does, until the quality 'auto' of the
 * app (`'app'`) or of the first <fft-ocean> (`'element'`) has come down to `until` (a level: one
 * step a window, WINDOW_SECONDS, of frames slower than the target), or until a window of them was
 * measured (`'a window measured'`: the quality's median frame time is known, for a fixed level,
 * which keeps it). Far over a 60 fps target's 20 ms whatever the machine, so what 'auto' does does
 * not depend on how fast this one draws. Gives up after 60 s.
 */
export function slowFramesUntil(
  page: Page,
  source: 'app' | 'element',
  until: 'medium' | 'low' | 'lowest' | 'a window measured',
): Promise<{ frames: number; seconds: number }> {
  return page.evaluate(
    async ({ source, until }) => {
      const quality = () => (source === 'app' ? window.oceanApp.quality : document.querySelector('fft-ocean')!.quality);
      const done = () => (until === 'a window measured' ? quality().medianFrameMs !== null : quality().level === until);
      const start = performance.now();
      let frames = 0;
      await new Promise<void>((resolve, reject) => {
        const frame = () => {
          if (done()) return resolve();
          if (performance.now() - start > 60_000) return reject(new Error(`slow frames for 60 s and still not ${until}: quality ${quality().level}`));
          const end = performance.now() + 250;
          while (performance.now() < end) {
            // busy
          }
          frames++;
          requestAnimationFrame(frame);
        };
        requestAnimationFrame(frame);
      });
      return { frames, seconds: (performance.now() - start) / 1000 };
    },
    { source, until },
  );
}
