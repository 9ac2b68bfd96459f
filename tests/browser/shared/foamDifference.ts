/**
 * How far a whitecap foam field is from the JS path's (the tests of the GPU foams against it:
 * tests/browser/simulation, the fragment passes; tests/browser/fft, the compute shader).
 */

/** The mean coverage of `inJs` and the largest difference of any texel of `other` from it (Infinity where one is NaN). */
export function foamDifference(inJs: Float32Array, other: Float32Array): { meanCoverage: number; maxDifference: number } {
  let maxDifference = 0;
  let sum = 0;
  inJs.forEach((value, i) => {
    const difference = Math.abs(value - other[i]);
    maxDifference = Number.isNaN(difference) ? Infinity : Math.max(maxDifference, difference);
    sum += value;
  });
  return { meanCoverage: sum / inJs.length, maxDifference };
}
