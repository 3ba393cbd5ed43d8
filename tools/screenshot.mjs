#!/usr/bin/env node
// Screenshots of the demo for the README, from Debian's Chromium (headless, Playwright).
//
//   node tools/screenshot.mjs                        docs/screenshot.png (default scene, 900x600,
//                                                    the panel open), docs/screenshot-phone.png
//                                                    (the default scene on a phone at t=0:
//                                                    390x844 CSS px at devicePixelRatio 2, touch,
//                                                    the panel as it starts there: closed; saved
//                                                    at CSS size) and
//                                                    docs/scene-NAME.png for every scene in
//                                                    build/web/site/scenes (900x600, paused at
//                                                    t=2, the panel closed)
//   node tools/screenshot.mjs OUT.png [query] [--phone] [--eval=EXPR]
//                                                    one picture (query default '?paused&t=2';
//                                                    --phone: as on the phone, else 900x600 with
//                                                    the panel open; EXPR: evaluated in the page
//                                                    once it is laid out, before the picture,
//                                                    e.g. --eval='window.demo.explainPixel(300,360)')
//
// Serves build/web/site with tools/serve.mjs on a free port, waits for demo.ready, renders the
// frame at the query's time and saves the page (canvas and its overlays) as a PNG.
import { spawn } from 'node:child_process';
import { createServer } from 'node:net';
import { existsSync, mkdirSync, readdirSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from '@playwright/test';

const repo = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const site = join(repo, 'build/web/site');
const args = process.argv.slice(2);
const phoneOnly = args.includes('--phone');
const evalArg = args.find((a) => a.startsWith('--eval='));
const evalExpression = evalArg ? evalArg.slice('--eval='.length) : null;
const positional = args.filter((a) => a !== '--phone' && a !== evalArg);
const single = positional[0] ? resolve(positional[0]) : null;
let singleQuery = positional[1] || '?paused&t=2';
if (!singleQuery.startsWith('?')) singleQuery = `?${singleQuery}`;

const DESKTOP = { viewport: { width: 900, height: 600 } };
const PHONE = { viewport: { width: 390, height: 844 }, deviceScaleFactor: 2, hasTouch: true, isMobile: true };

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
    const problems = [];
    const pages = new Map();  // device -> page
    const pageFor = async (device) => {
      if (!pages.has(device)) {
        const context = await browser.newContext(device);
        const page = await context.newPage();
        page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
        page.on('console', (m) => { if (m.type() === 'error') problems.push(`console error: ${m.text()}`); });
        pages.set(device, page);
      }
      return pages.get(device);
    };
    // panelOpen: true or false, or null to leave the panel as the page starts it.
    const shoot = async (out, query, { panelOpen, device = DESKTOP }) => {
      const page = await pageFor(device);
      await page.goto(url + query);
      await page.waitForFunction(() => window.demo !== undefined);
      await page.evaluate(() => window.demo.ready);
      if (panelOpen !== null) await page.evaluate((open) => window.demo.panel()?.open(open), panelOpen);
      if (evalExpression) {
        await page.waitForTimeout(300);  // the canvas takes its size once the panel is docked
        await page.evaluate(evalExpression);
      }
      // Let the stats line fill in (it shows after a couple of display frames; a paused page draws
      // on demand and says "idle" once it has drawn).
      await page.waitForFunction(() => /fps|idle/.test(document.getElementById('stats').textContent), null,
                                 { timeout: 10_000 });
      await page.waitForTimeout(500);
      const errors = await page.locator('#messages .message.error').allTextContents();
      if (errors.length) throw new Error(`${query}: the page shows an error: ${errors.join(' / ')}`);
      mkdirSync(dirname(out), { recursive: true });
      // At CSS size: a phone's picture as large as the page it shows, not twice that.
      await page.screenshot({ path: out, scale: 'css' });
      const open = await page.evaluate(() => !window.demo.panel()?._closed);
      const { width, height } = device.viewport;
      console.log(`wrote ${out} (${width}x${height}${device.deviceScaleFactor ? ` at devicePixelRatio ${device.deviceScaleFactor}` : ''}, ` +
                  `${query}, panel ${open ? 'open' : 'closed'})`);
    };
    if (single) {
      await shoot(single, singleQuery, phoneOnly ? { panelOpen: null, device: PHONE } : { panelOpen: true });
    } else {
      await shoot(join(repo, 'docs/screenshot.png'), '?paused&t=2', { panelOpen: true });
      // At t=0, where the three figures stand apart across the frame (the framing a phone gets).
      await shoot(join(repo, 'docs/screenshot-phone.png'), '?paused&t=0', { panelOpen: null, device: PHONE });
      const scenes = readdirSync(join(site, 'scenes')).filter((f) => f.endsWith('.json') && f !== 'index.json').sort();
      for (const file of scenes) {
        const name = file.replace(/\.json$/, '');
        await shoot(join(repo, `docs/scene-${name}.png`), `?scene=${name}&paused&t=2`, { panelOpen: false });
      }
    }
    for (const p of problems) console.log(`note: ${p}`);
  } finally {
    if (browser) await browser.close();
    server.kill();
  }
}

main().then(() => process.exit(0), (error) => {
  console.error(`screenshot: ${error.message}`);
  process.exit(1);
});
