/**
 * GLSL sources from shaders/, with `#include "path"` lines replaced by the named file (relative
 * to shaders/). Each formula lives in exactly one file and is included wherever it is needed.
 */
const files = import.meta.glob('/shaders/**/*.{glsl,vert,frag}', {
  query: '?raw',
  import: 'default',
  eager: true,
}) as Record<string, string>;

const INCLUDE = /^[ \t]*#include\s+"([^"]+)"[ \t]*$/gm;

/** The source of shaders/<path> with its includes expanded (each file at most once). */
export function shaderSource(path: string, included = new Set<string>()): string {
  const source = files[`/shaders/${path}`];
  if (source === undefined) throw new Error(`No shader file shaders/${path}`);
  included.add(path);
  return source.replace(INCLUDE, (_line, name: string) =>
    included.has(name) ? '' : `// ---- ${name}\n${shaderSource(name, included)}// ---- end ${name}`,
  );
}

/**
 * The source with LAYER_COUNT's value in the bounds of its loops over layers: three.js unrolls a
 * loop only when its bound is a number (see shaders/surface/waveLayers.glsl).
 */
export function withLayerCount(source: string, layerCount: number): string {
  return source.replaceAll('i < LAYER_COUNT - 1', `i < ${layerCount - 1}`).replaceAll('i < LAYER_COUNT', `i < ${layerCount}`);
}
