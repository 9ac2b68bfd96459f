/**
 * Inverse 2D FFT in WebGPU compute shaders (three.js's WebGPURenderer on its WebGPU backend), for
 * several complex fields at once, with the convention of the JS FFT (fft.ts):
 *   f(x_n, z_m) = Σ_{n', m'} F(n', m') · e^{+2πi·(n·n' + m·m')/N}   (no 1/N² factor, no shift)
 * so that its output is directly comparable with BatchedInverseFft2D's.
 *
 * Layout. One storage buffer of vec2<f32> (real, imaginary), field f's texel (column i, row j) at
 * f·N² + j·N + i, in natural order both as input (frequency texel) and as output (sample): the
 * transform works in place. With the four packed spectra of waveFieldLayout.ts as the fields, the
 * output holds the same numbers as the two field textures (field 2t in channels 0–1 of texture t,
 * field 2t + 1 in channels 2–3).
 *
 * Algorithm. The Stockham autosort FFT (Van Loan, "Computational Frameworks for the FFT", SIAM
 * 1992, §1.7), mixed radix as Govindaraju et al. give it for GPUs ("High Performance Discrete
 * Fourier Transforms on Graphics Processors", SC 2008): each stage reads a whole line and writes it
 * into a second array, reordered so that natural-order input gives natural-order output with no bit
 * reversal. A stage of radix R on sub-transforms of length Ns has butterfly u < N/R, k = u mod Ns:
 *   x_r = ω^{r·k}·in[u + r·N/R],  ω = e^{2πi/(R·Ns)},  r < R
 *   out[R·Ns·⌊u/Ns⌋ + k + q·Ns] = Σ_r x_r·e^{2πi·r·q/R},  q < R.
 * Radix 4 throughout (after one radix-2 stage when log2 N is odd) halves the stages, and so the
 * workgroup barriers, against radix 2.
 * One dispatch per axis: a workgroup transforms one line (one row or one column of one field) of N
 * values in workgroup memory, with N/4 invocations (one radix-4 butterfly or two radix-2 ones each
 * per stage). The first stage reads the line from the storage buffer and the last writes it back, so
 * the buffer is both input and output. Workgroup memory is two ping-pong arrays of N vec2<f32>: 8 KiB
 * at N = 512, within WebGPU's default maxComputeWorkgroupStorageSize (16 KiB), with 128 invocations
 * (the default maxComputeInvocationsPerWorkgroup is 256); N = 1024 would need the whole 16 KiB for
 * the two arrays, so N stops at 512, which is the largest cascade anyway. The defaults are what
 * every adapter offers, and three creates its device with them. (Measured once under SwiftShader
 * on a loaded machine: radix 2, with workgroups of 256 invocations at N = 512, took about 1.7×
 * as long a pass.)
 *
 * Twiddles. ω^{r·k} for every stage is e^{2πi·m/N} with m = r·k·N/(R·Ns) < 3N/4, so one table of
 * N values serves all stages. It is computed in double precision in JS and uploaded: WGSL's sin and
 * cos are approximations (SwiftShader's are off by up to 1.9e-4), which alone would put the result
 * off by about 5e-4 of its RMS.
 */
import { StorageBufferAttribute, type ComputeNode, type Node, type StorageBufferNode, type WebGPURenderer } from 'three/webgpu';
import { Fn, instanceIndex, storage, uint, workgroupArray, workgroupBarrier } from 'three/tsl';
import { complexMultiply, timesI } from './complexNodes';
import { MAX_SIZE, MIN_SIZE } from './computeSupport';
import { ParameterError } from '../parameters/options';
import type { Vec2Node } from '../webgpu/nodeTypes';

/** A u32 index in a kernel. */
type UintNode = Node<'uint'>;
/** A workgroup array of vec2 as the kernel uses it (@types/three leaves out its element()). */
type Vec2Array = { element(index: UintNode): Vec2Node };


export class ComputeInverseFft2D {
  /** The fields, in and out: 2·fieldCount·N² floats, (re, im) of field f's texel (i, j) at 2·((f·N + j)·N + i). */
  readonly data: StorageBufferAttribute;
  /** `data` for TSL nodes that read the fields (vec2 elements). */
  readonly fields: StorageBufferNode<'vec2'>;
  private readonly twiddles: StorageBufferAttribute;
  private readonly passes: readonly [ComputeNode, ComputeNode];

  constructor(
    private readonly renderer: WebGPURenderer,
    readonly size: number,
    readonly fieldCount: number,
  ) {
    if (!Number.isInteger(size) || size < MIN_SIZE || size > MAX_SIZE || (size & (size - 1)) !== 0) {
      throw new ParameterError('compute FFT size', size, `a power of two from ${MIN_SIZE} to ${MAX_SIZE}`);
    }
    if (!Number.isInteger(fieldCount) || fieldCount < 1) throw new ParameterError('compute FFT field count', fieldCount, 'a whole number ≥ 1');
    const n = size;
    this.data = new StorageBufferAttribute(new Float32Array(2 * fieldCount * n * n), 2);
    this.fields = storage(this.data, 'vec2', fieldCount * n * n);
    const table = new Float32Array(2 * n);
    for (let m = 0; m < n; m++) {
      const angle = (2 * Math.PI * m) / n; // + sign: inverse transform
      table[2 * m] = Math.cos(angle);
      table[2 * m + 1] = Math.sin(angle);
    }
    this.twiddles = new StorageBufferAttribute(table, 2);
    this.passes = [this.pass('x'), this.pass('z')];
  }

  /** Queues the transform of `data` (after uploading it if its needsUpdate was set): along x, then z. */
  run(): void {
    void this.renderer.compute([...this.passes]);
  }

  dispose(): void {
    for (const pass of this.passes) pass.dispose();
    this.data.dispose();
    this.twiddles.dispose();
  }

  /** The dispatch that transforms every line along `axis` of every field: one workgroup per line. */
  private pass(axis: 'x' | 'z'): ComputeNode {
    const n = this.size;
    const quarter = n / 4;
    // Radix 4 throughout, after one radix-2 stage when log2 N is odd.
    const radices = [...(Math.log2(n) % 2 === 1 ? [2] : []), ...Array<number>(Math.floor(Math.log2(n) / 2)).fill(4)];
    const fields = this.fields;
    const twiddles = storage(this.twiddles, 'vec2', n).toReadOnly();
    const kernel = Fn(() => {
      const line = instanceIndex.div(uint(quarter));
      const t = instanceIndex.bitAnd(uint(quarter - 1));
      // Lines along x are rows, contiguous; along z, column i of field f starts at f·N² + i.
      const first = axis === 'x' ? line.mul(uint(n)) : line.div(uint(n)).mul(uint(n * n)).add(line.bitAnd(uint(n - 1)));
      const stride = uint(axis === 'x' ? 1 : n);
      const at = (position: UintNode): UintNode => first.add(position.mul(stride));
      const work = workgroupArray('vec2', 2 * n) as unknown as Vec2Array;
      let ns = 1;
      radices.forEach((radix, s) => {
        // Stage s reads half (s − 1) mod 2 of the workgroup array and writes half s mod 2; the
        // first reads the storage buffer, the last writes it.
        const source = uint(((s + 1) % 2) * n);
        const target = uint((s % 2) * n);
        const last = s === radices.length - 1;
        const read = (position: UintNode): Vec2Node => (s === 0 ? fields.element(at(position)) : work.element(position.add(source)));
        const write = (position: UintNode, value: Vec2Node): void => {
          (last ? fields.element(at(position)) : work.element(position.add(target))).assign(value);
        };
        // The N/radix butterflies of the stage, 4/radix per invocation.
        for (let u = 0; u < quarter * 4; u += quarter * radix) {
          const butterfly = t.add(uint(u / radix));
          const k = butterfly.bitAnd(uint(ns - 1));
          const x = Array.from({ length: radix }, (_, r) => read(butterfly.add(uint((r * n) / radix))).toVar());
          if (ns > 1) {
            for (let r = 1; r < radix; r++) x[r].assign(complexMultiply(x[r], twiddles.element(k.mul(uint((r * n) / (radix * ns))))));
          }
          const out = butterfly.sub(k).mul(uint(radix)).add(k);
          dft(x).forEach((value, q) => write(out.add(uint(q * ns)), value));
        }
        if (!last) workgroupBarrier();
        ns *= radix;
      });
    });
    return kernel().compute(this.fieldCount * n * quarter, [quarter]);
  }
}

/** The inverse DFT of 2 or 4 values, y_q = Σ_r x_r·e^{+2πi·r·q/R}: for R = 4, e^{iπ/2·rq} = i^{rq}. */
function dft(x: readonly Vec2Node[]): Vec2Node[] {
  if (x.length === 2) return [x[0].add(x[1]), x[0].sub(x[1])];
  const even = x[0].add(x[2]).toVar();
  const evenDifference = x[0].sub(x[2]).toVar();
  const odd = x[1].add(x[3]).toVar();
  const oddDifference = x[1].sub(x[3]).toVar();
  const rotated = timesI(oddDifference);
  return [even.add(odd), evenDifference.add(rotated), even.sub(odd), evenDifference.sub(rotated)];
}
