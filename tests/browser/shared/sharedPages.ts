import { expect, test, type Browser, type Page } from '@playwright/test';

/**
 * Test pages that the tests of one spec file share, one per key (a canvas size, say): a page load
 * and its modules cost more than many tests take. `open` loads a new page for a key; `reset` sets
 * a page back as it loaded before each test that takes it. Call at the top level of a spec file:
 * it adds the hooks that close the pages after the file, and after a failed test, so that the
 * next test starts on a new page (a page left mid-evaluate, or in a state a failed test left,
 * fails no other test). Tests that need a fresh page (a page's first Ocean, its console, other
 * modules) keep Playwright's `page`.
 */
export function sharedPages(open: (page: Page, key: string) => Promise<void>, reset: (page: Page) => Promise<void>) {
  const pages = new Map<string, Page>();
  const closeAll = async () => {
    for (const page of pages.values()) await page.close();
    pages.clear();
  };
  test.afterEach(async ({ browser: _browser }, testInfo) => {
    if (testInfo.status !== testInfo.expectedStatus) await closeAll();
  });
  test.afterAll(closeAll);
  /** The shared page for `key`, set back as it loaded. */
  return async (browser: Browser, key = ''): Promise<Page> => {
    let page = pages.get(key);
    if (!page) {
      page = await browser.newPage();
      await open(page, key);
      pages.set(key, page);
    }
    await reset(page);
    return page;
  };
}

/**
 * One page for a whole spec file, loaded once before its tests (a page load and its shaders cost
 * more than most tests take): `url` must set its title to 'ready' when its harness is set up. The
 * page is handed to `opened` for the file's tests; after them, no uncaught error may have reached
 * the page. Call at the top level of a spec file. `viewport`: the page's size (Playwright's
 * default, 1280×720, when left out).
 */
export function onePageForFile(url: string, opened: (page: Page) => void | Promise<void>, viewport?: { width: number; height: number }): void {
  let page: Page | null = null;
  const errors: string[] = [];
  test.beforeAll(async ({ browser }) => {
    page = await browser.newPage(viewport ? { viewport } : {});
    page.on('pageerror', (error) => errors.push(error.message));
    await page.goto(url);
    await expect(page).toHaveTitle('ready');
    await opened(page);
  });
  test.afterAll(async () => {
    // The errors before closing: closing a page with GPU work under way can raise its own (WebGPU:
    // "Instance dropped in popErrorScope"), which are not the tests'.
    const uncaught = [...errors];
    await page?.close();
    expect(uncaught).toEqual([]);
  });
}
