/**
 * A plain radix-2 FFT for the tests' own measurements (autocorrelations, spectra of simulated
 * fields), written independently of src/fft so that it can check the product's results.
 *   fft2d(re, im, n, −1): F(k) = Σ_x f(x)·e^{−2πi·k·x/n}     (forward)
 *   fft2d(re, im, n, +1): f(x) = Σ_k F(k)·e^{+2πi·k·x/n}     (inverse, without the 1/n² factor)
 * In place, on n×n row-major arrays, n a power of two.
 */

function fft1d(re: Float64Array, im: Float64Array, offset: number, stride: number, n: number, sign: number): void {
  // Bit-reversal permutation.
  for (let i = 1, j = 0; i < n; i++) {
    let bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) {
      const a = offset + i * stride;
      const b = offset + j * stride;
      [re[a], re[b]] = [re[b], re[a]];
      [im[a], im[b]] = [im[b], im[a]];
    }
  }
  // Butterflies with e^{sign·2πi/len}.
  for (let len = 2; len <= n; len <<= 1) {
    const angle = (sign * 2 * Math.PI) / len;
    for (let q = 0; q < len / 2; q++) {
      const wr = Math.cos(angle * q);
      const wi = Math.sin(angle * q);
      for (let start = 0; start < n; start += len) {
        const a = offset + (start + q) * stride;
        const b = a + (len / 2) * stride;
        const xr = re[b] * wr - im[b] * wi;
        const xi = re[b] * wi + im[b] * wr;
        re[b] = re[a] - xr;
        im[b] = im[a] - xi;
        re[a] += xr;
        im[a] += xi;
      }
    }
  }
}

export function fft2d(re: Float64Array, im: Float64Array, n: number, sign: -1 | 1): void {
  for (let row = 0; row < n; row++) fft1d(re, im, row * n, 1, n, sign);
  for (let column = 0; column < n; column++) fft1d(re, im, column, n, n, sign);
}
