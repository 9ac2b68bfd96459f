/**
 * Test page for the WebGPU Ocean's shore (tests/browser/webgpu/shore.spec.ts): the page of
 * webgpu.ts (its renderer, pictures and vertex read-back, window.webgpuOcean) and, here, what
 * needs a seabed made in the page: the queries of both Oceans over the same seabed, bad seabeds,
 * and the memory of an Ocean whose seabed is replaced.
 */
import { PerspectiveCamera, Scene, WebGLRenderer } from 'three';
import { Ocean } from '../../../src/webgpu/index';
import { Ocean as WebGLOcean } from '../../../src/ocean';
import { islandSeabed } from '../../../src/objects/island';
import type { Seabed } from '../../../src/layers/seabed';
import { openedRenderer } from './webgpu';

/** The sea of webgpu.ts's pictures: N = 64, the JS FFT on this thread. */
const SEA = { resolution: 64, windSpeed: 10, seed: 3 };
/** A 1:50 plane beach, depth x/50 (land at x < 0), over this rectangle (tests/browser/seabed's). */
const BEACH_SLOPE = 1 / 50;
const BEACH_BOUNDS: [number, number, number, number] = [-300, -800, 2500, 800];
const seabeds: Record<'beach' | 'island', () => Seabed> = {
  beach: () => ({ depthAt: (x: number) => x * BEACH_SLOPE, bounds: BEACH_BOUNDS }),
  island: islandSeabed,
};

/**
 * heightAt, normalAt (x, y, z) and depthAt of this Ocean and of the WebGL Ocean (JS path, no local
 * waves) for the same options and seabed, at the same points and time; then again after both were
 * given the other seabed by setSeabed.
 */
function sameQueriesAsWebGL(points: [number, number][], t: number, first: 'beach' | 'island', second: 'beach' | 'island'): { webgpu: number[]; webgl: number[] } {
  const gl = new WebGLRenderer();
  const seas = {
    webgpu: new Ocean(openedRenderer(), { ...SEA, worker: false, seabed: seabeds[first]() }),
    webgl: new WebGLOcean(gl, { ...SEA, path: 'js', localWaves: false, worker: false, seabed: seabeds[first]() }),
  };
  const result = { webgpu: [] as number[], webgl: [] as number[] };
  for (const name of [first, second]) {
    for (const which of ['webgpu', 'webgl'] as const) {
      const sea = seas[which];
      sea.setSeabed(seabeds[name]());
      sea.update(t);
      result[which].push(...points.flatMap(([x, z]) => [sea.heightAt(x, z), ...sea.normalAt(x, z).toArray(), sea.depthAt(x, z)]));
    }
  }
  seas.webgpu.dispose();
  seas.webgl.dispose();
  gl.dispose();
  return result;
}

/**
 * What each bad seabed throws given to setSeabed of an Ocean over the beach ([name, parameter,
 * message]), and depthAt(1000, 0) after it (the beach's 20 m if the last good seabed stayed); and
 * what the constructor throws for a bad one.
 */
function badSeabeds(): { thrown: [string, string, string][]; depthAfter: number[]; constructed: [string, string] } {
  const ocean = new Ocean(openedRenderer(), { ...SEA, worker: false, seabed: seabeds.beach() });
  const bad: unknown[] = [
    { depthAt: () => NaN, bounds: [0, 0, 10, 10] },
    { depthAt: () => 1, bounds: [0, 0, 10, 0] },
    {
      depthAt: () => {
        throw new Error('no floor here');
      },
      bounds: [0, 0, 10, 10],
    },
    { depths: [1, 2, 3], width: 2, height: 2, bounds: [0, 0, 10, 10] },
    { meshes: [] },
    'sand',
  ];
  const thrown: [string, string, string][] = [];
  const depthAfter: number[] = [];
  for (const seabed of bad) {
    try {
      ocean.setSeabed(seabed as Seabed);
      thrown.push(['none', '', '']);
    } catch (error) {
      thrown.push([(error as Error).name, (error as { parameter?: string }).parameter ?? '', (error as Error).message]);
    }
    depthAfter.push(ocean.depthAt(1000, 0));
  }
  ocean.dispose();
  let constructed: [string, string] = ['none', ''];
  try {
    new Ocean(openedRenderer(), { ...SEA, worker: false, seabed: bad[0] as Seabed }).dispose();
  } catch (error) {
    constructed = [(error as Error).name, (error as { parameter?: string }).parameter ?? ''];
  }
  return { thrown, depthAfter, constructed };
}

/** renderer.info.memory before an Ocean over the beach, while it draws (after setSeabed gave it the island and setParameters a new wind), and after its dispose. */
async function memoryCycle(): Promise<{ before: Record<string, number>; during: Record<string, number>; after: Record<string, number> }> {
  const renderer = openedRenderer();
  const scene = new Scene();
  const camera = new PerspectiveCamera(60, 16 / 9, 0.5, 30_000);
  camera.position.set(0, 4, 200);
  renderer.render(scene, camera);
  const memory = () => ({ geometries: renderer.info.memory.geometries, textures: renderer.info.memory.textures });
  const before = memory();
  const ocean = new Ocean(renderer, { ...SEA, worker: false, seabed: seabeds.beach() });
  scene.add(ocean);
  ocean.update(1);
  renderer.render(scene, camera);
  ocean.setSeabed(seabeds.island());
  ocean.update(1.1);
  renderer.render(scene, camera);
  // New cascades under the same seabed: a new shoaling table and material.
  ocean.setParameters({ windSpeed: 14 });
  ocean.update(1.2);
  renderer.render(scene, camera);
  const during = memory();
  ocean.dispose();
  renderer.render(scene, camera);
  return { before, during, after: memory() };
}

/** A new seabed of this name (made in the page: its depthAt is a function). */
function seabed(name: 'beach' | 'island'): Seabed {
  return seabeds[name]();
}

const shore = { seabed, sameQueriesAsWebGL, badSeabeds, memoryCycle };
declare global {
  interface Window {
    webgpuShore: typeof shore;
  }
}
window.webgpuShore = shore;
document.title = 'ready';
