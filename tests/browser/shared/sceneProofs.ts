/**
 * Measures the proofs of the scene in the sea share (the WebGL Ocean's tests/browser/reflections and
 * refractions, the WebGPU Ocean's tests/browser/webgpu/sceneLight.spec.ts): the pixels a reflection
 * made redder, their bounds, whether a ray meets a box, and Fresnel's reflectance of water.
 */

export type Vec3 = [number, number, number];
/** The RGB levels of a picture's pixel (x, y), y from the top. */
export type PixelReader = (x: number, y: number) => Vec3;

/** Pixels whose red rose against the other picture by more than `threshold` over their green and blue. */
export function redderPixels(scene: PixelReader, sky: PixelReader, width: number, height: number, threshold: number): [number, number][] {
  const found: [number, number][] = [];
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const a = scene(x, y);
      const b = sky(x, y);
      if (a[0] - b[0] - Math.max(a[1] - b[1], a[2] - b[2], 0) > threshold) found.push([x, y]);
    }
  }
  return found;
}

export function bounds(points: [number, number][]): { left: number; right: number; top: number; bottom: number } {
  const xs = points.map((p) => p[0]);
  const ys = points.map((p) => p[1]);
  return { left: Math.min(...xs), right: Math.max(...xs), top: Math.min(...ys), bottom: Math.max(...ys) };
}

/**
 * Unpolarized Fresnel reflectance from air into water at incidence cos θi (Fresnel equations,
 * Hecht, "Optics", 5th ed., §4.6.2, eqs. 4.42–4.43, with Snell's law n_a·sin θi = n_w·sin θt):
 *   r_s = (cos θi − n·cos θt)/(cos θi + n·cos θt),  r_p = (n·cos θi − cos θt)/(n·cos θi + cos θt),
 *   R = (r_s² + r_p²)/2.
 */
export function fresnelReflectance(cosI: number, n: number): number {
  const cosT = Math.sqrt(1 - (1 - cosI * cosI) / (n * n));
  const rs = (cosI - n * cosT) / (cosI + n * cosT);
  const rp = (n * cosI - cosT) / (n * cosI + cosT);
  return (rs * rs + rp * rp) / 2;
}

/** Whether the ray o + t·d (t > 0) meets the box grown by `margin` metres (the slab method). */
export function rayMeetsBox(o: Vec3, d: Vec3, centre: Vec3, size: Vec3, margin: number): boolean {
  let near = 0;
  let far = Infinity;
  for (let a = 0; a < 3; a++) {
    const low = centre[a] - size[a] / 2 - margin;
    const high = centre[a] + size[a] / 2 + margin;
    if (Math.abs(d[a]) < 1e-12) {
      if (o[a] < low || o[a] > high) return false;
      continue;
    }
    const t1 = (low - o[a]) / d[a];
    const t2 = (high - o[a]) / d[a];
    near = Math.max(near, Math.min(t1, t2));
    far = Math.min(far, Math.max(t1, t2));
  }
  return near <= far;
}
