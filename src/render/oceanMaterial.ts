/**
 * The ocean surface's ShaderMaterial: shaders/surface/ocean.vert and ocean.frag, the course
 * report's shading model (exact Fresnel, cubemap reflection and refraction, Beer–Lambert
 * absorption, Guardado caustics) plus a sun glint, and debug modes that reproduce the report's
 * figures. Typed setters check their values and keep the last good one when a value is bad.
 */
import { Color, DoubleSide, ShaderMaterial, UniformsLib, UniformsUtils, Vector3, type Texture } from 'three';
import { shaderSource } from '../shaderSource';
import { ParameterError } from '../parameters/parameters';
import { RING_COUNT } from './horizonGrid';

/** Shading modes; all but 'full' reproduce one of the course report's figures. */
export const SHADING_MODES = ['full', 'fresnel', 'reflection', 'refraction', 'caustics', 'height'] as const;
export type ShadingMode = (typeof SHADING_MODES)[number];

export interface OceanShadingOptions {
  /** Refractive index of water n_w (> 1; air is 1). @defaultValue 1.333 */
  ior?: number;
  /** Beer–Lambert absorption σ per colour channel, 1/m (each ≥ 0). @defaultValue [0.45, 0.07, 0.04] */
  absorption?: [number, number, number];
  /** Colour of light scattered back out of the water (linear RGB). @defaultValue [0.0, 0.035, 0.06] */
  scatterColour?: [number, number, number];
  /** Caustic sharpness p in K = (t·l)^p (> 0). @defaultValue 32 */
  causticPower?: number;
  /** Caustic colour c_caustic (linear RGB, each ≥ 0). @defaultValue [0.12, 0.12, 0.12] */
  causticColour?: [number, number, number];
  /** @defaultValue 'full' */
  shadingMode?: ShadingMode;
}

export interface OceanMaterialInputs {
  displacement: { value: Texture | null };
  derivatives: { value: Texture | null };
  patchSize: { value: number };
  /** The environment cube, RGBM-encoded (SkyEnvironment.environment). */
  environment: { value: Texture | null };
  /** Towards the sun, unit length (SkyEnvironment.skyUniforms.skySunDirection: the sky's own sun). */
  sunDirection: { value: Vector3 };
}

export class OceanMaterial extends ShaderMaterial {
  constructor(inputs: OceanMaterialInputs, options: OceanShadingOptions = {}, defines: Record<string, unknown> = {}) {
    super({
      // SHADING_MODE is a define, not a uniform: a mode change recompiles (rare), and the full
      // shading runs without the debug modes' branches (a few per cent of a SwiftShader frame).
      defines: { RING_COUNT, SHADING_MODE: 0, ...defines },
      vertexShader: shaderSource('surface/ocean.vert'),
      fragmentShader: shaderSource('surface/ocean.frag'),
      side: DoubleSide,
      uniforms: UniformsUtils.merge([
        UniformsLib.common, // unused, keeps three's chunks happy
        {
          ringFrames: { value: new Float32Array(4 * (RING_COUNT + 1)) },
          ringUvOrigins: { value: new Float32Array(2 * (RING_COUNT + 1)) },
          ringOffsets: { value: new Float32Array(2 * (RING_COUNT + 1)) },
          halfRingCells: { value: 32 },
          sunColour: { value: new Color(12, 11, 9.5) },
          sunShininess: { value: 900 },
          iorAir: { value: 1 },
          iorWater: { value: 1.333 },
          absorption: { value: new Vector3(0.45, 0.07, 0.04) },
          scatterColour: { value: new Vector3(0.0, 0.035, 0.06) },
          viewDepth: { value: 4 },
          causticPower: { value: 32 },
          causticColour: { value: new Vector3(0.12, 0.12, 0.12) },
          heightScale: { value: 3 },
          captureRestPoint: { value: false },
          captureWidth: { value: 1 },
          captureHeight: { value: 1 },
        },
      ]),
    });
    // Shared uniform objects: whoever owns them updates them, this material never rebinds.
    this.uniforms.tDisplacement = inputs.displacement;
    this.uniforms.tDerivatives = inputs.derivatives;
    this.uniforms.patchSize = inputs.patchSize;
    this.uniforms.skyEnvironment = inputs.environment;
    this.uniforms.sunDirection = inputs.sunDirection;
    this.setShading(options);
  }

  /** Changes shading options; throws a ParameterError naming the first bad one and changes nothing. */
  setShading(options: OceanShadingOptions): void {
    const checks: [keyof OceanShadingOptions, boolean, string][] = [
      ['ior', options.ior === undefined || (Number.isFinite(options.ior) && options.ior > 1), 'a finite number > 1'],
      ['absorption', isColour(options.absorption), 'three finite numbers ≥ 0 (1/m)'],
      ['scatterColour', isColour(options.scatterColour), 'three finite numbers ≥ 0'],
      [
        'causticPower',
        options.causticPower === undefined || (Number.isFinite(options.causticPower) && options.causticPower > 0),
        'a finite number > 0',
      ],
      ['causticColour', isColour(options.causticColour), 'three finite numbers ≥ 0'],
      [
        'shadingMode',
        options.shadingMode === undefined || SHADING_MODES.includes(options.shadingMode),
        `one of ${SHADING_MODES.join(', ')}`,
      ],
    ];
    for (const [name, ok, allowed] of checks) if (!ok) throw new ParameterError(name, options[name], allowed);
    const u = this.uniforms;
    if (options.ior !== undefined) u.iorWater.value = options.ior;
    if (options.absorption) u.absorption.value.fromArray(options.absorption);
    if (options.scatterColour) u.scatterColour.value.fromArray(options.scatterColour);
    if (options.causticPower !== undefined) u.causticPower.value = options.causticPower;
    if (options.causticColour) u.causticColour.value.fromArray(options.causticColour);
    if (options.shadingMode && SHADING_MODES.indexOf(options.shadingMode) !== this.defines.SHADING_MODE) {
      this.defines.SHADING_MODE = SHADING_MODES.indexOf(options.shadingMode);
      this.needsUpdate = true;
    }
  }

  get shading(): Required<OceanShadingOptions> {
    const u = this.uniforms;
    return {
      ior: u.iorWater.value,
      absorption: u.absorption.value.toArray(),
      scatterColour: u.scatterColour.value.toArray(),
      causticPower: u.causticPower.value,
      causticColour: u.causticColour.value.toArray(),
      shadingMode: SHADING_MODES[this.defines.SHADING_MODE as number],
    };
  }
}

function isColour(value: unknown): boolean {
  return (
    value === undefined ||
    (Array.isArray(value) && value.length === 3 && value.every((c) => typeof c === 'number' && Number.isFinite(c) && c >= 0))
  );
}
