/**
 * Still frames for `npm run shot` (scripts/shot.mjs): the ocean at exactly the times asked for, one
 * frame at a time (not in real time), so the same arguments give the same picture. It draws the
 * way the app does (src/app/appView.ts: renderer, camera, ocean and per-frame steps are the app's),
 * and reads every option from the same tables the app's URL does, so neither the CLI nor this page
 * keeps its own copy of a rule.
 *
 * Query parameters (all optional):
 *   width, height  drawing-buffer size in pixels (default 1280×720), pixel ratio 1
 *   --<option>     a scene option as the CLI got it: each key of SIMULATION_OPTIONS, SUN_OPTIONS
 *                  and SHADING_OPTIONS (src/parameters/) in kebab-case (--wind-speed, --patch-sizes,
 *                  --shading-mode …), read with parseOptionText; --wind is --wind-speed, and each
 *                  alias of the tables in kebab-case is its option (--scatter-colour); and the
 *                  app's --path, --skybox, --wireframe, --inspector, --boat, --buoys, --scene, --quality,
 *                  --cam (read as the app's URL reads them, urlState.parseValue); the app's
 *                  --target-fps, --time-scale, --paused and --t are refused, saying why (NOT_IN_A_SHOT)
 *   time           the time drawn on load, s (default 0)
 *   camera         x,y,z,tx,ty,tz: position and look-at point (default: the app's cam)
 *   fov            vertical field of view in degrees (default the app's, 55)
 *   query          an app link's query (what follows "?"): exactly that scene, read by the app's
 *                  parseState; not together with the parameters above but width and height
 *   cli            the CLI's own option names, comma-separated: suggested for unknown options too
 *   help=1         no picture: window.shotHelp becomes the option list for `--help`
 *
 * Exposes window.renderFrame(t): draws time t and resolves once the GPU has finished the frame;
 * then canvas.toDataURL('image/png') is that frame. window.shotStart is { t, timeScale }, the first
 * frame's time and how fast a link's time runs. document.title becomes 'ready' after the first
 * frame, or 'error: …' (with window.shotError, and window.shotErrorKind 'usage' when an option,
 * the query or the skybox was bad, 'failure' otherwise, e.g. without WebGL 2).
 */
import { Scene } from 'three';
import { createAppCamera, createAppOcean, createAppRenderer, loadAppSkybox, startingQuality } from '../src/app/appView';
import { SceneOutput } from '../src/render/sceneOutput';
import { Boat, centreAhead } from '../src/objects/boat';
import { Buoys } from '../src/objects/buoys';
import { FlyControls } from '../src/app/flyControls';
import { Inspector } from '../src/app/inspector';
import { SunLight } from '../src/objects/sunLight';
import { wrapLongTime } from '../src/runtime/simulationClock';
import { FrameLoop } from '../src/runtime/frameLoop';
import {
  defaultState,
  DEFAULT_STATE,
  parseState,
  parseValue,
  roundTime,
  SCENES,
  simulationParameters,
  type AppState,
} from '../src/app/urlState';
import { SceneObjects, startingCam } from '../src/app/sceneChoice';
import { formatOptionText, kebabCase, nearestName, optionRoutes, parseDecimal, ParameterError, parseOptionText, type OptionRule } from '../src/parameters/options';
import { PATH_PREFERENCES } from '../src/layers/oceanSimulation';
import { SIMULATION_OPTIONS, validateParameters } from '../src/parameters/parameters';
import { SHADING_OPTIONS, SUN_OPTIONS } from '../src/parameters/sceneOptions';
import { AdaptiveQuality, QUALITY_SETTINGS } from '../src/runtime/adaptiveQuality';

declare global {
  interface Window {
    renderFrame: (t: number) => Promise<void>;
    shotStart?: { t: number; timeScale: number };
    shotError?: string;
    shotErrorKind?: 'usage' | 'failure';
    shotHelp?: string;
  }
}

/** A bad option, query or skybox: the CLI exits with 2 (usage error). */
class UsageError extends Error {}

type Table = Readonly<Record<string, OptionRule>>;

/** Where a --option goes: a key of one of the option tables, or an app-only AppState key. */
interface ShotOption {
  stateKey: keyof AppState;
  /** The table and key parseOptionText reads it with; none for the app-only options. */
  table?: Table;
  key?: string;
  /** For the app-only options' --help line. */
  placeholder?: string;
  help?: string;
  /** Given without a value it means 1 (--wireframe). */
  flag?: boolean;
}

/** Every scene option by its CLI name, in the order --help lists them. */
const OPTIONS = new Map<string, ShotOption>();
/** Other names the CLI takes: older ones, and the tables' aliases in kebab-case (--scatter-colour). */
const ALIASES: Record<string, string> = { wind: 'wind-speed' };
const TABLES: Readonly<Record<string, Table>> = { simulation: SIMULATION_OPTIONS, sun: SUN_OPTIONS, shading: SHADING_OPTIONS };
for (const [name, { group, key }] of optionRoutes(TABLES, kebabCase)) {
  if (name !== kebabCase(key)) ALIASES[name] = kebabCase(key);
  else OPTIONS.set(name, { table: TABLES[group], key, stateKey: (key === 'shadingMode' ? 'mode' : key) as keyof AppState });
}
OPTIONS.set('path', { stateKey: 'path', placeholder: PATH_PREFERENCES.join('|'), help: 'where the FFT runs: on the GPU, in JS, or auto (GPU if it can)' });
OPTIONS.set('skybox', {
  stateKey: 'skybox',
  placeholder: 'generated|<url>',
  help: 'the analytic sky, or the folder URL of six faces px.png … nz.png (relative to the app, e.g. /skybox/clear-afternoon/)',
});
OPTIONS.set('wireframe', { stateKey: 'wireframe', placeholder: '[1|0]', help: 'draw the surface as wireframe', flag: true });
OPTIONS.set('inspector', { stateKey: 'inspector', placeholder: '[1|0]', help: "the inspector's tiles along the bottom", flag: true });
OPTIONS.set('boat', { stateKey: 'boat', placeholder: '[1|0]', help: "the app's boat on its course ahead of the camera, with its wake run up to the time", flag: true });
OPTIONS.set('buoys', {
  stateKey: 'buoys',
  placeholder: '[1|0]',
  help: "the app's buoys, set down at rest ahead of the camera at the first frame's time (as the app does on load), then moved frame by frame",
  flag: true,
});
OPTIONS.set('scene', {
  stateKey: 'scene',
  placeholder: SCENES.join('|'),
  help: "the open sea, or the app's island (a beach, a cliff, a reef, a pier, a moored boat); with the island and neither --camera nor --cam, the view from offshore of its beach",
});
OPTIONS.set('quality', {
  stateKey: 'quality',
  placeholder: QUALITY_SETTINGS.join('|'),
  help: "the app's quality level: its grid, cascades and MSAA, at pixel ratio 1 (its render scale does not apply: the PNG has --size); auto is the level the app starts at, high",
});
OPTIONS.set('cam', { stateKey: 'cam', placeholder: 'x,y,z,yaw,pitch', help: "the app's camera: metres and degrees (instead of --camera)" });

/**
 * The app's settings that a shot has no use for, each with why: the CLI refuses them rather than
 * ignore them. (From a --query link they are read as the app reads them: see docs/embedding.md, "Headless shots".)
 */
const NOT_IN_A_SHOT: Readonly<Record<string, string>> = {
  'target-fps': "the frame rate quality 'auto' adapts to; a shot draws each frame however long it takes, at the level 'auto' starts at (high)",
  'time-scale': 'a shot draws the times asked for: --time, and with --frames one frame every 1/--fps seconds of simulated time',
  paused: 'a still shows one time (--time); frames move by 1/--fps each',
  t: 'the time of a shot is --time <seconds>',
};

function optionNamed(name: string): ShotOption | undefined {
  return OPTIONS.get(Object.hasOwn(ALIASES, name) ? ALIASES[name] : name);
}

/** The value of --name (written `text`), or a UsageError that names it. */
function readOption(name: string, option: ShotOption, text: string): unknown {
  const rename = (message: string, key: string) => (message.startsWith(key) ? `--${name}${message.slice(key.length)}` : `--${name}: ${message}`);
  if (option.table && option.key) {
    if (text === '') throw new UsageError(`--${name} needs a value: ${option.table[option.key].allowed}`);
    try {
      return parseOptionText(option.table, option.key, text);
    } catch (error) {
      if (error instanceof ParameterError) throw new UsageError(rename(error.message, option.key));
      throw error;
    }
  }
  const result = parseValue(option.stateKey, option.flag && text === '' ? '1' : text);
  if ('error' in result) throw new UsageError(rename(result.error, option.stateKey));
  return result.value;
}

/** The state the CLI's --options describe, over the app's defaults. */
function stateFromOptions(query: URLSearchParams): AppState {
  const state = defaultState();
  const given = new Map<keyof AppState, string>();
  const known = [...OPTIONS.keys(), ...Object.keys(ALIASES), ...Object.keys(NOT_IN_A_SHOT), ...(query.get('cli') ?? '').split(',').filter(Boolean)];
  for (const [parameter, text] of query) {
    if (!parameter.startsWith('--')) continue;
    const name = parameter.slice(2);
    if (Object.hasOwn(NOT_IN_A_SHOT, name)) throw new UsageError(`--${name} is an app setting a shot has no use for: ${NOT_IN_A_SHOT[name]}`);
    const option = optionNamed(name);
    if (!option) {
      const nearest = nearestName(name, known);
      throw new UsageError(`unknown option --${name}; did you mean --${Object.hasOwn(ALIASES, nearest) ? ALIASES[nearest] : nearest}? (--help lists them all)`);
    }
    const earlier = given.get(option.stateKey);
    if (earlier !== undefined) throw new UsageError(`--${name} is given twice${earlier === name ? '' : ` (also as --${earlier})`}`);
    given.set(option.stateKey, name);
    (state as unknown as Record<string, unknown>)[option.stateKey] = readOption(name, option, text);
  }
  if (given.has('cam') && query.has('camera')) throw new UsageError('give the camera once: --cam x,y,z,yaw,pitch or --camera x,y,z,tx,ty,tz');
  // Values fine alone can clash (patch sizes too far apart for the resolution …): name the option.
  try {
    validateParameters(simulationParameters(state));
  } catch (error) {
    if (!(error instanceof ParameterError)) throw error;
    const name = kebabCase(error.parameter);
    const message = error.message.startsWith(error.parameter) ? `--${name}${error.message.slice(error.parameter.length)}` : error.message;
    throw new UsageError(`${message} (with the options given)`);
  }
  return state;
}

/** The scene of an app link's query, exactly as the app reads it; any warning is an error here. */
function stateFromLink(text: string): AppState {
  const { state, warnings } = parseState(text);
  if (warnings.length > 0) {
    // The app would go on with defaults ("— using the default …"); a shot stops instead.
    const messages = warnings.map(({ message }) => message.replace(/ — using the default [\s\S]*$/, ''));
    throw new UsageError(`the query is not one the app reads cleanly: ${messages.join('; ')}`);
  }
  if (state.paused) state.t = roundTime(state.t); // as the app does: a paused t is what the URL holds
  return state;
}

function numberParameter(query: URLSearchParams, name: string): number | undefined {
  const raw = query.get(name);
  if (raw === null) return undefined;
  const value = parseDecimal(raw);
  if (!Number.isFinite(value)) throw new UsageError(`${name}=${raw} is not a number`);
  return value;
}

/** The --help lines for the scene options, from the tables (rules, units, defaults). */
function helpText(): string {
  const COLUMN = 34;
  const WIDTH = 100;
  const lines: string[] = [];
  /** `text` after `head`, wrapped at WIDTH and indented to COLUMN. */
  const entry = (head: string, text: string) => {
    const rows = [head.length < COLUMN ? head.padEnd(COLUMN) : head];
    if (head.length >= COLUMN) rows.push(''.padEnd(COLUMN));
    for (const word of text.split(' ')) {
      const row = rows[rows.length - 1];
      if (row.length > COLUMN && row.length + word.length > WIDTH) rows.push(`${''.padEnd(COLUMN)}${word}`);
      else rows[rows.length - 1] = row.length > COLUMN ? `${row} ${word}` : `${row}${word}`;
    }
    lines.push(...rows);
  };
  const unit = (rule: OptionRule) => (rule.unit === '°' ? 'deg' : rule.unit);
  const placeholder = (rule: OptionRule) => {
    if (rule.type === 'choice') return '<name>';
    if (rule.type === 'color') return '<#rrggbb|r,g,b>';
    return rule.type === 'numbers' ? `<${unit(rule) || 'n'},…>` : `<${unit(rule) || 'n'}>`;
  };
  const section = (title: string, names: string[]) => {
    lines.push('', title);
    for (const name of names) {
      const option = OPTIONS.get(name)!;
      const rule = option.table && option.key ? option.table[option.key] : undefined;
      const fallback = DEFAULT_STATE[option.stateKey];
      const value = typeof fallback === 'boolean' ? (fallback ? '1' : '0') : formatOptionText(fallback);
      const aliases = Object.keys(ALIASES).filter((alias) => ALIASES[alias] === name);
      entry(
        `  --${name} ${rule ? placeholder(rule) : option.placeholder}`,
        `${rule ? rule.allowed : option.help} (default ${value})` +
          aliases.map((alias) => `; --${alias} is --${name}`).join(''),
      );
    }
  };
  const names = [...OPTIONS.keys()];
  const from = (table: Table) => names.filter((name) => OPTIONS.get(name)!.table === table);
  section("Sea (src/parameters/parameters.ts; the app's URL names in kebab-case)", from(SIMULATION_OPTIONS));
  section('Sun and shading (src/parameters/sceneOptions.ts)', [...from(SUN_OPTIONS), ...from(SHADING_OPTIONS)]);
  section("The app's other settings (src/app/urlState.ts)", names.filter((name) => !OPTIONS.get(name)!.table));
  lines.push('', "The app's settings a shot has no use for (refused here; in a --query link read and left unused)");
  for (const [name, why] of Object.entries(NOT_IN_A_SHOT)) entry(`  --${name}`, why);
  return lines.join('\n').slice(1);
}

async function start(): Promise<void> {
  const query = new URLSearchParams(location.search);
  if (query.get('help') === '1') {
    window.shotHelp = helpText();
    document.title = 'help';
    return;
  }
  const width = numberParameter(query, 'width') ?? 1280;
  const height = numberParameter(query, 'height') ?? 720;
  for (const [name, value] of [['width', width], ['height', height]] as const) {
    if (!Number.isInteger(value) || value < 1 || value > 8192) throw new UsageError(`${name} must be an integer from 1 to 8192, got ${value}`);
  }
  const link = query.get('query');
  let state: AppState;
  if (link !== null) {
    const extra = [...query.keys()].filter((name) => !['width', 'height', 'query', 'cli'].includes(name));
    if (extra.length > 0) throw new UsageError(`the query is the whole scene: put ${extra.join(', ')} into it instead`);
    state = stateFromLink(link);
  } else {
    state = stateFromOptions(query);
    state.t = numberParameter(query, 'time') ?? state.t;
  }
  const fov = numberParameter(query, 'fov');
  const cameraText = query.get('camera');
  let lookAt: number[] | null = null;
  if (cameraText !== null) {
    lookAt = cameraText.split(',').map(parseDecimal);
    if (lookAt.length !== 6 || !lookAt.every(Number.isFinite)) throw new UsageError(`camera must be x,y,z,targetX,targetY,targetZ; got ${cameraText}`);
  }

  // The app's renderer; preserveDrawingBuffer keeps the frame for toDataURL (it changes no pixel).
  const renderer = createAppRenderer({ preserveDrawingBuffer: true });
  // Pixel ratio 1 at every quality level: the PNG has the size asked for (a level's grid, cascades
  // and MSAA still apply).
  renderer.setPixelRatio(1);
  renderer.setSize(width, height);
  document.body.appendChild(renderer.domElement);
  const gl = renderer.getContext();
  if (!(gl instanceof WebGL2RenderingContext)) throw new Error('WebGL 2 is not available');

  // The level's MSAA; the page lives as long as the shot, and the output with it.
  const output = new SceneOutput(renderer, startingQuality(state).msaa);
  // worker: false, so the JS path's fields are ready when update returns.
  const ocean = createAppOcean(renderer, state, { worker: false });
  // The level's grid floor too (as applyQualityStep sets it in the app; its pixel ratio is 1 here).
  ocean.surface.fewestCellsPerRing = startingQuality(state).fewestGridCells;
  const scene = new Scene();
  scene.add(ocean);
  const camera = createAppCamera(width / height);
  if (fov !== undefined) camera.fov = fov;
  camera.updateProjectionMatrix();
  // The island's view when it is chosen without a camera, as the app starts (sceneChoice.ts).
  state.cam = startingCam(state);
  if (lookAt) {
    camera.position.set(lookAt[0], lookAt[1], lookAt[2]);
    camera.lookAt(lookAt[3], lookAt[4], lookAt[5]);
    camera.updateMatrixWorld();
  } else {
    // The app places its camera from cam through FlyControls; do the same, without the input.
    const [x, y, z, yaw, pitch] = state.cam;
    new FlyControls(camera, renderer.domElement, { position: [x, y, z], yaw, pitch }).dispose();
  }
  try {
    await loadAppSkybox(ocean, state.skybox);
  } catch (error) {
    throw new UsageError(`skybox: ${error instanceof Error ? error.message : String(error)}`);
  }
  // As the app keeps its time: a frame sequence from t = 10^16 s moves (the sea at t mod its period).
  state.t = wrapLongTime(state.t, ocean.repeatPeriod);
  // The buoys and then the boat, as the app adds them on load (the order of their pressure on the
  // local waves, and the time the boat starts from, are the app's). The buoys are set down at rest
  // on the water of the first frame's time, as the app sets them down on the time it loads at.
  const buoys = state.buoys ? new Buoys(ocean) : null;
  if (buoys) {
    ocean.update(state.t, camera);
    buoys.dropAhead(camera);
    scene.add(buoys);
  }
  // The boat as the app shows it (its wake is run up to each frame's time: localWaves.ts warmUp).
  const boat = state.boat ? new Boat(ocean, centreAhead(camera)) : null;
  if (boat) scene.add(boat);
  // The open sea or the island, as the app shows it.
  const sceneObjects = new SceneObjects(scene, ocean);
  sceneObjects.show(state.scene);
  // The app's light for what floats and the island (the sea's shader uses no three.js light).
  const sunLight = new SunLight(ocean);
  if (boat || buoys || sceneObjects.island) scene.add(sunLight);
  // The inspector's tiles are part of the app's canvas when it is shown.
  const inspector = state.inspector ? new Inspector(ocean, document.body) : null;

  const pixel = new Uint8Array(4);
  // The app's frame loop, drawing the times asked for (its clock and adaptive quality stay unused).
  const loop = new FrameLoop(new AdaptiveQuality(state.quality, state.targetFps), { t: state.t });
  window.renderFrame = async (t: number) => {
    if (typeof t !== 'number' || !Number.isFinite(t)) throw new Error(`renderFrame: t must be a finite number, got ${t}`);
    loop.time.t = t;
    loop.draw(
      { ocean, scene, camera, output },
      {
        beforeRender: (drawn) => {
          buoys?.update(drawn);
          boat?.update();
          sceneObjects.update();
          sunLight.update();
        },
      },
    );
    inspector?.render(renderer);
    // A one-pixel readback waits for the GPU to finish the frame (gl.finish does not, in Chromium).
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
  };
  window.shotStart = { t: state.t, timeScale: link !== null ? state.timeScale : 1 };
  await window.renderFrame(state.t);
  document.title = 'ready';
}

start().catch((error: unknown) => {
  window.shotErrorKind = error instanceof UsageError ? 'usage' : 'failure';
  window.shotError = error instanceof Error ? error.message : String(error);
  document.title = `error: ${window.shotError}`;
});
