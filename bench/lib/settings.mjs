// Settings the groups share: the sizes, rounds and timeouts of the benchmarks (bench/run.mjs).

/** The grids of the fft2d and fields rows. */
export const SIZES = [64, 128, 256, 512];
/** Browser rounds per size (each round times every implementation once), after WARMUP_ROUNDS. */
export const BROWSER_ROUNDS = { 64: 60, 128: 50, 256: 40, 512: 30 };
export const BROWSER_WARMUP_ROUNDS = 6;
export const BROWSER_STEP_TIMEOUT_MS = 150_000;
/** The full frame (simulation, sky and surface) is timed at this canvas size. */
export const FRAME_SIZE = { width: 1280, height: 720 };
export const FRAME_ROUNDS = 30;
/** Patch sizes (m) per cascade count for the cascades and frame rows: ascending, each ≥ 2× and ≤ N/2× the one before. */
export const CASCADE_SETS = { 1: [457], 3: [13.7, 79.3, 457], 4: [2.37, 13.7, 79.3, 457] };
export const CASCADE_COUNTS = [1, 3, 4];
export const CASCADE_N = 256;

/** The app as opened adapts its quality for this long before it is timed, s (the comparison too). */
export const APP_SETTLE_SECONDS = 20;
/** Frames timed, for the app and the comparison alike. */
export const APP_FRAMES = 30;
