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
 * Gives the page's frames timestamps 250 ms apart (requestAnimationFrame's, which the app's and
 * the element's clocks read: frames of 250 ms as far as they can tell, however fast or slow the
 * machine really draws them) until the quality 'auto' of the app (`'app'`) or of the first
 * <fft-ocean> (`'element'`) has come down to `until` (a level: one step a window, WINDOW_SECONDS,
 * of frames slower than the target), or until a window of them was measured (`'a window
 * measured'`: the quality's median frame time is known, for a fixed level, which keeps it). Far
 * over a 60 fps target's 20 ms, so what 'auto' does depends on the frames alone. Gives up after
 * 100 frames (a window is 8 of them).
 */
export function slowFramesUntil(
  page: Page,
  source: 'app' | 'element',
  until: 'medium' | 'low' | 'lowest' | 'a window measured',
): Promise<{ frames: number }> {
  return page.evaluate(
    async ({ source, until }) => {
      const quality = () => (source === 'app' ? window.oceanApp.quality : document.querySelector('fft-ocean')!.quality);
      const done = () => (until === 'a window measured' ? quality().medianFrameMs !== null : quality().level === until);
      const original = window.requestAnimationFrame;
      // Every callback of one real frame gets the same made-up timestamp: the first frame's own,
      // then 250 ms more a frame.
      let real: number | null = null;
      let stamp = 0;
      let frames = 0;
      window.requestAnimationFrame = (callback) =>
        original.call(window, (now) => {
          if (now !== real) {
            stamp = real === null ? now : stamp + 250;
            real = now;
            frames++;
          }
          callback(stamp);
        });
      try {
        await new Promise<void>((resolve, reject) => {
          const frame = () => {
            if (done()) return resolve();
            if (frames > 100) return reject(new Error(`100 frames of 250 ms and still not ${until}: quality ${quality().level}`));
            requestAnimationFrame(frame);
          };
          requestAnimationFrame(frame);
        });
      } finally {
        window.requestAnimationFrame = original;
      }
      return { frames };
    },
    { source, until },
  );
}
