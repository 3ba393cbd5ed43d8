// Playwright drives Debian's Chromium (no browser download). The page is served by
// tools/serve.mjs from the web build; ./test.sh builds it first, starts the server on a port the
// system picks and passes its address in TEST_BASE_URL. Run by hand, the config starts one itself
// on TEST_PORT (default 8181).
import { defineConfig } from '@playwright/test';

const port = Number(process.env.TEST_PORT || 8181);
const given = process.env.TEST_BASE_URL || null;

export default defineConfig({
  testDir: 'tests/web',
  outputDir: 'build/playwright-results',
  workers: 1,  // two cores: one browser at a time keeps SwiftShader timings sane
  // A frame of the default (hierarchical) search costs 0.5-1 s in SwiftShader at 800x600 on a
  // loaded 2-core machine, and a test that opens two pages draws dozens: 60 s left one test
  // (url.spec's copied link) at 50 s alone and past 60 s beside other work. No test waits on a
  // time; this only bounds how long a hung test holds the run.
  timeout: 180_000,
  // Scene reloads and model loads on a shared 2-core machine can take seconds; tests that wait
  // for the page's jobs await demo.idle() instead of a time.
  expect: { timeout: 15_000 },
  reporter: [['list']],
  use: {
    baseURL: given || `http://127.0.0.1:${port}/`,
    viewport: { width: 800, height: 600 },
    launchOptions: {
      executablePath: process.env.CHROMIUM_PATH || '/usr/bin/chromium',
      args: ['--no-sandbox', '--disable-background-networking', '--disable-component-update',
             '--disable-sync', '--no-first-run', '--disable-default-apps'],
    },
  },
  webServer: given ? undefined : {
    command: `node tools/serve.mjs build/web/site ${port}`,
    url: `http://127.0.0.1:${port}/`,
    reuseExistingServer: false,
    timeout: 20_000,
  },
});
