// Loading: no errors, demo.ready, a non-blank picture, the stats line and counts, and the
// message shown when WebGL2 is missing.
import { test, expect } from '@playwright/test';
import { readFileSync } from 'node:fs';
import {
  animationFrames, canvasScreenshot, collectErrors, colourSummary, makeSphereTest, openDemo, readyOutcome, renderAndRead,
} from './helpers.mjs';

test('loads without errors, resolves demo.ready and draws a non-blank scene', async ({ page }) => {
  const errors = collectErrors(page);
  await openDemo(page, '?paused');
  await page.evaluate(() => window.demo.frame(0));
  const image = await canvasScreenshot(page);
  expect(image.width).toBe(800);
  expect(image.height).toBe(600);
  const { distinct, greyFraction } = colourSummary(image);
  expect(distinct, 'distinct colours in the canvas').toBeGreaterThan(500);
  expect(greyFraction, 'fraction of background grey').toBeLessThan(0.6);
  expect(greyFraction, 'the grey background above the horizon is there').toBeGreaterThan(0.2);
  // Nothing went wrong on the way.
  await expect(page.locator('#messages .message')).toHaveCount(0);
  expect(errors).toEqual([]);
});

// The contract: every frame re-captures the cube map, six faces, and more than 34 draw calls: the
// 3 objects whole in pass 1 and the 2 figures whole in pass 3 (which skips the flat ground) in
// each of the 6 faces, as the default stores two depth layers where figures can hide the floor,
// + 4 in the main pass; and pass 2's draws, the chunks of each object the face sees (at least the
// ground's, in the five faces that see it), whose number moves with the figures. A page whose
// stats name another capture `policy` (a planner that skips unchanged faces) re-captures fewer
// faces; for it the test checks that the counts are consistent and that a scene change is
// captured, and records an annotation saying so.
const EVERY_FRAME = (s) => s.policy === undefined || s.policy === 'every-frame';

test('stats line shows fps, faces, draws and triangles; demo.stats() has the counts', async ({ page }) => {
  const errors = collectErrors(page);
  // Every text the stats line ever shows, from the first one on.
  await page.addInitScript(() => {
    window.__statsTexts = [];
    document.addEventListener('DOMContentLoaded', () => {
      const element = document.getElementById('stats');
      new MutationObserver(() => window.__statsTexts.push(element.textContent))
        .observe(element, { childList: true, characterData: true, subtree: true });
    });
  });
  await openDemo(page, '?paused');
  const stats = page.locator('#stats');
  // Paused and unchanged, the page draws nothing, and the line says so.
  await expect(stats).toHaveText(/^idle: no frame drawn until something changes · last frame (cpu|gpu) \d+\.\d\d ms \(capture \d+\.\d\d\)\n\d faces · \d+ draws · \d+\.\dk tris · paused · idle$/);
  // Running, it draws every display frame. Two lines: timings (GPU timer queries where the
  // browser has them, else CPU), then counts.
  await page.evaluate(() => window.demo.pause(false));
  await expect(stats).toHaveText(/^\d+ fps · frame \d+\.\d ms · (cpu|gpu) \d+\.\d\d ms \(capture \d+\.\d\d\)\n\d faces · \d+ draws · \d+\.\dk tris$/);
  // The line is redrawn at most every 250 ms, from the frame drawn then; read it together with
  // demo.stats() (in one task) until both come from a frame of the same counts.
  const sample = () => page.evaluate(() => ({
    text: document.getElementById('stats').textContent, loop: window.demo.stats(),
  }));
  const agree = ({ text, loop }) => text.includes(`\n${loop.facesCaptured} faces · ${loop.drawCalls} draws · `) &&
                                     text.includes(`${(loop.triangles / 1000).toFixed(1)}k tris`);
  let agreed = null;
  await expect.poll(async () => {
    const now = await sample();
    if (agree(now)) agreed = now;
    return agreed !== null;
  }).toBe(true);
  const { text, loop } = agreed;
  const [, fps, frameMs] = text.match(/^(\d+) fps · frame ([\d.]+) ms/);
  expect(Number(fps)).toBeGreaterThan(0);
  expect(Number(frameMs)).toBeLessThan(5000);
  expect(text).toContain(`\n${loop.facesCaptured} faces · ${loop.drawCalls} draws · `);
  expect(text).toContain(`${(loop.triangles / 1000).toFixed(1)}k tris`);
  expect(loop.fps).toBeGreaterThan(0);
  // No line, not even the first, shows 0 fps or the 1/0 frame time of a frame without an interval.
  const shown = await page.evaluate(() => window.__statsTexts);
  expect(shown.length).toBeGreaterThan(0);
  for (const line of shown) {
    if (line.startsWith('idle: ')) continue;  // no frame drawn: no fps to show
    expect(line).not.toMatch(/^0 fps/);
    expect(Number(line.match(/frame ([\d.]+) ms/)[1])).toBeLessThan(5000);
  }

  // A frame that advances the orbit, as the running demo does.
  const s = await page.evaluate(() => window.demo.frame(1 / 60));
  expect(s.cubeFaceSize).toBe(256);
  expect(s.triangles).toBeGreaterThan(10_000);
  expect(s.frameMs).toBeGreaterThan(0);
  expect(s.captureMs).toBeGreaterThanOrEqual(0);
  expect(s.captureMs).toBeLessThanOrEqual(s.frameMs);
  expect(s.timing).toBe('gpu-finish');
  if (EVERY_FRAME(s)) {
    expect(s.facesCaptured).toBe(6);
    expect(s.drawCalls).toBeGreaterThanOrEqual(34 + 5);
    expect(loop.facesCaptured).toBe(6);
    expect(loop.drawCalls).toBeGreaterThanOrEqual(34 + 5);
    expect(text).toContain(`\n6 faces · ${loop.drawCalls} draws · `);
  } else if (s.tracedReflectors > 0) {
    // The default traces the mirror here: no probe, no face, the main pass's four draws.
    expect(s.tracedReflectors).toBe(1);
    expect(s.probes).toBe(0);
    expect(s.facesCaptured).toBe(0);
    expect(s.drawCalls).toBe(4);
    expect(text).toContain('\n0 faces · 4 draws · ');
  } else {
    test.info().annotations.push({ type: 'contract',
      description: `capture policy "${s.policy}": ${s.facesCaptured} faces / ${s.drawCalls} draws ` +
                   'for a moving frame, not the 6 faces of re-capturing every frame' });
    expect(s.facesCaptured).toBeGreaterThanOrEqual(1);  // the figures moved: something is redrawn
    expect(s.facesCaptured).toBeLessThanOrEqual(6);
    expect(s.drawCalls).toBeGreaterThanOrEqual(4);     // at least the main pass's four objects
    expect(s.drawCalls).toBeLessThanOrEqual(52);
  }
  expect(errors).toEqual([]);
});

test('?cube=128 captures 128-pixel faces', async ({ page }) => {
  // The cube map's size matters where the mirror is captured: the hierarchical search.
  await openDemo(page, '?paused&cube=128&search=hierarchical');
  const small = await renderAndRead(page, 0);
  const s = await page.evaluate(() => window.demo.frame(1 / 60));
  expect(s.cubeFaceSize).toBe(128);
  if (EVERY_FRAME(s)) expect(s.facesCaptured).toBe(6);
  // The size is really used: the reflection differs from the 256 default, the rest does not.
  await openDemo(page, '?paused&search=hierarchical');
  const large = await renderAndRead(page, 0);
  const inSphere = makeSphereTest(large.width, large.height, { radiusScale: 0.93 });
  const nearSphere = makeSphereTest(large.width, large.height, { radiusScale: 1.05 });
  let sphereDiffer = 0, elsewhereDiffer = 0;
  for (let y = 0; y < large.height; ++y) {
    for (let x = 0; x < large.width; ++x) {
      const i = (y * large.width + x) * 4;
      const differ = [0, 1, 2].some((c) => Math.abs(large.data[i + c] - small.data[i + c]) > 2);
      if (!differ) continue;
      if (inSphere(x, y)) ++sphereDiffer;
      else if (!nearSphere(x, y)) ++elsewhereDiffer;
    }
  }
  expect(sphereDiffer, 'sphere pixels that differ between cube 128 and 256').toBeGreaterThan(200);
  expect(elsewhereDiffer, 'pixels away from the sphere that differ').toBe(0);
});

test('?t=SECONDS sets the scene time, ?paused keeps it', async ({ page }) => {
  await openDemo(page, '?paused&t=2');
  await animationFrames(page, 10);  // frames that would have moved a running clock
  const s = await page.evaluate(() => window.demo.stats());
  expect(s.time).toBeCloseTo(2, 6);
  expect(s.orbitDegrees).toBeCloseTo(54, 4);  // 27 degrees a second
});

test('without WebGL2 a visible message says so and demo.ready rejects', async ({ page }) => {
  await page.addInitScript(() => { delete window.WebGL2RenderingContext; });
  await page.goto('?paused');
  expect(await readyOutcome(page)).toMatch(/^rejected: .*WebGL2/);
  const message = page.locator('#messages .message');
  await expect(message).toHaveCount(1);
  await expect(message).toBeVisible();
  await expect(message).toContainText('WebGL2');
  await expect(page.locator('#stats')).toHaveText('not running');
});

test('an unknown scene is named in a message, and the default scene runs instead of a black canvas', async ({ page }) => {
  await page.goto('?paused&scene=nosuch');
  expect(await readyOutcome(page)).toBe('resolved');
  // The message names the missing file and stays; a second one says what the page did instead.
  const missing = page.locator('#messages .message.error', { hasText: 'scenes/nosuch.json: HTTP 404' });
  await expect(missing).toBeVisible();
  await expect(page.locator('#messages .message.info', { hasText: 'showing the default scene (ex12-2) instead' }))
    .toBeVisible();
  expect(await page.evaluate(() => window.demo.scene().name)).toBe('ex12-2');
  // The default scene is drawn, and the link names it.
  await page.evaluate(() => window.demo.frame(0));
  const { distinct, greyFraction } = colourSummary(await canvasScreenshot(page));
  expect(distinct, 'distinct colours in the canvas').toBeGreaterThan(500);
  expect(greyFraction, 'fraction of background grey').toBeLessThan(0.6);
  await expect(page.locator('#stats')).not.toHaveText('not running');
  expect(await page.evaluate(() => window.demo.query())).toMatch(/^\?scene=ex12-2&/);
  await animationFrames(page, 5);
  await expect(missing).toBeVisible();  // still there once the page runs
});

// Load to first frame: index.html starts the first scene's downloads (its JSON, then the built-in
// models it names) before the wasm module is ready; the loader takes each of those responses
// instead of fetching again. Held: each file is downloaded once, every download is taken (the
// page's URL rule and scene_loader.js's agree), and the JSON's started before the module was ready.
for (const scene of ['ex12-2', 'probe-lit']) {
  test(`${scene}: the first scene's files start downloading before the module is ready, once each, and each is taken`, async ({ page }) => {
    const errors = collectErrors(page);
    await openDemo(page, scene === 'ex12-2' ? '?paused' : `?paused&scene=${scene}`);
    const seen = await page.evaluate(() => ({
      left: [...window.reflectPrefetch.keys()],
      ready: performance.getEntriesByName('reflect:wasm-ready', 'mark')[0].startTime,
      files: performance.getEntriesByType('resource')
        .map((e) => ({ path: new URL(e.name).pathname.split('/').slice(-2).join('/'), start: e.startTime }))
        .filter((f) => /^(models\/.+\.obj|scenes\/(?!index).+\.json)$/.test(f.path)),
    }));
    const json = JSON.parse(readFileSync(new URL(`../../assets/scenes/${scene}.json`, import.meta.url), 'utf8'));
    const models = [...new Set(json.objects.map((o) => `models/${o.mesh}`))];
    expect(seen.files.map((f) => f.path).sort()).toEqual([`scenes/${scene}.json`, ...models].sort());
    expect(seen.left).toEqual([]);
    expect(seen.files.find((f) => f.path.startsWith('scenes/')).start).toBeLessThan(seen.ready);
    expect(errors).toEqual([]);
  });
}

// Only what the scene needs: Emscripten would enable every extension the browser offers, one
// getExtension each; the page asks for the ones the renderer uses (web_main.cpp's kExtensions),
// and the float targets still work (inside.spec's face-use view renders into one).
test('the page enables only the WebGL extensions the renderer uses', async ({ page }) => {
  await page.addInitScript(() => {
    window.__extensionsAsked = [];
    const original = WebGL2RenderingContext.prototype.getExtension;
    WebGL2RenderingContext.prototype.getExtension = function (name) {
      window.__extensionsAsked.push(name);
      return original.call(this, name);
    };
  });
  await openDemo(page, '?paused');
  const asked = await page.evaluate(() => window.__extensionsAsked);
  expect([...new Set(asked)].sort()).toEqual([
    'EXT_color_buffer_float', 'EXT_color_buffer_half_float', 'EXT_disjoint_timer_query_webgl2',
    'EXT_float_blend', 'OES_texture_float_linear',
  ]);
});

test('index.html preloads every module the page imports at start, and nothing else', async ({ page }) => {
  // The modules are fetched at once instead of a level of imports after another (load to first
  // frame, issue 12); a module added to app.js's graph but not to the list would load late.
  const web = new URL('../../web/', import.meta.url);
  const graph = new Set();
  const generated = new Set(['wasm_exports.js']);  // written by the build into the site; no imports
  const visit = (name) => {
    if (graph.has(name)) return;
    graph.add(name);
    if (generated.has(name)) return;
    const text = readFileSync(new URL(name, web), 'utf8');
    for (const m of text.matchAll(/(?:from|import\()\s*'\.\/([\w/.-]+\.js)'/g)) {
      if (!m[1].startsWith('vendor/')) visit(m[1]);
      else graph.add(m[1]);
    }
  };
  visit('app.js');
  expect(graph.size).toBeGreaterThan(20);
  expect(graph).toContain('lod.js');  // three levels of imports below app.js
  const html = readFileSync(new URL('index.html', web), 'utf8');
  const preloaded = [...html.matchAll(/<link rel="modulepreload" href="([^"]+)">/g)].map((m) => m[1]);
  expect([...preloaded].sort()).toEqual([...graph].sort());
  // The page loads them all with no errors (each preload is used, none is a 404).
  const failed = [];
  page.on('response', (r) => { if (r.status() >= 400) failed.push(r.url()); });
  const errors = collectErrors(page);
  await openDemo(page, '?paused');
  expect(failed).toEqual([]);
  expect(errors).toEqual([]);
  // The levels-of-detail worker is no import of the page's: its script and its own wasm module
  // (built from src/platform/web/lod_worker_main.cpp) are in the site beside the page.
  const served = await page.evaluate(() => Promise.all(
    ['lod_worker.js', 'lod_module.js', 'lod_module.wasm'].map(async (f) => `${f} ${(await fetch(f)).status}`)));
  expect(served).toEqual(['lod_worker.js 200', 'lod_module.js 200', 'lod_module.wasm 200']);
});
