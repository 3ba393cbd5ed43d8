#!/usr/bin/env node
// The project's page against three.js peers (tools/peers/), in headless Chromium (Debian's,
// SwiftShader WebGL2). Not a test: it prints numbers and exits 0. Two peers draw the default
// scene (cubecamera, bvh); one reads a scene file (pmrem: a CubeCamera and a PMREM a mirror, rough
// mirrors), the one --scene NAME names (ex12-2 without it). Two pages are the floor, the main pass
// alone: the project's page with every reflector made a Phong object once it is up (plain) and a
// three.js page with the mirror a Phong object (three-plain); what they take, every method pays.
//
//   node tools/peer_bench.mjs [--heavy | --both] [--rounds N] [--frames N] [--warmup N] [--size WxH]
//                             [--site DIR] [--pages KEY,KEY,...] [--query EXTRA] [--scene NAME]
//                             [--reference PNG [--mask PNG | --save-mask PNG] [--time T]]
//   node tools/peer_bench.mjs --screenshots DIR [--time T] [--heavy] [--pages ...] [--size WxH]
//   node tools/peer_bench.mjs --serve [--heavy] [--site DIR]
//
// Serves one folder, build/peer-bench/: the project's site (build/web/site, or --site), the
// peers' pages, three and three-mesh-bvh from node_modules and, with --heavy, the 157k-triangle
// figure (tools/make_models.py --heavy) in place of mario for every page; --both measures the
// shipped models' scene, then the heavy one's, in one run, and prints both. Each round measures
// every page in turn (PAGES' order), each in a browser of its own (Debian's Chromium, with no
// shader program cache: no page's load compiles from the caches of the page before it):
//   load to first frame: performance.now() at the first draw call into the canvas (the default
//     framebuffer), hooked before any of the page's scripts (bench_lib.mjs's PAGE_HOOK), so the
//     project's page and the peers are measured the same way (from navigation start); its parts
//     from the pages' own performance marks (web/wasm_bridge.js, web/scene_loader.js,
//     tools/peers/peer_page.js), resource timing, and the hook's timing of the wasm module's
//     instantiateStreaming and of the shader compile and link calls (peer_report.mjs's loadSpans);
//   frame: after the page is ready (and the project's levels of detail are built), W warm-up and
//     F timed calls of frame(1/60) in one task: window.demo.frameWaitedOnce on the project's
//     page, window.peer.frame on the peers; each call's wall time, which includes the GPU's work
//     (both end with one read-back and wait nowhere else), and its CPU part (the wall time less
//     that inside the GL calls that wait for the GPU process). Its parts come from F more frames
//     with a read-back after each pass: the project's window.demo.frame (its stats' captureMs,
//     then frameMs less it; the round's line also prints that frame's wall time, which is what
//     this bench timed as the frame before 2026-11-29: one read-back more than the peers'), the
//     peers' frameSplit (the CubeCamera's update, then the render).
// It prints each round, then per page the medians over the rounds of each round's median, p10
// and p90 frame ms, the frame's and the load's parts, the floor, and each project page's frame and
// load against each peer (tools/peer_report.mjs).
// --screenshots DIR writes each page's picture at time T (default 0; three frames drawn there) as
// DIR/KEY.png instead; --serve only serves the folder, for a person to look at the pages.
// --reference PNG (a picture of the scene at --time T and --size WxH, e.g. `reflect render
// --scene NAME --time T --size WxH --reference PNG`): after the timing (none with --rounds 0),
// each page is drawn at T and read back, and compared with it over the reflector pixels (white in
// --mask PNG, or else the pmrem peer's mirrors drawn in its ?mask mode, which --save-mask keeps):
// PSNR and the pixels off by more than 32 levels (tools/peer_accuracy.mjs).
import { spawnSync } from 'node:child_process';
import { copyFileSync, existsSync, mkdirSync, readdirSync, rmSync, symlinkSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { PAGE_HOOK, freePort, loadParts, launchChromium, repo, startServer, summary } from './bench_lib.mjs';
import { FRAMES_AT_TIME, runAccuracy } from './peer_accuracy.mjs';
import { fmt, loadSpans, pageRows, printBoth, printTables } from './peer_report.mjs';

// The project's configurations: what each adds to index.html's query. Add a row for a new setting.
const PROJECT_PAGES = [
  { key: 'default', label: 'project default', query: '' },
  { key: 'exact', label: 'project exact', query: 'search=exact' },
  { key: 'course', label: 'project course setting', query: 'acc=original&policy=every-frame&captureLod=0' },
  { key: 'hierarchical', label: 'project hierarchical', query: 'search=hierarchical' },
  // Rough readers from prefiltered levels, narrow lobes too (the default before lobe taps).
  { key: 'prefiltered', label: 'project prefiltered', query: 'lobeTaps=0&narrowLobeRays=0' },
  // Narrow lobes read by taps like the rest (the default before they were traced).
  { key: 'narrow-taps', label: 'project, narrow lobes tapped', query: 'narrowLobeRays=0' },
  // One distance for a whole rough lobe (the default before each quarter was searched).
  { key: 'one-distance', label: 'project, one lobe distance', query: 'lobeQuarters=false' },
  // The floor: every reflector made a Phong object once the page is up (no capture, no trace).
  { key: 'plain', label: 'project, mirror as Phong', query: '', plain: true },
];
// The peers (tools/peers/), each driven through window.peer.
const PEER_PAGES = [
  { key: 'cubecamera', label: 'three.js CubeCamera', path: 'peers/index.html', query: 'rendition=cubecamera', peer: true },
  { key: 'bvh', label: 'three.js + three-mesh-bvh', path: 'peers/index.html', query: 'rendition=bvh', peer: true },
  { key: 'three-plain', label: 'three.js, mirror as Phong', path: 'peers/index.html', query: 'rendition=plain',
    peer: true, plain: true },
  // The scene file --scene names (sceneFile); without --scene it runs only when --pages names it.
  { key: 'pmrem', label: 'three.js CubeCamera + PMREM', path: 'peers/index.html', query: 'rendition=pmrem', peer: true,
    sceneFile: true },
  // Probe-lit figures (scene files with "ambient"): a CubeCamera and LightProbeGenerator a figure.
  { key: 'probelit', label: 'three.js CubeCamera + LightProbeGenerator', path: 'peers/index.html',
    query: 'rendition=probelit', peer: true, sceneFile: true },
  // Frosted glass (scene files with glass): three's MeshPhysicalMaterial transmission.
  { key: 'frosted', label: 'three.js MeshPhysicalMaterial transmission', path: 'peers/index.html',
    query: 'rendition=frosted', peer: true, sceneFile: true },
];
// With --against DIR, another build of the project's page (e.g. the last landing's
// build/web/site) is served under base/ and its configurations join as base-KEY.
const BASE_PAGES = PROJECT_PAGES.map((p) => ({ ...p, key: `base-${p.key}`, label: `base ${p.label.replace('project ', '')}`,
                                              path: 'base/index.html', base: true }));
const PAGES = [...PROJECT_PAGES, ...PEER_PAGES, ...BASE_PAGES];

function parseArgs(argv) {
  const o = { heavy: false, both: false, rounds: 2, frames: 20, warmup: 5, width: 800, height: 800,
              site: join(repo, 'build/web/site'), pages: PAGES.map((p) => p.key), query: '',
              screenshots: null, time: 0, serve: false, against: null, scene: null,
              reference: null, mask: null, saveMask: null };
  for (let i = 0; i < argv.length; ++i) {
    const arg = argv[i];
    const value = () => {
      if (i + 1 >= argv.length) throw new Error(`${arg} needs a value`);
      return argv[++i];
    };
    if (arg === '--heavy') o.heavy = true;
    else if (arg === '--both') o.both = true;
    else if (arg === '--rounds') o.rounds = Number(value());
    else if (arg === '--frames') o.frames = Number(value());
    else if (arg === '--warmup') o.warmup = Number(value());
    else if (arg === '--site') o.site = resolve(value());
    else if (arg === '--pages') o.pages = value().split(',').filter(Boolean);
    else if (arg === '--query') o.query = value().replace(/^[?&]+/, '');
    else if (arg === '--screenshots') o.screenshots = resolve(value());
    else if (arg === '--time') o.time = Number(value());
    else if (arg === '--serve') o.serve = true;
    else if (arg === '--against') o.against = resolve(value());
    else if (arg === '--scene') o.scene = value();
    else if (arg === '--reference') o.reference = resolve(value());
    else if (arg === '--mask') o.mask = resolve(value());
    else if (arg === '--save-mask') o.saveMask = resolve(value());
    else if (arg === '--size') {
      const m = /^(\d+)x(\d+)$/.exec(value());
      if (!m) throw new Error('--size wants WIDTHxHEIGHT');
      [o.width, o.height] = [Number(m[1]), Number(m[2])];
    } else if (arg === '--help' || arg === '-h') {
      console.log('usage: node tools/peer_bench.mjs [--heavy | --both] [--rounds N] [--frames N] [--warmup N] [--size WxH]\n' +
                  '                                 [--site DIR] [--pages KEY,...] [--query EXTRA] [--against DIR]\n' +
                  '                                 [--scene NAME] [--reference PNG [--mask PNG | --save-mask PNG] [--time T]]\n' +
                  '       node tools/peer_bench.mjs --screenshots DIR [--time T] [--heavy] [--pages KEY,...]\n' +
                  '       node tools/peer_bench.mjs --serve [--heavy] [--site DIR]\n' +
                  `pages: ${PAGES.map((p) => p.key).join(', ')}`);
      process.exit(0);
    } else throw new Error(`unknown argument ${arg}`);
  }
  for (const [name, min] of [['rounds', o.reference ? 0 : 1], ['frames', 1], ['warmup', 0]]) {
    if (!(Number.isInteger(o[name]) && o[name] >= min)) throw new Error(`--${name} wants an integer >= ${min}`);
  }
  if (!Number.isFinite(o.time)) throw new Error('--time wants a number of seconds');
  if (!o.against) o.pages = o.pages.filter((key) => !key.startsWith('base-'));
  else if (!argv.includes('--pages')) o.pages = PAGES.map((p) => p.key);
  if (o.scene && !/^[\w.-]+$/.test(o.scene)) throw new Error('--scene wants a shipped scene name');
  if ((o.mask || o.saveMask) && !o.reference) throw new Error('--mask and --save-mask go with --reference');
  // The default scene's peers draw it only; the scene-file peer joins by itself with --scene.
  const fixedPeer = (key) => PEER_PAGES.some((p) => p.key === key && !p.sceneFile);
  const filePeer = (key) => PEER_PAGES.some((p) => p.key === key && p.sceneFile);
  if (o.scene) o.pages = o.pages.filter((key) => !fixedPeer(key));
  else if (!argv.includes('--pages')) o.pages = o.pages.filter((key) => !filePeer(key));
  const unknown = o.pages.filter((key) => !PAGES.some((p) => p.key === key));
  if (unknown.length) throw new Error(`unknown page ${unknown.join(', ')}; pages: ${PAGES.map((p) => p.key).join(', ')}`);
  return o;
}

// build/peer-bench/, made afresh: links to the site's files, the peers and the libraries, and
// with --heavy a folder of the scene's models with the heavy figure as mario.obj.
function assemble(o) {
  if (!existsSync(join(o.site, 'index.html'))) {
    throw new Error(`${o.site} has no index.html: build the web preset first (cmake --build --preset web) or pass --site`);
  }
  const root = join(repo, 'build/peer-bench');
  rmSync(root, { recursive: true, force: true });
  mkdirSync(root, { recursive: true });
  const link = (target, path) => {
    mkdirSync(join(root, path, '..'), { recursive: true });
    symlinkSync(target, join(root, path));
  };
  // The names this folder fills itself win over the site's (web_bench.mjs --heavy leaves its own
  // heavy-bench/ in the site).
  const own = new Set(['peers', 'three', 'three-mesh-bvh', 'heavy-bench', 'base']);
  for (const entry of readdirSync(o.site)) if (!own.has(entry)) link(join(o.site, entry), entry);
  link(join(repo, 'tools/peers'), 'peers');
  if (o.against) {
    if (!existsSync(join(o.against, 'index.html'))) throw new Error(`${o.against} has no index.html`);
    link(o.against, 'base');
  }
  link(join(repo, 'node_modules/three/build'), 'three/build');
  link(join(repo, 'node_modules/three/examples/jsm'), 'three/examples/jsm');
  link(join(repo, 'node_modules/three-mesh-bvh/build'), 'three-mesh-bvh/build');
  if (o.heavy || o.both) {
    const heavy = join(repo, 'build/heavy/mario.obj');
    if (!existsSync(heavy)) {
      const made = spawnSync('python3', [join(repo, 'tools/make_models.py'), '--heavy'], { stdio: 'inherit' });
      if (made.status !== 0) throw new Error('tools/make_models.py --heavy failed');
    }
    mkdirSync(join(root, 'heavy-bench'));
    copyFileSync(heavy, join(root, 'heavy-bench/mario.obj'));
    for (const name of ['sonic.obj', 'sphere.obj', 'quad.obj']) {
      copyFileSync(join(repo, 'assets/models', name), join(root, 'heavy-bench', name));
    }
  }
  return root;
}

// The page's path and query; `extra` are further query parts (e.g. 'paused'). The peers are
// told not to animate themselves, except for a person looking at them (--serve).
function pageUrl(page, o, extra = []) {
  const parts = page.peer
    ? [page.query, o.serve ? '' : 'bench', o.heavy ? 'assets=../heavy-bench/' : '',
       page.sceneFile && o.scene ? `scene=${o.scene}` : '']
    : [o.heavy ? `assets=${page.base ? '../' : ''}heavy-bench/` : '', o.scene ? `scene=${o.scene}` : '', page.query,
       o.query];
  return `${page.path || 'index.html'}?${[...parts, ...extra].filter(Boolean).join('&')}`;
}

// A fresh context on the page, ready to be driven: { context, page, api, problems }.
async function openPage(browser, base, spec, o, extra = []) {
  const context = await browser.newContext({ viewport: { width: o.width, height: o.height }, deviceScaleFactor: 1 });
  const page = await context.newPage();
  page.setDefaultTimeout(600_000);  // the heavy figure's first frame in SwiftShader takes a while
  const problems = [];
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console error: ${m.text()}`); });
  await page.addInitScript(PAGE_HOOK);
  await page.goto(base + pageUrl(spec, o, extra));
  const api = spec.peer ? 'peer' : 'demo';
  await page.waitForFunction((name) => window[name] !== undefined, api);
  await page.evaluate(async (name) => {
    await window[name].ready;
    if (name === 'demo' && window.demo.lodReady) await window.demo.lodReady();
  }, api);
  if (!spec.peer) {
    // A setting the page does not take shows as an error message, not as a failed load.
    const errors = await page.evaluate(() => window.demo.messages().filter((m) => m.kind === 'error'));
    problems.push(...errors.map((m) => `page message: ${m.text}`));
  }
  if (spec.plain && !spec.peer) {
    const refused = await page.evaluate(() => window.demo.objects()
      .map((o, index) => (o.material.type === 'phong' ? '' : window.demo.setMaterial(index, { type: 'phong' })))
      .filter(Boolean));
    problems.push(...refused.map((text) => `setMaterial: ${text}`));
  }
  return { context, page, api, problems };
}

// W warm-up frames, then F timed ones, each frame's wall time and the part of it spent waiting for
// the GPU process (PAGE_HOOK), each frame waited for once at its end (the project's
// frameWaitedOnce, the peers' frame). Then F more for the passes' times, a wait after each pass:
// the project's frame (its stats' split; its wall time kept as wallPerPass, what this bench timed
// before 2026-11-29) and the peers' frameSplit.
function timeFrames({ name, warmup, count }) {
  const api = window[name];
  const once = name === 'demo' ? api.frameWaitedOnce : api.frame;
  for (let i = 0; i < warmup; ++i) once(1 / 60);
  const frames = [];
  for (let i = 0; i < count; ++i) {
    const waited = window.__glWaitMs;
    const start = performance.now();
    const r = once(1 / 60);
    const wall = performance.now() - start;
    frames.push({ wall, cpu: wall - (window.__glWaitMs - waited), traced: r.tracedReflectors,
                  faces: r.facesCaptured });
  }
  if (name === 'demo') {
    for (let i = 0; i < count; ++i) {
      const start = performance.now();
      const r = api.frame(1 / 60);
      // captureMs: from the frame's start (its plan) to its captures' end, waited for; frameMs
      // adds the main pass, waited for. What is left of the wall time is the bridge (JSON).
      Object.assign(frames[i], { capture: r.captureMs, main: r.frameMs - r.captureMs, gpu: r.gpuFrameMs,
                                 wallPerPass: performance.now() - start });
    }
  }
  if (name === 'peer') {
    for (let i = 0; i < count; ++i) {
      const { parts } = api.frameSplit(1 / 60);
      frames[i].capture = parts.capture ?? 0;
      frames[i].main = parts.main;
    }
  }
  return frames;
}

async function measure(browser, base, spec, o) {
  const { context, page, api, problems } = await openPage(browser, base, spec, o);
  try {
    const load = await page.evaluate(loadParts);
    const frames = await page.evaluate(timeFrames, { name: api, warmup: o.warmup, count: o.frames });
    const canvas = await page.evaluate(() => {
      const c = document.getElementById('canvas');
      return `${c.width}x${c.height}`;
    });
    const settings = spec.peer ? null : await page.evaluate(() => {
      const d = window.demo;
      return `${d.accuracy().describe}; policy ${d.planner().policy}, capture LOD ${d.planner().captureLod}`;
    });
    const med = (key) => summary(frames.map((f) => f[key])).median;
    const split = { capture: med('capture'), main: med('main'), cpu: med('cpu'), traced: med('traced'),
                    faces: med('faces'), gpu: med('gpu'), wallPerPass: med('wallPerPass') };
    return { firstDrawMs: load.firstDraw, load, frame: summary(frames.map((f) => f.wall)), split, canvas, settings,
             problems };
  } finally {
    await context.close();
  }
}

async function rendererString(browser) {
  const page = await browser.newPage();
  try {
    return await page.evaluate(() => {
      const gl = document.createElement('canvas').getContext('webgl2');
      if (!gl) return 'no WebGL2';
      const ext = gl.getExtension('WEBGL_debug_renderer_info');
      const text = `${gl.getParameter(ext ? ext.UNMASKED_RENDERER_WEBGL : gl.RENDERER)} ` +
                   `(${gl.getParameter(ext ? ext.UNMASKED_VENDOR_WEBGL : gl.VENDOR)})`;
      gl.getExtension('WEBGL_lose_context')?.loseContext();
      return text;
    });
  } finally {
    await page.close();
  }
}

async function bench(base, pages, o, title = '') {
  console.log(`${title ? `${title}: ` : ''}${o.rounds} round(s) of ${pages.map((p) => p.key).join(', ')}; ` +
              `${o.width}x${o.height} CSS px at device pixel ratio 1; ${o.frames} frames of frame(1/60) after ` +
              `${o.warmup} warm-up` + (o.heavy ? '; the heavy figure (157k triangles) as mario' : '; the shipped models') +
              (o.query ? `; project query +${o.query}` : ''));
  const samples = new Map(pages.map((p) => [p.key, []]));
  for (let round = 1; round <= o.rounds; ++round) {
    for (const spec of pages) {
      // A browser of its own: the GPU process's caches (ANGLE's pipelines, SwiftShader's
      // routines) start empty, so every page's load compiles its shaders as a first visit does.
      const once = async () => {
        const own = await launchBrowser();
        return measure(own, base, spec, o).finally(() => own.close().catch(() => {}));
      };
      // A browser that goes away under the page (this shared machine's other jobs) is noted and
      // the page measured once more.
      const r = await once().catch((error) => {
        if (!/closed|crash/i.test(error.message)) throw error;
        console.log(`round ${round} ${spec.label}: ${error.message.split('\n')[0]}; measured again`);
        return once();
      });
      samples.get(spec.key).push(r);
      const { split: x } = r;
      console.log(`round ${round} ${spec.label.padEnd(26)} frame ${fmt(r.frame.median, 7)} ms ` +
                  `(p10 ${fmt(r.frame.p10, 0)}, p90 ${fmt(r.frame.p90, 0)}; capture ${fmt(x.capture, 0)}, ` +
                  `main ${fmt(x.main, 0)}, CPU ${fmt(x.cpu, 0)}` +
                  (spec.peer ? '' : `, traced ${x.traced}, faces ${x.faces}; ` +
                    `waited after each pass ${fmt(x.wallPerPass, 0)}`) +
                  `), first frame ${fmt(r.firstDrawMs, 6)} ms, canvas ${r.canvas}` +
                  (round === 1 && r.settings ? `; ${r.settings}` : ''));
      const l = loadSpans(r.load, spec.peer);
      console.log(`  load: code ready ${fmt(l.code, 0)} ms` +
                  (spec.peer ? ` (three.module.js fetched ${fmt(r.load.threeFetched, 0)})`
                    : ` (wasm fetched ${fmt(r.load.wasmFetched, 0)}, instantiateStreaming ${fmt(r.load.wasmStart, 0)} to ` +
                      `${fmt(r.load.wasmEnd, 0)})`) +
                  `, models ${fmt(l.models, 0)} (last fetched at ${fmt(r.load.modelsFetched, 0)}), BVH ${fmt(l.bvh, 0)}, ` +
                  `setup ${fmt(l.setup, 0)}, to first draw ${fmt(l.first, 0)}; shaders ${fmt(l.shaders, 0)}`);
      for (const p of r.problems) console.log(`  note: ${p}`);
    }
  }
  const rows = pageRows(pages, samples);
  printTables(rows, o, title);
  return rows;
}

// The query parts that hold a page at --time: the project's page paused there (the peers are
// driven with ?bench and setTime alone).
const heldAt = (spec, o) => (spec.peer ? [] : ['paused', `t=${o.time}`]);

async function screenshots(browser, base, pages, o) {
  mkdirSync(o.screenshots, { recursive: true });
  for (const spec of pages) {
    const extra = heldAt(spec, o);
    const { context, page, api, problems } = await openPage(browser, base, spec, o, extra);
    try {
      // As the accuracy's read-back: several frames at T, so mirrors seen in a capture are at T too.
      await page.evaluate(({ name, t, frames }) => {
        window[name].setTime(t);
        for (let i = 0; i < frames; ++i) window[name].frame(0);
      }, { name: api, t: o.time, frames: FRAMES_AT_TIME });
      await page.waitForTimeout(300);  // for the frame to reach the compositor
      const path = join(o.screenshots, `${spec.key}.png`);
      await page.screenshot({ path });
      console.log(`wrote ${path} (${pageUrl(spec, o, extra)})`);
      for (const p of problems) console.log(`  note: ${p}`);
    } finally {
      await context.close();
    }
  }
}

// No program cache on disk or in the GPU process: a page compiles its shaders as a first visit does.
const launchBrowser = () => launchChromium(['--disable-gpu-program-cache', '--disable-gpu-shader-disk-cache']);

async function main() {
  const o = parseArgs(process.argv.slice(2));
  const root = assemble(o);
  const port = await freePort();
  const { child, url } = await startServer(port, root);
  if (o.serve) {
    for (const spec of PAGES) console.log(`${spec.label.padEnd(28)} ${url}${pageUrl(spec, o)}`);
    console.log('serving until interrupted (Ctrl-C)');
    await new Promise((done) => child.on('exit', done));
    return;
  }
  const browser = await launchBrowser();
  try {
    const pages = o.pages.map((key) => PAGES.find((p) => p.key === key));
    if (o.screenshots) await screenshots(browser, url, pages, o);
    else {
      console.log(`renderer: ${await rendererString(browser)}; ${browser.version()}`);
      if (o.rounds > 0 && o.both) {
        // The shipped scene, then the heavy figure's, in one run: each its own tables, then both.
        const light = await bench(url, pages, { ...o, heavy: false }, 'shipped scene');
        console.log('');
        const heavy = await bench(url, pages, { ...o, heavy: true }, 'heavy figure');
        console.log('');
        printBoth(light, heavy);
      } else if (o.rounds > 0) await bench(url, pages, o);
      if (o.reference) {
        await runAccuracy(browser, url, pages, o, { openPage, extraFor: (spec) => heldAt(spec, o),
                                                    maskPage: PEER_PAGES.find((p) => p.sceneFile) });
      }
    }
  } finally {
    await browser.close();
    child.kill();
  }
}

main().then(() => process.exit(0), (error) => {
  console.error(`peer_bench: ${error.message}`);
  process.exit(1);
});
