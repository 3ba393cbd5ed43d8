// Shared helpers for the browser tests: opening the demo, reading rendered pixels, the sphere's
// expected place on screen (from the camera numbers), and measuring the gold sphere in a picture.
import { expect } from '@playwright/test';
import { decodePng } from './png.mjs';

// The scene's fixed numbers (src/core/scene.cpp, camera settings).
export const SCENE = {
  eye: [0, 1, 7],
  fovYDeg: 70,
  sphereCentre: [0, 0.25, 0],
  sphereRadius: 1.2728,
  background: [102, 102, 102],
};

// A window in which the panel starts open (the page opens it from 1000 CSS px of width) with the
// canvas beside it at the tests' usual 800x600 (the panel's column is 260 px): for tests that
// use the panel's controls.
export const PANEL_OPEN_VIEWPORT = { width: 1060, height: 600 };

// Records console errors and uncaught page errors from the moment it is called.
export function collectErrors(page) {
  const errors = [];
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(`console.error: ${message.text()}`);
  });
  page.on('pageerror', (error) => errors.push(`pageerror: ${error.message}`));
  return errors;
}

// Opens the page with `query` and waits for demo.ready to resolve (the first frame is drawn), then
// for the levels of detail, which the page builds after it (demo.lodReady()): every picture a test
// takes afterwards is of the scene as it stays.
export async function openDemo(page, query = '?paused') {
  await page.goto(query);
  await page.waitForFunction(() => window.demo !== undefined);
  await page.evaluate(() => window.demo.ready);
  await page.evaluate(() => window.demo.lodReady());
}

// Resolves after the page's display has ticked `count` times (requestAnimationFrame): a check
// that nothing happened waits for the frames the page would have drawn in, not for a time.
export async function animationFrames(page, count) {
  await page.evaluate((n) => new Promise((resolve) => {
    let seen = 0;
    const tick = () => (++seen >= n ? resolve() : requestAnimationFrame(tick));
    requestAnimationFrame(tick);
  }), count);
}

// Resolves once the page's job queue (scene loads, model changes, the bench) is empty.
export async function idle(page) {
  await page.evaluate(() => window.demo.idle());
}

// Every message the page has shown ([{ text, kind }]), also those that have gone by themselves.
export function messages(page) {
  return page.evaluate(() => window.demo.messages());
}

// Waits until the page has shown a message containing `text` (of `kind`, when given): from the
// message history, so a message that removes itself after a few seconds is not missed.
export async function expectMessage(page, text, kind = null) {
  await expect.poll(async () => (await messages(page))
    .some((m) => m.text.includes(text) && (!kind || m.kind === kind)), { message: `a message with "${text}"` })
    .toBe(true);
}

// The settled outcome of demo.ready: 'resolved' or 'rejected: <message>'.
export async function readyOutcome(page) {
  await page.waitForFunction(() => window.demo !== undefined);
  return page.evaluate(() => window.demo.ready.then(() => 'resolved', (e) => `rejected: ${e && e.message}`));
}

// Renders one frame (optionally at scene time `t`) and reads the WebGL canvas back in the same
// task (preserveDrawingBuffer is false, so the pixels are only valid until the task ends).
// Returns { width, height, data: RGBA Uint8Array, stats }.
export async function renderAndRead(page, t) {
  const result = await page.evaluate(async (time) => {
    await window.demo.lodReady();  // the scene as it stays, not its first frames
    if (time !== undefined && time !== null) window.demo.setTime(time);
    const stats = window.demo.frame(0);
    const canvas = document.getElementById('canvas');
    const copy = document.createElement('canvas');
    copy.width = canvas.width;
    copy.height = canvas.height;
    const context = copy.getContext('2d');
    context.drawImage(canvas, 0, 0);
    const pixels = context.getImageData(0, 0, copy.width, copy.height).data;
    let binary = '';
    for (let i = 0; i < pixels.length; i += 0x8000) {
      binary += String.fromCharCode.apply(null, pixels.subarray(i, i + 0x8000));
    }
    return { width: copy.width, height: copy.height, base64: btoa(binary), stats };
  }, t);
  const data = new Uint8Array(Buffer.from(result.base64, 'base64'));
  return { width: result.width, height: result.height, data, stats: result.stats };
}

// The page's overlays (panel, numbers, messages, help, bench table): hidden for canvas screenshots.
export const OVERLAYS = '#panel, #left, #help, #help-overlay, #bench-box, #drop-hint';

// A PNG screenshot of the canvas element (without the overlays drawn over it), decoded.
export async function canvasScreenshot(page) {
  return decodePng(await page.locator('#canvas').screenshot({ style: `${OVERLAYS} { visibility: hidden !important; }` }));
}

export function pixel(image, x, y) {
  const i = (y * image.width + x) * 4;
  return [image.data[i], image.data[i + 1], image.data[i + 2]];
}

// Number of distinct RGB colours and the fraction of background-grey pixels.
export function colourSummary(image) {
  const colours = new Set();
  let grey = 0;
  const n = image.width * image.height;
  for (let i = 0; i < n; ++i) {
    const r = image.data[i * 4], g = image.data[i * 4 + 1], b = image.data[i * 4 + 2];
    colours.add((r << 16) | (g << 8) | b);
    if (Math.abs(r - 102) <= 1 && Math.abs(g - 102) <= 1 && Math.abs(b - 102) <= 1) ++grey;
  }
  return { distinct: colours.size, greyFraction: grey / n };
}

// tan of half the vertical field of view on a width x height picture: the camera keeps its 70
// degrees along the narrower side (LookCamera::fovYDeg), so a portrait picture has 70 across.
export function tanHalfFovY(width, height) {
  const tanHalf = Math.tan((SCENE.fovYDeg / 2) * Math.PI / 180);
  return width >= height ? tanHalf : tanHalf * height / width;
}

// Whether the eye ray through pixel (x, y) of a width x height picture passes within
// radiusScale * radius of the sphere's centre (camera at its reset pose: yaw 0, pitch 0).
export function makeSphereTest(width, height, { eye = SCENE.eye, radiusScale = 1 } = {}) {
  const tanHalf = tanHalfFovY(width, height);
  const aspect = width / height;
  const c = SCENE.sphereCentre.map((v, i) => v - eye[i]);
  const r = SCENE.sphereRadius * radiusScale;
  return (x, y) => {
    const d = [((2 * (x + 0.5)) / width - 1) * tanHalf * aspect, (1 - (2 * (y + 0.5)) / height) * tanHalf, -1];
    const dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    const cd = c[0] * d[0] + c[1] * d[1] + c[2] * d[2];
    const cc = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    return cd > 0 && cc - (cd * cd) / dd < r * r;  // squared distance from the centre to the ray
  };
}

// The pixel box { x0, y0, x1, y1 } (inclusive) that the sphere covers, from the camera numbers.
export function expectedSphereBox(width, height, options) {
  const inside = makeSphereTest(width, height, options);
  let x0 = width, y0 = height, x1 = -1, y1 = -1;
  for (let y = 0; y < height; ++y) {
    for (let x = 0; x < width; ++x) {
      if (!inside(x, y)) continue;
      if (x < x0) x0 = x;
      if (x > x1) x1 = x;
      if (y < y0) y0 = y;
      if (y > y1) y1 = y;
    }
  }
  return { x0, y0, x1, y1, cx: (x0 + x1) / 2, cy: (y0 + y1) / 2 };
}

// Pixels of two same-sized images, within `box` (default: all of them), whose colour differs in
// some channel by more than `threshold` levels.
export function countChanged(a, b, threshold, box = { x0: 0, y0: 0, x1: a.width - 1, y1: a.height - 1 }) {
  let n = 0;
  for (let y = box.y0; y <= box.y1; ++y) {
    for (let x = box.x0; x <= box.x1; ++x) {
      const i = (y * a.width + x) * 4;
      const differs = (k) => Math.abs(a.data[i + k] - b.data[i + k]) > threshold;
      if (differs(0) || differs(1) || differs(2)) ++n;
    }
  }
  return n;
}

// Pixels inside the sphere's expected box whose colour differs by more than 8 levels.
export function changedInSphere(a, b) {
  return countChanged(a, b, 8, expectedSphereBox(a.width, a.height));
}

// Gold-sphere pixels: shading is 0.78 * reflection + 0.3 * (0.95, 0.85, 0.4), so wherever the
// sphere reflects the grey background or the blue ground (both have red == green) its red exceeds
// its green by 0.3 * 0.1 * 255 = 7.65 levels. The ground and the background have red == green;
// the red figure has red - green >= 30; the green figure has green > red.
export function isGold([r, g, b]) {
  const d = r - g;
  return d >= 4 && d <= 12 && r > 60;
}

// Measures the gold sphere: flood-fills gold pixels from the one nearest the expected centre
// (within a window around the expected box) and returns the filled region's box and size.
export function measureGoldSphere(image, expected) {
  const { width, height } = image;
  const span = Math.max(expected.x1 - expected.x0, expected.y1 - expected.y0);
  const wx0 = Math.max(0, Math.floor(expected.x0 - span * 0.6));
  const wx1 = Math.min(width - 1, Math.ceil(expected.x1 + span * 0.6));
  const wy0 = Math.max(0, Math.floor(expected.y0 - span * 0.6));
  const wy1 = Math.min(height - 1, Math.ceil(expected.y1 + span * 0.6));
  const gold = (x, y) => isGold(pixel(image, x, y));

  // Seed: the gold pixel nearest the expected centre.
  let seed = null;
  for (let radius = 0; radius < span / 2 && !seed; ++radius) {
    for (let dy = -radius; dy <= radius && !seed; ++dy) {
      for (let dx = -radius; dx <= radius && !seed; ++dx) {
        const x = Math.round(expected.cx) + dx, y = Math.round(expected.cy) + dy;
        if (x >= wx0 && x <= wx1 && y >= wy0 && y <= wy1 && gold(x, y)) seed = [x, y];
      }
    }
  }
  if (!seed) return null;

  const seen = new Uint8Array(width * height);
  const stack = [seed];
  seen[seed[1] * width + seed[0]] = 1;
  let x0 = seed[0], x1 = seed[0], y0 = seed[1], y1 = seed[1], count = 0;
  while (stack.length) {
    const [x, y] = stack.pop();
    ++count;
    if (x < x0) x0 = x;
    if (x > x1) x1 = x;
    if (y < y0) y0 = y;
    if (y > y1) y1 = y;
    for (const [nx, ny] of [[x + 1, y], [x - 1, y], [x, y + 1], [x, y - 1]]) {
      if (nx < wx0 || nx > wx1 || ny < wy0 || ny > wy1) continue;
      const k = ny * width + nx;
      if (seen[k] || !gold(nx, ny)) continue;
      seen[k] = 1;
      stack.push([nx, ny]);
    }
  }
  return { x0, y0, x1, y1, width: x1 - x0 + 1, height: y1 - y0 + 1, count };
}

// Waits until the canvas drawing buffer matches its CSS size times devicePixelRatio.
export async function waitForCanvasSize(page) {
  await expect.poll(() => page.evaluate(() => {
    const c = document.getElementById('canvas');
    const dpr = window.devicePixelRatio;
    return c.width === Math.round(c.clientWidth * dpr) && c.height === Math.round(c.clientHeight * dpr);
  }), { timeout: 10_000 }).toBe(true);
  return page.evaluate(() => {
    const c = document.getElementById('canvas');
    return { width: c.width, height: c.height, clientWidth: c.clientWidth, clientHeight: c.clientHeight,
             dpr: window.devicePixelRatio };
  });
}
