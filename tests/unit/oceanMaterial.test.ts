import { describe, expect, it } from 'vitest';
import { DataTexture, Vector3, type Texture } from 'three';
import { OceanMaterial } from '../../src/render/oceanMaterial';
import { ParameterError } from '../../src/parameters/parameters';
import { SHADING_MODES } from '../../src/parameters/sceneOptions';
import type { WaveLayer } from '../../src/layers/waveLayer';

function material(): OceanMaterial {
  return new OceanMaterial({
    environment: { value: null },
    sunDirection: { value: new Vector3(0, 1, 0) },
  });
}

/** A layer with its own two textures; only what bindLayers reads is real. */
function fakeLayer(size: number, resolution: number): WaveLayer {
  const texture = (): Texture => new DataTexture(new Float32Array(4), 1, 1);
  const fields = { displacement: new Float32Array(4 * resolution * resolution), derivatives: new Float32Array(4 * resolution * resolution) };
  return {
    textures: { displacement: { value: texture() }, derivatives: { value: texture() } },
    frame: { size, origin: [0, 0], periodic: true, resolution },
    movesSideways: true,
    update: () => {},
    queryFields: (t: number) => ({ time: t, resolution, ...fields, velocities: () => fields.displacement }),
    fieldsOnCpu: () => fields,
    shownFieldsOnCpu: () => fields,
    dispose: () => {},
  };
}

describe('OceanMaterial shading options', () => {
  const bad: [string, object, RegExp][] = [
    ['ior = 1', { ior: 1 }, /^ior must be a number > 1 and at most 3; got 1$/],
    ['ior > 3', { ior: 3.5 }, /^ior must be/],
    ['ior < 1', { ior: 0.5 }, /^ior must be/],
    ['ior NaN', { ior: NaN }, /^ior must be/],
    ['negative absorption', { absorption: [0.4, -0.1, 0.1] }, /^absorption must be three numbers from 0 to 10000/],
    ['absorption of two numbers', { absorption: [0.4, 0.1] }, /^absorption must be/],
    ['caustic power 0', { causticPower: 0 }, /^causticPower must be a number > 0 and at most 10000; got 0$/],
    ['negative caustic power', { causticPower: -2 }, /^causticPower must be/],
    ['caustic colour with Infinity', { causticColor: [1, Infinity, 1] }, /^causticColor must be/],
    ['caustic colour under its British alias', { causticColour: '#zzz' }, /^causticColour must be a colour.*; got "#zzz"$/],
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
    m.setShading({ ior: 1.5, absorption: [1, 2, 3], causticPower: 8, causticColor: [0.5, 0.5, 0.5], scatterColour: 'white', shadingMode: 'caustics' });
    expect(m.uniforms.iorWater.value).toBe(1.5);
    expect(m.uniforms.absorption.value.toArray()).toEqual([1, 2, 3]);
    expect(m.uniforms.causticPower.value).toBe(8);
    expect(m.uniforms.causticColor.value.toArray()).toEqual([0.5, 0.5, 0.5]);
    expect(m.uniforms.scatterColor.value.toArray()).toEqual([1, 1, 1]);
    expect(m.defines.SHADING_MODE).toBe(SHADING_MODES.indexOf('caustics'));
  });
});

describe('OceanMaterial.bindLayers', () => {
  const layers = [fakeLayer(13.7, 256), fakeLayer(79.3, 256), fakeLayer(457, 128)];
  const foam = { value: null };

  it('binds each layer’s textures, size and LOD bias, the choppiness and the foam', () => {
    const m = material();
    m.bindLayers(layers, 1.5, foam);
    const u = m.uniforms;
    expect(m.defines.LAYER_COUNT).toBe(3);
    expect(u.choppiness.value).toBe(1.5);
    expect(u.tFoam).toBe(foam);
    layers.forEach((layer, i) => {
      expect(u.tLayerDisplacement.value[i]).toBe(layer.textures.displacement.value);
      expect(u.tLayerDerivatives.value[i]).toBe(layer.textures.derivatives.value);
      expect(u.layerSizes.value[i]).toBe(layer.frame.size);
    });
    // log2(finest texel / this layer's texel): 0 for the finest, negative (coarser mips) for others,
    const finest = 13.7 / 256;
    // Rounded to whole mip levels (oceanMaterial.ts: the vertex stage filters within one level).
    const want = [0, Math.log2(finest / (79.3 / 256)), Math.log2(finest / (457 / 128))].map(Math.round);
    expect(u.layerLodBias.value).toEqual(want);
    expect(want).toEqual([0, -3, -6]);
  });

  it('unrolls the shaders’ loops over the layers: every “i < LAYER_COUNT” becomes the count', () => {
    const m = material();
    expect(m.vertexShader).toContain('i < 1');
    m.bindLayers(layers, 1, foam);
    for (const source of [m.vertexShader, m.fragmentShader]) {
      expect(source).not.toContain('i < LAYER_COUNT');
    }
    expect(m.vertexShader).toContain('i < 3');
  });

  it('recompiles only when the number of layers changes; a new choppiness or texture is a uniform change', () => {
    const m = material();
    m.bindLayers(layers, 1, foam);
    const version = m.version;
    m.bindLayers(layers, 2.5, foam);
    expect(m.version).toBe(version);
    expect(m.uniforms.choppiness.value).toBe(2.5);
    const replaced = [layers[0], fakeLayer(79.3, 256), layers[2]];
    m.bindLayers(replaced, 2.5, foam);
    expect(m.version).toBe(version);
    expect(m.uniforms.tLayerDisplacement.value[1]).toBe(replaced[1].textures.displacement.value);
    m.bindLayers(layers.slice(0, 2), 2.5, foam);
    expect(m.version).toBeGreaterThan(version);
    expect(m.defines.LAYER_COUNT).toBe(2);
    expect(m.uniforms.tLayerDisplacement.value).toHaveLength(2);
    expect(m.uniforms.layerSizes.value).toEqual([13.7, 79.3]);
  });
});
