// Inside the frame: the faces view replaces the picture with the probe's cube map unfolded
// (its pixels and marks are held natively: tests/gl/faces_view_test.cpp). Here: the link key, the
// panel's folder, the F key, and the message when the frame has no cube map.
import { test, expect } from '@playwright/test';
import { idle, openDemo, PANEL_OPEN_VIEWPORT, pixel, renderAndRead } from './helpers.mjs';

const CROSS_BACKGROUND = [24, 24, 28];  // core/cube_cross.h, kCrossBackground

// Share of the picture's pixels that are the view's background.
function backgroundShare(image) {
  let count = 0;
  for (let i = 0; i < image.data.length; i += 4) {
    if (image.data[i] === 24 && image.data[i + 1] === 24 && image.data[i + 2] === 28) ++count;
  }
  return count / (image.width * image.height);
}

test('?inside=faces shows the course\'s cube map unfolded, and F gives the picture back', async ({ page }) => {
  await page.setViewportSize(PANEL_OPEN_VIEWPORT);
  await openDemo(page, '?preset=course&inside=faces&paused');
  expect((await page.evaluate(() => window.demo.view())).inside).toBe('faces');
  const faces = await renderAndRead(page, 1.0);
  expect(pixel(faces, 2, 2)).toEqual(CROSS_BACKGROUND);
  // The cross's six squares hold the scene (grey wall, blue floor, figures): a large part of the
  // picture, and the rest is the view's background.
  const share = backgroundShare(faces);
  expect(share).toBeGreaterThan(0.3);
  expect(share).toBeLessThan(0.8);
  // The panel's folder holds the view and its channel.
  await expect(page.locator('#control-view-inside select')).toHaveValue('faces');
  await expect(page.locator('#control-view-facesChannel select')).toHaveValue('colour');
  await expect(page.locator('.lil-title', { hasText: 'Inside the frame' })).toHaveCount(1);

  await page.keyboard.press('f');
  await idle(page);
  expect((await page.evaluate(() => window.demo.view())).inside).toBe('off');
  const picture = await renderAndRead(page, 1.0);
  expect(backgroundShare(picture)).toBe(0);
  await expect(page.locator('#control-view-inside select')).toHaveValue('off');
});

test('the faces view says why when the frame has no cube map (the default traces the sphere)', async ({ page }) => {
  await openDemo(page, '?inside=faces&paused');
  const shown = await renderAndRead(page, 1.0);
  expect(shown.stats.tracedReflectors).toBe(1);
  // The message image: the view's background with a few lines of text in its top-left corner.
  expect(backgroundShare(shown)).toBeGreaterThan(0.95);
  expect(pixel(shown, shown.width - 3, shown.height - 3)).toEqual(CROSS_BACKGROUND);
});

test('a channel the probe does not store is refused by name, and the link keeps the channel', async ({ page }) => {
  await openDemo(page, '?preset=course&inside=faces&facesChannel=distance&paused');
  // The course's plain lookup stores no distances: the view shows the message, not stale pixels.
  const shown = await renderAndRead(page, 1.0);
  expect(backgroundShare(shown)).toBeGreaterThan(0.95);
  await expect(page).toHaveURL(/facesChannel=distance/);
  await expect(page).toHaveURL(/inside=faces/);
});
