import { expect, type Page } from '@playwright/test';

/** Opens the test page; returns the page errors and console errors it collects from then on. */
export async function openRobustnessPage(page: Page): Promise<string[]> {
  const problems: string[] = [];
  page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
  page.on('console', (message) => {
    if (message.type() === 'error') problems.push(`console error: ${message.text()}`);
  });
  await page.goto('/tests/browser/robustness/robustness.html');
  await expect(page).toHaveTitle('ready');
  return problems;
}
