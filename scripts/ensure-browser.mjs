// Makes sure a Chromium exists for the browser tests: finds one (scripts/browser.mjs), or installs
// one, saying what it does, or stops with a message that says how to install one.
import { execSync } from 'node:child_process';
import { BROWSER_ENV_VARS, findBrowser } from './browser.mjs';

function run(command) {
  console.error(`ensure-browser: running: ${command}`);
  execSync(command, { stdio: 'inherit' });
}

function canUseApt() {
  try {
    execSync('command -v apt-get', { stdio: 'ignore' });
    return typeof process.getuid === 'function' && process.getuid() === 0;
  } catch {
    return false;
  }
}

let browser = findBrowser();
if (!browser) {
  console.error('ensure-browser: no Chromium found for the browser tests; installing one.');
  try {
    if (canUseApt()) {
      run('apt-get update -qq');
      run('DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium');
    } else {
      run('npx playwright install chromium');
    }
  } catch (error) {
    console.error(`ensure-browser: the install failed: ${error.message}`);
  }
  browser = findBrowser();
}
if (!browser) {
  console.error(
    'ensure-browser: no Chromium to run the browser tests. Install one, then run the tests again:\n' +
      '  Debian/Ubuntu (as root): apt-get install -y chromium\n' +
      '  anywhere else:           npx playwright install chromium\n' +
      `  or point ${BROWSER_ENV_VARS[0]} at a Chromium binary.`,
  );
  process.exit(1);
}
console.error(`ensure-browser: using ${browser}`);
