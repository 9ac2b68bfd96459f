/**
 * The frame pages' timed loop (frame.ts, island.ts, webgpu.ts): each round advances the simulated
 * time by a 30 fps frame and draws every subject once, interleaved so that the machine's drifts
 * fall on all alike. A frame is timed from an idle GPU to the end of `finish(subject)`, which
 * returns once the GPU has done the frame's work (on WebGL a 1-pixel readPixels, onePixelRead:
 * gl.finish does not block in Chromium, BROWSER.md), and yields to the event loop before the next one.
 * With `cpuClock` (Chromium's CPU time so far, ms, read by the bench in Node: bench/lib/cpuTime.mjs)
 * the CPU time each frame took goes into the subject's `cpuSamples` too, read between the same
 * two idle points.
 */
export async function timeRounds<S extends { samples: number[]; cpuSamples?: number[] }>(
  finish: (subject: S) => void | Promise<void>,
  subjects: readonly S[],
  counts: { warmup: number; rounds: number },
  /** Draws `subject` at time `t`; `timed` is false during the warm-up, whose frames are not kept. */
  drawFrame: (subject: S, t: number, round: number, timed: boolean) => void,
  cpuClock?: () => Promise<number | null>,
): Promise<void> {
  let t = 3;
  for (let round = 0; round < counts.warmup + counts.rounds; round++) {
    t += 1 / 30;
    const timed = round >= counts.warmup;
    for (const subject of subjects) {
      await finish(subject);
      const cpuStart = timed && cpuClock ? await cpuClock() : null;
      const start = performance.now();
      drawFrame(subject, t, round, timed);
      await finish(subject);
      const end = performance.now();
      if (timed) {
        subject.samples.push(end - start);
        const cpuEnd = cpuClock ? await cpuClock() : null;
        if (cpuStart !== null && cpuEnd !== null) subject.cpuSamples?.push(cpuEnd - cpuStart);
      }
      await new Promise((resolve) => setTimeout(resolve, 0));
    }
  }
}

/**
 * A `finish` for timeRounds on a WebGL context: a 1-pixel readPixels of the framebuffer bound for
 * reading, which cannot return before the commands before it are done.
 */
export function onePixelRead(gl: WebGLRenderingContext | WebGL2RenderingContext): () => void {
  const pixel = new Uint8Array(4);
  return () => gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
}
