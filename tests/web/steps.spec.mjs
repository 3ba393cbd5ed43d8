// Step through a frame (Inside the frame): the . key and the panel's step control draw the frame
// one step at a time, through the same C++ code as `reflect render --steps` (its images and
// labels are held natively: tests/gl/frame_steps_gl_test.cpp). Here: the page's step count is the
// plan's, its labels are the command line's, the last step is the normal frame, and stepping
// leaves the page idle.
import { test, expect } from '@playwright/test';
import { animationFrames, openDemo, PANEL_OPEN_VIEWPORT, renderAndRead } from './helpers.mjs';

// Steps on (demo.stepFrame) until the last, and copies the canvas in the same task (the drawing
// buffer is gone once the browser has composited it).
async function stepToTheEndAndRead(page) {
  const result = await page.evaluate(() => {
    let reply = window.demo.frameStep();
    while (!reply || reply.step + 1 < reply.count) reply = window.demo.stepFrame();
    const canvas = document.getElementById('canvas');
    const copy = document.createElement('canvas');
    copy.width = canvas.width;
    copy.height = canvas.height;
    copy.getContext('2d').drawImage(canvas, 0, 0);
    const pixels = copy.getContext('2d').getImageData(0, 0, copy.width, copy.height).data;
    return { reply, width: copy.width, height: copy.height, pixels: Array.from(pixels) };
  });
  return { ...result, data: Uint8Array.from(result.pixels) };
}

test('the course\'s frame steps through its six faces and the main pass, and ends on the frame', async ({ page }) => {
  await page.setViewportSize(PANEL_OPEN_VIEWPORT);
  await openDemo(page, '?preset=course&paused');
  const normal = await renderAndRead(page, 1.0);
  // The course captures every face every frame, one pass each (plain lookup: no depths).
  expect(normal.stats.facesCaptured).toBe(6);

  await page.keyboard.press('.');
  const first = await page.evaluate(() => window.demo.frameStep());
  expect(first.step).toBe(0);
  expect(first.count).toBe(normal.stats.facesCaptured + 1);
  expect(first.steps.length).toBe(first.count);
  // The command line's words and numbers (`reflect render --preset course --steps DIR`).
  expect(first.steps[0].label).toBe('colour (pass 1) into the probe of object 4, face +X, layer 1: 3 objects, 12548 triangles');
  expect(first.steps[6].label).toBe('main pass to the screen: 4 objects, 12868 triangles');
  expect(first.steps.map((s) => s.pass)).toEqual([...Array(6).fill('colour'), 'main pass']);
  await expect(page.locator('#step-readout')).toHaveText(`step 1 of 7: ${first.steps[0].label}`);
  expect(await page.evaluate(() => window.demo.paused())).toBe(true);

  // The panel's control is the key's twin.
  await page.locator('#control-frame-step button').click();
  await expect(page.locator('#step-readout')).toHaveText(/^step 2 of 7: colour \(pass 1\) into the probe of object 4, face -X/);

  const last = await stepToTheEndAndRead(page);
  expect(last.reply.step).toBe(6);
  expect([last.width, last.height]).toEqual([normal.width, normal.height]);
  let differing = 0;
  for (let i = 0; i < last.data.length; ++i) differing += last.data[i] !== normal.data[i] ? 1 : 0;
  expect(differing).toBe(0);  // the last step is the normal frame, pixel for pixel
  await expect(page.locator('#step-readout')).toHaveText(/^step 7 of 7: main pass/);

  // Stepping draws only when asked: the paused page stays idle.
  const drawn = await page.evaluate(() => window.demo.framesDrawn());
  await animationFrames(page, 5);
  expect(await page.evaluate(() => window.demo.framesDrawn())).toBe(drawn);
  expect(await page.evaluate(() => window.demo.drawingIdle())).toBe(true);
});

test('running again ends the stepping, and a page that never steps draws nothing new while paused', async ({ page }) => {
  await openDemo(page, '?preset=course&paused');
  await animationFrames(page, 3);
  const drawn = await page.evaluate(() => window.demo.framesDrawn());
  await animationFrames(page, 5);
  expect(await page.evaluate(() => window.demo.framesDrawn())).toBe(drawn);
  await page.keyboard.press('.');
  expect((await page.evaluate(() => window.demo.frameStep())).step).toBe(0);
  await page.keyboard.press(' ');  // run
  await animationFrames(page, 3);
  expect(await page.evaluate(() => window.demo.frameStep())).toBe(null);
});

test('step=N links to a step: the page opens on it paused, and the address bar follows the steps', async ({ page }) => {
  await page.setViewportSize(PANEL_OPEN_VIEWPORT);
  await openDemo(page, '?preset=course&paused&t=1&step=3');
  const shown = await page.evaluate(() => window.demo.frameStep());
  expect(shown.step).toBe(2);
  expect(shown.count).toBe(7);
  await expect(page.locator('#step-readout')).toHaveText(/^step 3 of 7: colour \(pass 1\) into the probe of object 4, face \+Y/);
  await expect(page).toHaveURL(/[?&]step=3(&|$)/);
  await page.keyboard.press('.');
  await expect(page).toHaveURL(/[?&]step=4(&|$)/);
  // A step past the frame's last is its last.
  await openDemo(page, '?preset=course&paused&step=99');
  expect((await page.evaluate(() => window.demo.frameStep())).step).toBe(6);
  await expect(page).toHaveURL(/[?&]step=7(&|$)/);
  // Running again ends the stepping, and the link loses its step.
  await page.keyboard.press(' ');
  await expect(page).not.toHaveURL(/step=/);
});
