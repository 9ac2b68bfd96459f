/**
 * The ocean test page's surface read back from its real vertex shader, vertex by vertex, against
 * the layers' fields on the CPU.
 */
import { Vector3 } from 'three';
import { OceanMaterial } from '../../../src/render/oceanMaterial';
import { finestTexel } from '../../../src/render/horizonGrid';
import { blendAngle, COPY_OFFSET, patchBlendUniforms } from '../../../src/layers/patchBlend';
import { camera, current, environment, renderer, scene, sunDirection } from './oceanPage';
import { captureVertices } from '../shared/vertexCapture';

/**
 * Draws the horizon grid as points with the real vertex shader (define CAPTURE_POSITIONS), one
 * float texel per vertex, reads back each vertex's displaced position and rest point, and checks
 * displaced − rest against the sum of the periodic layers' CPU fields (the contract's fieldsOnCpu:
 * the cascades' JS fields, and any layer added) sampled at the rest point (bilinear, REPEAT, at the
 * vertex's mip level in each layer, mips built by 2×2 averages as generateMipmap does), horizontal
 * parts scaled by the choppiness. The local waves are left out: no source has touched them here.
 */
export function geometryCheck(t: number, withRestPoints = false) {
  const sim = current.simulation!;
  const mesh = current.surface!;
  sim.update(t);
  mesh.onBeforeRender(renderer, scene, camera); // the viewport's ring size, and the rings under the camera
  const count = mesh.geometry.getAttribute('position').count;
  const material = new OceanMaterial({ environment, sunDirection: { value: sunDirection } }, {}, { CAPTURE_POSITIONS: 1 });
  const { choppiness } = sim.parameters;
  // Bound as the surface binds them (the local waves first: zero here, no source has touched them).
  material.bindLayers(sim.layers, choppiness, sim.foam.texture);
  for (const name of ['ringFrames', 'ringLayerUvOrigins', 'ringOffsets', 'halfRingCells', 'patchBlend']) {
    material.uniforms[name].value = mesh.material.uniforms[name].value;
  }
  const { displaced, rest } = captureVertices(renderer, camera, mesh.geometry, material);

  const layers = sim.layers
    .filter((layer) => layer.frame.periodic)
    .map((layer) => {
      const fields = layer.fieldsOnCpu(t);
      const n = layer.frame.resolution;
      const lodBias = material.uniforms.layerLodBias.value[sim.layers.indexOf(layer)] as number;
      return { size: layer.frame.size, n, fields, mips: mipChain(fields.displacement, n), lodBias };
    });
  // RMS of the summed height over the largest patch's grid (the sum does not repeat on a smaller one).
  const largest = layers[layers.length - 1];
  const n = largest.n;
  let sumSquares = 0;
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      const x = (i * largest.size) / n;
      const z = (j * largest.size) / n;
      let h = 0;
      for (const layer of layers) h += sampleBilinear(layer.fields.displacement, layer.n, x / layer.size + 0.5 / layer.n, z / layer.size + 0.5 / layer.n)[1];
      sumSquares += h * h;
    }
  }
  const rms = Math.sqrt(sumSquares / (n * n));
  const blend = patchBlendUniforms(largest.size, new Float64Array(12));
  /**
   * Σ over layers of the field sampled at rest point (x, z), each at its own mip level, the
   * largest as cos θ·P(x) + sin θ·P(x + o) (src/layers/patchBlend.ts).
   */
  const summed = (x: number, z: number, lod: number, pick: (layer: (typeof layers)[number], level: number) => Float32Array): number[] => {
    const total = [0, 0, 0, 0];
    const theta = blendAngle(blend, x, z);
    layers.forEach((layer, i) => {
      const level = Math.min(Math.max(0, Math.round(lod) + layer.lodBias), layer.mips.length - 1); // GL clamps
      const at = (u: number, v: number) => sampleBilinear(pick(layer, level), layer.n >> level, u + 0.5 / layer.n, v + 0.5 / layer.n);
      const [u, v] = [x / layer.size, z / layer.size];
      const copies: [number, number[]][] =
        i === layers.length - 1 ? [[Math.cos(theta), at(u, v)], [Math.sin(theta), at(u + COPY_OFFSET[0], v + COPY_OFFSET[1])]] : [[1, at(u, v)]];
      for (const [weight, value] of copies) for (let c = 0; c < 4; c++) total[c] += weight * value[c];
    });
    return total;
  };
  const byLevel: Record<string, { count: number; maxError: number }> = {};
  let skirt = 0;
  let maxOffGrid = 0;
  const heights: number[] = [];
  const restPoints: string[] = [];
  /** (x, y, z) displaced, and the Jacobian of the choppy map at the rest point. */
  const displacedAtMip0: [number, number, number, number][] = [];
  let farthest = 0;
  // The shader works in metres from the eye: back to world coordinates, in double precision.
  const eye = camera.getWorldPosition(new Vector3());
  for (let v = 0; v < count; v++) {
    const [restX, restZ, lod, ring] = rest.subarray(4 * v, 4 * v + 4);
    const [x, z] = [restX + eye.x, restZ + eye.z];
    const [px, py, pz] = [displaced[4 * v] + eye.x, displaced[4 * v + 1] + eye.y, displaced[4 * v + 2] + eye.z];
    farthest = Math.max(farthest, camera.position.distanceTo(new Vector3(px, py, pz)));
    if (lod > 500) { // SKIRT_LOD: the far edge, flat by design
      skirt++;
      continue;
    }
    const level = Math.min(Math.round(lod), layers[0].mips.length - 1); // of the finest layer
    const expected = summed(x, z, lod, (layer, mip) => layer.mips[mip]);
    const error = Math.max(
      Math.abs(px - x - choppiness * expected[0]),
      Math.abs(py - expected[1]),
      Math.abs(pz - z - choppiness * expected[2]),
    );
    const key = level === layers[0].mips.length - 1 ? 'coarsest' : String(level);
    byLevel[key] ??= { count: 0, maxError: 0 };
    byLevel[key].count++;
    byLevel[key].maxError = Math.max(byLevel[key].maxError, error / rms);
    // Rest points lie on the world grid of their ring: multiples of the ring's cell size (exact, in
    // double precision: the uniform's float32 cell is off by 6e-8 of itself, a whole cell at 10⁷ m).
    const cell = finestTexel(sim.layers) * 2 ** (mesh.material.uniforms.ringFrames.value[4 * ring + 3] as number);
    for (const c of [x, z]) maxOffGrid = Math.max(maxOffGrid, Math.abs(c / cell - Math.round(c / cell)));
    heights.push(py);
    if (level === 0 && layers.every((layer) => Math.round(lod) + layer.lodBias <= 0)) {
      const [, , dxx, dzz] = summed(x, z, 0, (layer) => layer.fields.derivatives);
      const dxz = choppiness * expected[3];
      displacedAtMip0.push([px, py, pz, (1 + choppiness * dxx) * (1 + choppiness * dzz) - dxz * dxz]);
    }
    // Keyed by the unclamped mip level: the coarser layers' levels go on growing past the finest's last.
    if (withRestPoints) restPoints.push(`${x},${z},${Math.round(lod)}`);
  }
  return { count, skirt, rms, byLevel, maxOffGrid, heights, restPoints, displacedAtMip0, farthest };
}

/** Mip levels of an RGBA N×N texture by 2×2 averaging, level 0 first. */
function mipChain(level0: Float32Array, n: number): Float32Array[] {
  const levels = [level0];
  for (let size = n / 2; size >= 1; size /= 2) {
    const previous = levels[levels.length - 1];
    const next = new Float32Array(4 * size * size);
    for (let j = 0; j < size; j++) {
      for (let i = 0; i < size; i++) {
        for (let c = 0; c < 4; c++) {
          const at = (jj: number, ii: number) => previous[4 * (jj * 2 * size + ii) + c];
          next[4 * (j * size + i) + c] = 0.25 * (at(2 * j, 2 * i) + at(2 * j, 2 * i + 1) + at(2 * j + 1, 2 * i) + at(2 * j + 1, 2 * i + 1));
        }
      }
    }
    levels.push(next);
  }
  return levels;
}

/** GL-style bilinear sample with REPEAT at (u, v) of an RGBA size×size texture. */
function sampleBilinear(data: Float32Array, size: number, u: number, v: number): number[] {
  const x = u * size - 0.5;
  const y = v * size - 0.5;
  const x0 = Math.floor(x);
  const y0 = Math.floor(y);
  const fx = x - x0;
  const fy = y - y0;
  const wrap = (i: number) => ((i % size) + size) % size;
  const texel = (i: number, j: number, c: number) => data[4 * (wrap(j) * size + wrap(i)) + c];
  return [0, 1, 2, 3].map(
    (c) =>
      (1 - fy) * ((1 - fx) * texel(x0, y0, c) + fx * texel(x0 + 1, y0, c)) +
      fy * ((1 - fx) * texel(x0, y0 + 1, c) + fx * texel(x0 + 1, y0 + 1, c)),
  );
}
