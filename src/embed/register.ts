/**
 * Side-effect module: importing it defines <fft-ocean> (once, however often it is imported).
 *
 *   import 'three-fft-ocean/register';
 *   // <fft-ocean wind-speed="14"></fft-ocean> now works anywhere in the page
 */
import { defineFftOceanElement } from './fftOceanElement';

defineFftOceanElement();

export { FftOceanElement } from './fftOceanElement';
