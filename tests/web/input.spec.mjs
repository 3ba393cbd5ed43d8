// Input: pointer drags (mouse and touch) turn the view by 100 degrees per canvas height, keys
// move and reset the camera, Space pauses.
import { test, expect } from '@playwright/test';
import { animationFrames, openDemo, PANEL_OPEN_VIEWPORT, renderAndRead } from './helpers.mjs';

const camera = (page) => page.evaluate(() => window.demo.camera());

function changedShare(a, b) {
  let changed = 0;
  const n = a.width * a.height;
  for (let i = 0; i < n; ++i) {
    const k = i * 4;
    if (Math.abs(a.data[k] - b.data[k]) + Math.abs(a.data[k + 1] - b.data[k + 1]) +
        Math.abs(a.data[k + 2] - b.data[k + 2]) > 30) ++changed;
  }
  return changed / n;
}

test('a mouse drag turns the view by dx * 100 / clientHeight degrees', async ({ page }) => {
  await openDemo(page, '?paused');
  const before = await renderAndRead(page, 0);
  const clientHeight = await page.evaluate(() => document.getElementById('canvas').clientHeight);
  expect(clientHeight).toBe(600);
  expect(await camera(page)).toEqual({ eye: [0, 1, 7], yaw: 0, pitch: 0 });

  const dx = 150, dy = -48;
  await page.mouse.move(400, 300);
  await page.mouse.down();
  await page.mouse.move(400 + dx / 2, 300 + dy / 2, { steps: 3 });
  await page.mouse.move(400 + dx, 300 + dy, { steps: 3 });
  await page.mouse.up();
  const turned = await camera(page);
  expect(Math.abs(turned.yaw - dx * 100 / clientHeight), `yaw ${turned.yaw}`).toBeLessThan(0.5);
  expect(Math.abs(turned.pitch - dy * 100 / clientHeight), `pitch ${turned.pitch}`).toBeLessThan(0.5);
  expect(turned.eye).toEqual([0, 1, 7]);  // turning does not move

  // Moving the mouse after the button is released turns nothing.
  await page.mouse.move(100, 100, { steps: 2 });
  expect(await camera(page)).toEqual(turned);

  const after = await renderAndRead(page, 0);
  expect(changedShare(before, after), 'share of pixels changed by the turn').toBeGreaterThan(0.1);
});

test('pitch is clamped to +/-89 degrees', async ({ page }) => {
  await openDemo(page, '?paused');
  await page.mouse.move(400, 20);
  await page.mouse.down();
  await page.mouse.move(400, 590, { steps: 4 });  // 570 px = 95 degrees
  await page.mouse.up();
  expect((await camera(page)).pitch).toBeCloseTo(89, 3);
  await page.mouse.move(400, 590);
  await page.mouse.down();
  for (let i = 0; i < 2; ++i) {  // 2 x 570 px up = -190 degrees
    await page.mouse.move(400, 20, { steps: 4 });
    await page.mouse.up();
    await page.mouse.move(400, 590);
    await page.mouse.down();
  }
  await page.mouse.up();
  expect((await camera(page)).pitch).toBeCloseTo(-89, 3);
});

test.describe('touch', () => {
  test.use({ hasTouch: true });

  test('a one-finger touch drag turns the view', async ({ page }) => {
    await openDemo(page, '?paused');
    await page.evaluate(() => {
      window.__pointerTypes = new Set();
      document.getElementById('canvas').addEventListener('pointermove', (e) => window.__pointerTypes.add(e.pointerType));
    });
    const before = await renderAndRead(page, 0);
    const cdp = await page.context().newCDPSession(page);
    const touch = (type, x, y) => cdp.send('Input.dispatchTouchEvent', {
      type, touchPoints: type === 'touchEnd' ? [] : [{ x, y, id: 1 }],
    });
    const dx = -120, y = 320;
    await touch('touchStart', 500, y);
    for (let i = 1; i <= 6; ++i) await touch('touchMove', 500 + (dx * i) / 6, y);
    await touch('touchEnd');
    await cdp.detach();

    expect([...await page.evaluate(() => [...window.__pointerTypes])]).toEqual(['touch']);
    const turned = await camera(page);
    expect(Math.abs(turned.yaw - dx * 100 / 600), `yaw ${turned.yaw}`).toBeLessThan(0.5);
    expect(Math.abs(turned.pitch)).toBeLessThan(0.5);
    // The page did not scroll or zoom instead (touch-action: none).
    expect(await page.evaluate(() => [window.scrollX, window.scrollY, window.visualViewport.scale]))
      .toEqual([0, 0, 1]);
    const after = await renderAndRead(page, 0);
    expect(changedShare(before, after)).toBeGreaterThan(0.1);
  });
});

test('W / ArrowUp move forward 0.1, S / ArrowDown back, R resets the camera', async ({ page }) => {
  await openDemo(page, '?paused');
  await page.locator('#canvas').focus();
  for (let i = 0; i < 3; ++i) await page.keyboard.press('w');
  let c = await camera(page);
  expect(c.eye[0]).toBeCloseTo(0, 5);
  expect(c.eye[1]).toBeCloseTo(1, 5);
  expect(c.eye[2]).toBeCloseTo(6.7, 4);
  await page.keyboard.press('ArrowUp');
  expect((await camera(page)).eye[2]).toBeCloseTo(6.6, 4);
  await page.keyboard.press('s');
  await page.keyboard.press('ArrowDown');
  await page.keyboard.press('ArrowDown');
  expect((await camera(page)).eye[2]).toBeCloseTo(6.9, 4);
  await page.keyboard.press('Shift+W');  // caps: still forward
  expect((await camera(page)).eye[2]).toBeCloseTo(6.8, 4);

  // Turned 90 degrees to the left (drag right: yaw +90), forward is -X.
  await page.mouse.move(100, 300);
  await page.mouse.down();
  await page.mouse.move(100 + 540, 300, { steps: 4 });  // 540 px = 90 degrees
  await page.mouse.up();
  expect((await camera(page)).yaw).toBeCloseTo(90, 3);
  await page.keyboard.press('w');
  c = await camera(page);
  expect(c.eye[0]).toBeCloseTo(-0.1, 4);
  expect(c.eye[2]).toBeCloseTo(6.8, 4);

  // Browser shortcuts are left alone: Ctrl+R / Ctrl+S neither reset nor move, nor are prevented.
  await page.evaluate(() => {
    window.__prevented = [];
    window.addEventListener('keydown', (e) => window.__prevented.push(e.defaultPrevented));
  });
  await page.keyboard.press('Control+r');
  await page.keyboard.press('Control+s');
  expect(await camera(page)).toEqual(c);
  expect(await page.evaluate(() => window.__prevented)).toEqual([false, false, false, false]);

  await page.keyboard.press('r');
  expect(await camera(page)).toEqual({ eye: [0, 1, 7], yaw: 0, pitch: 0 });
});

test('Space toggles pause', async ({ page }) => {
  await openDemo(page, '?paused&t=1');
  await page.locator('#canvas').focus();
  await animationFrames(page, 10);
  expect((await page.evaluate(() => window.demo.stats())).time).toBe(1);
  await page.keyboard.press(' ');
  await expect.poll(async () => (await page.evaluate(() => window.demo.stats())).time).toBeGreaterThan(1.05);
  await expect(page.locator('#stats')).not.toContainText('paused');
  await page.keyboard.press(' ');
  await expect(page.locator('#stats')).toContainText('paused');
  const t = (await page.evaluate(() => window.demo.stats())).time;
  await animationFrames(page, 10);
  expect((await page.evaluate(() => window.demo.stats())).time).toBe(t);
});

test('A / D strafe and Q / E go down / up by 0.1, also when turned', async ({ page }) => {
  await openDemo(page, '?paused');
  await page.locator('#canvas').focus();
  await page.keyboard.press('d');
  await page.keyboard.press('d');
  let c = await camera(page);
  expect(c.eye[0]).toBeCloseTo(0.2, 4);
  expect(c.eye[1]).toBeCloseTo(1, 4);
  expect(c.eye[2]).toBeCloseTo(7, 4);
  await page.keyboard.press('a');
  await page.keyboard.press('ArrowLeft');
  await page.keyboard.press('ArrowLeft');
  expect((await camera(page)).eye[0]).toBeCloseTo(-0.1, 4);
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('e');
  await page.keyboard.press('e');
  await page.keyboard.press('q');
  c = await camera(page);
  expect(c.eye[0]).toBeCloseTo(0, 4);
  expect(c.eye[1]).toBeCloseTo(1.1, 4);
  expect([c.yaw, c.pitch]).toEqual([0, 0]);  // moving does not turn

  // Turned 90 degrees left (looking down -X), right is -Z; looking down 30 degrees, strafing
  // stays level.
  await page.evaluate(() => window.demo.setCamera(0, 1, 7, 90, -30));
  await page.keyboard.press('d');
  c = await camera(page);
  expect(c.eye[0]).toBeCloseTo(0, 4);
  expect(c.eye[1]).toBeCloseTo(1, 4);
  expect(c.eye[2]).toBeCloseTo(6.9, 4);
  expect(c.yaw).toBeCloseTo(90, 3);
  expect(c.pitch).toBeCloseTo(-30, 3);
});

test.describe('with the panel open', () => {
  test.use({ viewport: PANEL_OPEN_VIEWPORT });

  test('keys typed into a panel field move nothing', async ({ page }) => {
    await openDemo(page, '?paused');
    const field = page.locator('#control-captureLod input');
    await field.focus();
    for (const key of ['w', 'a', 's', 'd', 'q', 'e', 'r', ' ', 'ArrowUp']) await field.press(key);
    expect(await camera(page)).toEqual({ eye: [0, 1, 7], yaw: 0, pitch: 0 });
    expect(await page.evaluate(() => window.demo.paused())).toBe(true);
    await expect(page.locator('#help-overlay')).toBeHidden();
    await page.locator('#control-policy select').focus();
    await page.keyboard.press('w');
    expect(await camera(page)).toEqual({ eye: [0, 1, 7], yaw: 0, pitch: 0 });
  });
});

test('the mouse wheel moves along the view, and does not scroll the page', async ({ page }) => {
  await openDemo(page, '?paused');
  await page.mouse.move(300, 300);
  await page.mouse.wheel(0, -100);  // one notch away from the user: forward one step
  await expect.poll(async () => (await camera(page)).eye[2]).toBeCloseTo(6.9, 4);
  await page.mouse.wheel(0, -300);
  await expect.poll(async () => (await camera(page)).eye[2]).toBeCloseTo(6.6, 4);
  await page.mouse.wheel(0, 200);
  await expect.poll(async () => (await camera(page)).eye[2]).toBeCloseTo(6.8, 4);
  expect(await page.evaluate(() => [window.scrollX, window.scrollY])).toEqual([0, 0]);
});

test.describe('touch pinch', () => {
  test.use({ hasTouch: true });

  test('spreading two fingers moves forward, pinching them moves back; no turn', async ({ page }) => {
    await openDemo(page, '?paused');
    const cdp = await page.context().newCDPSession(page);
    const touch = (type, points) => cdp.send('Input.dispatchTouchEvent', {
      type, touchPoints: points.map(([x, y], i) => ({ x, y, id: i + 1 })),
    });
    // 100 px apart -> 200 px apart: 100 px / 20 px a step = 5 steps of 0.1.
    await touch('touchStart', [[250, 300], [350, 300]]);
    for (let i = 1; i <= 5; ++i) await touch('touchMove', [[250 - 10 * i, 300], [350 + 10 * i, 300]]);
    await touch('touchEnd', []);
    let c = await camera(page);
    expect(c.eye[2]).toBeCloseTo(6.5, 3);
    expect([c.yaw, c.pitch]).toEqual([0, 0]);
    await touch('touchStart', [[200, 300], [400, 300]]);
    for (let i = 1; i <= 4; ++i) await touch('touchMove', [[200 + 10 * i, 300], [400 - 10 * i, 300]]);
    await touch('touchEnd', []);
    await cdp.detach();
    c = await camera(page);
    expect(c.eye[2]).toBeCloseTo(6.9, 3);
    expect([c.yaw, c.pitch]).toEqual([0, 0]);
  });
});
