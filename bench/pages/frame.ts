/**
 * Full-frame benchmark page for `npm run bench`: the Ocean (simulation + sky + surface) rendered
 * at a fixed camera into a canvas of the requested size, timed per frame from an idle GPU through
 * ocean.update(t) and renderer.render() to a 1-pixel readPixels of the canvas (which cannot
 * return before the frame is drawn; gl.finish() does not block in Chromium).
 *
 * One Ocean per set of patch sizes (one FFT cascade per size), all drawn by the same renderer into
 * the same canvas; each round renders a frame of every one of them in turn, so machine noise hits
 * the cascade counts alike.
 */
import { ACESFilmicToneMapping, BoxGeometry, Mesh, MeshBasicMaterial, PerspectiveCamera, Scene, Vector3, WebGLRenderer } from 'three';
import type { PressureSource } from '../../src/layers/localWaves';
import { Ocean, type OceanOptions } from '../../src/ocean';
import { islandFrames } from './island';
import { withoutBeaufortLook, withoutSlopeLight } from './lightingCost';
import { onePixelRead, timeRounds } from './timedRounds';

export interface FrameOptions {
  resolution: number;
  width: number;
  height: number;
  warmup: number;
  rounds: number;
  /** One Ocean per entry; undefined keeps the default patch sizes. */
  patchSizeSets: (number[] | undefined)[];
  /**
   * Instead of patchSizeSets: one Ocean per entry with these options (default patch sizes), and,
   * with `activeLocalWaves`, a hull circling ahead of the camera and a stone every second, so that
   * the local waves step every frame (the living-surface rows).
   */
  variants?: { label: string; options: OceanOptions; activeLocalWaves: boolean; boxes?: boolean; surface?: SurfaceEdit }[];
  /** The canvas with 4× MSAA, as the 'high' quality level draws (the lighting rows). */
  antialias?: boolean;
}

/** What the lighting rows leave out of a variant's surface (lightingCost.ts). */
type SurfaceEdit = 'without slope light' | 'without Beaufort look';

export interface FrameSamples {
  label: string;
  patchSizes: number[];
  cascades: number;
  samples: number[];
  calls: number;
  triangles: number;
  vertices: number;
  simulationPasses: number;
  path: string;
}

async function frames(options: FrameOptions): Promise<FrameSamples[]> {
  const renderer = new WebGLRenderer({ antialias: options.antialias ?? false });
  renderer.setPixelRatio(1);
  renderer.setSize(options.width, options.height);
  renderer.toneMapping = ACESFilmicToneMapping;
  document.body.appendChild(renderer.domElement);
  const gl = renderer.getContext();
  const camera = new PerspectiveCamera(55, options.width / options.height, 0.5, 1e5);
  camera.position.set(0, 12, 0);
  camera.lookAt(60, 0, -80);
  const variants: NonNullable<FrameOptions['variants']> =
    options.variants ?? options.patchSizeSets.map((patchSizes) => ({ label: 'frame', options: patchSizes ? { patchSizes } : {}, activeLocalWaves: false, boxes: false }));
  const box = new BoxGeometry(6, 4, 6);
  const red = new MeshBasicMaterial({ color: 0xc02020 });
  const subjects = variants.map(({ label, options: oceanOptions, activeLocalWaves, boxes, surface }) => {
    const scene = new Scene();
    // With `boxes`: five boxes ahead of the camera, for the sea to reflect (the reflections rows).
    if (boxes) for (let i = 0; i < 5; i++) scene.add(new Mesh(box, red).translateX(30 + 12 * i).translateY(2).translateZ(-40 - 10 * i));
    const ocean = new Ocean(renderer, { resolution: options.resolution, seed: 7, path: 'gpu', ...oceanOptions });
    scene.add(ocean);
    const hull: PressureSource | null = activeLocalWaves ? (ocean.localWaves?.addPressure({ length: 8, beam: 2.6, draft: 0.6 }, { x: 30, z: -40, heading: 0 }) ?? null) : null;
    if (surface === 'without slope light') withoutSlopeLight(ocean.surface.material);
    return { label, scene, ocean, hull, surface, samples: [] as number[], calls: 0, triangles: 0 };
  });
  try {
    await timeRounds(onePixelRead(gl), subjects, options, (subject, t, round) => {
      if (subject.hull) {
        // 5 m/s round a 30 m circle ahead of the camera, and a stone every second.
        const angle = t / 6;
        subject.hull.setPose(30 + 30 * Math.cos(angle), -40 + 30 * Math.sin(angle), angle + Math.PI / 2);
        if (round % 30 === 0) subject.ocean.localWaves?.drop(20, -25);
      }
      subject.ocean.update(t);
      // After the first draw, whose bindLayers sets the wind's look: three uniform writes a frame.
      if (subject.surface === 'without Beaufort look') withoutBeaufortLook(subject.ocean.surface.material);
      camera.far = Math.max(1e4, 1.5 * subject.ocean.horizonDistance);
      camera.updateProjectionMatrix();
      renderer.render(subject.scene, camera);
      subject.calls = renderer.info.render.calls;
      subject.triangles = renderer.info.render.triangles;
    });
    return subjects.map(({ label, ocean, samples, calls, triangles }) => ({
      label,
      patchSizes: [...ocean.simulation.parameters.patchSizes],
      cascades: ocean.simulation.cascades.length,
      samples,
      calls,
      triangles,
      vertices: ocean.surface.geometry.getAttribute('position').count,
      simulationPasses: ocean.simulation.passCount,
      path: ocean.simulation.path,
    }));
  } finally {
    subjects.forEach(({ ocean }) => ocean.dispose());
    box.dispose();
    red.dispose();
    renderer.dispose();
    renderer.domElement.remove();
  }
}

/**
 * Queries from the main thread as a user makes them: `points` heightsAt / velocitiesAt (one batch
 * call) over the default sea at N = `resolution`, with the CPU fields already computed for the time
 * (the first call at a new time computes them; that cost is reported apart, as `firstMs`).
 */
async function queries(options: { resolution: number; points: number; rounds: number }): Promise<Record<string, { firstMs: number; samples: number[] }>> {
  const renderer = new WebGLRenderer();
  const ocean = new Ocean(renderer, { resolution: options.resolution, seed: 7, path: 'gpu' });
  const xz = new Float64Array(2 * options.points);
  for (let p = 0; p < options.points; p++) [xz[2 * p], xz[2 * p + 1]] = [(p % 40) * 3.7 - 70, Math.floor(p / 40) * 4.1 - 50];
  const out = new Float64Array(3 * options.points);
  const result: Record<string, { firstMs: number; samples: number[] }> = {};
  try {
    // The last row over a 1:50 beach under the points (docs/shores.md): what a seabed adds to a query.
    const beach = { depthAt: (x: number) => (x + 100) / 50, bounds: [-200, -100, 100, 100] as const };
    for (const [name, query] of [
      ['heightsAt', () => ocean.heightsAt(xz, out)],
      ['velocitiesAt', () => ocean.velocitiesAt(xz, out)],
      ['heightsAt over a seabed', () => ocean.heightsAt(xz, out)],
    ] as const) {
      if (name === 'heightsAt over a seabed') ocean.setSeabed(beach);
      ocean.update(12.5 + Object.keys(result).length);
      let start = performance.now();
      query();
      const firstMs = performance.now() - start;
      const samples: number[] = [];
      for (let round = 0; round < options.rounds; round++) {
        start = performance.now();
        query();
        samples.push(performance.now() - start);
        await new Promise((resolve) => setTimeout(resolve, 0));
      }
      result[name] = { firstMs, samples };
    }
    return result;
  } finally {
    ocean.dispose();
    renderer.dispose();
  }
}

/**
 * The queries as an app asks them, on the GPU path at N = `resolution`, from the frame after the
 * ocean is built: each frame update(t), then heightAt and normalAt at 5 points (a boat and four
 * buoys), then a pause of `frameMs` (a frame of a slow renderer), with steps of 1/60 s. Every
 * call's time on the main thread (`callMs`, the first `warmUpCalls` of them in the first `warmUp`
 * frames, while the query workers start), the first frame's calls together, and how often the
 * fields were computed here after the warm-up.
 *
 * `controlMs`: beside each call (after it on even frames, before it on odd ones), the time of a
 * fixed few microseconds of arithmetic. On this machine (two cores shared with SwiftShader's
 * threads, the workers and other tenants) the main thread is now and then held up for
 * milliseconds whatever it runs, and V8 finishes on it what it compiled in the background in
 * whatever runs next; a control call over 1 ms says how often, beside the queries' count.
 *
 * Each call runs in a task of its own, marked `query-call-<i>` (i: its index in callMs) or
 * `control-call-<i>`, so that a trace of the page gives the task's main-thread CPU time beside the
 * call's wall time (bench/groups/query-frames.mjs): a call held up by other threads has the one, not the other.
 */
async function queryFrames(options: { resolution: number; warmUp: number; frames: number; frameMs: number }): Promise<{ firstFrameMs: number; callMs: number[]; warmUpCalls: number; controlMs: number[]; computedHere: number }> {
  const renderer = new WebGLRenderer();
  const ocean = new Ocean(renderer, { resolution: options.resolution, seed: 7, path: 'gpu', localWaves: false });
  const points = [[0, 0], [12, -8], [-15, 4], [30, 22], [-6, -25]];
  const normal = new Vector3();
  const computedHere = () => ocean.simulation.cascades.reduce((sum, layer) => sum + layer.fieldsComputedHere, 0);
  const [callMs, controlMs]: number[][] = [[], []];
  const timed = (call: () => unknown, into: number[]) =>
    new Promise<void>((resolve) => {
      const channel = new MessageChannel();
      channel.port1.onmessage = () => {
        performance.mark(`${into === callMs ? 'query' : 'control'}-call-${into.length}`);
        const start = performance.now();
        call();
        into.push(performance.now() - start);
        channel.port1.close();
        // The rest of the frame in a task of its own, not in this one.
        setTimeout(resolve, 0);
      };
      channel.port2.postMessage(null);
    });
  let [firstFrameMs, computedAtWarmUp, warmUpCalls, sink] = [0, 0, 0, 0];
  const control = () => {
    for (let i = 1; i <= 2000; i++) sink += Math.sqrt(i);
  };
  try {
    for (let frame = 0; frame < options.warmUp + options.frames; frame++) {
      ocean.update(30 + frame / 60);
      // On odd frames each control goes first: the first task after the update (which meets whatever V8
      // finished compiling in the background meanwhile) is then a query's on half the frames, a control's on the other.
      const controlFirst = frame % 2 === 1;
      for (const [x, z] of points) {
        for (const query of [() => ocean.heightAt(x, z), () => ocean.normalAt(x, z, normal)]) {
          if (controlFirst) await timed(control, controlMs);
          await timed(query, callMs);
          if (!controlFirst) await timed(control, controlMs);
        }
      }
      if (frame === 0) firstFrameMs = callMs.reduce((sum, ms) => sum + ms, 0);
      if (frame === options.warmUp - 1) [computedAtWarmUp, warmUpCalls] = [computedHere(), callMs.length];
      await new Promise((resolve) => setTimeout(resolve, options.frameMs));
    }
    if (!Number.isFinite(sink)) throw new Error('the control sum is not finite');
    return { firstFrameMs, callMs, warmUpCalls, controlMs, computedHere: computedHere() - computedAtWarmUp };
  } finally {
    ocean.dispose();
    renderer.dispose();
  }
}

/**
 * A parameter change as the app's panel makes one, on the GPU path at N = `resolution` with the
 * default cascades: setParameters (a new wind: new spectra), then the next two frames as an app
 * draws them (update, heightAt and normalAt at 5 points, render at `width`×`height`). The main
 * thread's time for each, per round; the GPU is let finish between them, so each part is timed
 * from an idle GPU.
 */
async function parameterChanges(options: { resolution: number; rounds: number; width: number; height: number }): Promise<{ setMs: number[]; firstFrameMs: number[]; secondFrameMs: number[] }> {
  const renderer = new WebGLRenderer({ antialias: false });
  renderer.setPixelRatio(1);
  renderer.setSize(options.width, options.height);
  const gl = renderer.getContext();
  const camera = new PerspectiveCamera(55, options.width / options.height, 0.5, 1e5);
  camera.position.set(0, 12, 0);
  camera.lookAt(60, 0, -80);
  const scene = new Scene();
  const ocean = new Ocean(renderer, { resolution: options.resolution, seed: 7, path: 'gpu', localWaves: false });
  scene.add(ocean);
  const normal = new Vector3();
  const pixel = new Uint8Array(4);
  let t = 10;
  const frame = () => {
    const start = performance.now();
    ocean.update((t += 1 / 60));
    for (let i = 0; i < 5; i++) {
      ocean.heightAt(7 * i, 3);
      ocean.normalAt(7 * i, 3, normal);
    }
    camera.far = 1.5 * ocean.horizonDistance;
    camera.updateProjectionMatrix();
    renderer.render(scene, camera);
    return performance.now() - start;
  };
  const idle = async () => {
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
    await new Promise((resolve) => setTimeout(resolve, 300));
  };
  const result = { setMs: [] as number[], firstFrameMs: [] as number[], secondFrameMs: [] as number[] };
  try {
    for (let i = 0; i < 8; i++) {
      frame();
      await idle();
    }
    for (let round = 0; round < options.rounds; round++) {
      const start = performance.now();
      ocean.setParameters({ windSpeed: 8 + (round % 3) });
      result.setMs.push(performance.now() - start);
      result.firstFrameMs.push(frame());
      await idle();
      result.secondFrameMs.push(frame());
      await idle();
    }
    return result;
  } finally {
    ocean.dispose();
    renderer.dispose();
  }
}

declare global {
  interface Window {
    frameBench: { frames: typeof frames; queries: typeof queries; queryFrames: typeof queryFrames; parameterChanges: typeof parameterChanges; islandFrames: typeof islandFrames };
  }
}
window.frameBench = { frames, queries, queryFrames, parameterChanges, islandFrames };
document.title = 'ready';
