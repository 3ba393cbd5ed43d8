// Loading: no errors, demo.ready, a non-blank picture, the stats line and counts, and the
// message shown when WebGL2 is missing.
import { test, expect } from '@playwright/test';
import { canvasScreenshot, collectErrors, colourSummary, openDemo, readyOutcome } from './helpers.mjs';

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
  await expect(stats).toHaveText(/^\d+ fps · frame \d+\.\d ms · cpu \d+\.\d\d ms \(capture \d+\.\d\d\) · 6 faces · 22 draws · \d+\.\dk tris · paused$/);
  const text = await stats.textContent();
  const [, fps, frameMs] = text.match(/^(\d+) fps · frame ([\d.]+) ms/);
  expect(Number(fps)).toBeGreaterThan(0);
  expect(Number(frameMs)).toBeLessThan(5000);
  // No line, not even the first, shows 0 fps or the 1/0 frame time of a frame without an interval.
  const shown = await page.evaluate(() => window.__statsTexts);
  expect(shown.length).toBeGreaterThan(0);
  for (const line of shown) {
    expect(line).not.toMatch(/^0 fps/);
    expect(Number(line.match(/frame ([\d.]+) ms/)[1])).toBeLessThan(5000);
  }

  const s = await page.evaluate(() => { window.demo.frame(0); return window.demo.stats(); });
  expect(s.facesCaptured).toBe(6);
  expect(s.drawCalls).toBe(22);
  expect(s.cubeFaceSize).toBe(256);
  expect(s.triangles).toBeGreaterThan(50_000);
  expect(s.frameMs).toBeGreaterThan(0);
  expect(s.captureMs).toBeGreaterThan(0);
  expect(s.captureMs).toBeLessThanOrEqual(s.frameMs);
  expect(s.fps).toBeGreaterThan(0);
  // The line's triangle count is the renderer's.
  expect(text).toContain(`${(s.triangles / 1000).toFixed(1)}k tris`);
  expect(errors).toEqual([]);
});

test('?cube=128 captures 128-pixel faces', async ({ page }) => {
  await openDemo(page, '?paused&cube=128');
  const s = await page.evaluate(() => window.demo.frame(0));
  expect(s.cubeFaceSize).toBe(128);
  expect(s.facesCaptured).toBe(6);
});

test('?t=SECONDS sets the scene time, ?paused keeps it', async ({ page }) => {
  await openDemo(page, '?paused&t=2');
  await page.waitForTimeout(300);  // a few rAF frames
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
