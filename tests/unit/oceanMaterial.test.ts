import { describe, expect, it } from 'vitest';
import { Vector3 } from 'three';
import { OceanMaterial, SHADING_MODES } from '../../src/render/oceanMaterial';
import { ParameterError } from '../../src/parameters/parameters';

function material(): OceanMaterial {
  return new OceanMaterial({
    displacement: { value: null },
    derivatives: { value: null },
    patchSize: { value: 250 },
    environment: { value: null },
    sunDirection: { value: new Vector3(0, 1, 0) },
  });
}

describe('OceanMaterial shading options', () => {
  const bad: [string, object, RegExp][] = [
    ['ior = 1', { ior: 1 }, /^ior must be a finite number > 1; got 1$/],
    ['ior < 1', { ior: 0.5 }, /^ior must be/],
    ['ior NaN', { ior: NaN }, /^ior must be/],
    ['negative absorption', { absorption: [0.4, -0.1, 0.1] }, /^absorption must be three finite numbers ≥ 0/],
    ['absorption of two numbers', { absorption: [0.4, 0.1] }, /^absorption must be/],
    ['caustic power 0', { causticPower: 0 }, /^causticPower must be a finite number > 0; got 0$/],
    ['negative caustic power', { causticPower: -2 }, /^causticPower must be/],
    ['caustic colour with Infinity', { causticColour: [1, Infinity, 1] }, /^causticColour must be/],
    ['unknown shading mode', { shadingMode: 'sepia' }, /^shadingMode must be one of full, fresnel/],
  ];
  for (const [name, options, message] of bad) {
    it(`rejects ${name} with a ParameterError and keeps every last good value`, () => {
      const m = material();
      m.setShading({ ior: 1.34, causticPower: 12, shadingMode: 'height' });
      const before = m.shading;
      // A bad value anywhere in the call changes nothing, not even the good values beside it.
      expect(() => m.setShading({ ...options, absorption: (options as { absorption?: number[] }).absorption ?? [1, 1, 1] } as never)).toThrow(
        ParameterError,
      );
      expect(() => m.setShading(options as never)).toThrow(message);
      expect(m.shading).toEqual(before);
    });
  }

  it('applies good values to the uniforms the shader reads', () => {
    const m = material();
    m.setShading({ ior: 1.5, absorption: [1, 2, 3], causticPower: 8, causticColour: [0.5, 0.5, 0.5], shadingMode: 'caustics' });
    expect(m.uniforms.iorWater.value).toBe(1.5);
    expect(m.uniforms.absorption.value.toArray()).toEqual([1, 2, 3]);
    expect(m.uniforms.causticPower.value).toBe(8);
    expect(m.defines.SHADING_MODE).toBe(SHADING_MODES.indexOf('caustics'));
  });
});
