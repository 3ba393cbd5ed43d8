#!/usr/bin/env node
// Benchmarks of the web build in Debian's Chromium (headless, via Playwright). Not a test: it
// prints numbers and exits 0.
//
//   node tools/web_bench.mjs [--scene NAME] [--frames N] [--size WxH] [--query '&cube=128']
//   node tools/web_bench.mjs --raw [--frames N] [--warmup N] [--size WxH] [--query '?paused&cube=128']
//   node tools/web_bench.mjs --heavy [--runs N] [--frames N] [--warmup N] [--against OTHER_SITE] [--as-loaded]
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
// --heavy: the page where the weight is. The heavy figure (tools/make_models.py --heavy: 157k
// triangles, written to build/heavy if it is not there) stands in for mario through ?assets=.
// Each run launches a fresh browser per page and measures, for the default scene and for the
// heavy one:
//   load to first frame: performance.now() of the first draw call into the canvas (the default
//     framebuffer), hooked from outside the page's code, so any build of the page is measured
//     the same way (from navigation start);
//   frame: N calls of demo.frame(1/60) (animated, the page's default settings) after a warm-up,
//     once the page's levels of detail are built (demo.lodReady(), awaited where the page has it;
//     it asks for every level the settings could draw). --as-loaded: only what the page builds by
//     itself (demo.levelsSettled(), where the page has it: it builds levels only once a frame
//     draws them; a page without it builds every level by itself, and lodReady waits for that);
//   memory: the resident memory (VmRSS, /proc) summed over the browser's renderer processes
//     (--type=renderer), after a garbage collection (--js-flags=--expose-gc), read from outside
//     the browser; the heavy page's growth is its total minus the default scene's. The wasm
//     memories' sizes are read by hooking WebAssembly.instantiate (reflect's, and others such as
//     npm meshoptimizer's when the page runs it on the main thread), the JS heap in use
//     (performance.memory, after the collection), the Workers the page started and its meshes'
//     bytes (demo.stats(): meshBytes as the GPU holds them, meshCpuBytes as the demo keeps them).
// --against DIR: the same for another build of the page (e.g. an older commit's build/web/site),
// run alternately with this one (A B, then B A, ...), and the two summarised side by side.
//
// Either way: serves build/web/site with tools/serve.mjs on a free port, 800x800 viewport.
import { existsSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { freePort, launchChromium, repo, startServer, summary } from './bench_lib.mjs';
import { heavyAssets, measurePage } from './page_memory.mjs';

const site = join(repo, 'build/web/site');

function parseArgs(argv) {
  const options = { frames: 60, warmup: 10, width: 800, height: 800, query: null, scene: null, raw: false,
                    heavy: false, runs: 3, against: null, site, asLoaded: false };
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
    else if (arg === '--heavy') options.heavy = true;
    else if (arg === '--runs') options.runs = Number(value());
    else if (arg === '--against') options.against = resolve(value());
    else if (arg === '--as-loaded') options.asLoaded = true;
    else if (arg === '--site') options.site = resolve(value());
    else if (arg === '--size') {
      const m = /^(\d+)x(\d+)$/.exec(value());
      if (!m) throw new Error('--size wants WIDTHxHEIGHT');
      options.width = Number(m[1]);
      options.height = Number(m[2]);
    } else if (arg === '--help' || arg === '-h') {
      console.log('usage: node tools/web_bench.mjs [--scene NAME] [--frames N] [--size WxH] [--query Q]\n' +
                  '       node tools/web_bench.mjs --raw [--frames N] [--warmup N] [--size WxH] [--query Q]\n' +
                  '       node tools/web_bench.mjs --heavy [--runs N] [--frames N] [--warmup N] [--size WxH] ' +
                  '[--site DIR] [--against DIR] [--as-loaded]');
      process.exit(0);
    } else throw new Error(`unknown argument ${arg}`);
  }
  if (!(Number.isInteger(options.frames) && options.frames > 0)) throw new Error('--frames wants a positive integer');
  if (!(Number.isInteger(options.warmup) && options.warmup >= 0)) throw new Error('--warmup wants an integer >= 0');
  if (options.scene !== null && !/^[\w.-]+$/.test(options.scene)) throw new Error('--scene wants a scene name like ex12-2');
  if (!(Number.isInteger(options.runs) && options.runs > 0)) throw new Error('--runs wants a positive integer');
  if (options.heavy) return options;
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

function distinct(values) {
  const set = [...new Set(values)].sort((a, b) => a - b);
  return set.length === 1 ? String(set[0]) : `${set[0]}..${set[set.length - 1]} (varies)`;
}

// The GPU and browser the page runs on, and its drawing buffer's size.
function rendererInfo(page) {
  return page.evaluate(() => {
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
}

// demo.frame(1/60) `options.frames` times after `options.warmup`, each call's wall time and stats.
function timeFrames(page, options) {
  // All frames in one task: the page's own rAF loop cannot slip frames in between.
  return page.evaluate(({ warmup, count }) => {
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
}

// The raw frames' table: medians and spread of each time, the counts a frame draws.
function printFrames(frames, info, options) {
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
}

async function main() {
  const options = parseArgs(process.argv.slice(2));
  if (options.heavy) return heavyBench(options);
  if (!existsSync(join(site, 'index.html'))) {
    throw new Error(`${site} has no index.html: build the web preset first (cmake --build --preset web)`);
  }
  const port = await freePort();
  const { child, url } = await startServer(port, site);
  let browser;
  try {
    browser = await launchChromium();
    const page = await browser.newPage({ viewport: { width: options.width, height: options.height } });
    const problems = [];
    page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
    page.on('console', (m) => { if (m.type() === 'error') problems.push(`console error: ${m.text()}`); });
    await page.goto(url + options.query);
    await page.waitForFunction(() => window.demo !== undefined);
    await page.evaluate(() => window.demo.ready);

    const info = await rendererInfo(page);

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

    const frames = await timeFrames(page, options);
    printFrames(frames, info, options);
    for (const p of problems) console.log(`note: ${p}`);
  } finally {
    if (browser) await browser.close();
    child.kill();
  }
}

// --- --heavy ---------------------------------------------------------------------------------

async function heavyBench(options) {
  const sites = [{ name: 'this build', root: options.site }];
  if (options.against) sites.push({ name: 'against', root: options.against });
  for (const s of sites) {
    if (!existsSync(join(s.root, 'index.html'))) throw new Error(`${s.root} has no index.html: build the web preset first`);
    s.prefix = heavyAssets(s.root);
    s.port = await freePort();
    s.server = await startServer(s.port, s.root);
    s.samples = [];
  }
  const mb = (bytes) => (bytes / (1024 * 1024)).toFixed(1);
  try {
    console.log(`heavy bench: ${options.runs} run(s), ${options.width}x${options.height}, ` +
                `${options.frames} frames after ${options.warmup} warm-up` +
                (options.asLoaded ? ', as loaded (levels the page builds by itself)' : '') + '; sites: ' +
                sites.map((s) => `${s.name} = ${s.root}`).join(', '));
    for (let run = 0; run < options.runs; ++run) {
      const order = run % 2 === 0 ? sites : [...sites].reverse();
      for (const s of order) {
        const base = s.server.url;
        const light = await measurePage(base, options);
        const heavy = await measurePage(`${base}?assets=${s.prefix}`, options);
        const sample = { light, heavy };
        s.samples.push(sample);
        const median = (r) => summary(r.frames.map((f) => f.wallMs)).median;
        console.log(`run ${run + 1} ${s.name}: first frame ${light.firstFrameMs?.toFixed(0)} / ` +
                    `${heavy.firstFrameMs?.toFixed(0)} ms (default / heavy), levels ready ` +
                    `${heavy.lodMs.toFixed(0)} ms; frame ${median(light).toFixed(1)} / ${median(heavy).toFixed(1)} ms; ` +
                    `renderer RSS ${light.memory.mb.toFixed(0)} / ${heavy.memory.mb.toFixed(0)} MB ` +
                    `(+${(heavy.memory.mb - light.memory.mb).toFixed(0)}); reflect wasm memory ` +
                    `${mb(light.reflectHeap)} / ${mb(heavy.reflectHeap)} MB; other wasm ${mb(heavy.otherWasm)} MB` +
                    (heavy.stats.meshBytes !== undefined ? `; meshes as drawn ${mb(heavy.stats.meshBytes)} MB` : '') +
                    `; workers ${light.workers} / ${heavy.workers}`);
        for (const p of [...light.problems, ...heavy.problems]) console.log(`  note: ${p}`);
      }
    }
    const med = (values) => summary(values).median;
    console.log('');
    console.log('medians over the runs (heavy figure through ?assets=, against the default scene):');
    const rows = [
      ['load to first frame, default scene (ms)', (x) => x.light.firstFrameMs],
      ['load to first frame, heavy (ms)', (x) => x.heavy.firstFrameMs],
      ['levels of detail ready, heavy (ms)', (x) => x.heavy.lodMs],
      ['frame, default scene (ms, wall)', (x) => med(x.light.frames.map((f) => f.wallMs))],
      ['frame, heavy (ms, wall)', (x) => med(x.heavy.frames.map((f) => f.wallMs))],
      ['frame, heavy (ms, page frameMs)', (x) => med(x.heavy.frames.map((f) => f.frameMs))],
      ['triangles a frame, heavy', (x) => med(x.heavy.frames.map((f) => f.triangles))],
      ['capture triangles a frame, heavy', (x) => med(x.heavy.frames.map((f) => f.captureTriangles))],
      ['renderer RSS, default scene (MB)', (x) => x.light.memory.mb],
      ['renderer RSS, heavy (MB)', (x) => x.heavy.memory.mb],
      ['renderer RSS growth, heavy over default (MB)', (x) => x.heavy.memory.mb - x.light.memory.mb],
      ['reflect wasm memory, default scene (MB)', (x) => x.light.reflectHeap / 1048576],
      ['reflect wasm memory, heavy (MB)', (x) => x.heavy.reflectHeap / 1048576],
      ['other wasm memory, heavy (MB)', (x) => x.heavy.otherWasm / 1048576],
      ['meshes as drawn, default scene (MB; demo.stats().meshBytes)', (x) => (x.light.stats.meshBytes ?? NaN) / 1048576],
      ['meshes as drawn, heavy (MB; demo.stats().meshBytes)', (x) => (x.heavy.stats.meshBytes ?? NaN) / 1048576],
      ['meshes kept on the CPU, default scene (MB; meshCpuBytes)', (x) => (x.light.stats.meshCpuBytes ?? NaN) / 1048576],
      ['meshes kept on the CPU, heavy (MB; meshCpuBytes)', (x) => (x.heavy.stats.meshCpuBytes ?? NaN) / 1048576],
      ['JS heap in use, default scene (MB; performance.memory)', (x) => (x.light.jsHeap ?? NaN) / 1048576],
      ['JS heap in use, heavy (MB; performance.memory)', (x) => (x.heavy.jsHeap ?? NaN) / 1048576],
      ['Workers started, default scene', (x) => x.light.workers],
      ['Workers started, heavy', (x) => x.heavy.workers],
      ['reflect wasm memory over meshes as drawn, heavy (x)', (x) => x.heavy.reflectHeap / (x.heavy.stats.meshBytes ?? NaN)],
      // What the heap is made of (builds whose stats have them): malloc's bytes in use after the
      // frames, what malloc has taken from the heap in all, and the most stack ever used.
      ['malloc in use, default scene (MB)', (x) => (x.light.stats.mallocInUseBytes ?? NaN) / 1048576],
      ['malloc in use, heavy (MB)', (x) => (x.heavy.stats.mallocInUseBytes ?? NaN) / 1048576],
      ['malloc arena, heavy (MB)', (x) => (x.heavy.stats.mallocArenaBytes ?? NaN) / 1048576],
      ['stack high water, heavy (kB)', (x) => (x.heavy.stats.stackHighWaterBytes ?? NaN) / 1024],
    ];
    const width = Math.max(...rows.map(([label]) => label.length)) + 2;
    console.log(''.padEnd(width) + sites.map((s) => s.name.padStart(14)).join(''));
    for (const [label, get] of rows) {
      console.log(label.padEnd(width) + sites.map((s) => {
        const v = med(s.samples.map(get).filter((x) => x !== null && x !== undefined && !Number.isNaN(x)));
        return (Number.isFinite(v) ? (Math.abs(v) >= 1000 ? v.toFixed(0) : v.toFixed(1)) : 'n/a').padStart(14);
      }).join(''));
    }
    if (sites.length === 2) {
      console.log('');
      for (const [label, get] of rows.slice(0, 11)) {
        const a = med(sites[0].samples.map(get)), b = med(sites[1].samples.map(get));
        if (Number.isFinite(a) && Number.isFinite(b) && b !== 0) console.log(`${label}: ${(a / b).toFixed(2)}x`);
      }
    }
  } finally {
    for (const s of sites) s.server.child.kill();
  }
}

main().then(() => process.exit(0), (error) => {
  console.error(`web_bench: ${error.message}`);
  process.exit(1);
});
