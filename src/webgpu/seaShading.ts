/**
 * The WebGPU Ocean's shading options (ShadingOptions, src/parameters/sceneOptions.ts) in its
 * uniforms (seaNodes.ts's SeaUniforms): read back as the WebGL Ocean's OceanMaterial.shading gives
 * them, and written after SHADING_OPTIONS' own checks (mergeOptions), as OceanMaterial.setShading.
 */
import { mergeOptions } from '../parameters/options';
import { SHADING_OPTIONS, type ShadingChanges, type ShadingOptions } from '../parameters/sceneOptions';
import type { SeaUniforms } from './seaNodes';
import type { SceneLightOptions } from './sceneLightNodes';

/**
 * The shading drawn now: the uniforms' values, the scene's reflections and refractions as the
 * Ocean was made with them (`sceneLight`), and the one debug mode it draws ('full', its NOT_YET).
 */
export function shadingOf(uniforms: SeaUniforms, sceneLight: Readonly<SceneLightOptions>): ShadingOptions {
  return {
    ior: uniforms.ior.value,
    absorption: uniforms.absorption.value.toArray(),
    scatterColor: uniforms.scatterColor.value.toArray(),
    causticPower: uniforms.causticPower.value,
    causticColor: uniforms.causticColor.value.toArray(),
    shadingMode: 'full',
    refractions: sceneLight.refractions ? 'scene' : 'sky',
    reflections: sceneLight.reflections ? 'scene' : 'sky',
  };
}

/**
 * The shading `changes` ask for over the one drawn now: a ParameterError names the first bad value
 * (British spellings taken, colours in any ColorInput form made linear [r, g, b]).
 */
export function shadingWith(uniforms: SeaUniforms, sceneLight: Readonly<SceneLightOptions>, changes: ShadingChanges): ShadingOptions {
  return mergeOptions(SHADING_OPTIONS, changes, shadingOf(uniforms, sceneLight));
}

/** Puts `shading`'s values into the uniforms (the modes are the caller's to have refused). */
export function writeShading(uniforms: SeaUniforms, shading: ShadingOptions): void {
  uniforms.ior.value = shading.ior;
  uniforms.absorption.value.fromArray(shading.absorption);
  uniforms.scatterColor.value.fromArray(shading.scatterColor);
  uniforms.causticPower.value = shading.causticPower;
  uniforms.causticColor.value.fromArray(shading.causticColor);
}
