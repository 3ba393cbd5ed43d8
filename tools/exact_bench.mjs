#!/usr/bin/env node
// Issue 13's numbers in Debian's headless Chromium (SwiftShader WebGL2), via Playwright. Not a
// test: it prints numbers and exits 0.
//
//   node tools/exact_bench.mjs [--frames N] [--size WxH] [--heavy DIR] [--budgets 50,100,400]
//                              [--screenshot docs/error-view.png]
//
//  - frame ms of the course's setting, the default and the exact mode (demo.frame(1/60), blocks of
//    N frames taken in turn twice: A B C A B C), on the default scene and, with --heavy DIR (after
//    python3 tools/make_models.py --heavy), with DIR/mario.obj in place of mario;
//  - what the error view costs (its own ms, and the frame with it against without);
//  - what auto picks under each budget, the table it measured, and how long the measuring took;
//  - with --screenshot, the page with the error view on (the default mode), saved as a PNG.
// Serves build/web/site with tools/serve.mjs on a free port.
import { copyFileSync, mkdirSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import { freePort, launchChromium, repo, startServer } from './bench_lib.mjs';

const site = join(repo, 'build/web/site');

const COURSE = { captureAtOrigin: true, search: 'plain', depthBits: 16, glassSurfaces: 1 };
const CONFIGS = [
  { label: 'course (plain, origin, every-frame)', accuracy: COURSE, planner: { policy: 'every-frame' } },
  { label: 'default (hierarchical, layers 2)', accuracy: {}, planner: { policy: 'when-changed' } },
  { label: 'exact', accuracy: { search: 'exact' }, planner: { policy: 'when-changed' } },
];

function parseArgs(argv) {
  const o = { frames: 20, width: 800, height: 800, heavy: null, budgets: [50, 100, 400], screenshot: null };
  for (let i = 0; i < argv.length; ++i) {
    const value = () => argv[++i];
    const a = argv[i];
    if (a === '--frames') o.frames = Number(value());
    else if (a === '--heavy') o.heavy = value();
    else if (a === '--budgets') o.budgets = value().split(',').map(Number);
    else if (a === '--screenshot') o.screenshot = value();
    else if (a === '--size') [o.width, o.height] = value().split('x').map(Number);
    else throw new Error(`unknown argument ${a}`);
  }
  return o;
}

const median = (v) => { const s = [...v].sort((a, b) => a - b); return s[Math.floor(s.length / 2)]; };

async function open(browser, url, query, o) {
  const page = await browser.newPage({ viewport: { width: o.width, height: o.height } });
  page.on('pageerror', (e) => console.log(`page error: ${e.message}`));
  await page.goto(url + query);
  await page.waitForFunction(() => window.demo !== undefined);
  await page.evaluate(() => window.demo.ready);
  await page.evaluate(() => window.demo.idle());
  return page;
}

// Frame ms of each config: blocks of `frames`, in turn, twice.
async function frameTimes(page, frames) {
  const ms = CONFIGS.map(() => []);
  for (let round = 0; round < 2; ++round) {
    for (let c = 0; c < CONFIGS.length; ++c) {
      const times = await page.evaluate(async ({ config, frames: n }) => {
        const d = window.demo;
        const defaults = Object.fromEntries(d.schema().accuracy.map((i) => [i.name, i.default]));
        d.setAccuracy({ ...defaults, ...config.accuracy });
        d.setPlanner(config.planner);
        d.setTime(2);
        for (let i = 0; i < 3; ++i) d.frame(1 / 60);
        const out = [];
        for (let i = 0; i < n; ++i) {
          const t0 = performance.now();
          const s = d.frame(1 / 60);
          out.push({ wall: performance.now() - t0, frameMs: s.gpuFrameMs >= 0 ? s.gpuFrameMs : s.frameMs });
        }
        return out;
      }, { config: CONFIGS[c], frames });
      ms[c].push(...times.map((t) => t.frameMs));
    }
  }
  return ms.map(median);
}

async function errorViewCost(page, frames) {
  return page.evaluate((n) => {
    const d = window.demo;
    const defaults = Object.fromEntries(d.schema().accuracy.map((i) => [i.name, i.default]));
    d.setAccuracy(defaults);
    d.setPlanner({ policy: 'when-changed' });
    const run = (on) => {
      d.setView({ showError: on });
      d.setTime(2);
      for (let i = 0; i < 2; ++i) d.frame(1 / 60);
      const wall = [], view = [];
      let last = null;
      for (let i = 0; i < n; ++i) {
        const t0 = performance.now();
        last = d.frame(1 / 60);
        wall.push(performance.now() - t0);
        if (last.errorView) view.push(last.errorView.ms);
      }
      const med = (v) => { const s = [...v].sort((a, b) => a - b); return s[Math.floor(s.length / 2)]; };
      return { wall: med(wall), view: view.length ? med(view) : 0, last: last.errorView };
    };
    const off = run(false), on = run(true);
    d.setView({ showError: false });
    return { off, on };
  }, frames);
}

async function autoPicks(page, budgets) {
  const out = [];
  for (const budget of budgets) {
    out.push(await page.evaluate(async (b) => {
      const d = window.demo;
      d.setView({ auto: true, budget: b });
      const t0 = performance.now();
      const r = await d.runAutoPick();
      return { budget: b, ms: performance.now() - t0, reason: r.pick.reason, table: r.pick.table };
    }, budget));
  }
  await page.evaluate(() => window.demo.setView({ auto: false }));
  return out;
}

async function main() {
  const o = parseArgs(process.argv.slice(2));
  const port = await freePort();
  const { child, url } = await startServer(port, site);
  const browser = await launchChromium();
  try {
    const scenes = [{ label: 'default scene', query: '?paused&t=2' }];
    if (o.heavy) {
      // The shipped models with the heavy mario, served from the site.
      const dir = join(site, 'heavy');
      mkdirSync(dir, { recursive: true });
      for (const f of readdirSync(join(site, 'models'))) copyFileSync(join(site, 'models', f), join(dir, f));
      copyFileSync(join(o.heavy, 'mario.obj'), join(dir, 'mario.obj'));
      scenes.push({ label: 'heavy figure', query: '?paused&t=2&assets=heavy/' });
    }
    for (const s of scenes) {
      const page = await open(browser, url, s.query, o);
      const size = await page.evaluate(() => window.demo.frame(0));
      const ms = await frameTimes(page, o.frames);
      console.log(`${s.label}, ${size.width}x${size.height}, ${o.frames} x 2 frames each (median frame ms; ` +
                  `${size.gpuFrameMs >= 0 ? 'GPU timer' : 'CPU with a read-back'}):`);
      CONFIGS.forEach((c, i) => console.log(`  ${c.label.padEnd(38)} ${ms[i].toFixed(1).padStart(8)} ms  ` +
                                            `(${(ms[i] / ms[1]).toFixed(2)}x the default)`));
      const cost = await errorViewCost(page, Math.max(5, Math.floor(o.frames / 2)));
      console.log(`  error view (default mode): frame ${cost.off.wall.toFixed(1)} -> ${cost.on.wall.toFixed(1)} ms a call; ` +
                  `its own part ${cost.on.view.toFixed(1)} ms; reflector PSNR ${cost.on.last.psnrDb.toFixed(2)} dB, ` +
                  `${cost.on.last.pixelsOver32} of ${cost.on.last.reflectorPixels} px off by >32`);
      if (s === scenes[0]) {
        for (const a of await autoPicks(page, o.budgets)) {
          console.log(`  auto, budget ${a.budget} ms (measuring took ${(a.ms / 1000).toFixed(1)} s): ${a.reason}`);
          console.log(a.table.replace(/^/gm, '      ').trimEnd());
        }
      }
      await page.close();
    }
    if (o.screenshot) {
      const page = await open(browser, url, '?paused&t=1.5&showError=true&cam=0.6,0.5,4,8,-3', o);
      await page.evaluate(() => window.demo.frame(0));
      await page.waitForTimeout(500);
      await page.screenshot({ path: o.screenshot });
      console.log(`wrote ${o.screenshot}`);
      await page.close();
    }
  } finally {
    await browser.close();
    child.kill();
  }
}

main().then(() => process.exit(0), (e) => { console.error(`exact_bench: ${e.message}`); process.exit(1); });
