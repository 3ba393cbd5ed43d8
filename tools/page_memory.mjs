// The page's load and memory, measured in a fresh browser (web_bench.mjs --heavy): the hooks the
// page is opened with, the heavy figure's asset folder, and one measured load.
import { spawnSync } from 'node:child_process';
import { copyFileSync, existsSync, mkdirSync } from 'node:fs';
import { join } from 'node:path';
import { chromium } from '@playwright/test';
import { chromiumOptions, rendererMemory, repo } from './bench_lib.mjs';

// Runs before any script of the page: the time of the first draw into the canvas, and every wasm
// instance's memory (reflect's and any other the page runs, e.g. npm meshoptimizer's).
const PAGE_HOOKS = () => {
  window.__firstFrameMs = null;
  const proto = WebGL2RenderingContext.prototype;
  const drawElements = proto.drawElements;
  proto.drawElements = function (...args) {
    if (window.__firstFrameMs === null && this.getParameter(this.DRAW_FRAMEBUFFER_BINDING) === null) {
      window.__firstFrameMs = performance.now();
      proto.drawElements = drawElements;
    }
    return drawElements.apply(this, args);
  };
  window.__workers = 0;
  const NativeWorker = window.Worker;
  window.Worker = class extends NativeWorker {
    constructor(...args) {
      ++window.__workers;
      super(...args);
    }
  };
  window.__wasmInstances = [];
  const keep = (result) => {
    const instance = result.instance || result;
    if (instance && instance.exports) window.__wasmInstances.push(instance);
    return result;
  };
  const instantiate = WebAssembly.instantiate;
  WebAssembly.instantiate = function (...args) { return instantiate.apply(this, args).then(keep); };
  const streaming = WebAssembly.instantiateStreaming;
  if (streaming) {
    WebAssembly.instantiateStreaming = function (...args) { return streaming.apply(this, args).then(keep); };
  }
};

// The heavy figure in DIR/heavy-bench/ with the other built-in models beside it (as a folder of
// the course's models would be), made once.
export function heavyAssets(root) {
  const heavy = join(repo, 'build/heavy/mario.obj');
  if (!existsSync(heavy)) {
    const made = spawnSync('python3', [join(repo, 'tools/make_models.py'), '--heavy'], { stdio: 'inherit' });
    if (made.status !== 0) throw new Error('tools/make_models.py --heavy failed');
  }
  const dir = join(root, 'heavy-bench');
  mkdirSync(dir, { recursive: true });
  copyFileSync(heavy, join(dir, 'mario.obj'));
  for (const name of ['sonic.obj', 'sphere.obj', 'quad.obj']) copyFileSync(join(repo, 'assets/models', name), join(dir, name));
  return 'heavy-bench/';
}

const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

// One page in a fresh browser: load to first frame, frames, memory.
export async function measurePage(url, options) {
  // A server, so the browser's process id is known (its renderers are among its descendants).
  const server = await chromium.launchServer(chromiumOptions(['--js-flags=--expose-gc']));
  const browser = await chromium.connect(server.wsEndpoint());
  try {
    const page = await browser.newPage({ viewport: { width: options.width, height: options.height } });
    const problems = [];
    page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
    page.on('console', (m) => { if (m.type() === 'error') problems.push(`console error: ${m.text()}`); });
    await page.addInitScript(PAGE_HOOKS);
    await page.goto(url);
    await page.waitForFunction(() => window.demo !== undefined);
    const readyMs = await page.evaluate(() => window.demo.ready.then(() => performance.now()));
    const lodMs = await page.evaluate(async (asLoaded) => {
      if (asLoaded && window.demo.levelsSettled) await window.demo.levelsSettled();
      else if (window.demo.lodReady) await window.demo.lodReady();
      return performance.now();
    }, options.asLoaded);
    const firstFrameMs = await page.evaluate(() => window.__firstFrameMs);
    const frames = await page.evaluate(({ warmup, count }) => {
      for (let i = 0; i < warmup; ++i) window.demo.frame(1 / 60);
      const out = [];
      for (let i = 0; i < count; ++i) {
        const start = performance.now();
        const s = window.demo.frame(1 / 60);
        out.push({ wallMs: performance.now() - start, frameMs: s.frameMs, triangles: s.triangles,
                   captureTriangles: s.captureTriangles, mainTriangles: s.mainTriangles });
      }
      return out;
    }, { warmup: options.warmup, count: options.frames });
    for (let i = 0; i < 2; ++i) {
      await page.evaluate(() => window.gc && window.gc());
      await sleep(500);
    }
    const memory = rendererMemory(server.process().pid);
    const wasm = await page.evaluate(() => window.__wasmInstances.map((instance) => {
      const memories = Object.values(instance.exports).filter((e) => e instanceof WebAssembly.Memory);
      // Emscripten minifies reflect's export names; npm meshoptimizer's keep theirs.
      const meshopt = Object.keys(instance.exports).some((name) => name.startsWith('meshopt_'));
      return { reflect: !meshopt, bytes: memories.reduce((a, m) => a + m.buffer.byteLength, 0) };
    }));
    const stats = await page.evaluate(() => window.demo.stats());
    const jsHeap = await page.evaluate(() => performance.memory?.usedJSHeapSize ?? null);
    const workers = await page.evaluate(() => window.__workers);
    return {
      firstFrameMs, readyMs, lodMs, frames, memory, problems, stats, jsHeap, workers,
      reflectHeap: wasm.filter((w) => w.reflect).reduce((a, w) => a + w.bytes, 0),
      otherWasm: wasm.filter((w) => !w.reflect).reduce((a, w) => a + w.bytes, 0),
    };
  } finally {
    await browser.close();
    await server.close();
  }
}
