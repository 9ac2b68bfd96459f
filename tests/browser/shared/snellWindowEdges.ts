/**
 * Where Snell's window ends in a square picture taken straight up from under a calm sea with a
 * lens of `fov` degrees, as the WebGL Ocean's and the WebGPU Ocean's tests measure it: along the
 * picture's middle row and column, scanning out from the centre, the angle from the zenith of the
 * first pixel that shows only deep water (`red(x, y)` 0: scatterColor has no red), degrees.
 * `size`: the picture's side in pixels.
 */
export function snellWindowEdges(red: (x: number, y: number) => number, size: number, fov: number): number[] {
  const centre = size / 2;
  const toAngle = (pixelsFromCentre: number) => (Math.atan((pixelsFromCentre / centre) * Math.tan(((fov / 2) * Math.PI) / 180)) * 180) / Math.PI;
  const edgeAngles: number[] = [];
  for (const [dx, dy] of [[1, 0], [-1, 0], [0, 1], [0, -1]]) {
    for (let r = 0; r < centre; r++) {
      if (red(centre + dx * r, centre + dy * r) === 0) {
        edgeAngles.push(toAngle(r - 0.5)); // the edge lies between this pixel's centre and the last lit one's
        break;
      }
    }
  }
  return edgeAngles;
}
