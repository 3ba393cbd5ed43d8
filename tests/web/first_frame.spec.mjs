// First frame first (issue 12): the page draws the scene as soon as its meshes are parsed, and
// builds chunks and levels of detail afterwards, in a Web Worker. Every check is an ordering or a
// count, never a duration: the first draw into the canvas, the first frame's stats and the level
// builder's events are recorded as they happen, and compared.
import { test, expect } from '@playwright/test';
import { animationFrames, collectErrors } from './helpers.mjs';

// Runs before the page's scripts: the time of the first draw call into the canvas (the default
// framebuffer), as tools/web_bench.mjs hooks it, and whether a Worker was made before it.
const HOOKS = () => {
  window.__firstDrawAt = null;
  window.__workersBeforeFirstDraw = 0;
  const proto = WebGL2RenderingContext.prototype;
  const drawElements = proto.drawElements;
  proto.drawElements = function (...args) {
    if (window.__firstDrawAt === null && this.getParameter(this.DRAW_FRAMEBUFFER_BINDING) === null) {
      window.__firstDrawAt = performance.now();
    }
    return drawElements.apply(this, args);
  };
  const NativeWorker = window.Worker;
  window.Worker = class extends NativeWorker {
    constructor(...args) {
      if (window.__firstDrawAt === null) ++window.__workersBeforeFirstDraw;
      super(...args);
    }
  };
};

test('the first frame is drawn before the levels of detail are built, at load and after a scene switch', async ({ page }) => {
  const errors = collectErrors(page);
  await page.addInitScript(HOOKS);
  await page.goto('?paused');
  await page.waitForFunction(() => window.demo !== undefined);
  await page.evaluate(() => window.demo.ready);
  const first = await page.evaluate(() => ({
    stats: window.demo.firstFrameStats(),
    drawAt: window.__firstDrawAt,
    workers: window.__workersBeforeFirstDraw,
  }));
  // The first frame was drawn into the canvas, from meshes without chunks or levels, and no level
  // builder had been started before it.
  expect(first.drawAt).not.toBeNull();
  expect(first.stats).not.toBeNull();
  expect(first.stats.lodReady).toBe(false);
  expect(first.stats.triangles).toBeGreaterThan(0);
  expect(first.workers).toBe(0);

  const levels = await page.evaluate(() => window.demo.lodReady());
  expect(levels['mario.obj']?.length).toBeGreaterThan(1);  // captureLod is on by default
  const events = await page.evaluate(() => window.demo.levelEvents());
  const start = events.find((e) => e.event === 'start');
  const done = events.find((e) => e.event === 'done');
  expect(start, JSON.stringify(events)).toBeTruthy();
  expect(done, JSON.stringify(events)).toBeTruthy();
  expect(start.at).toBeGreaterThanOrEqual(first.drawAt);
  expect(done.at).toBeGreaterThan(start.at);
  // Once they are in, frames say so.
  expect((await page.evaluate(() => window.demo.frame(0))).lodReady).toBe(true);

  // Another scene: its first frame, too, comes before its levels.
  await page.evaluate(() => window.demo.loadScene('skybox'));
  expect((await page.evaluate(() => window.demo.firstFrameStats())).lodReady).toBe(false);
  await page.evaluate(() => window.demo.lodReady());
  expect((await page.evaluate(() => window.demo.frame(0))).lodReady).toBe(true);
  expect(errors).toEqual([]);
});

// Issue 34: nothing built that nothing draws. Chunks cull a captured face's draws and capture
// LOD's levels are drawn only into captured faces; the default page traces its mirror (no probe,
// no face), so it builds neither: no worker is started, and the worker's script and wasm module
// are not even fetched. A page that captures with capture LOD on builds them by itself after its
// first frame, as does view LOD. Every check is a count or a state: the worker constructor and
// the requests are recorded as they happen, and demo.levelsSettled() waits for whatever the frames
// wanted without asking for more (demo.lodReady() would ask for every level).
const WORKER_HOOK = () => {
  window.__workers = [];
  const NativeWorker = window.Worker;
  window.Worker = class extends NativeWorker {
    constructor(url, ...rest) {
      window.__workers.push(String(url));
      super(url, ...rest);
    }
  };
};

// Opens `query`, draws `frames` animated frames, waits for what they want built; the state then.
async function levelsAfterFrames(page, query, frames) {
  await page.goto(query);
  await page.waitForFunction(() => window.demo !== undefined);
  await page.evaluate(() => window.demo.ready);
  const state = await page.evaluate(async (count) => {
    let stats = null;
    for (let i = 0; i < count; ++i) stats = window.demo.frame(1 / 60);
    await window.demo.levelsSettled();
    return { stats };
  }, frames);
  await animationFrames(page, 5);  // the display loop's frames too, and any task they start
  return page.evaluate(({ stats }) => ({
    stats,
    meshLevels: Object.fromEntries(window.demo.scene().meshes.map((name) => [name, window.demo.meshLevels(name)])),
    lodLevels: window.demo.lodLevels('mario.obj'),
    events: window.demo.levelEvents().map((e) => e.event),
    workers: [...window.__workers],
    wanted: window.demo.frame(0).levelsWanted,
  }), state);
}

test('the default page builds no chunks or levels and fetches no worker; capture LOD and view LOD build theirs', async ({ page }) => {
  const errors = collectErrors(page);
  const lodRequests = [];
  page.on('request', (r) => {
    const file = new URL(r.url()).pathname.split('/').pop();
    if (file.startsWith('lod_worker') || file.startsWith('lod_module')) lodRequests.push(file);
  });
  await page.addInitScript(WORKER_HOOK);

  // The default page (ex12-2, no keys): the mirror is traced, every mesh keeps its one level.
  const plain = await levelsAfterFrames(page, '?paused', 10);
  expect(plain.stats.tracedReflectors).toBe(1);
  expect(plain.stats.probes).toBe(0);
  expect(plain.wanted).toBe(false);
  expect(plain.stats.lodReady).toBe(false);  // chunks and levels the settings could draw: not built
  for (const [name, levels] of Object.entries(plain.meshLevels)) expect(levels, name).toHaveLength(1);
  expect(plain.lodLevels).toBeNull();
  expect(plain.events).toEqual([]);
  expect(plain.workers).toEqual([]);
  expect(lodRequests).toEqual([]);

  // The hierarchical search captures the mirror's probe: capture LOD's levels are built, by the
  // native rules (MeshChunks.ShippedMarioLevelsAreThePagesLevels), in one worker.
  const captured = await levelsAfterFrames(page, '?paused&captureLod=0.5&search=hierarchical', 2);
  expect(captured.stats.probes).toBe(1);
  expect(captured.wanted).toBe(false);
  expect(captured.meshLevels['mario.obj']).toEqual([7258, 1814, 528]);
  expect(captured.lodLevels).toEqual([7258, 1814, 528]);
  expect(captured.events).toEqual(['start', 'done']);
  expect(captured.workers).toHaveLength(1);
  expect([...new Set(lodRequests)].sort()).toEqual(['lod_module.js', 'lod_module.wasm', 'lod_worker.js']);

  // Capture LOD off, the same capture: chunks only, no coarser level.
  const chunksOnly = await levelsAfterFrames(page, '?paused&captureLod=0&search=hierarchical', 2);
  expect(chunksOnly.stats.probes).toBe(1);
  expect(chunksOnly.wanted).toBe(false);
  expect(chunksOnly.meshLevels['mario.obj']).toEqual([7258]);
  expect(chunksOnly.events).toEqual(['start', 'done']);

  // View LOD draws coarser levels in the main pass, traced mirror or not.
  const view = await levelsAfterFrames(page, '?paused&viewLod=0.05', 2);
  expect(view.stats.tracedReflectors).toBe(1);
  expect(view.wanted).toBe(false);
  expect(view.meshLevels['mario.obj']).toEqual([7258, 1814, 528]);
  expect(view.workers).toHaveLength(1);
  expect(errors).toEqual([]);
});
