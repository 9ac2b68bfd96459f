/**
 * Test page for hostile input and long runs (fuzz.spec.ts, soak.spec.ts): fast-check runs here,
 * in the page, against the real Ocean and <fft-ocean> in this browser's WebGL2, and a soak runs
 * thousands of frames. Live Web Workers and WebGL framebuffers are counted from the page's start,
 * before anything makes one.
 */
import fc from 'fast-check';
import { FloatType, PerspectiveCamera, RGBAFormat, Scene, WebGLRenderer, WebGLRenderTarget, type Texture } from 'three';
import { allFinite, anyNumber, anyText, anyValue } from '../../arbitraries';
import '../../../src/embed/register';
import { FFT_OCEAN_ATTRIBUTES } from '../../../src/embed/fftOceanElement';
import { FullscreenPass, fullscreenMaterial, runPasses } from '../../../src/device/webgl2/fullscreenPass';
import { Ocean } from '../../../src/ocean';
import { DisposedError, ParameterError } from '../../../src/parameters/options';
import { DEFAULT_PARAMETERS, SIMULATION_OPTIONS } from '../../../src/parameters/parameters';
import { DEFAULT_SHADING, DEFAULT_SUN, SHADING_OPTIONS } from '../../../src/parameters/sceneOptions';

// ---- counters of what the page holds

/** Workers made and not terminated; every one made. */
const workers = { live: new Set<Worker>(), made: 0 };
window.Worker = class extends window.Worker {
  constructor(url: string | URL, options?: WorkerOptions) {
    super(url, options);
    workers.live.add(this);
    workers.made++;
  }

  terminate(): void {
    workers.live.delete(this);
    super.terminate();
  }
};

// Framebuffers alive in any WebGL2 context of the page, counted on the contexts' own calls: the
// GPU FFT makes framebuffers of its own (gpuWaveFields.ts), which renderer.info does not see.
const liveFramebuffers = new Set<WebGLFramebuffer>();
{
  const context = WebGL2RenderingContext.prototype;
  const create = context.createFramebuffer;
  const remove = context.deleteFramebuffer;
  context.createFramebuffer = function (this: WebGL2RenderingContext) {
    const framebuffer = create.call(this);
    liveFramebuffers.add(framebuffer);
    return framebuffer;
  };
  context.deleteFramebuffer = function (this: WebGL2RenderingContext, framebuffer: WebGLFramebuffer | null) {
    if (framebuffer) liveFramebuffers.delete(framebuffer);
    remove.call(this, framebuffer);
  };
}

// ---- what is not finite in a scene

const copyPass = new FullscreenPass();
const copyMaterial = fullscreenMaterial(
  'uniform highp sampler2D source;\nlayout(location = 0) out highp vec4 texel;\nvoid main() { texel = texelFetch(source, ivec2(gl_FragCoord.xy), 0); }',
  { source: { value: null } },
);

/**
 * The texels of `texture`'s level 0 as float32 RGBA, whatever holds them (a simulation target on
 * the GPU path, a DataTexture on the JS path): copied through a float target of its size.
 */
function texelsOf(renderer: WebGLRenderer, texture: Texture): Float32Array {
  const { width, height } = texture.image as { width: number; height: number };
  const target = new WebGLRenderTarget(width, height, { type: FloatType, format: RGBAFormat, depthBuffer: false });
  copyMaterial.uniforms.source.value = texture;
  runPasses(renderer, () => {
    renderer.setRenderTarget(target);
    copyPass.draw(renderer, copyMaterial);
  });
  copyMaterial.uniforms.source.value = null;
  const texels = new Float32Array(4 * width * height);
  renderer.readRenderTargetPixels(target, 0, 0, width, height, texels);
  target.dispose();
  return texels;
}

/**
 * What in `ocean` is not finite, in words (empty when everything is): its parameters (but deep
 * water's depth), each texture the surface samples (every layer's fields, the foam) with its count
 * of NaN or infinite texel values, and the surface's and the sky's uniforms.
 */
function nonFiniteInOcean(ocean: Ocean, renderer: WebGLRenderer): string[] {
  const problems: string[] = [];
  for (const [key, value] of Object.entries(ocean.parameters)) {
    if (!allFinite(value) && !(key === 'depth' && value === Infinity)) problems.push(`parameter ${key} = ${value}`);
  }
  const { layers, foam } = ocean.simulation;
  const textures: [string, Texture | null][] = layers.flatMap((layer, i) => [
    [`layer ${i} displacement`, layer.textures.displacement.value],
    [`layer ${i} derivatives`, layer.textures.derivatives.value],
  ]);
  textures.push(['foam', foam.texture.value]);
  for (const [name, texture] of textures) {
    if (!texture) continue;
    const texels = texelsOf(renderer, texture);
    const bad = texels.filter((value) => !Number.isFinite(value)).length;
    if (bad > 0) problems.push(`${name}: ${bad} of ${texels.length} texel values not finite`);
  }
  for (const [owner, uniforms] of [['surface', ocean.surface.material.uniforms], ['sky', ocean.sky.skyUniforms]] as const) {
    for (const [name, { value }] of Object.entries(uniforms)) if (!allFinite(value)) problems.push(`${owner} uniform ${name} not finite`);
  }
  return problems;
}

/** What a fuzz run reports: fast-check's report of the first failure (null if none), and counts. */
interface FuzzReport {
  failure: string | null;
  runs: number;
  /** Per method or attribute kind: calls made, and how many a ParameterError or a warning refused. */
  tally: Record<string, { calls: number; refused: number }>;
}

/** fast-check's report of a failed check, with the error the counterexample gave; null when it passed. */
function failureOf<Ts>(details: fc.RunDetails<Ts>): string | null {
  return details.failed ? `${fc.defaultReportMessage(details)}\n${String(details.errorInstance)}` : null;
}

function count(tally: FuzzReport['tally'], key: string, refused: boolean): void {
  tally[key] ??= { calls: 0, refused: 0 };
  tally[key].calls++;
  if (refused) tally[key].refused++;
}

// ---- Ocean's setters

type OceanMethod = 'setParameters' | 'setShading' | 'setSun' | 'setPath' | 'update' | 'heightAt';
interface OceanCall {
  method: OceanMethod;
  args: unknown[];
}

/** An option name: mostly one the table knows (an alias too), sometimes any text. */
const optionName = (known: readonly string[]) => fc.oneof({ weight: 4, arbitrary: fc.constantFrom(...known) }, { weight: 1, arbitrary: fc.string({ maxLength: 12 }) });
/** What a setter taking an object of options may be given: such an object, or anything at all. */
const changesOf = (known: readonly string[]) =>
  fc.oneof({ weight: 4, arbitrary: fc.dictionary(optionName(known), anyValue, { maxKeys: 3 }) }, { weight: 1, arbitrary: anyValue });

const oceanCall: fc.Arbitrary<OceanCall> = fc.oneof(
  changesOf(Object.keys(SIMULATION_OPTIONS)).map((changes) => ({ method: 'setParameters' as const, args: [changes] })),
  changesOf([...Object.keys(SHADING_OPTIONS), 'scatterColour', 'causticColour']).map((changes) => ({ method: 'setShading' as const, args: [changes] })),
  fc.oneof(changesOf(['elevation', 'azimuth', 'direction']).map((sun) => [sun]), fc.tuple(anyNumber, anyValue)).map((args) => ({ method: 'setSun' as const, args })),
  fc.oneof(fc.constantFrom('auto', 'gpu', 'js'), anyValue).map((path) => ({ method: 'setPath' as const, args: [path] })),
  anyValue.map((t) => ({ method: 'update' as const, args: [t] })),
  fc.tuple(anyValue, anyValue).map((xz) => ({ method: 'heightAt' as const, args: xz })),
);

/**
 * The names a ParameterError from `call` may give: an option it was given (by the name it was
 * given under), or what the method calls its argument. setParameters may also name the option
 * whose bound a change moved (patchSizes, repeatPeriod), setSun the angle an elevation, azimuth
 * or direction became.
 */
function namesFor({ method, args }: OceanCall): string[] {
  const given = args.flatMap((arg) => (typeof arg === 'object' && arg !== null ? Object.keys(arg) : []));
  const own: Record<OceanMethod, string[]> = {
    setParameters: ['setParameters', 'patchSizes', 'repeatPeriod'],
    setShading: ['setShading'],
    setSun: ['setSun', 'sunElevation', 'sunAzimuth'],
    setPath: ['path'],
    update: ['time'],
    heightAt: ['heightAt(x, z)'],
  };
  return [...given, ...own[method]];
}

/** Finite numbers as hostile as anyNumber's: ±1e308, 5e-324 and the like. */
const finiteNumber = anyNumber.filter(Number.isFinite);

/**
 * Makes `call` on `ocean`: it must either work (a height asked for must then be finite) or throw
 * a ParameterError naming what was wrong (namesFor). Throws an Error saying how it failed.
 */
function attempt(ocean: Ocean, call: OceanCall, tally: FuzzReport['tally']): void {
  let result: unknown;
  try {
    result = (ocean[call.method] as (...args: unknown[]) => unknown)(...call.args);
  } catch (error) {
    if (!(error instanceof ParameterError) || error instanceof DisposedError) throw error;
    const names = namesFor(call);
    if (!names.includes(error.parameter)) throw new Error(`${call.method} threw naming ${error.parameter}, not one of ${names.join(', ')}: ${error.message}`);
    count(tally, call.method, true);
    return;
  }
  if (call.method === 'heightAt' && !Number.isFinite(result)) throw new Error(`heightAt(${call.args.join(', ')}) = ${result}`);
  count(tally, call.method, false);
}

/**
 * fast-check over the Ocean's setters (seeded): each run makes an Ocean (N = 16, on `path`,
 * without a worker so its fields are there at once), makes one to four calls with hostile
 * arguments (attempt), then updates it to a hostile but finite time, renders it and reads back
 * what it holds: every texel, uniform and parameter must be finite, and a height asked for at a
 * hostile finite point must be, or be refused.
 */
function fuzzOcean(path: 'gpu' | 'js', numRuns: number, seed: number): FuzzReport {
  const renderer = new WebGLRenderer();
  renderer.setSize(160, 90);
  document.body.append(renderer.domElement);
  const scene = new Scene();
  const camera = new PerspectiveCamera(50, 16 / 9, 0.5, 1e6);
  camera.position.set(0, 5, 0);
  camera.lookAt(40, 0, -40);
  // An Ocean like each run's kept through the runs: three.js keeps the programs it compiled for
  // it, so each run's new Ocean reuses them instead of compiling its own (a second in SwiftShader).
  const keeper = new Ocean(renderer, { resolution: 16, path, worker: false });
  scene.add(keeper);
  keeper.update(0);
  renderer.render(scene, camera);
  scene.remove(keeper);
  const tally: FuzzReport['tally'] = {};
  const details = fc.check(
    fc.property(fc.array(oceanCall, { minLength: 1, maxLength: 4 }), finiteNumber, finiteNumber, finiteNumber, (calls, t, x, z) => {
      const ocean = new Ocean(renderer, { resolution: 16, path, worker: false });
      scene.add(ocean);
      try {
        for (const call of calls) attempt(ocean, call, tally);
        ocean.update(t);
        renderer.render(scene, camera);
        const problems = nonFiniteInOcean(ocean, renderer);
        if (problems.length > 0) throw new Error(`at t = ${t}, path ${ocean.path.running}: ${problems.join('; ')}`);
        attempt(ocean, { method: 'heightAt', args: [x, z] }, tally);
      } finally {
        scene.remove(ocean);
        ocean.dispose();
      }
    }),
    { seed, numRuns },
  );
  keeper.dispose();
  renderer.dispose();
  renderer.forceContextLoss();
  renderer.domElement.remove();
  return { failure: failureOf(details), runs: details.numRuns, tally };
}

// ---- <fft-ocean>'s attributes

/** Resolves after the next animation frame. */
const nextFrame = () => new Promise((resolve) => requestAnimationFrame(resolve));

/**
 * A change to the element: of an attribute, mostly one it reads, sometimes any other (null
 * removes it), or of its time.
 */
type ElementChange = { attribute: string; text: string | null } | { time: unknown };
const elementChange: fc.Arbitrary<ElementChange> = fc.oneof(
  { weight: 9, arbitrary: fc.record({ attribute: fc.constantFrom(...FFT_OCEAN_ATTRIBUTES), text: fc.option(anyText, { freq: 8 }) }) },
  { weight: 1, arbitrary: fc.record({ attribute: fc.stringMatching(/^[a-z][a-z-]{0,11}$/), text: fc.option(anyText, { freq: 8 }) }) },
  { weight: 1, arbitrary: fc.record({ time: anyValue }) },
);

/** The start every warning about `change` must have (null: it must give none). */
function warningFor(change: ElementChange): string | null {
  if ('time' in change) return '<fft-ocean>: ignoring time = ';
  return (FFT_OCEAN_ATTRIBUTES as readonly string[]).includes(change.attribute) ? `<fft-ocean>: ignoring ${change.attribute}=` : null;
}

/**
 * fast-check over <fft-ocean>'s attributes and time (seeded), on one element 160×90 px with
 * resolution 16 (each run starts from its defaults, but for that). Each run makes one to four
 * changes: every console warning a change gives must name its attribute (or time; an attribute
 * the element does not read gives none); after them, and a frame of its own, the element must
 * draw, and its ocean must hold finite texels, uniforms and parameters, and a finite heightAt.
 */
async function fuzzElement(numRuns: number, seed: number): Promise<FuzzReport> {
  const el = document.createElement('fft-ocean');
  el.setAttribute('resolution', '16');
  document.body.append(el);
  while (el.frameCount === 0) await nextFrame();
  const warnings: string[] = [];
  const realWarn = console.warn;
  console.warn = (...args: unknown[]) => warnings.push(args.map(String).join(' '));
  const tally: FuzzReport['tally'] = {};
  try {
    const details = await fc.check(
      fc.asyncProperty(fc.array(elementChange, { minLength: 1, maxLength: 4 }), async (changes) => {
        for (const name of el.getAttributeNames()) if (name !== 'resolution') el.removeAttribute(name);
        el.setAttribute('resolution', '16');
        for (const change of changes) {
          warnings.length = 0;
          if ('time' in change) el.time = change.time as number;
          else if (change.text === null) el.removeAttribute(change.attribute);
          else el.setAttribute(change.attribute, change.text);
          const start = warningFor(change);
          const strays = warnings.filter((warning) => start === null || !warning.startsWith(start));
          if (strays.length > 0) throw new Error(`${JSON.stringify(change)} gave warnings that do not name it: ${strays.join(' | ')}`);
          const kind = 'time' in change ? 'time' : start === null ? 'other attribute' : 'attribute the element reads';
          count(tally, kind, warnings.length > 0);
        }
        await nextFrame();
        if (!el.renderFrame()) throw new Error('the element does not draw');
        const ocean = el.ocean!;
        const problems = nonFiniteInOcean(ocean, el.renderer!);
        const height = ocean.heightAt(3, -7);
        if (!Number.isFinite(height)) problems.push(`heightAt(3, -7) = ${height}`);
        if (problems.length > 0) throw new Error(`at t = ${el.time}, path ${ocean.path.running}: ${problems.join('; ')}`);
      }),
      { seed, numRuns },
    );
    return { failure: failureOf(details), runs: details.numRuns, tally };
  } finally {
    console.warn = realWarn;
    el.remove();
  }
}

// ---- the soak

/** A setting the soak changes: how to set it away from the Ocean's first settings, and back. */
const SOAK_SETTINGS: { name: string; set: (ocean: Ocean, away: boolean) => void }[] = [
  { name: 'windSpeed', set: (ocean, away) => ocean.setParameters({ windSpeed: away ? 17 : DEFAULT_PARAMETERS.windSpeed }) },
  { name: 'spectrum', set: (ocean, away) => ocean.setParameters({ spectrum: away ? 'phillips' : DEFAULT_PARAMETERS.spectrum }) },
  { name: 'resolution', set: (ocean, away) => ocean.setParameters({ resolution: away ? 32 : 16 }) },
  { name: 'path', set: (ocean, away) => ocean.setPath(away ? 'js' : 'gpu') },
  { name: 'choppiness', set: (ocean, away) => ocean.setParameters({ choppiness: away ? 2.5 : DEFAULT_PARAMETERS.choppiness }) },
  { name: 'sun', set: (ocean, away) => ocean.setSun(away ? { elevation: 5, azimuth: 200 } : { elevation: DEFAULT_SUN.sunElevation, azimuth: DEFAULT_SUN.sunAzimuth }) },
  // Shallow water rebuilds the local waves too.
  { name: 'depth', set: (ocean, away) => ocean.setParameters({ depth: away ? 20 : DEFAULT_PARAMETERS.depth }) },
  // Two cascades instead of three: the surface's shaders are compiled for another layer count.
  { name: 'patchSizes', set: (ocean, away) => ocean.setParameters({ patchSizes: away ? [20, 100] : [...DEFAULT_PARAMETERS.patchSizes] }) },
  { name: 'seed', set: (ocean, away) => ocean.setParameters({ seed: away ? 9 : DEFAULT_PARAMETERS.seed }) },
  // Another shading mode: another program for the surface.
  { name: 'shadingMode', set: (ocean, away) => ocean.setShading({ shadingMode: away ? 'fresnel' : DEFAULT_SHADING.shadingMode }) },
];

/** What the page holds: three.js's geometries, textures and programs, WebGL framebuffers, live workers. */
interface Holdings {
  geometries: number;
  textures: number;
  programs: number;
  framebuffers: number;
  workers: number;
}

const channel = new MessageChannel();
/** Resolves after one turn of the event loop (a message to itself: no timer's 4 ms clamp), in which the workers' replies arrive. */
function turn(): Promise<void> {
  return new Promise((resolve) => {
    channel.port1.onmessage = () => resolve();
    channel.port2.postMessage(null);
  });
}

/**
 * The soak: an Ocean (N = 16, first on the GPU path; its JS path in workers) in a 160×90 canvas,
 * updated for `frames` frames of 1/60 s and drawn every `drawEvery`, with a turn of the event
 * loop after each (so the workers answer). After every `changeEvery` frames one setting changes
 * (SOAK_SETTINGS in turn: each away from the first settings, then each back), so every
 * 2 × SOAK_SETTINGS.length changes the settings are the first again: what the page holds then is
 * sampled (before the next change), and once more after the last change and a frame.
 */
async function soak(frames: number, changeEvery: number, drawEvery: number) {
  const started = performance.now();
  const renderer = new WebGLRenderer();
  renderer.setSize(160, 90);
  document.body.append(renderer.domElement);
  const holdings = (): Holdings => ({
    ...renderer.info.memory,
    programs: renderer.info.programs!.length,
    framebuffers: liveFramebuffers.size,
    workers: workers.live.size,
  });
  const empty = holdings();
  const scene = new Scene();
  const camera = new PerspectiveCamera(50, 16 / 9, 0.5, 1e6);
  camera.position.set(0, 8, 0);
  camera.lookAt(60, 0, -60);
  const ocean = new Ocean(renderer, { resolution: 16, path: 'gpu' });
  scene.add(ocean);
  const paths: string[] = [];
  ocean.addEventListener('pathchange', ({ path }) => paths.push(path.running + (path.reason && ` (${path.reason})`)));
  const atFirstSettings: (Holdings & { frame: number })[] = [];
  let mostWorkers = 0;
  let draws = 0;
  const cycle = 2 * SOAK_SETTINGS.length;
  const frame = async (n: number, draw: boolean) => {
    ocean.update(n / 60);
    if (draw) {
      renderer.render(scene, camera);
      draws++;
    }
    mostWorkers = Math.max(mostWorkers, workers.live.size);
    await turn();
  };
  for (let n = 1; n <= frames; n++) {
    await frame(n, n % drawEvery === 0);
    if (n % changeEvery !== 0) continue;
    const change = n / changeEvery; // from 1
    if ((change - 1) % cycle === 0) atFirstSettings.push({ frame: n, ...holdings() });
    const setting = SOAK_SETTINGS[(change - 1) % SOAK_SETTINGS.length];
    setting.set(ocean, (change - 1) % cycle < SOAK_SETTINGS.length);
  }
  // A frame with the settings the last change left, drawn.
  await frame(frames + 1, true);
  const last = { frame: frames + 1, ...holdings() };
  const problems = nonFiniteInOcean(ocean, renderer);
  const height = ocean.heightAt(12, -5);
  scene.remove(ocean);
  ocean.dispose();
  renderer.dispose();
  renderer.forceContextLoss();
  return {
    empty,
    atFirstSettings,
    last,
    settings: SOAK_SETTINGS.map(({ name }) => name),
    changes: Math.floor(frames / changeEvery),
    cycles: Math.floor(frames / changeEvery) / cycle,
    draws,
    mostWorkers,
    workersMade: workers.made,
    paths,
    problems,
    height,
    seconds: (performance.now() - started) / 1000,
  };
}

const harness = { fuzzOcean, fuzzElement, soak };

declare global {
  interface Window {
    robustness: typeof harness;
  }
}
window.robustness = harness;
document.title = 'ready';
