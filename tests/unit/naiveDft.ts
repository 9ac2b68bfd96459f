/**
 * The test oracle for the FFT: the inverse 2D DFT evaluated term by term in double precision,
 *   f(n, m) = Σ_{n', m'} F(n', m') · e^{+2πi·(n·n' + m·m')/N},
 * for one complex field stored row-major ([row m][column n]).
 */
export function naiveInverseDft2D(real: Float64Array, imag: Float64Array, n: number): [Float64Array, Float64Array] {
  const outReal = new Float64Array(n * n);
  const outImag = new Float64Array(n * n);
  for (let m = 0; m < n; m++) {
    for (let c = 0; c < n; c++) {
      let sumReal = 0;
      let sumImag = 0;
      for (let mm = 0; mm < n; mm++) {
        for (let cc = 0; cc < n; cc++) {
          // Reduce the integer phase mod N first so the angle stays small and exact.
          const angle = (2 * Math.PI * ((c * cc + m * mm) % n)) / n;
          const cos = Math.cos(angle);
          const sin = Math.sin(angle);
          const re = real[mm * n + cc];
          const im = imag[mm * n + cc];
          sumReal += re * cos - im * sin;
          sumImag += re * sin + im * cos;
        }
      }
      outReal[m * n + c] = sumReal;
      outImag[m * n + c] = sumImag;
    }
  }
  return [outReal, outImag];
}
