/**
 * The island benchmark (bench/groups/island.mjs): examples/island.html's scene (src/objects/island.ts:
 * the terrain, the reef, the pier and the moored boat, with its seabed under the sea, lit by the
 * sea's sun) seen from ISLAND_VIEW, timed per frame as the frame page times the open sea
 * (frame.ts): from an idle GPU through ocean.update(t), island.update and renderer.render() to a
 * 1-pixel readPixels, the Oceans of one call interleaved round by round. A quality level is put
 * in force as applyQuality.ts does, but for its MSAA (this page draws straight into an unsampled
 * canvas): the pixel ratio, the simulation's grid and cascades, the refraction capture's and the
 * reflection's scale. Each frame's ocean.update(t) is also timed alone (the simulation's share),
 * and where the bench gives the page Chromium's CPU time (window.benchCpuMs, bench/lib/cpuTime.mjs)
 * each frame's CPU time too.
 */
import { ACESFilmicToneMapping, PerspectiveCamera, Scene, WebGLRenderer } from 'three';
import { Island, ISLAND_VIEW } from '../../src/objects/island';
import { SunLight } from '../../src/objects/sunLight';
import { fitFarPlane, Ocean } from '../../src/index';
import { ParameterError } from '../../src/parameters/options';
import { QUALITY_STEPS, simulationAtQuality, type QualityLevel } from '../../src/runtime/adaptiveQuality';
import { onePixelRead, timeRounds } from './timedRounds';

export interface IslandFrameOptions {
  width: number;
  height: number;
  warmup: number;
  rounds: number;
  quality: QualityLevel;
  /** One Ocean each: reflections and refractions 'scene' (else 'sky'), with the island's seabed or none. */
  variants: { label: string; scene: boolean; seabed: boolean }[];
}

export interface IslandFrameSamples {
  label: string;
  samples: number[];
  updateSamples: number[];
  /** Chromium's CPU time per frame, ms; empty without window.benchCpuMs. */
  cpuSamples: number[];
  resolution: number;
  cascades: number;
  pixelRatio: number;
  calls: number;
}

declare global {
  interface Window {
    /** Chromium's CPU time so far, ms (null where the system does not tell it), when the bench exposes it. */
    benchCpuMs?: () => Promise<number | null>;
  }
}

export async function islandFrames(options: IslandFrameOptions): Promise<IslandFrameSamples[]> {
  const step = QUALITY_STEPS[options.quality];
  const renderer = new WebGLRenderer({ antialias: false });
  renderer.setPixelRatio(step.renderScale);
  renderer.setSize(options.width, options.height);
  renderer.toneMapping = ACESFilmicToneMapping;
  document.body.appendChild(renderer.domElement);
  const gl = renderer.getContext();
  const camera = new PerspectiveCamera(50, options.width / options.height, 0.5, 1e4);
  camera.position.fromArray(ISLAND_VIEW.position);
  camera.lookAt(...ISLAND_VIEW.target);
  // One island, moved into the scene of the Ocean being drawn (an Object3D has one parent).
  const island = new Island();
  const subjects = options.variants.map(({ label, scene: withScene, seabed }) => {
    const source = withScene ? 'scene' : 'sky';
    // examples/island.html's sea.
    const ocean = new Ocean(renderer, { seed: 5, windSpeed: 7, windDirection: -75, resolution: 128, sunElevation: 14, sunAzimuth: 60, path: 'gpu', reflections: source, refractions: source });
    const wanted = simulationAtQuality(ocean.parameters, step);
    try {
      ocean.setParameters(wanted);
    } catch (error) {
      if (!(error instanceof ParameterError)) throw error;
      ocean.setParameters({ patchSizes: wanted.patchSizes }); // as applyQuality.ts falls back
    }
    ocean.surface.refraction.scale = step.refractionScale;
    ocean.surface.reflectionScale = step.reflectionScale;
    if (seabed) ocean.setSeabed(island.seabed);
    const light = new SunLight(ocean);
    light.update();
    const scene = new Scene();
    scene.add(ocean, light);
    return { label, scene, ocean, samples: [] as number[], updateSamples: [] as number[], cpuSamples: [] as number[], calls: 0 };
  });
  try {
    await timeRounds(onePixelRead(gl), subjects, options, (subject, t, _round, timed) => {
      subject.scene.add(island); // a reparenting, nothing drawn
      const start = performance.now();
      subject.ocean.update(t, camera);
      if (timed) subject.updateSamples.push(performance.now() - start);
      island.update(subject.ocean);
      fitFarPlane(camera, subject.ocean);
      renderer.render(subject.scene, camera);
      subject.calls = renderer.info.render.calls;
    }, window.benchCpuMs);
    return subjects.map(({ label, ocean, samples, updateSamples, cpuSamples, calls }) => ({
      label,
      samples,
      updateSamples,
      cpuSamples,
      resolution: ocean.parameters.resolution,
      cascades: ocean.parameters.patchSizes.length,
      pixelRatio: renderer.getPixelRatio(),
      calls,
    }));
  } finally {
    subjects.forEach(({ ocean }) => ocean.dispose());
    island.removeFromParent();
    island.dispose();
    renderer.dispose();
    renderer.domElement.remove();
  }
}
