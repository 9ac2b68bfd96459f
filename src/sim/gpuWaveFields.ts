/**
 * The GPU simulation path: every field of waveFieldLayout.ts computed in fragment-shader passes
 * over float render targets (WebGL2 through three.js), with no CPU readback.
 *
 * Per update: one pass evolves the spectrum into two render targets (MRT) holding the four packed
 * complex spectra, then log4-many Stockham passes along x and as many along z (a radix-2 pass
 * first when log2 N is odd) ping-pong between two such targets. The last pass writes into the
 * output target, whose two textures (`displacement`, `derivatives`) wrap with REPEAT and, where the
 * format is filterable, filter linearly with mipmaps generated after the pass.
 *
 * Textures (all N×N RGBA unless said):
 *   amplitudes  (h̃0(k), h̃0*(−k))               static, from spectrum.ts
 *   waveVectors (kx, kz, 1/k, m)                static, from spectrum.ts
 *   phases      256×1, (e^{ijφ}, e^{i256jφ})    uploaded each update, from dispersion.ts
 *   twiddles    N×1, (cos 2πj/N, sin 2πj/N)     static
 *   ping, pong  2 targets × (packed spectra)    working storage
 *   output      (displacement, derivatives)     the result
 * This object owns all of them and frees them in dispose().
 */
import {
  BufferAttribute,
  BufferGeometry,
  Camera,
  DataTexture,
  FloatType,
  GLSL3,
  HalfFloatType,
  LinearFilter,
  LinearMipmapLinearFilter,
  Mesh,
  NearestFilter,
  RepeatWrapping,
  RGBAFormat,
  RGFormat,
  ShaderMaterial,
  WebGLRenderTarget,
  type PixelFormat,
  type Texture,
  type TextureDataType,
  type WebGLRenderer,
} from 'three';
import { shaderSource } from '../shaderSource';
import { fillPhaseTable, PHASE_TABLE_SIZE } from './dispersion';
import type { InitialSpectrum } from './spectrum';
import { FIELD_TEXTURES } from './waveFieldLayout';

export type GpuPrecision = 'float32' | 'float16';

/** The FFT runs along x (alongZ = false), then along z. */
const AXES = [false, true] as const;

/** Which GPU precision this renderer can render to, best first; null when neither works. */
export function supportedGpuPrecision(renderer: WebGLRenderer): GpuPrecision | null {
  if (!renderer.capabilities.isWebGL2) return null;
  if (renderer.extensions.has('EXT_color_buffer_float')) return 'float32';
  if (renderer.extensions.has('EXT_color_buffer_half_float')) return 'float16';
  return null;
}

export class GpuWaveFields {
  /** (Dx, h, Dz, ∂Dx/∂z) */
  readonly displacement: Texture;
  /** (∂h/∂x, ∂h/∂z, ∂Dx/∂x, ∂Dz/∂z) */
  readonly derivatives: Texture;
  /** Fragment passes per update (evolution + FFT). */
  readonly passCount: number;
  readonly output: WebGLRenderTarget;

  private readonly amplitudes: DataTexture;
  private readonly waveVectors: DataTexture;
  private readonly phases: DataTexture;
  private readonly twiddles: DataTexture;
  private readonly ping: WebGLRenderTarget;
  private readonly pong: WebGLRenderTarget;
  private readonly evolveMaterial: ShaderMaterial;
  private readonly radix4Material: ShaderMaterial;
  private readonly radix2Material: ShaderMaterial | null;
  private readonly quad: Mesh;
  private readonly camera = new Camera();
  /** Sub-transform lengths p before each pass along one axis, and the radix of that pass. */
  private readonly stages: { radix: 2 | 4; subtransformSize: number }[] = [];

  constructor(
    private readonly renderer: WebGLRenderer,
    spectrum: InitialSpectrum,
    choppiness: number,
    private readonly repeatPeriod: number,
    readonly precision: GpuPrecision,
  ) {
    const n = spectrum.resolution;
    const type: TextureDataType = precision === 'float32' ? FloatType : HalfFloatType;
    this.amplitudes = dataTexture(spectrum.amplitudes, n, n, RGBAFormat);
    this.waveVectors = dataTexture(spectrum.waveVectors, n, n, RGBAFormat);
    this.phases = dataTexture(new Float32Array(4 * PHASE_TABLE_SIZE), PHASE_TABLE_SIZE, 1, RGBAFormat);
    const twiddleTable = new Float32Array(2 * n);
    for (let j = 0; j < n; j++) {
      twiddleTable[2 * j] = Math.cos((2 * Math.PI * j) / n);
      twiddleTable[2 * j + 1] = Math.sin((2 * Math.PI * j) / n);
    }
    this.twiddles = dataTexture(twiddleTable, n, 1, RGFormat);

    this.ping = workTarget(n, type);
    this.pong = workTarget(n, type);
    // Float32 textures filter linearly only with OES_texture_float_linear; half floats always do.
    const filterable = precision === 'float16' || renderer.extensions.has('OES_texture_float_linear');
    this.output = new WebGLRenderTarget(n, n, {
      count: 2,
      type,
      format: RGBAFormat,
      depthBuffer: false,
      wrapS: RepeatWrapping,
      wrapT: RepeatWrapping,
      magFilter: filterable ? LinearFilter : NearestFilter,
      minFilter: filterable ? LinearMipmapLinearFilter : NearestFilter,
      generateMipmaps: filterable,
    });
    [this.displacement, this.derivatives] = this.output.textures;
    this.output.textures.forEach((texture, i) => (texture.name = FIELD_TEXTURES[i]));

    const vertexShader = shaderSource('sim/fullscreen.vert');
    this.evolveMaterial = new ShaderMaterial({
      glslVersion: GLSL3,
      vertexShader,
      fragmentShader: shaderSource('sim/evolveSpectrum.frag'),
      uniforms: {
        tAmplitudes: { value: this.amplitudes },
        tWaveVectors: { value: this.waveVectors },
        tPhases: { value: this.phases },
        choppiness: { value: choppiness },
      },
      depthTest: false,
      depthWrite: false,
    });
    const fftMaterial = (radix: number): ShaderMaterial =>
      new ShaderMaterial({
        glslVersion: GLSL3,
        defines: { RADIX: radix, RADIX_LOG2: Math.log2(radix) },
        vertexShader,
        fragmentShader: shaderSource('sim/fftPass.frag'),
        uniforms: {
          tSpectra0: { value: null },
          tSpectra1: { value: null },
          tTwiddles: { value: this.twiddles },
          sizeLog2: { value: Math.log2(n) },
          subtransformLog2: { value: 0 },
          alongZ: { value: false },
        },
        depthTest: false,
        depthWrite: false,
      });
    this.radix4Material = fftMaterial(4);
    const log2 = Math.log2(n);
    this.radix2Material = log2 % 2 === 1 ? fftMaterial(2) : null;
    let p = 1;
    if (this.radix2Material) {
      this.stages.push({ radix: 2, subtransformSize: 1 });
      p = 2;
    }
    for (; p < n; p *= 4) this.stages.push({ radix: 4, subtransformSize: p });
    this.passCount = 1 + 2 * this.stages.length;

    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(new Float32Array([-1, -1, 0, 3, -1, 0, -1, 3, 0]), 3));
    this.quad = new Mesh(geometry, this.evolveMaterial);
    this.quad.frustumCulled = false;
  }

  /** Computes every field at time t (seconds) into `displacement` and `derivatives`. */
  update(t: number): void {
    fillPhaseTable(this.phases.image.data as Float32Array, t, this.repeatPeriod);
    this.phases.needsUpdate = true;

    const renderer = this.renderer;
    const previousTarget = renderer.getRenderTarget();
    const previousXr = renderer.xr.enabled;
    renderer.xr.enabled = false;

    this.draw(this.evolveMaterial, this.ping);
    let source = this.ping;
    let spare = this.pong;
    const passes = this.stages.length * 2;
    let pass = 0;
    for (const alongZ of AXES) {
      for (const stage of this.stages) {
        const material = stage.radix === 4 ? this.radix4Material : this.radix2Material!;
        const uniforms = material.uniforms;
        uniforms.tSpectra0.value = source.textures[0];
        uniforms.tSpectra1.value = source.textures[1];
        uniforms.subtransformLog2.value = Math.log2(stage.subtransformSize);
        uniforms.alongZ.value = alongZ;
        pass++;
        const target = pass === passes ? this.output : spare;
        this.draw(material, target);
        spare = source;
        source = target;
      }
    }

    renderer.xr.enabled = previousXr;
    renderer.setRenderTarget(previousTarget);
  }

  private draw(material: ShaderMaterial, target: WebGLRenderTarget): void {
    this.quad.material = material;
    this.renderer.setRenderTarget(target);
    this.renderer.render(this.quad, this.camera);
  }

  dispose(): void {
    for (const texture of [this.amplitudes, this.waveVectors, this.phases, this.twiddles]) texture.dispose();
    for (const target of [this.ping, this.pong, this.output]) target.dispose();
    this.evolveMaterial.dispose();
    this.radix4Material.dispose();
    this.radix2Material?.dispose();
    this.quad.geometry.dispose();
  }
}

function dataTexture(data: Float32Array, width: number, height: number, format: PixelFormat): DataTexture {
  const texture = new DataTexture(data, width, height, format, FloatType);
  texture.minFilter = NearestFilter;
  texture.magFilter = NearestFilter;
  texture.needsUpdate = true;
  return texture;
}

function workTarget(n: number, type: TextureDataType): WebGLRenderTarget {
  return new WebGLRenderTarget(n, n, {
    count: 2,
    type,
    format: RGBAFormat,
    depthBuffer: false,
    minFilter: NearestFilter,
    magFilter: NearestFilter,
    generateMipmaps: false,
  });
}
