#!/usr/bin/env node
// A 900x600 screenshot of the demo for the README, from Debian's Chromium (headless, Playwright).
//
//   node tools/screenshot.mjs [OUT.png] [query]      (defaults: docs/screenshot.png '?paused&t=2')
//
// Serves build/web/site with tools/serve.mjs on a free port, waits for demo.ready, renders the
// frame at the query's time and saves the page (canvas and its overlays) as a PNG.
import { spawn } from 'node:child_process';
import { createServer } from 'node:net';
import { existsSync, mkdirSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from '@playwright/test';

const repo = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const site = join(repo, 'build/web/site');
const out = resolve(process.argv[2] || join(repo, 'docs/screenshot.png'));
let query = process.argv[3] || '?paused&t=2';
if (!query.startsWith('?')) query = `?${query}`;

function freePort() {
  return new Promise((resolvePort, reject) => {
    const server = createServer();
    server.on('error', reject);
    server.listen(0, '127.0.0.1', () => {
      const { port } = server.address();
      server.close(() => resolvePort(port));
    });
  });
}

async function main() {
  if (!existsSync(join(site, 'index.html'))) {
    throw new Error(`${site} has no index.html: build the web preset first (cmake --build --preset web)`);
  }
  const port = await freePort();
  const server = spawn(process.execPath, [join(repo, 'tools/serve.mjs'), site, String(port)], {
    stdio: ['ignore', 'ignore', 'inherit'],
  });
  const url = `http://127.0.0.1:${port}/`;
  let browser;
  try {
    for (let attempt = 0; ; ++attempt) {
      try {
        if ((await fetch(url)).ok) break;
      } catch { /* not listening yet */ }
      if (attempt > 100 || server.exitCode !== null) throw new Error(`server did not answer at ${url}`);
      await new Promise((r) => setTimeout(r, 100));
    }
    browser = await chromium.launch({
      executablePath: process.env.CHROMIUM_PATH || '/usr/bin/chromium',
      args: ['--no-sandbox', '--disable-background-networking', '--disable-component-update',
             '--disable-sync', '--no-first-run', '--disable-default-apps'],
    });
    const page = await browser.newPage({ viewport: { width: 900, height: 600 } });
    await page.goto(url + query);
    await page.waitForFunction(() => window.demo !== undefined);
    await page.evaluate(() => window.demo.ready);
    // Let the stats line fill in (it shows after a couple of display frames).
    await page.waitForFunction(() => /fps/.test(document.getElementById('stats').textContent), null,
                               { timeout: 10_000 });
    await page.waitForTimeout(500);
    mkdirSync(dirname(out), { recursive: true });
    await page.screenshot({ path: out });
    console.log(`wrote ${out} (900x600, ${query})`);
  } finally {
    if (browser) await browser.close();
    server.kill();
  }
}

main().then(() => process.exit(0), (error) => {
  console.error(`screenshot: ${error.message}`);
  process.exit(1);
});
