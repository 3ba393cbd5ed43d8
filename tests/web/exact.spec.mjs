// Issue 13 in the page: the exact mode (search=exact), the live error view (show error), the
// frame-budget pick (auto) and drawing on demand (no frame at all while idle).
import { test, expect } from '@playwright/test';
import { animationFrames, collectErrors, idle, openDemo } from './helpers.mjs';

test('idle: paused and unchanged, the page draws no frame in 2 s; a change draws at once', async ({ page }) => {
  await openDemo(page, '?paused&t=1');
  await idle(page);
  await expect.poll(() => page.evaluate(() => window.demo.drawingIdle())).toBe(true);
  await expect(page.locator('#stats')).toContainText('idle');
  const before = await page.evaluate(() => window.demo.framesDrawn());
  await animationFrames(page, 60);  // a second of display frames, none of them drawn
  expect(await page.evaluate(() => window.demo.framesDrawn())).toBe(before);
  expect(await page.evaluate(() => window.demo.drawingIdle())).toBe(true);
  // Any change draws again: a camera step, then a setting.
  await page.evaluate(() => window.demo.setCamera(0, 1, 6.5, 0, 0));
  await expect.poll(() => page.evaluate(() => window.demo.framesDrawn())).toBeGreaterThan(before);
  await expect.poll(() => page.evaluate(() => window.demo.drawingIdle())).toBe(true);
  const after = await page.evaluate(() => window.demo.framesDrawn());
  await page.evaluate(() => window.demo.setPlanner({ captureLod: 0.5 }));
  await expect.poll(() => page.evaluate(() => window.demo.framesDrawn())).toBeGreaterThan(after);
  // demo.frame is unaffected by idling: it draws and returns its stats.
  const s = await page.evaluate(() => window.demo.frame(0));
  expect(s.width).toBeGreaterThan(0);
});

test('frameWaitedOnce (the peer bench\'s frame: one wait at its end) draws what frame draws', async ({ page }) => {
  await openDemo(page, '?paused&t=1');
  await idle(page);
  // Each draws the same paused frame; the canvas read after each.
  const drawn = await page.evaluate(() => {
    const sum = ({ data }) => data.reduce((a, v) => a + v, 0);
    const perPass = window.demo.frame(0);
    const a = sum(window.demo.readPixels());
    const once = window.demo.frameWaitedOnce(0);
    const b = sum(window.demo.readPixels());
    return { a, b, traced: [perPass.tracedReflectors, once.tracedReflectors] };
  });
  expect(drawn.a).toBeGreaterThan(0);
  expect(drawn.b).toBe(drawn.a);
  expect(drawn.traced).toEqual([1, 1]);
});

test('the canvas keeps its picture while idle', async ({ page }) => {
  await openDemo(page, '?paused&t=1');
  await idle(page);
  await expect.poll(() => page.evaluate(() => window.demo.drawingIdle())).toBe(true);
  await animationFrames(page, 15);
  const shot = await page.locator('#canvas').screenshot();
  // The screenshot is the composited canvas: not cleared (the sphere's gold and the ground's blue
  // are there), though no frame was drawn for it.
  const { decodePng } = await import('./png.mjs');
  const png = decodePng(shot);
  let coloured = 0;
  for (let i = 0; i < png.data.length; i += 4) {
    if (Math.abs(png.data[i] - png.data[i + 2]) > 40) ++coloured;
  }
  expect(coloured).toBeGreaterThan(1000);
});

test('exact mode: search=exact from the link, the schema, the panel; the error view is zero', async ({ page }) => {
  const errors = collectErrors(page);
  await openDemo(page, '?paused&t=2&search=exact&showError=true');
  await idle(page);
  expect(await page.evaluate(() => window.demo.accuracy().search)).toBe('exact');
  expect(await page.evaluate(() => window.demo.view().showError)).toBe(true);
  const choices = await page.evaluate(() => window.demo.schema().accuracy.find((i) => i.name === 'search').choices);
  expect(choices).toContain('exact');
  await expect(page.locator('#control-view-showError')).toHaveCount(1);
  const s = await page.evaluate(() => window.demo.frame(0));
  expect(s.errorView.reflectorPixels).toBeGreaterThan(1000);
  expect(s.errorView.rmse).toBe(0);
  expect(s.errorView.pixelsOver32).toBe(0);
  await expect(page.locator('#stats')).toContainText('∞ dB (exact)');
  // The current default against it: an error to see.
  expect(await page.evaluate(() => window.demo.setAccuracy({ search: 'hierarchical' }))).toBe('');
  const h = await page.evaluate(() => window.demo.frame(0));
  expect(h.errorView.rmse).toBeGreaterThan(0);
  expect(h.errorView.psnrDb).toBeLessThan(99);
  expect(await page.evaluate(() => window.demo.query())).toContain('showError=true');
  expect(errors).toEqual([]);
});

test('auto picks the most accurate search within the budget it is given', async ({ page }) => {
  await openDemo(page, '?paused&t=2');
  await idle(page);
  for (const budget of [1, 1000]) {
    expect(await page.evaluate((b) => window.demo.setView({ auto: true, budget: b }), budget)).toBe('');
    const result = await page.evaluate(() => window.demo.runAutoPick());
    const { pick, candidates } = result;
    expect(candidates.length).toBe(5);
    const chosen = candidates[pick.index];
    const accuracy = await page.evaluate(() => window.demo.accuracy());
    expect(accuracy.search).toBe(chosen.accuracy.search);
    if (pick.fits) {
      expect(chosen.frameMs).toBeLessThanOrEqual(budget);
      for (const c of candidates) if (c.frameMs <= budget) expect(chosen.psnrDb).toBeGreaterThanOrEqual(c.psnrDb);
    } else {
      for (const c of candidates) expect(c.frameMs).toBeGreaterThan(budget);
    }
    await expect(page.locator('#auto-readout')).toContainText(pick.reason);
    // Within the budget, the exact mode is the most accurate of all.
    const exact = candidates.find((c) => c.accuracy.search === 'exact');
    if (exact.frameMs <= budget) expect(chosen.accuracy.search).toBe('exact');
  }
});
