// The course's scheme one pick away: ?preset=course and the panel's preset apply the schema's
// named preset (core/presets.h), and the link's own keys override it.
import { test, expect } from '@playwright/test';
import { idle, openDemo, PANEL_OPEN_VIEWPORT } from './helpers.mjs';

test('?preset=course gives the course\'s capture and lookup; a key of the link overrides it', async ({ page }) => {
  await openDemo(page, '?preset=course&paused');
  const planner = await page.evaluate(() => window.demo.planner());
  const accuracy = await page.evaluate(() => window.demo.accuracy());
  expect(planner.policy).toBe('every-frame');
  expect(planner.captureLod).toBe(0);
  expect(accuracy.search).toBe('plain');
  expect(accuracy.captureAtOrigin).toBe(true);
  expect(accuracy.layers).toBe(1);
  const stats = await page.evaluate(() => window.demo.frame(1 / 60));
  expect(stats.facesCaptured).toBe(6);  // six faces, every frame
  expect(stats.tracedReflectors).toBe(0);
  expect(stats.courseFrame).toBe(true);  // drawn by src/course/course_frame.cpp
  // A view that looks inside the frame reads the general renderer's captures: it draws instead.
  await page.evaluate(() => window.demo.setView({ inside: 'faces' }));
  expect((await page.evaluate(() => window.demo.frame(1 / 60))).courseFrame).toBe(false);

  await openDemo(page, '?preset=course&search=hierarchical&paused');
  expect((await page.evaluate(() => window.demo.accuracy())).search).toBe('hierarchical');
  expect((await page.evaluate(() => window.demo.planner())).policy).toBe('every-frame');
});

test('the panel\'s preset switches to the course\'s scheme and back to the defaults', async ({ page }) => {
  await page.setViewportSize(PANEL_OPEN_VIEWPORT);  // a window where the panel starts open
  await openDemo(page, '?paused');
  expect((await page.evaluate(() => window.demo.accuracy())).search).toBe('planned');
  await page.locator('#control-preset select').selectOption('course');
  await idle(page);
  expect((await page.evaluate(() => window.demo.accuracy())).search).toBe('plain');
  expect((await page.evaluate(() => window.demo.planner())).policy).toBe('every-frame');
  await page.locator('#control-preset select').selectOption('default');
  await idle(page);
  expect((await page.evaluate(() => window.demo.accuracy())).search).toBe('planned');
  expect((await page.evaluate(() => window.demo.planner())).policy).toBe('when-changed');
});
