import { relative } from 'node:path';
import type { Reporter, TestCase, TestResult } from '@playwright/test/reporter';

/**
 * A Playwright reporter that prints, at the end of a run, each test file's time: the durations of
 * its tests (hooks and retries included) added up, slowest first. Listed before 'list' in
 * playwright.config.ts so that the list reporter's summary ("N passed (Xs)") stays the last line.
 */
export default class FileTimesReporter implements Reporter {
  private readonly files = new Map<string, { ms: number; tests: number }>();

  onTestEnd(test: TestCase, result: TestResult): void {
    const file = relative(process.cwd(), test.location.file);
    const entry = this.files.get(file) ?? { ms: 0, tests: 0 };
    entry.ms += result.duration;
    if (result.retry === 0) entry.tests++;
    this.files.set(file, entry);
  }

  onEnd(): void {
    if (this.files.size === 0) return;
    const rows = [...this.files].sort((a, b) => b[1].ms - a[1].ms);
    const total = rows.reduce((sum, [, { ms }]) => sum + ms, 0);
    const lines = rows.map(([file, { ms, tests }]) => `  ${(ms / 1000).toFixed(1).padStart(7)} s  ${file} (${tests} test${tests === 1 ? '' : 's'})`);
    console.log(['', 'Time per test file:', ...lines, `  ${(total / 1000).toFixed(1).padStart(7)} s  in all`].join('\n'));
  }

  printsToStdio(): boolean {
    return true;
  }
}
