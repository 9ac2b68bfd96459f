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
 * Algorithm. The Stockham autosort formulation of the radix-2 FFT (Van Loan, "Computational
 * Frameworks for the FFT and Convolution", SIAM 1992, §1.7; in the GPU form of Govindaraju et al.,
 * "High Performance Discrete Fourier Transforms on Graphics Processors", SC 2008): each stage reads
 * a whole line and writes it into a second array, reordered so that natural-order input gives
 * natural-order output with no bit reversal. Stage s (Ns = 2^s) has thread t < N/2 combine elements
 * t and t + N/2 with k = t mod Ns:
 *   a = x[t],  b = ω^k·x[t + N/2],  ω = e^{2πi/2Ns}
 *   y[2Ns·⌊t/Ns⌋ + k] = a + b,   y[2Ns·⌊t/Ns⌋ + k + Ns] = a − b.
 * One dispatch per axis: a workgroup transforms one line (one row or one column of one field) of
 * N values in workgroup memory, N/2 invocations, one butterfly each per stage. The first stage
 * reads the line from the storage buffer and the last writes it back, so the buffer is both input
 * and output. Workgroup memory is two ping-pong arrays of N vec2<f32>: 8 KiB at N = 512, within
 * WebGPU's default maxComputeWorkgroupStorageSize (16 KiB); N/2 = 256 invocations at N = 512 is
 * WebGPU's default maxComputeInvocationsPerWorkgroup, which is why N stops at 512 (the default
 * limits are what every adapter offers; the device is three's, created with them).
 *
 * Twiddles. ω^k for every stage is e^{2πi·m/N} with m = k·N/2Ns < N/2, so one table of N/2 values
 * serves all stages. It is computed in double precision in JS and uploaded: WGSL's sin and cos are
 * approximations (SwiftShader's are off by up to 1.9e-4), which alone would put the result off by
 * about 5e-4 of its RMS.
 */
import { StorageBufferAttribute, type ComputeNode, type Node, type StorageBufferNode, type WebGPURenderer } from 'three/webgpu';
import { Fn, instanceIndex, storage, uint, vec2, workgroupArray, workgroupBarrier } from 'three/tsl';
import { ParameterError } from '../parameters/options';
import type { Vec2Node } from '../webgpu/nodeTypes';

/** A u32 index in a kernel. */
type UintNode = Node<'uint'>;
/** A workgroup array of vec2 as the kernel uses it (@types/three leaves out its element()). */
type Vec2Array = { element(index: UintNode): Vec2Node };

/** The sizes one workgroup per line can transform under WebGPU's default limits (see above). */
const MIN_SIZE = 16;
const MAX_SIZE = 512;

export class ComputeInverseFft2D {
  /** The fields, in and out: 2·fieldCount·N² floats, (re, im) of field f's texel (i, j) at 2·index(f, i, j). */
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
    const table = new Float32Array(n);
    for (let m = 0; m < n / 2; m++) {
      const angle = (2 * Math.PI * m) / n; // + sign: inverse transform
      table[2 * m] = Math.cos(angle);
      table[2 * m + 1] = Math.sin(angle);
    }
    this.twiddles = new StorageBufferAttribute(table, 2);
    this.passes = [this.pass('x'), this.pass('z')];
  }

  /** Where field f's texel (column i, row j) is, in vec2 elements of `data` (twice that in floats). */
  index(field: number, i: number, j: number): number {
    return (field * this.size + j) * this.size + i;
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
    const half = n / 2;
    const stages = Math.log2(n);
    const fields = this.fields;
    const twiddles = storage(this.twiddles, 'vec2', half).toReadOnly();
    const kernel = Fn(() => {
      const line = instanceIndex.div(uint(half));
      const t = instanceIndex.bitAnd(uint(half - 1));
      // Lines along x are rows, contiguous; along z, column i of field f starts at f·N² + i.
      const first = axis === 'x' ? line.mul(uint(n)) : line.div(uint(n)).mul(uint(n * n)).add(line.bitAnd(uint(n - 1)));
      const stride = uint(axis === 'x' ? 1 : n);
      const at = (position: UintNode): UintNode => first.add(position.mul(stride));
      const work = workgroupArray('vec2', 2 * n) as unknown as Vec2Array;
      for (let s = 0; s < stages; s++) {
        const ns = 1 << s;
        // Stage s reads from half (s − 1) mod 2 of the workgroup array and writes half s mod 2; the
        // first reads the storage buffer, the last writes it.
        const source = ((s + 1) % 2) * n;
        const target = (s % 2) * n;
        const a = (s === 0 ? fields.element(at(t)) : work.element(t.add(uint(source)))).toVar();
        const b = (s === 0 ? fields.element(at(t.add(uint(half)))) : work.element(t.add(uint(source + half)))).toVar();
        const k = t.bitAnd(uint(ns - 1));
        if (s > 0) {
          const w = twiddles.element(k.mul(uint(n / (2 * ns))));
          b.assign(vec2(b.x.mul(w.x).sub(b.y.mul(w.y)), b.x.mul(w.y).add(b.y.mul(w.x))));
        }
        const out = t.sub(k).mul(uint(2)).add(k);
        if (s < stages - 1) {
          work.element(out.add(uint(target))).assign(a.add(b));
          work.element(out.add(uint(target + ns))).assign(a.sub(b));
          workgroupBarrier();
        } else {
          fields.element(at(out)).assign(a.add(b));
          fields.element(at(out.add(uint(ns)))).assign(a.sub(b));
        }
      }
    });
    return kernel().compute(this.fieldCount * n * half, [half]);
  }
}
