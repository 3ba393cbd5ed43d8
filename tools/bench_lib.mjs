// What the browser benches share: the repository's root, a free port, the static server
// (tools/serve.mjs) started on it, Debian's Chromium launched as playwright.config.mjs launches it,
// percentiles, the renderer processes' memory, and a page's load and GL waits (PAGE_HOOK, loadParts).
import { readFileSync, readdirSync } from 'node:fs';
import { spawn } from 'node:child_process';
import { createServer } from 'node:net';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from '@playwright/test';

export const repo = resolve(dirname(fileURLToPath(import.meta.url)), '..');

// The same launch options as playwright.config.mjs; `extraArgs` for a bench's own flags
// (e.g. --js-flags=--expose-gc).
export function chromiumOptions(extraArgs = []) {
  return {
    executablePath: process.env.CHROMIUM_PATH || '/usr/bin/chromium',
    args: ['--no-sandbox', '--disable-background-networking', '--disable-component-update',
           '--disable-sync', '--no-first-run', '--disable-default-apps', ...extraArgs],
  };
}

export const launchChromium = (extraArgs = []) => chromium.launch(chromiumOptions(extraArgs));

export function freePort() {
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

// Serves `root` on 127.0.0.1:`port`; resolves once it answers, to { child, url }.
export async function startServer(port, root) {
  const child = spawn(process.execPath, [join(repo, 'tools/serve.mjs'), root, String(port)], {
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

// Linear interpolation between the nearest ranks (p in [0, 1]).
export function percentile(values, p) {
  const sorted = [...values].sort((a, b) => a - b);
  const index = (sorted.length - 1) * p;
  const lo = Math.floor(index), hi = Math.ceil(index);
  return sorted[lo] + (sorted[hi] - sorted[lo]) * (index - lo);
}

export function summary(values) {
  return { p10: percentile(values, 0.1), median: percentile(values, 0.5), p90: percentile(values, 0.9) };
}

// Resident memory (VmRSS) summed over the renderer processes among `pid`'s descendants.
export function rendererMemory(pid) {
  const parents = new Map();
  for (const entry of readdirSync('/proc')) {
    if (!/^\d+$/.test(entry)) continue;
    try {
      const stat = readFileSync(`/proc/${entry}/stat`, 'utf8');
      const fields = stat.slice(stat.lastIndexOf(')') + 2).split(' ');
      parents.set(Number(entry), Number(fields[1]));
    } catch { /* gone */ }
  }
  const descends = (p) => {
    for (let q = p, depth = 0; q && depth < 64; q = parents.get(q), ++depth) if (q === pid) return true;
    return false;
  };
  let kb = 0, count = 0;
  for (const p of parents.keys()) {
    if (!descends(p)) continue;
    try {
      if (!readFileSync(`/proc/${p}/cmdline`, 'utf8').includes('--type=renderer')) continue;
      const rss = /VmRSS:\s+(\d+) kB/.exec(readFileSync(`/proc/${p}/status`, 'utf8'));
      if (rss) { kb += Number(rss[1]); ++count; }
    } catch { /* gone */ }
  }
  return { mb: kb / 1024, processes: count };
}

// An init script for a page (page.addInitScript), run before any of its scripts: what its load
// and frames spend where, read back from window after the fact.
//   __firstDrawMs         performance.now() at the first draw call into the default framebuffer
//                         (the canvas); both kinds of draw call are hooked;
//   __shaderMs            main-thread ms inside shader compile and link calls and their status and
//                         log queries (where the browser waits for the GPU process's compiler);
//                         __shaderMsAtFirstDraw, the same at the first draw;
//   __glWaitMs            ms inside the calls that wait for the GPU process to finish the work
//                         before them (finish, readPixels, clientWaitSync, getBufferSubData);
//   __wasm                [{ name, start, end }] of each WebAssembly compile or instantiate call,
//                         from its call to its promise's settling (with instantiateStreaming: the
//                         module's fetch and its compile, which overlap).
export const PAGE_HOOK = () => {
  Object.assign(window, { __firstDrawMs: null, __shaderMs: 0, __shaderMsAtFirstDraw: null, __glWaitMs: 0, __wasm: [] });
  const proto = WebGL2RenderingContext.prototype;
  const timed = (names, add) => {
    for (const name of names) {
      const original = proto[name];
      proto[name] = function (...args) {
        const start = performance.now();
        try {
          return original.apply(this, args);
        } finally {
          add(performance.now() - start);
        }
      };
    }
  };
  timed(['finish', 'readPixels', 'clientWaitSync', 'getBufferSubData'], (ms) => { window.__glWaitMs += ms; });
  timed(['compileShader', 'linkProgram', 'getShaderParameter', 'getProgramParameter', 'getShaderInfoLog',
         'getProgramInfoLog'], (ms) => { window.__shaderMs += ms; });
  const draws = { drawElements: proto.drawElements, drawArrays: proto.drawArrays };
  for (const [name, original] of Object.entries(draws)) {
    proto[name] = function (...args) {
      if (window.__firstDrawMs === null && this.getParameter(this.DRAW_FRAMEBUFFER_BINDING) === null) {
        window.__firstDrawMs = performance.now();
        window.__shaderMsAtFirstDraw = window.__shaderMs;
        Object.assign(proto, draws);
      }
      return original.apply(this, args);
    };
  }
  for (const name of ['instantiateStreaming', 'compileStreaming', 'instantiate', 'compile']) {
    const original = WebAssembly[name];
    if (!original) continue;
    WebAssembly[name] = function (...args) {
      const start = performance.now();
      const promise = original.apply(this, args);
      const done = () => window.__wasm.push({ name, start, end: performance.now() });
      promise.then(done, done);
      return promise;
    };
  }
};

// Run in the page (page.evaluate(loadParts)): the load's parts, from the page's own marks
// (web/wasm_bridge.js, web/scene_loader.js; tools/peers/peer_page.js), resource timing and
// PAGE_HOOK's records; ms from navigation start.
export function loadParts() {
  const mark = (name) => performance.getEntriesByName(name, 'mark')[0];
  const resource = (suffix) => performance.getEntriesByType('resource').filter((e) => e.name.split('?')[0].endsWith(suffix));
  const last = (entries) => (entries.length ? Math.max(...entries.map((e) => e.responseEnd)) : undefined);
  const wasm = window.__wasm.find((w) => w.name.startsWith('instantiate'));
  const committed = mark('reflect:scene-committed');
  return {
    firstDraw: window.__firstDrawMs, shaderMs: window.__shaderMsAtFirstDraw,
    // the project's page
    wasmFetched: last(resource('.wasm')), wasmStart: wasm?.start, wasmEnd: wasm?.end,
    wasmReady: mark('reflect:wasm-ready')?.startTime, modelsIn: mark('reflect:models-in')?.startTime,
    committed: committed?.startTime, bvhMs: committed?.detail?.bvhMs,
    modelsFetched: last(resource('.obj')),
    // the peers
    scriptStart: mark('peer:script-start')?.startTime, peerModelsIn: mark('peer:models-in')?.startTime,
    renditionMade: mark('peer:rendition-made')?.startTime, threeFetched: last(resource('three.module.js')),
  };
}
