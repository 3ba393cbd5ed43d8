#!/usr/bin/env node
// Benchmarks of the web build in Debian's Chromium (headless, via Playwright). Not a test: it
// prints numbers and exits 0.
//
//   node tools/web_bench.mjs [--scene NAME] [--frames N] [--size WxH] [--query '&cube=128']
//   node tools/web_bench.mjs --raw [--frames N] [--warmup N] [--size WxH] [--query '?paused&cube=128']
//
// Default: the page's bench mode (?bench): on the scene, for each capture policy (every-frame,
// when-changed, when-changed + LOD 0.5, + view LOD 0.5, time-sliced 2, every-n 4) it resets the time to 0 and
// renders N frames of demo.frame(1/60), then prints frame ms (median, p10, p90), faces, draw calls
// and triangles per frame, and the largest pixel difference from every-frame over the same
// animation. --query adds to the page's query (e.g. '&cube=128').
//
// --raw: times N calls of demo.frame(1/60) under the page's own settings (default ?paused) after
// a warm-up: the page's frameMs / captureMs and the wall time of each call (median, p10, p90);
// triangles and draw calls per frame.
//
// Either way: serves build/web/site with tools/serve.mjs on a free port, 800x800 viewport.
import { spawn } from 'node:child_process';
import { createServer } from 'node:net';
import { existsSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from '@playwright/test';

const repo = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const site = join(repo, 'build/web/site');

function parseArgs(argv) {
  const options = { frames: 60, warmup: 10, width: 800, height: 800, query: null, scene: null, raw: false };
  for (let i = 0; i < argv.length; ++i) {
    const arg = argv[i];
    const value = () => {
      if (i + 1 >= argv.length) throw new Error(`${arg} needs a value`);
      return argv[++i];
    };
    if (arg === '--frames') options.frames = Number(value());
    else if (arg === '--warmup') options.warmup = Number(value());
    else if (arg === '--query') options.query = value();
    else if (arg === '--scene') options.scene = value();
    else if (arg === '--raw') options.raw = true;
    else if (arg === '--size') {
      const m = /^(\d+)x(\d+)$/.exec(value());
      if (!m) throw new Error('--size wants WIDTHxHEIGHT');
      options.width = Number(m[1]);
      options.height = Number(m[2]);
    } else if (arg === '--help' || arg === '-h') {
      console.log('usage: node tools/web_bench.mjs [--scene NAME] [--frames N] [--size WxH] [--query Q]\n' +
                  '       node tools/web_bench.mjs --raw [--frames N] [--warmup N] [--size WxH] [--query Q]');
      process.exit(0);
    } else throw new Error(`unknown argument ${arg}`);
  }
  if (!(Number.isInteger(options.frames) && options.frames > 0)) throw new Error('--frames wants a positive integer');
  if (!(Number.isInteger(options.warmup) && options.warmup >= 0)) throw new Error('--warmup wants an integer >= 0');
  if (options.scene !== null && !/^[\w.-]+$/.test(options.scene)) throw new Error('--scene wants a scene name like ex12-2');
  if (options.raw) {
    if (options.query === null) options.query = '?paused';
    if (options.scene) options.query += `&scene=${options.scene}`;
    if (!options.query.startsWith('?')) options.query = `?${options.query}`;
  } else {
    const extra = (options.query || '').replace(/^[?&]+/, '');
    options.query = `?bench&frames=${options.frames}` + (options.scene ? `&scene=${options.scene}` : '') +
                    (extra ? `&${extra}` : '');
  }
  return options;
}

function freePort() {
  return new Promise((resolvePort, reject) => {
    const server = createServer();
    server.unref();
    server.on('error', reject);
    server.listen(0, '127.0.0.1', () => {
      const { port } = server.address();
      server.close(() => resolvePort(port));
    });
  });
}

async function startServer(port) {
  const child = spawn(process.execPath, [join(repo, 'tools/serve.mjs'), site, String(port)], {
    stdio: ['ignore', 'ignore', 'inherit'],
  });
  const url = `http://127.0.0.1:${port}/`;
  for (let attempt = 0; attempt < 100; ++attempt) {
    if (child.exitCode !== null) throw new Error(`serve.mjs exited with ${child.exitCode}`);
    try {
      if ((await fetch(url)).ok) return { child, url };
    } catch { /* not listening yet */ }
    await new Promise((r) => setTimeout(r, 100));
  }
  child.kill();
  throw new Error(`server did not answer at ${url}`);
}

function percentile(values, p) {
  const sorted = [...values].sort((a, b) => a - b);
  const index = (sorted.length - 1) * p;
  const lo = Math.floor(index), hi = Math.ceil(index);
  return sorted[lo] + (sorted[hi] - sorted[lo]) * (index - lo);
}

function summary(values) {
  return { p10: percentile(values, 0.1), median: percentile(values, 0.5), p90: percentile(values, 0.9) };
}

function distinct(values) {
  const set = [...new Set(values)].sort((a, b) => a - b);
  return set.length === 1 ? String(set[0]) : `${set[0]}..${set[set.length - 1]} (varies)`;
}

async function main() {
  const options = parseArgs(process.argv.slice(2));
  if (!existsSync(join(site, 'index.html'))) {
    throw new Error(`${site} has no index.html: build the web preset first (cmake --build --preset web)`);
  }
  const port = await freePort();
  const { child, url } = await startServer(port);
  let browser;
  try {
    // Same launch options as playwright.config.mjs.
    browser = await chromium.launch({
      executablePath: process.env.CHROMIUM_PATH || '/usr/bin/chromium',
      args: ['--no-sandbox', '--disable-background-networking', '--disable-component-update',
             '--disable-sync', '--no-first-run', '--disable-default-apps'],
    });
    const page = await browser.newPage({ viewport: { width: options.width, height: options.height } });
    const problems = [];
    page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
    page.on('console', (m) => { if (m.type() === 'error') problems.push(`console error: ${m.text()}`); });
    await page.goto(url + options.query);
    await page.waitForFunction(() => window.demo !== undefined);
    await page.evaluate(() => window.demo.ready);

    const info = await page.evaluate(() => {
      const canvas = document.getElementById('canvas');
      const gl = document.createElement('canvas').getContext('webgl2');
      let renderer = 'unknown', vendor = 'unknown';
      if (gl) {
        const ext = gl.getExtension('WEBGL_debug_renderer_info');
        renderer = gl.getParameter(ext ? ext.UNMASKED_RENDERER_WEBGL : gl.RENDERER);
        vendor = gl.getParameter(ext ? ext.UNMASKED_VENDOR_WEBGL : gl.VENDOR);
        gl.getExtension('WEBGL_lose_context')?.loseContext();
      }
      return { renderer, vendor, width: canvas.width, height: canvas.height, userAgent: navigator.userAgent };
    });

    if (!options.raw) {
      // The page runs the bench itself after demo.ready; each policy's frames in one task.
      const limitMs = Math.max(120_000, options.frames * 5 * 2000);
      await page.waitForFunction(() => window.demo.benchResults || document.querySelector('#messages .message.error'),
                                 null, { timeout: limitMs, polling: 500 });
      const results = await page.evaluate(() => window.demo.benchResults);
      if (!results) {
        throw new Error(await page.locator('#messages .message.error').first().textContent());
      }
      console.log(`renderer:        ${info.renderer} (${info.vendor})`);
      console.log(`browser:         ${info.userAgent}`);
      console.log(`page:            ${options.query} at ${options.width}x${options.height} CSS px`);
      console.log('');
      console.log(results.table);
      for (const p of problems) console.log(`note: ${p}`);
      return;
    }

    // All frames in one task: the page's own rAF loop cannot slip frames in between.
    const frames = await page.evaluate(({ warmup, count }) => {
      for (let i = 0; i < warmup; ++i) window.demo.frame(1 / 60);
      const out = [];
      for (let i = 0; i < count; ++i) {
        const start = performance.now();
        const s = window.demo.frame(1 / 60);
        const wallMs = performance.now() - start;
        out.push({ wallMs, frameMs: s.frameMs, captureMs: s.captureMs, triangles: s.triangles,
                   drawCalls: s.drawCalls, facesCaptured: s.facesCaptured, cubeFaceSize: s.cubeFaceSize,
                   timing: s.timing, policy: s.policy, gpuFrameMs: s.gpuFrameMs, gpuCaptureMs: s.gpuCaptureMs });
      }
      return out;
    }, { warmup: options.warmup, count: options.frames });

    const fmt = (x) => x.toFixed(2).padStart(8);
    const row = (label, values) => {
      const s = summary(values);
      return `${label.padEnd(22)}${fmt(s.median)}${fmt(s.p10)}${fmt(s.p90)}`;
    };
    const last = frames[frames.length - 1];
    console.log(`renderer:        ${info.renderer} (${info.vendor})`);
    console.log(`browser:         ${info.userAgent}`);
    console.log(`page:            ${options.query} at ${options.width}x${options.height} CSS px, ` +
                `drawing buffer ${info.width}x${info.height}, cube faces ${last.cubeFaceSize} px` +
                (last.policy ? `, capture policy ${last.policy}` : ''));
    console.log(`frames:          ${frames.length} timed of demo.frame(1/60) after ${options.warmup} warm-up ` +
                `(timing: ${last.timing})`);
    console.log('');
    console.log(`${''.padEnd(22)}${'median'.padStart(8)}${'p10'.padStart(8)}${'p90'.padStart(8)}`);
    console.log(row('frame ms (page)', frames.map((f) => f.frameMs)));
    console.log(row('capture ms (page)', frames.map((f) => f.captureMs)));
    console.log(row('main pass ms (page)', frames.map((f) => f.frameMs - f.captureMs)));
    console.log(row('wall ms per call', frames.map((f) => f.wallMs)));
    // GPU timer queries (EXT_disjoint_timer_query), where the page reports them (-1: unavailable).
    const gpu = frames.filter((f) => f.gpuFrameMs >= 0);
    if (gpu.length) {
      console.log(row('gpu frame ms', gpu.map((f) => f.gpuFrameMs)));
      console.log(row('gpu capture ms', gpu.filter((f) => f.gpuCaptureMs >= 0).map((f) => f.gpuCaptureMs)));
    } else if (frames.some((f) => f.gpuFrameMs !== undefined)) {
      console.log('gpu timer queries:    not available in this browser');
    }
    console.log('');
    console.log(`triangles/frame: ${distinct(frames.map((f) => f.triangles))}`);
    console.log(`draw calls/frame: ${distinct(frames.map((f) => f.drawCalls))}`);
    console.log(`faces captured/frame: ${distinct(frames.map((f) => f.facesCaptured))}`);
    console.log(`=> ${(1000 / summary(frames.map((f) => f.wallMs)).median).toFixed(1)} frames/s at the median wall time`);
    for (const p of problems) console.log(`note: ${p}`);
  } finally {
    if (browser) await browser.close();
    child.kill();
  }
}

main().then(() => process.exit(0), (error) => {
  console.error(`web_bench: ${error.message}`);
  process.exit(1);
});
