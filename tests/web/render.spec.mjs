// The picture: the reflection follows the orbiting figures, and the view keeps its aspect (a
// round sphere, a drawing buffer of CSS size x devicePixelRatio) through resizes.
import { test, expect } from '@playwright/test';
import {
  canvasScreenshot, collectErrors, expectedSphereBox, makeSphereTest, measureGoldSphere, openDemo, renderAndRead,
  waitForCanvasSize,
} from './helpers.mjs';

// Compares two renders: within the sphere (shrunk a little, the mesh is faceted) and in bands of
// time-independent ground and sky far from the figures.
function compareRenders(a, b) {
  const { width, height } = a;
  const inSphere = makeSphereTest(width, height, { radiusScale: 0.93 });
  let spherePixels = 0, sphereChanged = 0, staticPixels = 0, staticChanged = 0;
  const diff = (i) => Math.max(...[0, 1, 2].map((c) => Math.abs(a.data[i + c] - b.data[i + c])));
  for (let y = 0; y < height; ++y) {
    // Ground in the bottom 40 rows and sky in the top quarter: no figure reaches either.
    const staticRow = y >= height - 40 || y < height / 4;
    for (let x = 0; x < width; ++x) {
      const i = (y * width + x) * 4;
      if (inSphere(x, y)) {
        ++spherePixels;
        if (diff(i) > 20) ++sphereChanged;
      } else if (staticRow) {
        ++staticPixels;
        if (diff(i) > 2) ++staticChanged;
      }
    }
  }
  return { spherePixels, sphereChanged, staticPixels, staticChanged };
}

test('the sphere reflection changes as the figures orbit; static ground does not', async ({ page }) => {
  await openDemo(page, '?paused');
  const t0 = await renderAndRead(page, 0);
  const t0again = await renderAndRead(page, 0);
  // t = 2 s: 54 degrees on, the green figure has come in front of the sphere.
  const t2 = await renderAndRead(page, 2.0);
  // t = 4 s: 108 degrees on, neither figure is in front of the sphere, so only the reflection
  // can have changed there.
  const t4 = await renderAndRead(page, 4.0);
  expect(t0.stats.time).toBe(0);
  expect(t2.stats.orbitDegrees).toBeCloseTo(54, 4);
  expect(t4.stats.orbitDegrees).toBeCloseTo(108, 4);

  // Deterministic: the same time gives the same picture.
  const same = compareRenders(t0, t0again);
  expect(same.sphereChanged).toBe(0);
  expect(same.staticChanged).toBe(0);

  for (const [label, later] of [['t=2', t2], ['t=4', t4]]) {
    const c = compareRenders(t0, later);
    expect(c.spherePixels).toBeGreaterThan(15_000);  // ~ pi * 75^2 at 800x600
    expect(c.sphereChanged / c.spherePixels, `${label}: share of sphere pixels changed by > 20 levels`)
      .toBeGreaterThan(0.02);
    expect(c.staticPixels).toBeGreaterThan(100_000);
    expect(c.staticChanged, `${label}: static ground/sky pixels that changed`).toBe(0);
  }
});

// Screenshots the canvas and checks that the gold sphere is where the camera puts it and round.
async function expectRoundSphere(page, label) {
  const size = await waitForCanvasSize(page);
  await page.evaluate(() => window.demo.frame(0));
  const image = await canvasScreenshot(page);  // device pixels: the drawing buffer's size
  expect(image.width, `${label}: screenshot width`).toBe(size.width);
  expect(image.height, `${label}: screenshot height`).toBe(size.height);
  const expected = expectedSphereBox(size.width, size.height);
  const measured = measureGoldSphere(image, expected);
  expect(measured, `${label}: gold sphere found`).not.toBeNull();
  const expectedHeight = expected.y1 - expected.y0 + 1;
  expect(measured.width / measured.height, `${label}: sphere width / height`).toBeGreaterThan(0.97);
  expect(measured.width / measured.height, `${label}: sphere width / height`).toBeLessThan(1.03);
  expect(Math.abs(measured.height - expectedHeight) / expectedHeight, `${label}: sphere height vs camera`)
    .toBeLessThan(0.05);
  expect(Math.abs((measured.x0 + measured.x1) / 2 - expected.cx), `${label}: sphere centre x`)
    .toBeLessThan(expectedHeight * 0.05);
  expect(Math.abs((measured.y0 + measured.y1) / 2 - expected.cy), `${label}: sphere centre y`)
    .toBeLessThan(expectedHeight * 0.05);
  return { size, measured };
}

test('resizing keeps the drawing buffer at CSS size and the sphere round', async ({ page }) => {
  await openDemo(page, '?paused');
  await page.setViewportSize({ width: 1200, height: 600 });
  const wide = await expectRoundSphere(page, '1200x600');
  expect(wide.size).toMatchObject({ width: 1200, height: 600, clientWidth: 1200, clientHeight: 600, dpr: 1 });

  await page.setViewportSize({ width: 600, height: 900 });
  const tall = await expectRoundSphere(page, '600x900');
  expect(tall.size).toMatchObject({ width: 600, height: 900, clientWidth: 600, clientHeight: 900, dpr: 1 });
  // The field of view is kept along the narrower side (600 px both times: the height of the wide
  // canvas, the width of the tall one), so the sphere keeps its size.
  expect(tall.measured.height / wide.measured.height).toBeCloseTo(1, 1);

  // Square: the same again (600 px each way).
  await page.setViewportSize({ width: 600, height: 600 });
  const square = await expectRoundSphere(page, '600x600');
  expect(square.measured.height / wide.measured.height).toBeCloseTo(1, 1);
});

test.describe('at devicePixelRatio 2', () => {
  test.use({ viewport: { width: 500, height: 400 }, deviceScaleFactor: 2 });

  test('the drawing buffer is twice the CSS size and the sphere is round', async ({ page }) => {
    await openDemo(page, '?paused');
    const { size } = await expectRoundSphere(page, 'dpr 2');
    expect(size).toMatchObject({ width: 1000, height: 800, clientWidth: 500, clientHeight: 400, dpr: 2 });
  });
});

// A canvas whose drawing buffer would be wider than the GPU allows (its MAX_VIEWPORT_DIMS, and
// the texture and renderbuffer limits): the browser gives a smaller buffer. The frame must be
// drawn into the buffer the browser gave, at its aspect, not at the canvas element's size. The
// viewport is made from the limit the browser reports (SwiftShader's is 8192: 2800 x 300 CSS
// pixels at devicePixelRatio 3).
test.describe('a canvas wider than the GPU allows', () => {
  test.use({ viewport: { width: 800, height: 300 }, deviceScaleFactor: 3 });

  test('is drawn at the drawing buffer the browser gives, and the sphere stays round', async ({ page }) => {
    const errors = collectErrors(page);
    await openDemo(page, '?paused');
    const limit = await page.evaluate(() => {
      const gl = document.getElementById('canvas').getContext('webgl2');
      return Math.min(gl.getParameter(gl.MAX_VIEWPORT_DIMS)[0], gl.getParameter(gl.MAX_TEXTURE_SIZE),
                      gl.getParameter(gl.MAX_RENDERBUFFER_SIZE));
    });
    // 2.5% past the limit (8400 device pixels for 8192): the browser shows the smaller buffer
    // stretched to the element, so further past it the sphere would look oval whatever the page did.
    const cssWidth = Math.ceil((limit * 1.025) / 3);
    await page.setViewportSize({ width: cssWidth, height: 300 });
    const { size } = await expectRoundSphere(page, 'oversized');
    expect(size).toMatchObject({ width: cssWidth * 3, height: 900 });
    const buffer = await page.evaluate(() => {
      const gl = document.getElementById('canvas').getContext('webgl2');
      return { width: gl.drawingBufferWidth, height: gl.drawingBufferHeight };
    });
    expect(buffer.width).toBeLessThan(cssWidth * 3);
    expect(buffer.width).toBeLessThanOrEqual(limit);
    const stats = await page.evaluate(() => window.demo.frame(0));
    expect([stats.width, stats.height]).toEqual([buffer.width, buffer.height]);
    expect(errors).toEqual([]);
  });
});

test('after a lost and restored WebGL context the same picture comes back', async ({ page }) => {
  await openDemo(page, '?paused');
  const before = await renderAndRead(page, 1.5);
  await page.evaluate(() => {
    window.__loseContext = document.getElementById('canvas').getContext('webgl2').getExtension('WEBGL_lose_context');
    window.__loseContext.loseContext();
  });
  await expect(page.locator('#messages .message', { hasText: 'WebGL context lost' })).toBeVisible();
  // While lost, a frame draws nothing and does not throw.
  expect((await page.evaluate(() => window.demo.frame(0))).drawCalls).toBe(0);
  await page.evaluate(() => window.__loseContext.restoreContext());
  await expect(page.locator('#messages .message', { hasText: 'WebGL context restored' })).toBeVisible();
  const after = await renderAndRead(page, 1.5);
  expect(after.stats.drawCalls).toBeGreaterThan(0);
  let differ = 0;
  for (let i = 0; i < after.data.length; i += 4) {
    if (Math.abs(after.data[i] - before.data[i]) + Math.abs(after.data[i + 1] - before.data[i + 1]) +
        Math.abs(after.data[i + 2] - before.data[i + 2]) > 6) ++differ;
  }
  expect(differ, 'pixels that differ from the picture before the loss').toBe(0);
});
