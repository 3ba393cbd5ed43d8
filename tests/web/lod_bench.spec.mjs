// Levels of detail built in the browser with meshoptimizer (for captures and the main view), and
// the page's bench mode.
import { test, expect } from '@playwright/test';
import {
  collectErrors, countChanged, openDemo, PANEL_OPEN_VIEWPORT, renderAndRead,
} from './helpers.mjs';

// The panel's controls are used: a window where it starts open, the canvas 800x600 beside it.
test.use({ viewport: PANEL_OPEN_VIEWPORT });

test('LOD levels are built for every mesh after the scene loads, by the native rules', async ({ page }) => {
  const infos = [];
  page.on('console', (m) => { if (m.type() === 'info') infos.push(m.text()); });
  await openDemo(page, '?paused');
  await page.evaluate(() => window.demo.lodReady());
  const levels = await page.evaluate(() => Object.fromEntries(
    window.demo.scene().meshes.map((name) => [name, window.demo.lodLevels(name)])));
  expect(levels['quad.obj']).toEqual([2]);  // under minTriangles: no coarser level
  for (const name of ['mario.obj', 'sonic.obj']) {
    const t = levels[name];
    expect(t.length, `${name}: levels ${t}`).toBe(3);  // maxLevels 3
    for (let k = 1; k < t.length; ++k) {
      expect(t[k], `${name} level ${k}`).toBeLessThanOrEqual(t[k - 1] * 0.75);
      expect(t[k], `${name} level ${k}`).toBeGreaterThan(0);
    }
  }
  expect(infos.some((line) => line.startsWith('capture LOD levels (triangles):') && line.includes('mario.obj 7258 > ')))
    .toBe(true);
  await expect(page.locator('#control-lod-levels input')).toHaveValue(/mario 3/);
});

test('with captureLod=0.5 the capture draws fewer triangles than with captureLod=0 (skybox scene)', async ({ page }) => {
  // Capture LOD serves captured probes: the skybox scene's live mirror, searched hierarchically.
  await openDemo(page, '?paused&scene=skybox&captureLod=0.25&search=hierarchical');
  expect((await page.evaluate(() => window.demo.planner())).captureLod).toBe(0.25);
  await page.evaluate(() => window.demo.lodReady());
  // A new LOD setting makes when-changed recapture every face, so both frames capture all of them.
  const captureTriangles = (lod) => page.evaluate((l) => {
    window.demo.setPlanner({ policy: 'when-changed', captureLod: l });
    window.demo.setTime(1);
    return window.demo.frame(0);
  }, lod);
  const full = await captureTriangles(0);
  const coarse = await captureTriangles(0.5);
  expect(full.facesCaptured).toBe(6);
  expect(coarse.facesCaptured).toBe(6);
  expect(coarse.captureTriangles, `capture triangles ${coarse.captureTriangles} vs ${full.captureTriangles}`)
    .toBeLessThan(full.captureTriangles * 0.75);
});

test('view LOD draws the figures with fewer triangles in the main pass; viewLod= is in the URL', async ({ page }) => {
  const errors = collectErrors(page);
  // The default scene's figures are light (12k triangles in all): at 0.5 triangles per pixel
  // they keep full detail, so ask for 0.05.
  await openDemo(page, '?paused&t=1&viewLod=0.05');
  expect((await page.evaluate(() => window.demo.planner())).viewLod).toBe(0.05);
  await page.evaluate(() => window.demo.lodReady());
  const coarse = await renderAndRead(page);
  await expect.poll(() => new URL(page.url()).search).toContain('viewLod=0.05');
  expect(await page.evaluate(() => window.demo.setPlanner({ captureLod: 0, viewLod: 0 }))).toBe('');
  const full = await renderAndRead(page);
  expect(coarse.stats.mainTriangles, `main triangles ${coarse.stats.mainTriangles} vs ${full.stats.mainTriangles}`)
    .toBeLessThan(full.stats.mainTriangles * 0.75);
  // The picture changes little: the figures are small on screen.
  expect(countChanged(full, coarse, 16) / (full.width * full.height)).toBeLessThan(0.02);
  await expect.poll(() => new URL(page.url()).search).not.toContain('viewLod=');
  expect(errors).toEqual([]);
});

test('?bench runs every policy and prints the table; when-changed matches every-frame exactly', async ({ page }) => {
  test.setTimeout(120_000);
  const infos = [];
  page.on('console', (m) => { if (m.type() === 'info') infos.push(m.text()); });
  // The policies are the capture's: the mirror captured and searched (the default traces it).
  await openDemo(page, '?bench&frames=8&search=hierarchical');
  await page.waitForFunction(() => window.demo.benchResults, null, { timeout: 100_000 });
  const results = await page.evaluate(() => window.demo.benchResults);
  expect(results.scene).toBe('ex12-2');
  expect(results.frames).toBe(8);
  expect(results.rows.map((r) => r.label)).toEqual(
    ['every-frame', 'when-changed', 'when-changed+LOD 0.5', 'when-changed+LOD+view 0.5', 'time-sliced 2',
     'every-n 4']);
  const row = Object.fromEntries(results.rows.map((r) => [r.label, r]));
  expect(row['every-frame'].facesCapturedPerFrame).toBe(6);
  // 6 faces x (3 objects whole in pass 1, and the 2 figures whole in pass 3, which skips the
  // ground: a flat mesh the probe sees only the front of has no backs) + 4 in the main pass = 34;
  // and pass 2 (what the figures hide) draws only the chunks of each object a face sees, at the
  // second layer's coarser level: over these 8 frames from t = 0 (the bench waits for the chunks
  // and levels, so the count is the same in every run), 11.25 draws a frame.
  expect(row['every-frame'].drawCallsPerFrame).toBe(45.25);
  expect(row['when-changed'].maxDiff).toBe(0);
  expect(row['when-changed'].comparedFrames).toBe(8);
  expect(row['time-sliced 2'].facesCapturedPerFrame).toBeLessThanOrEqual(2);
  expect(row['every-n 4'].facesCapturedPerFrame).toBeLessThan(6);
  expect(row['every-n 4'].maxDiff).toBeGreaterThan(0);  // stale faces show
  for (const r of results.rows) {
    expect(r.frameMs.median).toBeGreaterThan(0);
    expect(r.frameMs.p10).toBeLessThanOrEqual(r.frameMs.median);
    expect(r.frameMs.p90).toBeGreaterThanOrEqual(r.frameMs.median);
    expect(r.trianglesPerFrame).toBeGreaterThan(0);
  }
  const table = page.locator('#bench');
  await expect(table).toBeVisible();
  for (const r of results.rows) await expect(table).toContainText(r.label);
  expect(infos.some((line) => line.startsWith('bench: scene ex12-2'))).toBe(true);
  // The user's settings come back afterwards.
  expect((await page.evaluate(() => window.demo.planner())).policy).toBe('when-changed');
});
