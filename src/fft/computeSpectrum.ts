/**
 * The time evolution of a cascade's spectrum in a WebGPU compute shader, into the compute FFT's
 * buffer (computeFft.ts): the TSL twin of shaders/fft/evolveSpectrum.frag (the WebGL GPU path's
 * evolution pass), which computes what CpuWaveFields.evolve (cpuWaveFields.ts) does in JS.
 *
 *   h̃(k, t) = h̃0(k)·e^{iωt} + h̃0*(−k)·e^{−iωt}        (Tessendorf 2001, eq. 26)
 *   ω = m·2π/T, m the mode's quantized frequency index, with the water's depth in it
 *   (src/spectrum/dispersion.ts, Tessendorf 2001, eqs. 15 and 17), stored in waveVectors.w
 * and the four packed field spectra of waveFieldLayout.ts (Tessendorf 2001, eqs. 20, 29, and the
 * slopes and Jacobian terms of §4.6) as multiples of h̃.
 *
 * Precision. A float32 phase ω·t would lose the waves' phases within minutes. As on the WebGL GPU
 * path, e^{iωt} comes from the phase table of dispersion.ts, computed each update in double
 * precision from t wrapped into the repeat period: e^{i·m·φ} = table[m mod 256].low ·
 * table[m div 256].high. The kernel multiplies two unit complex numbers and never calls WGSL's
 * sin or cos (SwiftShader's are off by up to 1.9e-4).
 *
 * Buffers: amplitudes (h̃0(k), h̃0*(−k)) and wave vectors (kx, kz, 1/k, m), N² vec4 each, from
 * initialSpectrum.ts, static; the phase table, 256 vec4, uploaded at each update. The spectra are
 * written to the FFT's buffer, field f's texel (i, j) at f·N² + j·N + i, every texel (the modes
 * outside the cascade's band have zero amplitudes, so they write zeros). Owns its three buffers
 * and the kernel; dispose() frees them.
 */
import { StorageBufferAttribute, type ComputeNode, type StorageBufferNode, type WebGPURenderer } from 'three/webgpu';
import { Fn, instanceIndex, storage, uint } from 'three/tsl';
import { fillPhaseTable, PHASE_TABLE_SIZE } from '../spectrum/dispersion';
import type { InitialSpectrum } from '../spectrum/initialSpectrum';
import { complexConjugate, complexMultiply, timesI } from './complexNodes';

/** Invocations per workgroup: one per texel. */
const WORKGROUP = 64;

export class ComputeSpectrumEvolution {
  private readonly amplitudes: StorageBufferAttribute;
  private readonly waveVectors: StorageBufferAttribute;
  /** (cos jφ, sin jφ, cos 256jφ, sin 256jφ) for j < 256: dispersion.ts' fillPhaseTable. */
  private readonly phases: StorageBufferAttribute;
  private readonly kernel: ComputeNode;
  private readonly repeatPeriod: number;

  /** `spectra`: the FFT's buffer (ComputeInverseFft2D.fields) of four fields of N² each. */
  constructor(
    private readonly renderer: WebGPURenderer,
    spectrum: Pick<InitialSpectrum, 'resolution' | 'repeatPeriod' | 'amplitudes' | 'waveVectors'>,
    spectra: StorageBufferNode<'vec2'>,
  ) {
    const n = spectrum.resolution;
    this.repeatPeriod = spectrum.repeatPeriod;
    this.amplitudes = new StorageBufferAttribute(spectrum.amplitudes, 4);
    this.waveVectors = new StorageBufferAttribute(spectrum.waveVectors, 4);
    this.phases = new StorageBufferAttribute(new Float32Array(4 * PHASE_TABLE_SIZE), 4);
    const amplitudes = storage(this.amplitudes, 'vec4', n * n).toReadOnly();
    const waveVectors = storage(this.waveVectors, 'vec4', n * n).toReadOnly();
    const phases = storage(this.phases, 'vec4', PHASE_TABLE_SIZE).toReadOnly();
    const evolve = Fn(() => {
      const texel = instanceIndex;
      const amplitude = amplitudes.element(texel).toVar();
      const wave = waveVectors.element(texel).toVar();
      const m = uint(wave.w).toVar(); // an exact integer < 256², stored as a float
      // e^{iωt} = e^{i·(m mod 256)·φ} · e^{i·256·(m div 256)·φ}, both factors exact from double precision.
      const phase = complexMultiply(phases.element(m.bitAnd(uint(PHASE_TABLE_SIZE - 1))).xy, phases.element(m.shiftRight(uint(8))).zw).toVar();
      const h = complexMultiply(amplitude.xy, phase).add(complexMultiply(amplitude.zw, complexConjugate(phase))).toVar();
      const kx = wave.x;
      const kz = wave.y;
      const d = wave.z; // λ/k with λ = 1: the surface scales by the choppiness (waveFieldLayout.ts)
      const slopeX = timesI(h.mul(kx)).toVar(); // i·kx·h̃
      const slopeZ = timesI(h.mul(kz)).toVar(); // i·kz·h̃
      const dispX = slopeX.mul(d); // i·λ·kx/k·h̃
      const dispZ = slopeZ.mul(d);
      const dispXZ = h.mul(d.mul(kx).mul(kz).negate()); // −λ·kx·kz/k·h̃
      const dispXX = h.mul(d.mul(kx).mul(kx).negate());
      const dispZZ = h.mul(d.mul(kz).mul(kz).negate());
      // F + i·G packs two real fields into one complex transform, in waveFieldLayout.ts' order.
      const packed = [dispX.add(timesI(h)), dispZ.add(timesI(dispXZ)), slopeX.add(timesI(slopeZ)), dispXX.add(timesI(dispZZ))];
      packed.forEach((value, f) => spectra.element(texel.add(uint(f * n * n))).assign(value));
    });
    this.kernel = evolve().compute(n * n, [WORKGROUP]);
  }

  /** Queues the evolution to time t (s, any finite value) into the FFT's buffer. */
  run(t: number): void {
    fillPhaseTable(this.phases.array as Float32Array, t, this.repeatPeriod);
    this.phases.needsUpdate = true;
    void this.renderer.compute(this.kernel);
  }

  dispose(): void {
    this.kernel.dispose();
    for (const buffer of [this.amplitudes, this.waveVectors, this.phases]) buffer.dispose();
  }
}
