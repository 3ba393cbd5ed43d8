// The page on a phone and in small and large windows: the course's three figures in the frame
// (the camera keeps its field of view along the canvas's narrower side), the live numbers, the
// panel's title bar and the hint line apart, the open panel beside or below the scene and never
// over it, hints for the device (touch or keys), and touch gestures turning and sliding the view.
import { test, expect } from '@playwright/test';
import { openDemo, renderAndRead, waitForCanvasSize } from './helpers.mjs';

const FIGURES = ['sphere.obj', 'mario.obj', 'sonic.obj'];
const PHONE = { viewport: { width: 390, height: 844 }, deviceScaleFactor: 2, hasTouch: true, isMobile: true };

// Boxes (CSS px, { left, top, right, bottom }) of what is on screen: the numbers (#hud), the
// panel's title bar, the hint line, the canvas and the panel; null for what is not shown.
function layout(page) {
  return page.evaluate(() => {
    const box = (selector) => {
      const e = document.querySelector(selector);
      if (!e || !e.getClientRects().length) return null;
      const r = e.getBoundingClientRect();
      return { left: r.left, top: r.top, right: r.right, bottom: r.bottom };
    };
    return {
      stats: box('#hud'), header: box('#panel > .lil-title'), help: box('#help'), canvas: box('#canvas'),
      panel: box('#panel'), panelOpen: !window.demo.panel()._closed,
      window: { width: innerWidth, height: innerHeight },
    };
  });
}

const overlapArea = (a, b) => Math.max(0, Math.min(a.right, b.right) - Math.max(a.left, b.left)) *
                              Math.max(0, Math.min(a.bottom, b.bottom) - Math.max(a.top, b.top));

// The figures' boxes on the canvas from the C++ side (demo.objects()[i].screen: the bounding box
// projected by the camera, in fractions of the canvas), and in CSS px.
async function figureBoxes(page) {
  const [objects, canvas] = await Promise.all([
    page.evaluate(() => window.demo.objects()), layout(page).then((l) => l.canvas),
  ]);
  return FIGURES.map((mesh) => {
    const s = objects.find((o) => o.mesh === mesh).screen;
    const w = canvas.right - canvas.left, h = canvas.bottom - canvas.top;
    return { mesh, ...s, css: { left: canvas.left + s.x0 * w, right: canvas.left + s.x1 * w,
                                top: canvas.top + s.y0 * h, bottom: canvas.top + s.y1 * h } };
  });
}

// Every check of the layout at one size and panel state: the three figures inside the canvas,
// the numbers, the panel's title bar and the hint line apart, all of them inside the window, and
// an open panel neither over the canvas's centre nor over any figure.
async function expectGoodLayout(page, label) {
  await waitForCanvasSize(page);
  const l = await layout(page);
  const shown = { stats: l.stats, 'panel header': l.header, 'hint line': l.help };
  for (const [name, box] of Object.entries(shown)) {
    expect(box, `${label}: ${name} shown`).not.toBeNull();
    expect(box.left, `${label}: ${name} left`).toBeGreaterThanOrEqual(0);
    expect(box.top, `${label}: ${name} top`).toBeGreaterThanOrEqual(0);
    expect(box.right, `${label}: ${name} right`).toBeLessThanOrEqual(l.window.width + 0.5);
    expect(box.bottom, `${label}: ${name} bottom`).toBeLessThanOrEqual(l.window.height + 0.5);
  }
  const names = Object.keys(shown);
  for (let i = 0; i < names.length; ++i) {
    for (let j = i + 1; j < names.length; ++j) {
      expect(overlapArea(shown[names[i]], shown[names[j]]), `${label}: ${names[i]} and ${names[j]} overlap`).toBe(0);
    }
  }
  for (const f of await figureBoxes(page)) {
    expect(f.inFront, `${label}: ${f.mesh} in front of the eye`).toBe(true);
    expect(f.x0, `${label}: ${f.mesh} left edge`).toBeGreaterThanOrEqual(0);
    expect(f.y0, `${label}: ${f.mesh} top edge`).toBeGreaterThanOrEqual(0);
    expect(f.x1, `${label}: ${f.mesh} right edge`).toBeLessThanOrEqual(1);
    expect(f.y1, `${label}: ${f.mesh} bottom edge`).toBeLessThanOrEqual(1);
    if (l.panelOpen) expect(overlapArea(f.css, l.panel), `${label}: the open panel over ${f.mesh}`).toBe(0);
  }
  if (l.panelOpen) {
    const centre = { left: (l.canvas.left + l.canvas.right) / 2, top: (l.canvas.top + l.canvas.bottom) / 2 };
    const under = centre.left >= l.panel.left && centre.left <= l.panel.right &&
                  centre.top >= l.panel.top && centre.top <= l.panel.bottom;
    expect(under, `${label}: the canvas's centre under the open panel`).toBe(false);
  }
  return l;
}

// The help overlay's rows for each kind of input (data-input) shown or hidden as `shown` says.
async function expectRows(overlay, shown) {
  for (const [kind, visible] of Object.entries(shown)) {
    const rows = overlay.locator(`tr[data-input="${kind}"]`);
    expect(await rows.count(), `rows for ${kind}`).toBeGreaterThan(0);
    for (const row of await rows.all()) {
      if (visible) await expect(row, `a ${kind} row`).toBeVisible();
      else await expect(row, `a ${kind} row`).toBeHidden();
    }
  }
}

// Waits until the panel has finished opening or closing (lil-gui animates the height of its
// controls after a click on the title bar, marking the panel lil-transition meanwhile).
async function panelSettled(page, open) {
  await expect.poll(() => page.evaluate(() => {
    const panel = document.getElementById('panel');
    return { open: !panel.classList.contains('lil-closed'), moving: panel.classList.contains('lil-transition') };
  })).toEqual({ open, moving: false });
  return waitForCanvasSize(page);
}

// Opens or closes the panel (as its title bar does) and waits for the canvas to follow.
async function setPanel(page, open) {
  await page.evaluate((o) => window.demo.panel().open(o), open);
  return waitForCanvasSize(page);
}

// Touch points through the DevTools protocol, as a finger would (pointer events of type touch).
async function touchSession(page) {
  const cdp = await page.context().newCDPSession(page);
  return {
    touch: (type, points) => cdp.send('Input.dispatchTouchEvent', {
      type, touchPoints: points.map(([x, y], i) => ({ x, y, id: i + 1 })),
    }),
    detach: () => cdp.detach(),
  };
}

// Pixels of the red and the green figure (mario 1, 0.4, 0.4; sonic 0.4, 1, 0.4) outside the
// sphere's box (its reflections of them are inside): their bounding boxes in drawing-buffer
// pixels, and how many.
function figurePixels(image, sphere) {
  const { width, height, data } = image;
  const found = { red: { n: 0, x0: width, y0: height, x1: -1, y1: -1 }, green: { n: 0, x0: width, y0: height, x1: -1, y1: -1 } };
  for (let y = 0; y < height; ++y) {
    for (let x = 0; x < width; ++x) {
      if (x >= sphere.x0 * width && x <= sphere.x1 * width && y >= sphere.y0 * height && y <= sphere.y1 * height) continue;
      const i = (y * width + x) * 4;
      const [r, g, b] = [data[i], data[i + 1], data[i + 2]];
      const kind = r - g >= 30 && r - b >= 30 ? 'red' : g - r >= 30 && g - b >= 30 ? 'green' : null;
      if (!kind) continue;
      const k = found[kind];
      ++k.n;
      k.x0 = Math.min(k.x0, x); k.x1 = Math.max(k.x1, x);
      k.y0 = Math.min(k.y0, y); k.y1 = Math.max(k.y1, y);
    }
  }
  return found;
}

// The phone's settings for each block of phone tests.
function usePhone() {
  test.use(PHONE);
  // Every display frame draws 780x1688 pixels (four times the other tests' canvas) in SwiftShader,
  // and each step waits for the page between frames: more than the default minute on a busy
  // machine. (A limit on the test, not a check of how long anything takes.)
  test.describe.configure({ timeout: 180_000 });
}

test.describe('on a phone (390x844, devicePixelRatio 2, touch): the frame and the panel', () => {
  usePhone();

  test('the three figures are in the frame, on the canvas as the C++ boxes say', async ({ page }) => {
    await openDemo(page, '?paused');
    const size = await waitForCanvasSize(page);
    expect(size).toMatchObject({ dpr: 2, width: size.clientWidth * 2, height: size.clientHeight * 2 });
    expect(size.clientWidth).toBe(390);
    expect(await page.evaluate(() => window.demo.panel()._closed)).toBe(true);  // below 1000 px
    await expectGoodLayout(page, 'phone, panel closed');
    // The picture agrees: mario's and sonic's pixels lie inside their boxes, and mario's stop
    // short of the right edge (with 70 degrees vertically he was cut off there).
    const image = await renderAndRead(page, 0);
    const boxes = Object.fromEntries((await figureBoxes(page)).map((f) => [f.mesh, f]));
    const pixels = figurePixels(image, boxes['sphere.obj']);
    for (const [kind, mesh] of [['red', 'mario.obj'], ['green', 'sonic.obj']]) {
      const p = pixels[kind], b = boxes[mesh];
      expect(p.n, `${mesh}: pixels of its colour`).toBeGreaterThan(2000);
      expect(p.x0, `${mesh}: left`).toBeGreaterThanOrEqual(Math.floor(b.x0 * image.width) - 1);
      expect(p.x1, `${mesh}: right`).toBeLessThanOrEqual(Math.ceil(b.x1 * image.width) + 1);
      expect(p.y0, `${mesh}: top`).toBeGreaterThanOrEqual(Math.floor(b.y0 * image.height) - 1);
      expect(p.y1, `${mesh}: bottom`).toBeLessThanOrEqual(Math.ceil(b.y1 * image.height) + 1);
    }
    expect(pixels.red.x1, 'mario inside the right edge').toBeLessThan(image.width - 1);
    expect(pixels.green.x0, 'sonic inside the left edge').toBeGreaterThan(0);
    // The horizontal field of view is the course's 70 degrees: the sphere (radius 1.2728 at
    // 7 units) spans what it spans on a square canvas of the same width.
    const sphere = boxes['sphere.obj'];
    expect(sphere.x1 - sphere.x0).toBeCloseTo(0.3174, 3);
  });

  test('the open panel is a sheet below the scene: the figures stay in the frame above it', async ({ page }) => {
    await openDemo(page, '?paused');
    const closed = await layout(page);
    await page.locator('#panel > .lil-title').tap();
    await panelSettled(page, true);
    const open = await expectGoodLayout(page, 'phone, panel open');
    expect(open.canvas.bottom).toBeLessThan(closed.canvas.bottom - 200);
    expect(open.panel.top).toBeGreaterThanOrEqual(open.canvas.bottom - 0.5);
    expect(open.panel.bottom).toBeLessThanOrEqual(844.5);
    expect(open.panel.top).toBeLessThanOrEqual(844 / 2 + 1);  // at most half the height
    // Its controls scroll inside it: the last folder can be reached.
    await page.locator('#control-help').scrollIntoViewIfNeeded();
    await expect(page.locator('#control-help button')).toBeInViewport();
    await page.locator('#panel > .lil-title').tap();
    await panelSettled(page, false);
    expect((await expectGoodLayout(page, 'phone, panel closed again')).canvas).toEqual(closed.canvas);
  });
});

test.describe('on a phone (390x844, devicePixelRatio 2, touch): touch', () => {
  usePhone();

  test('the hints name touch, here and in the help overlay', async ({ page }) => {
    await openDemo(page, '?paused');
    const help = page.locator('#help');
    await expect(help).toContainText('touch');
    await expect(help).toContainText('pinch');
    await expect(help).toContainText('two-finger drag');
    await expect(help).not.toContainText('W/A/S/D');
    await expect(page.locator('#canvas')).toHaveAttribute('aria-label', /pinch/);
    await page.locator('#panel > .lil-title').tap();
    await panelSettled(page, true);
    await expect(page.locator('#control-help .lil-name')).toHaveText('touch gestures');
    await page.locator('#control-help button').tap();
    const overlay = page.locator('#help-overlay');
    await expect(overlay).toBeVisible();
    await expect(page.locator('#help-title')).toHaveText('Touch');
    await expectRows(overlay, { keys: false, touch: true, 'touch-only': true });
    await expect(overlay).toContainText('two-finger drag');
  });

  test('a one-finger drag turns the view; two fingers dragged together slide it', async ({ page }) => {
    await openDemo(page, '?paused');
    const height = await page.evaluate(() => document.getElementById('canvas').clientHeight);
    const { touch, detach } = await touchSession(page);
    const dx = -150, y = 400;
    await touch('touchStart', [[300, y]]);
    for (let i = 1; i <= 5; ++i) await touch('touchMove', [[300 + (dx * i) / 5, y]]);
    await touch('touchEnd', []);
    let camera = await page.evaluate(() => window.demo.camera());
    expect(Math.abs(camera.yaw - dx * 100 / height), `yaw ${camera.yaw}`).toBeLessThan(0.5);
    expect(camera.eye).toEqual([0, 1, 7]);

    await page.evaluate(() => window.demo.setCamera(0, 1, 7, 0, 0));
    // Both fingers 100 px to the right: the scene follows them, the eye goes 10 steps (1.0) left.
    await touch('touchStart', [[100, 400], [250, 400]]);
    for (let i = 1; i <= 5; ++i) await touch('touchMove', [[100 + 20 * i, 400], [250 + 20 * i, 400]]);
    // Then 50 px up: the eye goes 0.5 down.
    for (let i = 1; i <= 5; ++i) await touch('touchMove', [[200, 400 - 10 * i], [350, 400 - 10 * i]]);
    await touch('touchEnd', []);
    await detach();
    camera = await page.evaluate(() => window.demo.camera());
    expect(camera.eye[0]).toBeCloseTo(-1, 3);
    expect(camera.eye[1]).toBeCloseTo(0.5, 3);
    expect(camera.eye[2]).toBeCloseTo(7, 3);  // the fingers kept their distance: no move along the view
    expect([camera.yaw, camera.pitch]).toEqual([0, 0]);
  });
});

test.describe('in an 800x800 window', () => {
  test.use({ viewport: { width: 800, height: 800 } });

  test('the panel starts closed; opened, it takes a column beside the scene; hints name keys', async ({ page }) => {
    await openDemo(page, '?paused');
    await expect(page.locator('#help')).toContainText('W/A/S/D');
    await expect(page.locator('#help')).not.toContainText('pinch');
    const closed = await expectGoodLayout(page, '800x800, panel closed');
    expect(closed.panelOpen).toBe(false);
    expect(closed.canvas).toEqual({ left: 0, top: 0, right: 800, bottom: 800 });
    await page.locator('#panel > .lil-title').click();
    await panelSettled(page, true);
    const open = await expectGoodLayout(page, '800x800, panel open');
    expect(open.canvas).toEqual({ left: 0, top: 0, right: 540, bottom: 800 });
    expect(overlapArea(open.canvas, open.panel)).toBe(0);
    // After a drag the mirror is still in view: nothing covers the canvas.
    await page.mouse.move(270, 400);
    await page.mouse.down();
    await page.mouse.move(370, 400, { steps: 4 });
    await page.mouse.up();
    expect((await page.evaluate(() => window.demo.camera())).yaw).toBeCloseTo(12.5, 1);
    const sphere = (await figureBoxes(page))[0];
    expect(sphere.inFront).toBe(true);
    expect(sphere.x1).toBeLessThanOrEqual(1);
    expect(overlapArea(sphere.css, open.panel)).toBe(0);
    const overlay = page.locator('#help-overlay');
    await page.locator('#control-help button').click();
    await expect(page.locator('#help-title')).toHaveText('Keys and mouse');
    await expectRows(overlay, { keys: true, touch: false, 'touch-only': false });
    await expect(overlay.locator('tr', { hasText: 'Q, E' })).toBeVisible();
  });
});

test.describe('in a 1920x1080 window', () => {
  test.use({ viewport: { width: 1920, height: 1080 } });

  test('the panel starts open beside the scene; the figures are in the frame; hints name keys', async ({ page }) => {
    await openDemo(page, '?paused');
    await expect(page.locator('#help')).toContainText('W/A/S/D');
    const open = await expectGoodLayout(page, '1920x1080, panel open');
    expect(open.panelOpen).toBe(true);
    expect(open.canvas).toEqual({ left: 0, top: 0, right: 1660, bottom: 1080 });
    expect(overlapArea(open.canvas, open.panel)).toBe(0);
    await setPanel(page, false);
    await expectGoodLayout(page, '1920x1080, panel closed');
  });
});

// From 320x480 up, in both panel states: nothing of the three overlaps, and the open panel is
// never over the scene.
test('every size from 320x480 up keeps the numbers, the panel and the hints apart', async ({ page }) => {
  test.setTimeout(240_000);
  await openDemo(page, '?paused');
  // The smallest, a phone, both sides of the column layout's 640 px and of the open panel's 1000
  // px, and a laptop.
  const sizes = [[320, 480], [390, 844], [639, 480], [640, 480], [999, 700], [1000, 700], [1366, 768]];
  for (const [width, height] of sizes) {
    await page.setViewportSize({ width, height });
    for (const open of [false, true]) {
      await setPanel(page, open);
      await expectGoodLayout(page, `${width}x${height}, panel ${open ? 'open' : 'closed'}`);
    }
  }
});
