import { expect, test, type Browser, type Page } from '@playwright/test';
import { DEFAULT_PARAMETERS } from '../../../src/parameters/parameters';
import { boatWake } from '../shared/boatWake';
import { sharedPages } from '../shared/sharedPages';
import { slowFrames, slowFramesUntil } from '../shared/slowFrames';
import { withoutWebGL2 } from '../shared/withoutWebGL2';

// <fft-ocean> in a page: zero-configuration rendering, sizing, live attributes, pausing when it
// cannot be seen, and the message a browser without WebGL 2 gets. Small boxes and N = 64 keep
// SwiftShader fast.

/** What a page said: its uncaught errors and its console warnings. */
interface PageLog {
  errors: string[];
  warnings: string[];
}
const logs = new WeakMap<Page, PageLog>();

/** Loads the test page into `page`, listening to what it says. */
async function loadPage(page: Page): Promise<PageLog> {
  const log: PageLog = { errors: [], warnings: [] };
  logs.set(page, log);
  page.on('pageerror', (error) => log.errors.push(error.message));
  page.on('console', (message) => {
    if (message.type() === 'warning') log.warnings.push(message.text());
  });
  await page.goto('/tests/browser/embed/embed.html');
  await expect(page).toHaveTitle('ready');
  return log;
}

// One page for the file's tests (a page load and its modules cost about as much as a test),
// set back as it loaded before each (window.embed.reset: no element, nothing added to the body,
// scrolled to the top) with its log emptied; after each test no uncaught error may have reached
// it. Tests that need a page of their own (an init script, no WebGL 2) keep Playwright's `page`.
const sharedEmbedPage = sharedPages(
  async (page) => void (await loadPage(page)),
  async (page) => {
    await page.evaluate(() => window.embed.reset());
    const log = logs.get(page)!;
    log.errors.length = 0;
    log.warnings.length = 0;
  },
);
let testLog: PageLog | null = null;
test.afterEach(() => {
  const errors = testLog?.errors ?? [];
  testLog = null;
  expect(errors, 'uncaught errors on the shared page').toEqual([]);
});

/** The shared page, as it loaded, and its log from now on. */
async function openPage(browser: Browser): Promise<{ page: Page } & PageLog> {
  const page = await sharedEmbedPage(browser);
  testLog = logs.get(page)!;
  return { page, ...testLog };
}

test('with no attributes and no size it fills its container at 16:9 and draws the sea', async ({ browser }) => {
  const { page, errors } = await openPage(browser);
  const result = await page.evaluate(async () => {
    const el = window.embed.create({ resolution: '64' });
    await window.embed.drawn(el, 3);
    const box = el.getBoundingClientRect();
    const canvas = el.shadowRoot!.querySelector('canvas')!;
    return {
      box: [box.width, box.height],
      buffer: [canvas.width, canvas.height],
      display: getComputedStyle(el).display,
      pixels: window.embed.pixels(el),
      path: el.ocean!.simulation.path,
    };
  });
  expect(result.display).toBe('block');
  expect(result.box).toEqual([480, 270]);
  expect(result.buffer).toEqual([480, 270]); // device pixel ratio 1 here
  expect(result.path).toBe('gpu-rgba32f');
  // Not black, not blank: sky above, darker water below, waves in between.
  expect(result.pixels.mean).toBeGreaterThan(40);
  expect(result.pixels.spread).toBeGreaterThan(15);
  const rows = 16;
  const rowMean = (row: number) => result.pixels.samples.slice(row * rows, (row + 1) * rows).reduce((a, b) => a + b) / rows;
  expect(rowMean(0), 'the bottom rows (water) are darker than the top (sky)').toBeLessThan(rowMean(rows - 1));
  expect(errors).toEqual([]);
});

test('its shadow root is styled by a constructed stylesheet, or by a <style> where there is none (Safari before 16.4)', async ({ browser, page: withoutReplaceSync }) => {
  const styling = (page: Page) =>
    page.evaluate(() => {
      const el = window.embed.create({ resolution: '64', paused: '' });
      const box = el.getBoundingClientRect();
      return { box: [box.width, box.height], adopted: el.shadowRoot!.adoptedStyleSheets.length, styleElements: el.shadowRoot!.querySelectorAll('style').length };
    });
  // A constructed stylesheet is what a strict CSP allows (style-src 'self' blocks <style>: csp.spec.ts).
  expect(await styling((await openPage(browser)).page)).toEqual({ box: [480, 270], adopted: 1, styleElements: 0 });
  // A page of its own, whose CSSStyleSheet cannot be constructed from text.
  await withoutReplaceSync.addInitScript(() => delete (CSSStyleSheet.prototype as Partial<CSSStyleSheet>).replaceSync);
  const { errors } = await loadPage(withoutReplaceSync);
  expect(await styling(withoutReplaceSync)).toEqual({ box: [480, 270], adopted: 0, styleElements: 1 });
  expect(errors).toEqual([]);
});

test('it follows its box: a page-given height, then a resize', async ({ browser }) => {
  const { page } = await openPage(browser);
  const sizes = await page.evaluate(async () => {
    const el = window.embed.create({ resolution: '64' });
    el.style.height = '150px';
    await window.embed.drawn(el);
    await window.embed.frames(3);
    const first = [el.canvas!.width, el.canvas!.height, el.camera!.aspect];
    el.style.width = '240px';
    el.style.height = '200px';
    await window.embed.frames(4);
    return [first, [el.canvas!.width, el.canvas!.height, el.camera!.aspect]];
  });
  expect(sizes[0]).toEqual([480, 150, 480 / 150]);
  expect(sizes[1]).toEqual([240, 200, 240 / 200]);
});

test('attributes apply live; a bad value warns, naming the attribute, and keeps the last good one', async ({ browser }) => {
  const { page, ...log } = await openPage(browser);
  const result = await page.evaluate(async () => {
    // Attributes present before the element is connected are used to create the ocean.
    const el = window.embed.create({ resolution: '64', 'wind-speed': '6', seed: '9', 'sun-elevation': '10' });
    await window.embed.drawn(el);
    const ocean = el.ocean!;
    const initial = { ...ocean.parameters, sun: ocean.sky.sunElevation };
    el.setAttribute('wind-speed', '20');
    el.setAttribute('wind-direction', '-45');
    el.setAttribute('choppiness', '1.5');
    el.setAttribute('sun-azimuth', '200');
    el.setAttribute('cloud-cover', '0.5');
    el.setAttribute('shading-mode', 'height');
    el.setAttribute('patch-sizes', '20,100');
    const changed = {
      ...ocean.parameters,
      sunAzimuth: ocean.sky.sunAzimuth,
      cloudCover: ocean.sky.cloudCover,
      mode: ocean.shading.shadingMode,
      cascades: ocean.simulation.cascades.map((layer) => layer.spectrum.patchSize),
    };
    el.setAttribute('wind-speed', 'fast');
    el.setAttribute('resolution', '100');
    el.setAttribute('patch-sizes', '100,20');
    el.setAttribute('sun-elevation', '95');
    el.setAttribute('cloud-cover', '2');
    el.setAttribute('shading-mode', 'shiny');
    el.setAttribute('time-scale', 'NaN');
    el.setAttribute('time-scale', '1e308'); // finite, but a frame's step would overflow
    const kept = { ...ocean.parameters, sun: ocean.sky.sunElevation, cloudCover: ocean.sky.cloudCover, mode: ocean.shading.shadingMode };
    el.removeAttribute('wind-speed'); // back to the default
    const defaulted = ocean.parameters.windSpeed;
    return { initial, changed, kept, defaulted, sameOcean: el.ocean === ocean };
  });
  expect(result.initial).toMatchObject({ resolution: 64, windSpeed: 6, seed: 9, sun: 10 });
  expect(result.changed).toMatchObject({ windSpeed: 20, windDirection: -45, choppiness: 1.5, sunAzimuth: 200, cloudCover: 0.5, mode: 'height', patchSizes: [20, 100] });
  expect(result.changed.cascades).toEqual([20, 100]);
  expect(result.kept).toMatchObject({ windSpeed: 20, resolution: 64, sun: 10, cloudCover: 0.5, mode: 'height', patchSizes: [20, 100] });
  expect(result.defaulted).toBe(DEFAULT_PARAMETERS.windSpeed);
  expect(result.sameOcean).toBe(true);
  const warnings = log.warnings.join('\n');
  for (const [name, value] of [
    ['wind-speed', 'fast'],
    ['resolution', '100'],
    ['sun-elevation', '95'],
    ['cloud-cover', '2'],
    ['shading-mode', 'shiny'],
    ['time-scale', 'NaN'],
    ['time-scale', '1e308'],
    ['patch-sizes', '100,20'],
  ]) {
    expect(warnings).toContain(`<fft-ocean>: ignoring ${name}="${value}"`);
  }
  expect(warnings).toContain('keeping 20'); // wind-speed kept its last good value
  expect(warnings).toContain('a power of two from 16 to 1024');
  expect(warnings).toContain('keeping 20,100'); // patch-sizes kept its last good value
});

test('quality and target-fps: a level sets the render scale, MSAA, N and cascades; auto lowers them to hold the frame rate and says so; bad values warn as the URL does', async ({ browser }) => {
  test.setTimeout(120_000);
  const { page, ...log } = await openPage(browser);
  const settled = await page.evaluate(async () => {
    const el = window.embed.create({ resolution: '64' }); // quality high (the harness's default)
    await window.embed.drawn(el, 2);
    const look = () => ({
      level: el.quality.level,
      pixelRatio: el.renderer!.getPixelRatio(),
      msaa: el.output!.msaa,
      samples: el.output!.multisampleTarget?.samples ?? 0,
      resolution: el.ocean!.parameters.resolution,
      cascades: el.ocean!.simulation.cascades.map((layer) => layer.spectrum.patchSize),
    });
    const high = look();
    el.setAttribute('quality', 'lowest');
    await window.embed.drawn(el, el.frameCount + 2);
    const lowest = look();
    // Bad values: the last good ones stay.
    el.setAttribute('quality', 'best');
    el.setAttribute('target-fps', '1000');
    el.setAttribute('target-fps', 'fast');
    const kept = { ...look(), targetFps: el.quality.targetFps };
    // 'auto' for 120 fps: down a level per 2-second window of frames slower than the target.
    const changes: { level: string; medianFrameMs: number | null }[] = [];
    el.addEventListener('fft-ocean-quality-change', (event) => changes.push((event as CustomEvent).detail));
    el.setAttribute('quality', 'auto');
    el.setAttribute('target-fps', '120');
    Object.assign(window, { qualityAfterAuto: async () => {
      await window.embed.drawn(el, el.frameCount + 2);
      return { auto: look(), changes, targetFps: el.quality.targetFps };
    } });
    return { high, lowest, kept };
  });
  // Frames of 250 ms (by their timestamps) until 'auto' is at the lowest level: 120 fps is then out of
  // reach on any machine, however fast it draws (a real GPU would hold it unslowed).
  await slowFramesUntil(page, 'element', 'lowest');
  const levels = { ...settled, ...(await page.evaluate(() => (window as unknown as { qualityAfterAuto: () => Promise<{ auto: unknown; changes: { level: string; medianFrameMs: number | null }[]; targetFps: number }> }).qualityAfterAuto())) };
  console.log(`<fft-ocean> auto for 120 fps: ${levels.changes.map(({ level, medianFrameMs }) => `${level} (median ${medianFrameMs?.toFixed(0)} ms)`).join(' → ')}`);
  expect(levels.high).toEqual({ level: 'high', pixelRatio: 1, msaa: true, samples: 4, resolution: 64, cascades: [13.7, 79.3, 457] });
  expect(levels.lowest).toEqual({ level: 'lowest', pixelRatio: 0.3, msaa: false, samples: 0, resolution: 32, cascades: [79.3, 457] });
  expect(levels.kept).toEqual({ ...levels.lowest, targetFps: 30 });
  expect(levels.auto).toEqual(levels.lowest);
  expect(levels.targetFps).toBe(120);
  // It went down one level at a time from high, and said so each time.
  expect(levels.changes.map(({ level }) => level)).toEqual(['medium', 'low', 'lowest']);
  for (const { medianFrameMs } of levels.changes) expect(medianFrameMs).toBeGreaterThan(1000 / 120);
  const warnings = log.warnings.join('\n');
  // The app's URL rules and messages (parameters/qualityOptions.ts), under the attribute's name.
  expect(warnings).toContain('<fft-ocean>: ignoring quality="best": quality must be one of auto, high, medium, low, lowest; got "best"; keeping lowest');
  expect(warnings).toContain('<fft-ocean>: ignoring target-fps="1000": targetFps must be a number of frames per second from 5 to 240; got "1000"; keeping 30');
  expect(warnings).toContain('<fft-ocean>: ignoring target-fps="fast": targetFps must be');
});

test('shading attributes from the table: colours as "#rrggbb", CSS or linear "r,g,b", also under their British names', async ({ browser }) => {
  const { page, ...log } = await openPage(browser);
  const result = await page.evaluate(async () => {
    const el = window.embed.create({ resolution: '64', 'scatter-colour': '#1a6b80', 'caustic-color': '0.5,0.25,0.125', ior: '1.34' });
    await window.embed.drawn(el);
    const ocean = el.ocean!;
    const initial = ocean.shading;
    el.setAttribute('caustic-colour', 'rgb(26, 107, 128)');
    el.setAttribute('absorption', '0.1,0.2,0.3');
    const changed = ocean.shading;
    el.setAttribute('scatter-color', 'seaweed');
    el.setAttribute('caustic-power', '0');
    const kept = ocean.shading;
    el.removeAttribute('scatter-colour');
    el.removeAttribute('ior');
    return { initial, changed, kept, removed: ocean.shading };
  });
  const teal = [0.010329823026364548, 0.14702726648767014, 0.21586050010324415]; // new Color(0x1a6b80), linear
  result.initial.scatterColor.forEach((c, i) => expect(c).toBeCloseTo(teal[i], 6));
  expect(result.initial).toMatchObject({ causticColor: [0.5, 0.25, 0.125], ior: 1.34 });
  result.changed.causticColor.forEach((c, i) => expect(c).toBeCloseTo(teal[i], 6));
  expect(result.changed.absorption).toEqual([0.1, 0.2, 0.3]);
  expect(result.kept).toEqual(result.changed);
  expect(result.removed).toMatchObject({ scatterColor: [0, 0.035, 0.06], ior: 1.333, causticColor: result.changed.causticColor });
  const warnings = log.warnings.join('\n');
  expect(warnings).toContain('<fft-ocean>: ignoring scatter-color="seaweed": scatterColor must be a colour');
  expect(warnings).toContain('got "seaweed"; keeping 0.0103298,0.147027,0.21586');
  expect(warnings).toContain('<fft-ocean>: ignoring caustic-power="0": causticPower must be a number > 0');
});

test('warnings quote the attribute as written (its first 40 characters) and say deep water "deep"', async ({ browser }) => {
  const { page, ...log } = await openPage(browser);
  await page.evaluate(async () => {
    const el = window.embed.create({ resolution: '64' });
    await window.embed.drawn(el);
    el.setAttribute('wind-speed', 'abc');
    el.setAttribute('wind-direction', '');
    el.setAttribute('depth', '-1');
    el.setAttribute('seed', `${'7'.repeat(45)}`);
    el.setAttribute('camera-height', 'high');
  });
  const warnings = log.warnings.filter((warning) => warning.startsWith('<fft-ocean>'));
  expect(warnings).toEqual([
    '<fft-ocean>: ignoring wind-speed="abc": windSpeed must be a speed in m/s from 0 to 60; got "abc"; keeping 10',
    '<fft-ocean>: ignoring wind-direction="": windDirection must be a finite angle in degrees (at most 1e6 in size); got ""; keeping 30',
    '<fft-ocean>: ignoring depth="-1": depth must be a depth in metres > 0, or Infinity (written "deep") for deep water; got "-1"; keeping deep',
    `<fft-ocean>: ignoring seed="${'7'.repeat(40)}…": seed must be an integer from 0 to 4294967295; got "${'7'.repeat(40)}…"; keeping 1`,
    '<fft-ocean>: ignoring camera-height="high": it must be a number of metres above 0 and at most 10000; keeping 8',
  ]);
  expect(warnings.join('\n')).not.toContain('NaN');
});

test('paused freezes time and draws only on changes; the time can be set', async ({ browser }) => {
  const { page } = await openPage(browser);
  const result = await page.evaluate(async () => {
    const el = window.embed.create({ resolution: '64', paused: '' });
    await window.embed.drawn(el);
    await window.embed.frames(5);
    const frames0 = el.frameCount;
    const time0 = el.time;
    await window.embed.frames(10);
    const idle = el.frameCount - frames0;
    el.time = 42.5;
    el.setAttribute('wind-speed', '15');
    await window.embed.frames(3);
    const afterChange = el.frameCount - frames0;
    el.removeAttribute('paused');
    await window.embed.frames(10);
    return { time0, idle, afterChange, timeAfterChange: el.time, running: el.frameCount - frames0 };
  });
  expect(result.time0).toBe(0);
  expect(result.idle).toBe(0);
  expect(result.afterChange).toBe(1); // two changes in one task: one frame
  expect(result.timeAfterChange).toBeGreaterThan(42.5);
  expect(result.running).toBeGreaterThan(4);
});

test('a time set far ahead shows the sea of that time as a double resolves it, seen from within reach', async ({ browser }) => {
  const { page, errors } = await openPage(browser);
  const result = await page.evaluate(async () => {
    const el = window.embed.create({ resolution: '64', paused: '' });
    await window.embed.drawn(el);
    el.time = 1e300;
    const far = window.embed.pixels(el); // drawn at once
    const camera = el.camera!.position.toArray();
    el.time = 1e300 % el.ocean!.repeatPeriod; // where the sea is the same
    const near = window.embed.pixels(el);
    return { far: far.samples, near: near.samples, camera };
  });
  // Before: the view drifted 1.5e300 m out, where the surface's coordinates overflow.
  expect(Math.hypot(result.camera[0], result.camera[2])).toBeLessThan(1e8);
  expect(result.far).toEqual(result.near);
  expect(errors).toEqual([]);
});

test('it draws only while on screen, and time does not jump when it comes back', async ({ browser }) => {
  const { page } = await openPage(browser);
  const result = await page.evaluate(async () => {
    const spacer = document.createElement('div');
    spacer.style.height = '3000px';
    document.body.prepend(spacer);
    const el = window.embed.create({ resolution: '64' }); // below the fold
    await new Promise((resolve) => setTimeout(resolve, 800));
    const offscreenFrames = el.frameCount;
    el.scrollIntoView();
    await window.embed.drawn(el, 5);
    window.scrollTo(0, 0);
    // The observer reports (at a frame's rendering update): from then on it draws nothing.
    const away = performance.now();
    while (el.active) {
      if (performance.now() - away > 20_000) throw new Error('still active 20 s after scrolling away');
      await new Promise((resolve) => setTimeout(resolve, 50));
    }
    const frames1 = el.frameCount;
    const time1 = el.time;
    await new Promise((resolve) => setTimeout(resolve, 1000));
    const framesWhileAway = el.frameCount - frames1;
    el.scrollIntoView();
    const back = performance.now();
    await window.embed.drawn(el, el.frameCount + 3);
    return { offscreenFrames, framesWhileAway, timeGained: el.time - time1, backFor: (performance.now() - back) / 1000 };
  });
  expect(result.offscreenFrames).toBe(0);
  expect(result.framesWhileAway).toBe(0);
  // The real time since it came back, at most: not the second it was away.
  expect(result.timeGained).toBeGreaterThan(0);
  expect(result.timeGained).toBeLessThanOrEqual(result.backFor + 1e-3);
});

test('24 elements down a page: each draws when scrolled into view, at most 16 hold a WebGL context at once, the first draw again after scrolling back', async ({ browser }) => {
  // Chromium keeps 16 WebGL contexts per page and drops the oldest beyond that for good, so
  // elements off screen must give theirs back. Paused elements draw once per (re)build: cheap.
  const { page, errors } = await openPage(browser);
  const result = await page.evaluate(async () => {
    const { create, pixels, frames } = window.embed;
    const elements = Array.from({ length: 24 }, (_, i) => {
      const el = create({ resolution: '16', paused: '', seed: String(i + 1) });
      el.style.width = '160px';
      el.style.height = '90px';
      el.time = i;
      return el;
    });
    // Sampled every frame from here to the end: elements holding a renderer, and contexts the
    // browser took from an element still holding it.
    let mostHolding = 0;
    let takenByBrowser = 0;
    /** Per element: frames drawn when last seen without a renderer (a new frame is a new build's). */
    const framesWhenReleased = elements.map(() => 0);
    let sampling = true;
    const sample = () => {
      const holding = elements.filter((el) => el.renderer);
      mostHolding = Math.max(mostHolding, holding.length);
      takenByBrowser = Math.max(takenByBrowser, holding.filter((el) => el.renderer!.getContext().isContextLost()).length);
      elements.forEach((el, i) => {
        if (!el.renderer) framesWhenReleased[i] = el.frameCount;
      });
      if (sampling) requestAnimationFrame(sample);
    };
    sample();
    /** Whether the element drew on its own since its last build, and its picture then (null: it did not). */
    const look = async (i: number) => {
      const el = elements[i];
      const start = performance.now();
      while (!(el.active && el.frameCount > framesWhenReleased[i])) {
        if (el.renderer?.getContext().isContextLost() || performance.now() - start > 15_000) return null;
        await frames(1);
      }
      return pixels(el, 4);
    };
    const inView = () => elements.map((el, i) => [el.getBoundingClientRect(), i] as const).filter(([box]) => box.top >= 0 && box.bottom <= innerHeight).map(([, i]) => i);

    const firstLooks: (ReturnType<typeof pixels> | null)[] = elements.map(() => null);
    const seen = new Set<number>();
    const atTheTop = inView();
    for (let y = 0; ; y += innerHeight / 2) {
      scrollTo(0, y);
      await frames(2); // the observers report
      for (const i of inView()) {
        if (seen.has(i)) continue;
        seen.add(i);
        firstLooks[i] = await look(i);
      }
      if (scrollY + innerHeight >= document.documentElement.scrollHeight) break;
    }
    const topReleased = atTheTop.every((i) => !elements[i].renderer);
    scrollTo(0, 0);
    await frames(2);
    const backLooks = await Promise.all(atTheTop.map((i) => look(i)));
    sampling = false;
    return {
      seen: seen.size,
      firstLooks,
      topReleased,
      backLooks,
      backTimes: atTheTop.map((i) => elements[i].time),
      mostHolding,
      takenByBrowser,
    };
  });
  const seaLike = (look: { mean: number; samples: number[] } | null) =>
    // Not black; the top row (sky) brighter than the bottom row (water); rows are bottom-up.
    !!look && look.mean > 40 && look.samples.slice(12, 16).reduce((a, b) => a + b) > look.samples.slice(0, 4).reduce((a, b) => a + b);
  console.log(
    `drew a sea: ${result.firstLooks.filter(seaLike).length} of ${result.firstLooks.length} scrolling down, ` +
      `${result.backLooks.filter(seaLike).length} of ${result.backLooks.length} back at the top; ` +
      `at most ${result.mostHolding} held a context; the browser took ${result.takenByBrowser}`,
  );
  expect(result.seen).toBe(24);
  expect(result.firstLooks.map(seaLike)).toEqual(result.firstLooks.map(() => true));
  expect(result.mostHolding).toBeLessThanOrEqual(16);
  expect(result.takenByBrowser).toBe(0);
  expect(result.topReleased).toBe(true);
  expect(result.backLooks.map(seaLike)).toEqual(result.backLooks.map(() => true));
  expect(result.backLooks.length).toBeGreaterThanOrEqual(7);
  // Rebuilt at the same time with the same settings: the same picture as on the way down.
  expect(result.backTimes).toEqual(result.backLooks.map((_, i) => i));
  result.backLooks.forEach((look, i) => {
    const first = result.firstLooks[i]!;
    expect(Math.max(...look!.samples.map((value, j) => Math.abs(value - first.samples[j]))), `element ${i}`).toBeLessThan(1);
  });
  expect(errors).toEqual([]);
});

test('it stops while the tab is hidden and resumes without a jump in time', async ({ browser }) => {
  const { page } = await openPage(browser);
  const result = await page.evaluate(async () => {
    const el = window.embed.create({ resolution: '64' });
    await window.embed.drawn(el, 3);
    const setHidden = (hidden: boolean) => {
      if (hidden) Object.defineProperty(document, 'visibilityState', { configurable: true, get: () => 'hidden' });
      else delete (document as { visibilityState?: unknown }).visibilityState;
      document.dispatchEvent(new Event('visibilitychange'));
    };
    const hiding = performance.now();
    setHidden(true);
    await window.embed.frames(2);
    const frames1 = el.frameCount;
    const time1 = el.time;
    const activeWhileHidden = el.active;
    // The frames' own length, as this machine draws them now: the clock counts the first frame
    // after a gap as one ordinary frame (src/runtime/simulationClock.ts), at most this long.
    const frameLength = (performance.now() - hiding) / 1000;
    await new Promise((resolve) => setTimeout(resolve, 1200));
    const framesWhileHidden = el.frameCount - frames1;
    setHidden(false);
    const back = performance.now();
    await window.embed.drawn(el, el.frameCount + 3);
    return { activeWhileHidden, framesWhileHidden, timeGained: el.time - time1, backFor: (performance.now() - back) / 1000, frameLength };
  });
  expect(result.activeWhileHidden).toBe(false);
  expect(result.framesWhileHidden).toBe(0);
  expect(result.timeGained).toBeGreaterThan(0);
  // Not the 1.2 s it was hidden: the time it has been back, and at most one ordinary frame for the gap.
  expect(result.timeGained).toBeLessThanOrEqual(result.backFor + result.frameLength + 1e-3);
});

test('its time follows real time × time-scale when frames are slow', async ({ browser }) => {
  const { page } = await openPage(browser);
  await page.evaluate(() => window.embed.drawn(window.embed.create({ resolution: '64', 'time-scale': '1.5' }), 2));
  const { simulated, real } = await slowFrames(page, 'element'); // the old clock, at most 0.1 s a frame, ran at 0.4×
  expect(real).toBeGreaterThan(1);
  expect(simulated / real).toBeCloseTo(1.5, 1);
});

test('a click on its sea drops a stone there: the local waves get rings', async ({ browser }) => {
  const { page } = await openPage(browser);
  // Two frames drawn: the canvas has its size and the camera its place, which the click's ray needs.
  const calmBefore = await page.evaluate(async () => {
    const el = window.embed.create({ resolution: '64', 'wind-speed': '3' });
    await window.embed.drawn(el, 2);
    return !el.ocean!.localWaves!.active;
  });
  expect(calmBefore).toBe(true); // nothing has made a local wave yet: the layer does not step
  const box = (await page.locator('fft-ocean').boundingBox())!;
  await page.mouse.click(box.x + box.width / 2, box.y + box.height * 0.8); // the sea below the horizon
  const result = await page.evaluate(async () => {
    const el = document.querySelector('fft-ocean')!;
    const waves = el.ocean!.localWaves!;
    // The click's handler ran (Playwright's click returns once the page has handled it): a stone
    // dropped inside the grid wakes the layer (drop() returns true); it falls at the next update.
    const dropped = waves.active;
    // Then a fixed stretch of simulated time, not a count of frames: however many frames the
    // element drew before this line ran, or however slow they are, the stone has fallen and its
    // rings have spread for at least a second (they stay above 6 cm for 6 s).
    const [time, frame] = [el.time, el.frameCount];
    const start = performance.now();
    while (el.time < time + 1 || el.frameCount < frame + 1) {
      if (performance.now() - start > 60_000) throw new Error(`simulated time moved ${el.time - time} s in 60 s (${el.frameCount - frame} frames)`);
      await window.embed.frames(1);
    }
    const { displacement } = waves.fieldsOnCpu(0);
    let largest = 0;
    for (let i = 1; i < displacement.length; i += 4) largest = Math.max(largest, Math.abs(displacement[i]));
    return { dropped, largest, simulated: el.time - time };
  });
  console.log(`a click's stone: rings up to ${(100 * result.largest).toFixed(1)} cm after ${result.simulated.toFixed(2)} s`);
  expect(result.dropped).toBe(true);
  expect(result.largest).toBeGreaterThan(0.02); // a 0.8 m deep dip leaves rings of centimetres
});

test('boat: a boat circles ahead of the drifting view with a wake behind it; removing the attribute takes it off the sea', async ({ browser }) => {
  const { page, errors } = await openPage(browser);
  const result = await page.evaluate(async () => {
    const el = window.embed.create({ resolution: '64', 'wind-speed': '2', paused: '', boat: '' });
    el.time = 40; // a still: the wake is run up over the 20 s before (localWaves.ts)
    await window.embed.drawn(el);
    const boat = el.scene!.getObjectByName('boat')!;
    const camera = el.camera!;
    // In view: in front of the camera and inside its frustum.
    const seen = boat.position.clone().project(camera);
    return { seen: [seen.x, seen.y, seen.z], distance: boat.position.distanceTo(camera.position), lit: !!el.scene!.getObjectByName('sun light') };
  });
  expect(Math.abs(result.seen[0])).toBeLessThan(1);
  expect(Math.abs(result.seen[1])).toBeLessThan(1);
  expect(result.seen[2]).toBeLessThan(1);
  expect(result.distance).toBeGreaterThan(20);
  expect(result.distance).toBeLessThan(110);
  expect(result.lit).toBe(true);
  const wake = await boatWake(page, 'element');
  expect(wake.onCourse).toBeLessThan(1e-6); // a still: exactly where its course puts it
  expect(wake.astern).toBeGreaterThan(0.02);
  expect(wake.astern).toBeGreaterThan(3 * wake.ahead); // waves behind, calm water ahead
  // And foam along its track, none ahead (hullFoam.ts): 12 m from its centre is 8 m astern, foam
  // 1.6 s old at 5 m/s, e^(−1.6/3) = 0.59 of its full coverage (Froude number 0.56: full).
  expect(wake.foamAstern).toBeGreaterThan(0.4);
  expect(wake.foamAhead).toBe(0);
  const after = await page.evaluate(async () => {
    const el = document.querySelector('fft-ocean')!;
    el.removeAttribute('boat');
    el.time = 60;
    await window.embed.drawn(el, el.frameCount + 1);
    return { boat: !!el.scene!.getObjectByName('boat'), light: !!el.scene!.getObjectByName('sun light') };
  });
  expect(after).toEqual({ boat: false, light: false });
  expect(errors).toEqual([]);
});

test('defining it twice is harmless', async ({ browser }) => {
  const { page, errors } = await openPage(browser);
  const result = await page.evaluate(() => {
    const again = window.embed.defineFftOceanElement();
    return { same: again === customElements.get('fft-ocean'), isClass: again === window.embed.FftOceanElement };
  });
  expect(result).toEqual({ same: true, isClass: true });
  expect(errors).toEqual([]);
});

test('without WebGL 2 the box shows a message instead of staying blank', async ({ page }) => {
  await withoutWebGL2(page);
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(error.message));
  await page.goto('/tests/browser/embed/embed.html');
  await expect(page).toHaveTitle('ready');
  const result = await page.evaluate(async () => {
    let event: string | null = null;
    const el = document.createElement('fft-ocean');
    el.addEventListener('fft-ocean-error', (e) => (event = (e as CustomEvent).detail.message));
    document.querySelector('#box')!.append(el);
    await window.embed.frames(3);
    const message = el.shadowRoot!.querySelector('[part="message"]') as HTMLElement | null;
    const box = el.getBoundingClientRect();
    return {
      text: message?.textContent ?? null,
      visible: message ? message.getBoundingClientRect().height > 100 : false,
      canvas: el.shadowRoot!.querySelector('canvas') !== null,
      box: [box.width, box.height],
      ocean: el.ocean,
      event,
    };
  });
  expect(result.text).toContain('needs WebGL 2');
  expect(result.visible).toBe(true);
  expect(result.canvas).toBe(false);
  expect(result.box).toEqual([480, 270]);
  expect(result.ocean).toBeNull();
  expect(result.event).toContain('WebGL 2');
  expect(errors).toEqual([]); // a message, not an uncaught exception
  await expect(page.getByText('This ocean needs WebGL 2')).toBeVisible(); // what a person sees
});

test('a frame that fails to draw: the box says so and the page gets fft-ocean-error, once, with no uncaught error', async ({ browser }) => {
  const { page, errors } = await openPage(browser);
  const result = await page.evaluate(async () => {
    const events: string[] = [];
    const el = document.createElement('fft-ocean');
    el.addEventListener('fft-ocean-error', (e) => events.push((e as CustomEvent).detail.message));
    document.querySelector('#box')!.append(el);
    // The element makes its ocean once it is seen near the screen (an observer's callback), so wait for drawn frames.
    await window.embed.drawn(el, 2);
    // A fault nothing can recover from inside a frame (here: the ocean's update throws).
    el.ocean!.update = () => {
      throw new Error('a failure inside the frame');
    };
    await window.embed.frames(2); // the element's next frame throws, however long it takes
    const message = el.shadowRoot!.querySelector('[part="message"]');
    return { events, message: message?.textContent ?? null };
  });
  expect(result.events).toEqual(['Drawing the ocean failed; it has stopped.']);
  expect(result.message).toBe('Drawing the ocean failed; it has stopped.');
  expect(errors).toEqual([]);
});
