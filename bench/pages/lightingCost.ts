/**
 * What the bench's lighting rows (bench/groups/lighting.mjs) leave out of the WebGL Ocean's
 * surface, on the bench page only: the shipped shaders have no switch for issue 26's sub-pixel
 * slope light, and none is added for a benchmark.
 *
 * withoutSlopeLight edits the surface's fragment shader as three compiles it (onBeforeCompile;
 * three keys the program by that function too, so an edited Ocean and a whole one in one renderer
 * get programs of their own): the six slope taps (shaders/surface/slopeTaps.glsl) become one tap at
 * the pixel's own normal with weight 1, the mirror reflection of the sky (and of the scene, in
 * sceneReflection.glsl's loop), and the crest glow (seaLighting.glsl's crestGlow) is not added.
 * Each edit must find its text, or this throws: a shader changed under it is not timed unnoticed.
 *
 * withoutBeaufortLook sets the uniforms of the streaks and the spray to what they are below force 7
 * (foamStreaks.glsl, spray.glsl skip their work on them); the Ocean sets them again only when the
 * wind changes (OceanMaterial.bindLayers).
 */
import type { ShaderMaterial } from 'three';

const SLOPE_LIGHT_EDITS: [string, string][] = [
  ['#define SLOPE_TAPS 6', '#define SLOPE_TAPS 1'],
  ['if (node == 0) return vec3(side * 1.3556262, 0.0, 0.2220759);', 'if (node == 0) return vec3(0.0, 0.0, 1.0);'],
  ['colour += crestGlow(view, normal, sunDirection, vFromEye.y + cameraPosition.y, reflectance, sunLight, scatterColor);', ''],
];

export function withoutSlopeLight(material: ShaderMaterial): void {
  material.onBeforeCompile = (shader) => {
    for (const [text, replacement] of SLOPE_LIGHT_EDITS) {
      if (!shader.fragmentShader.includes(text)) throw new Error(`lightingCost.ts: the surface's fragment shader no longer has "${text}"`);
      shader.fragmentShader = shader.fragmentShader.split(text).join(replacement);
    }
  };
  material.needsUpdate = true;
}

export function withoutBeaufortLook(material: ShaderMaterial): void {
  for (const name of ['streakShare', 'sprayExtinction', 'spindrift']) {
    if (!material.uniforms[name]) throw new Error(`lightingCost.ts: the surface has no uniform ${name}`);
    material.uniforms[name].value = 0;
  }
}
