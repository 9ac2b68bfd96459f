/**
 * Side-effect module: importing it defines `<fft-ocean>` (once, however often it is imported).
 *
 * ```ts
 * import 'three-fft-ocean/register';
 * // <fft-ocean wind-speed="14"></fft-ocean> now works anywhere in the page
 * ```
 * @module three-fft-ocean/register
 */
import { defineFftOceanElement } from './fftOceanElement';

defineFftOceanElement();

export { FftOceanElement } from './fftOceanElement';
