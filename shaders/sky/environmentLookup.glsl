// Reads SkyEnvironment's cube (src/render/skyEnvironment.ts) in a world direction (y up), for
// materials that sample it themselves (reflections, refraction into the deep water).
//
// three.js samples cube textures made from six images (CubeTextureLoader) with x mirrored —
// cube-map images follow the left-handed RenderMan convention, three.js is right-handed — but
// cube render targets unmirrored. Bind skyEnvironmentFlipX to SkyEnvironment.environmentFlipX
// (1 for the generated sky, −1 for a loaded face set) and both agree with sunDirection.
uniform samplerCube skyEnvironment;
uniform float skyEnvironmentFlipX;

// lod: mip level, 0 = sharpest (the cube has mipmaps for rough reflections).
vec3 environmentRadiance(vec3 direction, float lod) {
  return textureLod(skyEnvironment, vec3(skyEnvironmentFlipX * direction.x, direction.yz), lod).rgb;
}
