/**
 * The WebGPU spec files' pictures: saving what a page read back as a PNG to look at, and how far
 * one picture is from another (the WebGPU Ocean's from the WebGL Ocean's).
 */
import { writeFileSync } from 'node:fs';
import { PNG } from 'pngjs';

/** A decoded picture. */
export type Picture = InstanceType<typeof PNG>;

/** Writes an RGBA picture { width, height, data } (rows from the top) as a PNG under .tmp/ and returns it decoded. */
export function savePicture({ width, height, data }: { width: number; height: number; data: number[] }, name: string): Picture {
  const png = new PNG({ width, height });
  png.data.set(data);
  writeFileSync(`.tmp/${name}.png`, PNG.sync.write(png));
  return png;
}

/**
 * How far picture `a` is from `b` over rows [fromRow, toRow): the mean absolute difference of the
 * RGB levels, the share of pixels whose every channel is within 8 levels (and the number beyond),
 * the share whose green and blue are (`greenBlueWithin8`: the WebGL Ocean dithers its background,
 * dither.glsl, by ±1/255 of the linear value an sRGB target then encodes, up to 13 levels in the
 * deep water's red, which is 0, and 1–2 in its green and blue; the WebGPU Ocean's sky is not
 * dithered), and the largest difference; also writes the difference (|a − b| × 8, so a 32-level
 * miss is white) as a PNG.
 */
export function pictureDifference(a: Picture, b: Picture, name: string, fromRow = 0, toRow = a.height): { mean: number; within8: number; beyond8: number; greenBlueWithin8: number; worst: number } {
  const difference = new PNG({ width: a.width, height: a.height });
  let sum = 0;
  let within = 0;
  let greenBlueWithin = 0;
  let worst = 0;
  for (let p = fromRow * a.width; p < toRow * a.width; p++) {
    let largest = 0;
    for (let c = 0; c < 3; c++) {
      const d = Math.abs(a.data[4 * p + c] - b.data[4 * p + c]);
      sum += d;
      largest = Math.max(largest, d);
      difference.data[4 * p + c] = Math.min(255, 8 * d);
    }
    difference.data[4 * p + 3] = 255;
    if (largest <= 8) within++;
    if (Math.abs(a.data[4 * p + 1] - b.data[4 * p + 1]) <= 8 && Math.abs(a.data[4 * p + 2] - b.data[4 * p + 2]) <= 8) greenBlueWithin++;
    worst = Math.max(worst, largest);
  }
  writeFileSync(`.tmp/${name}.png`, PNG.sync.write(difference));
  const count = (toRow - fromRow) * a.width;
  return { mean: sum / (3 * count), within8: within / count, beyond8: count - within, greenBlueWithin8: greenBlueWithin / count, worst };
}
