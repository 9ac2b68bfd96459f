/**
 * How the ocean runs in the app and <fft-ocean>: with which of three's renderers, which
 * simulation path, and how fast simulated time goes. The app's URL and panel, the element's attributes and the shot CLI read them by these
 * rules, with one range each, and say the same of a bad value. (The shot CLI draws the times asked
 * for and takes no time scale.)
 */
import { PATH_PREFERENCES, PATH_PREFERENCES_TEXT, type PathPreference } from '../layers/oceanSimulation';
import { between, oneOf, type OptionTable } from './options';

/** The renderers the app and <fft-ocean> can draw with. */
export const RENDERERS = ['webgl', 'webgpu'] as const;
export type RendererChoice = (typeof RENDERERS)[number];

export interface RunOptions {
  /**
   * Which of three's renderers draws: 'webgl' (WebGLRenderer and the Ocean of three-fft-ocean) or
   * 'webgpu' (WebGPURenderer and the Ocean of three-fft-ocean/webgpu, loaded only when asked for;
   * on its WebGL2 backend where the browser has no WebGPU adapter). @defaultValue 'webgl'
   */
  renderer: RendererChoice;
  /** Which simulation path runs: 'auto', 'gpu' or 'js' (the Ocean's path option). @defaultValue 'auto' */
  path: PathPreference;
  /** Simulated seconds per real second, [-1000, 1000]; negative runs the sea backwards. @defaultValue 1 */
  timeScale: number;
}

/**
 * The fastest time scale, either way. The range is the wider of the two the app and the element
 * once had ([0, 10] and [-1000, 1000]): a sea run backwards is as well defined as forwards (the
 * FFT sea is a function of t), and a fast-forward of a hundred times or more is useful to watch a
 * swell or a fetch-limited sea develop. Beyond 1000 nothing more is seen: the default sea's 200 s
 * repeat period passes in a fifth of a second and frames show unrelated seas; far beyond it a
 * frame's step overflows to Infinity (time scale 1e308), and the time with it.
 */
export const MAX_TIME_SCALE = 1000;

export const RUN_OPTIONS: OptionTable<RunOptions> = {
  renderer: { type: 'choice', unit: '', allowed: "'webgl' or 'webgpu'", check: oneOf(RENDERERS), choices: RENDERERS },
  path: { type: 'choice', unit: '', allowed: PATH_PREFERENCES_TEXT, check: oneOf(PATH_PREFERENCES), choices: PATH_PREFERENCES },
  timeScale: {
    type: 'number',
    unit: 's/s',
    allowed: `a number of simulated seconds per second from -${MAX_TIME_SCALE} to ${MAX_TIME_SCALE}`,
    check: between(-MAX_TIME_SCALE, MAX_TIME_SCALE),
  },
};

export const DEFAULT_RUN: Readonly<RunOptions> = Object.freeze({ renderer: 'webgl', path: 'auto', timeScale: 1 });
