/**
 * The seam between the simulation and the GPU: what the FFT engine (src/fft/gpuFft.ts), the GPU
 * cascades (src/fft/gpuWaveFields.ts), the GPU local waves (src/layers/gpuLocalWaves.ts) and the
 * GPU foam (src/layers/whitecapFoam.ts) ask of a device: float field targets, fullscreen passes
 * into them, read-back, and what the device can do (asked by gpuSupport, src/fft/gpuWaveFields.ts,
 * and the simulation). src/device/webgl2/ implements it on three.js's WebGLRenderer; another
 * backend is one more folder that implements it (docs/architecture.md, "Adding a GPU backend").
 */
import type { ShaderMaterial, Texture } from 'three';

/** The float type of a target's texels. */
export type GpuPrecision = 'float32' | 'float16';

export interface FieldTargetOptions {
  /** Texels along each side (targets are square). */
  size: number;
  precision: GpuPrecision;
  /** Textures written at once (one per fragment output); 1 if omitted. */
  count?: number;
  /** Four channels, or one ('red': a field of one number); 'rgba' if omitted. */
  channels?: 'rgba' | 'red';
  /**
   * How a surface samples it: 'periodic' (REPEAT, and where the precision filters, linear with
   * mipmaps made after each pass), 'clamped' (clamped to the edge, linear where it filters), or
   * 'texels' (nearest, read only by texel); 'texels' if omitted.
   */
  sampling?: 'periodic' | 'clamped' | 'texels';
}

/** A square float target a pass draws into; its textures are what shaders sample. */
export interface FieldTarget {
  readonly size: number;
  readonly precision: GpuPrecision;
  /** One per fragment output. */
  readonly textures: readonly Texture[];
  dispose(): void;
}

/** Colour attachments of a LayeredTarget, all written by each pass: two array textures of four layers. */
export const LAYERED_ATTACHMENTS = 8;

/**
 * The FFT's working storage (gpuFft.ts): two (size × size) array textures of four layers, all
 * eight layers written by one pass (a butterfly's four outputs to each).
 */
export interface LayeredTarget {
  readonly textures: readonly [Texture, Texture];
  dispose(): void;
}

/** Rows first … first + count − 1 of texels. */
export interface TexelRows {
  first: number;
  count: number;
}

/** A fragment shader (GLSL 3, see src/shaderSource.ts) with its uniforms, drawn over a whole target. */
export type PassMaterial = ShaderMaterial;

/** What a device can lack, as the capability flags of GpuDevice name it. */
export type GpuCapability = 'float32Targets' | 'float16Targets' | 'float32Filterable' | 'drawBuffers';

export interface GpuDevice {
  /**
   * Why this device cannot run passes at all, in words (no WebGL 2, say, or a three.js whose
   * internals the device reaches into have changed), or null when it can. Asked before the flags
   * below, which mean nothing when it is not null.
   */
  readonly unavailableReason: string | null;
  /** Whether float32 targets can be rendered to. */
  readonly float32Targets: boolean;
  /** Whether float16 targets can be rendered to. */
  readonly float16Targets: boolean;
  /** Whether float32 textures filter linearly (float16 ones always do). */
  readonly float32Filterable: boolean;
  /** How many textures one pass can write at once (a LayeredTarget needs LAYERED_ATTACHMENTS). */
  readonly drawBuffers: number;
  /** Whether the device renders in software, where each pass has a high fixed cost. */
  readonly software: boolean;
  /**
   * What the device calls `capability`, for a message that says what it lacks: its extension or
   * limit (on WebGL 2, 'EXT_color_buffer_float' for float32Targets, 'MAX_DRAW_BUFFERS' for drawBuffers).
   */
  capabilityName(capability: GpuCapability): string;
  createFieldTarget(options: FieldTargetOptions): FieldTarget;
  /** Throws an UnsupportedError if the device cannot render to all eight layers at once (or is unavailable). */
  createLayeredTarget(size: number, precision: GpuPrecision): LayeredTarget;
  /** A material for `draw`: `fragmentShader` is GLSL source (shaderSource). */
  passMaterial(fragmentShader: string, uniforms: Record<string, { value: unknown }>, defines?: Record<string, unknown>): PassMaterial;
  /** Runs `passes` (draws, clears) without disturbing what the caller's renderer had set. */
  runPasses(passes: () => void): void;
  /** Draws `material` over `target` (over `rows` of it only, if given). Inside runPasses. */
  draw(material: PassMaterial, target: FieldTarget | LayeredTarget, rows?: TexelRows | null): void;
  /** Sets `target` (`rows` of it, if given) to zero. Inside runPasses. */
  clear(target: FieldTarget | LayeredTarget, rows?: TexelRows | null): void;
  /** The first texture of `target`, as floats (four a texel, or one for 'red'), waiting for the GPU. */
  readBack(target: FieldTarget, into: Float32Array): void;
  /** As readBack, without waiting: resolves once `into` holds them, rejects if the device was lost. */
  readBackLater(target: FieldTarget, into: Float32Array): Promise<void>;
  /** Frees what the device itself holds (not the targets or materials it made: their owners free them). */
  dispose(): void;
}
