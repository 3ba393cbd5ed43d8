// First frame first (issue 12): the page draws the scene as soon as its meshes are parsed, and
// builds chunks and levels of detail afterwards, in a Web Worker. Every check is an ordering or a
// count, never a duration: the first draw into the canvas, the first frame's stats and the level
// builder's events are recorded as they happen, and compared.
import { test, expect } from '@playwright/test';
import { collectErrors } from './helpers.mjs';

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
