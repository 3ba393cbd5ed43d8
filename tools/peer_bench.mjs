#!/usr/bin/env node
// The project's page against three.js peers (tools/peers/), in one headless Chromium (Debian's,
// SwiftShader WebGL2). Not a test: it prints numbers and exits 0. Two peers draw the default
// scene (cubecamera, bvh); one reads a scene file (pmrem: a CubeCamera and a PMREM a mirror, rough
// mirrors), the one --scene NAME names (ex12-2 without it).
//
//   node tools/peer_bench.mjs [--heavy] [--rounds N] [--frames N] [--warmup N] [--size WxH]
//                             [--site DIR] [--pages KEY,KEY,...] [--query EXTRA] [--scene NAME]
//                             [--reference PNG [--mask PNG | --save-mask PNG] [--time T]]
//   node tools/peer_bench.mjs --screenshots DIR [--time T] [--heavy] [--pages ...] [--size WxH]
//   node tools/peer_bench.mjs --serve [--heavy] [--site DIR]
//
// Serves one folder, build/peer-bench/: the project's site (build/web/site, or --site), the
// peers' pages, three and three-mesh-bvh from node_modules and, with --heavy, the 157k-triangle
// figure (tools/make_models.py --heavy) in place of mario for every page. Each round measures
// every page in turn (PAGES' order), each in a fresh browser context:
//   load to first frame: performance.now() at the first draw call into the canvas (the default
//     framebuffer), hooked before any of the page's scripts, so the project's page and the peers
//     are measured the same way (from navigation start);
//   frame: after the page is ready (and the project's levels of detail are built), W warm-up and
//     F timed calls of frame(1/60) in one task: window.demo.frame on the project's page,
//     window.peer.frame on the peers; each call's wall time, which includes the GPU's work
//     (both end with a read-back).
// It prints each round, then per page the medians over the rounds of each round's median, p10
// and p90 frame ms and its load time, then each project page's frame and load against each peer.
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
import { freePort, launchChromium, repo, startServer, summary } from './bench_lib.mjs';
import { FRAMES_AT_TIME, runAccuracy } from './peer_accuracy.mjs';

// The project's configurations: what each adds to index.html's query. Add a row for a new setting.
const PROJECT_PAGES = [
  { key: 'default', label: 'project default', query: '' },
  { key: 'exact', label: 'project exact', query: 'search=exact' },
  { key: 'course', label: 'project course setting', query: 'acc=original&policy=every-frame&captureLod=0' },
  { key: 'hierarchical', label: 'project hierarchical', query: 'search=hierarchical' },
];
// The peers (tools/peers/), each driven through window.peer.
const PEER_PAGES = [
  { key: 'cubecamera', label: 'three.js CubeCamera', path: 'peers/index.html', query: 'rendition=cubecamera', peer: true },
  { key: 'bvh', label: 'three.js + three-mesh-bvh', path: 'peers/index.html', query: 'rendition=bvh', peer: true },
  // The scene file --scene names (sceneFile); without --scene it runs only when --pages names it.
  { key: 'pmrem', label: 'three.js CubeCamera + PMREM', path: 'peers/index.html', query: 'rendition=pmrem', peer: true,
    sceneFile: true },
];
// With --against DIR, another build of the project's page (e.g. the last landing's
// build/web/site) is served under base/ and its configurations join as base-KEY.
const BASE_PAGES = PROJECT_PAGES.map((p) => ({ ...p, key: `base-${p.key}`, label: `base ${p.label.replace('project ', '')}`,
                                              path: 'base/index.html', base: true }));
const PAGES = [...PROJECT_PAGES, ...PEER_PAGES, ...BASE_PAGES];

function parseArgs(argv) {
  const o = { heavy: false, rounds: 2, frames: 20, warmup: 5, width: 800, height: 800,
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
      console.log('usage: node tools/peer_bench.mjs [--heavy] [--rounds N] [--frames N] [--warmup N] [--size WxH]\n' +
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
  if (o.heavy) {
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

// Runs before any script of the page: the time of the first draw call into the default
// framebuffer (the canvas). Both kinds of draw call are hooked, so the measure does not depend on
// which one a page happens to draw with first.
const FIRST_DRAW_HOOK = () => {
  window.__firstDrawMs = null;
  const proto = WebGL2RenderingContext.prototype;
  const originals = { drawElements: proto.drawElements, drawArrays: proto.drawArrays };
  for (const [name, original] of Object.entries(originals)) {
    proto[name] = function (...args) {
      if (window.__firstDrawMs === null && this.getParameter(this.DRAW_FRAMEBUFFER_BINDING) === null) {
        window.__firstDrawMs = performance.now();
        Object.assign(proto, originals);
      }
      return original.apply(this, args);
    };
  }
};

// A fresh context on the page, ready to be driven: { context, page, api, problems }.
async function openPage(browser, base, spec, o, extra = []) {
  const context = await browser.newContext({ viewport: { width: o.width, height: o.height }, deviceScaleFactor: 1 });
  const page = await context.newPage();
  page.setDefaultTimeout(600_000);  // the heavy figure's first frame in SwiftShader takes a while
  const problems = [];
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console error: ${m.text()}`); });
  await page.addInitScript(FIRST_DRAW_HOOK);
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
  return { context, page, api, problems };
}

async function measure(browser, base, spec, o) {
  const { context, page, api, problems } = await openPage(browser, base, spec, o);
  try {
    const firstDrawMs = await page.evaluate(() => window.__firstDrawMs);
    // The project page's load in parts (performance marks of web/wasm_bridge.js, scene_loader.js).
    const parts = spec.peer ? null : await page.evaluate(() => {
      const at = (name) => performance.getEntriesByName(name, 'mark')[0];
      const committed = at('reflect:scene-committed');
      return { wasm: at('reflect:wasm-ready')?.startTime, models: at('reflect:models-in')?.startTime,
               committed: committed?.startTime, bvhMs: committed?.detail?.bvhMs };
    });
    const frames = await page.evaluate(({ name, warmup, count }) => {
      const api = window[name];
      for (let i = 0; i < warmup; ++i) api.frame(1 / 60);
      const wall = [];
      for (let i = 0; i < count; ++i) {
        const start = performance.now();
        api.frame(1 / 60);
        wall.push(performance.now() - start);
      }
      return wall;
    }, { name: api, warmup: o.warmup, count: o.frames });
    const canvas = await page.evaluate(() => {
      const c = document.getElementById('canvas');
      return `${c.width}x${c.height}`;
    });
    const settings = spec.peer ? null : await page.evaluate(() => {
      const d = window.demo;
      return `${d.accuracy().describe}; policy ${d.planner().policy}, capture LOD ${d.planner().captureLod}`;
    });
    return { firstDrawMs, parts, frame: summary(frames), canvas, settings, problems };
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

const fmt = (x, width = 9) => (Number.isFinite(x) ? x.toFixed(1) : 'n/a').padStart(width);
const median = (values) => summary(values).median;

async function bench(browser, base, pages, o) {
  console.log(`renderer: ${await rendererString(browser)}`);
  console.log(`${o.rounds} round(s) of ${pages.map((p) => p.key).join(', ')}; ${o.width}x${o.height} CSS px at ` +
              `device pixel ratio 1; ${o.frames} frames of frame(1/60) after ${o.warmup} warm-up` +
              (o.heavy ? '; the heavy figure (157k triangles) as mario' : '') +
              (o.query ? `; project query +${o.query}` : ''));
  const samples = new Map(pages.map((p) => [p.key, []]));
  for (let round = 1; round <= o.rounds; ++round) {
    for (const spec of pages) {
      const r = await measure(browser, base, spec, o);
      samples.get(spec.key).push(r);
      console.log(`round ${round} ${spec.label.padEnd(26)} frame ${fmt(r.frame.median, 7)} ms ` +
                  `(p10 ${fmt(r.frame.p10, 0)}, p90 ${fmt(r.frame.p90, 0)}), first frame ${fmt(r.firstDrawMs, 6)} ms, ` +
                  `canvas ${r.canvas}` + (round === 1 && r.settings ? `; ${r.settings}` : ''));
      if (r.parts?.committed !== undefined) {
        const p = r.parts;
        console.log(`  load: wasm ready ${fmt(p.wasm, 0)} ms, models in ${fmt(p.models, 0)}, scene made ` +
                    `${fmt(p.committed, 0)} (of which the trees ${fmt(p.bvhMs, 0)}), first draw ${fmt(r.firstDrawMs, 0)}`);
      }
      for (const p of r.problems) console.log(`  note: ${p}`);
    }
  }
  const rows = pages.map((spec) => {
    const s = samples.get(spec.key);
    return { spec, frame: median(s.map((r) => r.frame.median)), p10: median(s.map((r) => r.frame.p10)),
             p90: median(s.map((r) => r.frame.p90)), load: median(s.map((r) => r.firstDrawMs ?? NaN)) };
  });
  console.log('');
  console.log(`medians over ${o.rounds} round(s) of each round's figures:`);
  console.log(`${'page'.padEnd(28)}${'frame ms'.padStart(9)}${'p10'.padStart(9)}${'p90'.padStart(9)}` +
              `${'load to first frame ms'.padStart(24)}`);
  for (const r of rows) {
    console.log(`${r.spec.label.padEnd(28)}${fmt(r.frame)}${fmt(r.p10)}${fmt(r.p90)}${fmt(r.load, 24)}`);
  }
  const peers = rows.filter((r) => r.spec.peer);
  const projects = rows.filter((r) => !r.spec.peer);
  if (peers.length && projects.length) {
    console.log('');
    console.log('project pages against the peers (x the peer\'s: frame, load to first frame):');
    for (const r of projects) {
      console.log(`${r.spec.label.padEnd(28)}` + peers.map((p) => `vs ${p.spec.key}: ` +
        `frame ${(r.frame / p.frame).toFixed(2)}x, load ${(r.load / p.load).toFixed(2)}x`).join('; '));
    }
  }
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
  const browser = await launchChromium();
  try {
    const pages = o.pages.map((key) => PAGES.find((p) => p.key === key));
    if (o.screenshots) await screenshots(browser, url, pages, o);
    else {
      if (o.rounds > 0) await bench(browser, url, pages, o);
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
