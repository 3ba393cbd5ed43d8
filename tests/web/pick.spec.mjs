// Pick a pixel in the page (issue 23): P and a click on the sphere's centre pixel show the C++
// explanation (rf_explain_pixel, the code `reflect explain` prints) in the readout, with the same
// numbers the native command gives for that pixel, and the frame draws its rays only while the
// pick is shown. The explanation's own numbers are held against Embree and closed forms natively
// (tests/reference/pixel_explain_test.cpp).
import { test, expect } from '@playwright/test';
import { countChanged, openDemo, PANEL_OPEN_VIEWPORT, pixel, renderAndRead } from './helpers.mjs';

// The sphere's centre (0, 0.25, 0) seen from the eye (0, 1, 7) with a 70 degree vertical field on
// the 800x600 canvas: 0.75 below the eye 7 ahead, ndc y = -(0.75 / 7) / tan(35 deg) = -0.1530,
// row (1 + 0.1530) / 2 x 600 = 345.9; straight ahead, column 400.
const PIXEL = { x: 400, y: 345 };

// `reflect explain --pixel 400,345 --size 800x600 --search hierarchical` (t = 0), natively:
//   view ray (0.0012, -0.1056, -0.9944) meets the surface at (0.0067, 0.3896, 1.2527), ...
//   course lookup: direction (0.0118, 0.1160, 0.9932) from the probe centre, angular error 0.000 deg
//   exact: meets nothing (the sky), direction (0.0118, 0.1160, 0.9932)
// (at the centre the mirror sends the ray back past the eye, up over the camera to the sky). The
// CPU's numbers are the same C++ in wasm: equal to the printed digits.
const NATIVE = {
  surfacePoint: [0.0067, 0.3896, 1.2527],
  courseDirection: [0.0118, 0.1160, 0.9932],
  exactObject: -1,
  courseErrorDeg: 0.0,
};

function expectClose(actual, expected, tolerance) {
  expect(actual.length).toBe(expected.length);
  actual.forEach((value, i) => expect(Math.abs(value - expected[i])).toBeLessThan(tolerance));
}

test('P and a click on the sphere explain its centre pixel with reflect explain\'s numbers', async ({ page }) => {
  await openDemo(page, '?paused&t=0&search=hierarchical');
  const plain = await renderAndRead(page, 0);
  expect([plain.width, plain.height]).toEqual([800, 600]);

  await page.keyboard.press('p');
  await page.locator('#canvas').click({ position: { x: PIXEL.x + 0.5, y: PIXEL.y + 0.5 } });
  const clicked = await page.evaluate(() => window.demo.lastPick());
  expect(clicked.error).toBeUndefined();
  expect([clicked.x, clicked.y]).toEqual([PIXEL.x, PIXEL.y]);
  expect(clicked.message).toBe('');
  expect(clicked.material).toBe('mirror');
  expect(clicked.search).toBe('hierarchical');
  // The readout is the explanation's lines, the lines `reflect explain` prints.
  await expect(page.locator('#pick')).toHaveText(clicked.lines.join('\n'));
  expect(clicked.lines[0]).toBe('pixel 400,345 of 800x600 at t=0.000 s');

  // The same request made directly gives the same explanation.
  const direct = await page.evaluate(({ x, y }) => window.demo.explainPixel(x, y), PIXEL);
  expect(direct.lines).toEqual(clicked.lines);
  // And the native command's numbers.
  expectClose(clicked.surfacePoint, NATIVE.surfacePoint, 1e-3);
  expectClose(clicked.courseDirection, NATIVE.courseDirection, 1e-3);
  expect(clicked.exactObject).toBe(NATIVE.exactObject);
  expectClose(clicked.exactDirection, NATIVE.courseDirection, 1e-3);
  expect(Math.abs(clicked.courseErrorDeg - NATIVE.courseErrorDeg)).toBeLessThan(0.001);
  // Every number the readout prints is the native command's, to its printed digits, but the
  // search's and the frame's, which are the GPU's (SwiftShader here, llvmpipe natively).
  expect(clicked.lines.slice(0, 7)).toEqual([
    'pixel 400,345 of 800x600 at t=0.000 s',
    '  object 4 (sphere.obj), mirror, search hierarchical',
    '  eye (0.0000, 1.0000, 7.0000)',
    '  view ray (0.0012, -0.1056, -0.9944) meets the surface at (0.0067, 0.3896, 1.2527), normal (0.0053, 0.1108, 0.9938)',
    '  reflected: direction (0.0118, 0.1160, 0.9932)',
    '  probe centre (0.0000, 0.2500, 0.0000)',
    '  course lookup: direction (0.0118, 0.1160, 0.9932) from the probe centre, angular error 0.000 deg',
  ]);
  expect(clicked.lines[8]).toBe('  exact: meets nothing (the sky), direction (0.0118, 0.1160, 0.9932)');

  // The rays are drawn over the frame while the pick is shown, and gone with P. At the centre the
  // rays run almost along the line of sight (the mirror sends the view ray back past the eye):
  // short on screen (49 pixels changed in SwiftShader).
  const withRays = await renderAndRead(page, 0);
  expect(countChanged(plain, withRays, 0)).toBeGreaterThan(30);
  // The probe centre's red cross: its horizontal arm (0.16 units, about 10 pixels at 7 units)
  // through the centre's own pixel, row 345 (y 345.9), a few pixels left of column 400.
  const red = [344, 345, 346].map((y) => pixel(withRays, 395, y))
    .filter(([r, g, b]) => r > 200 && g < 80 && b < 80);
  expect(red.length).toBeGreaterThan(0);
  await page.keyboard.press('p');
  expect(await page.evaluate(() => window.demo.pickReadout())).toBe('');
  const after = await renderAndRead(page, 0);
  expect(countChanged(plain, after, 0)).toBe(0);
});

test('a pixel with nothing to explain says so, and the default search says the sphere is traced', async ({ page }) => {
  await openDemo(page, '?paused&t=0');
  const sky = await page.evaluate(() => window.demo.explainPixel(5, 5));
  expect(sky.message).toBe('the view ray meets nothing there: the pixel shows the background');
  await expect(page.locator('#pick')).toHaveText(`pixel 5,5 of 800x600 at t=0.000 s\n  ${sky.message}`);
  const sphere = await page.evaluate(({ x, y }) => window.demo.explainPixel(x, y), PIXEL);
  expect(sphere.message).toContain('traced exactly this frame');
  const outside = await page.evaluate(() => window.demo.explainPixel(800, 0));
  expect(outside.outside).toBe(true);
  expect(outside.message).toBe('pixel 800,0 is outside the 800x600 frame (x 0..799, y 0..599)');
});

test('a probe-lit figure\'s pixel names the irradiance it was lit with', async ({ page }) => {
  // probe-lit at t = 1 s: a pixel of mario's side facing away from the light (its normal
  // -0.96, 0.20, 0.17), so its colour is the figure's 0.9 times the irradiance alone. The reply
  // names mario's own probe and E / pi there; the frame's pixel is that light, within 2 levels.
  await openDemo(page, '?scene=probe-lit&paused&t=1');
  const frame = await renderAndRead(page, 1);
  const reply = await page.evaluate(() => window.demo.explainPixel(547, 437));
  expect(reply.object).toBe(2);
  expect(reply.irradianceProbe).toBe(2);
  expect(reply.message).toContain('is phong, lit by probe');
  expect(reply.message).toContain(`E / pi = ${reply.irradiance.map((v) => v.toFixed(3)).join(', ')}`);
  const drawn = pixel(frame, 547, 437);
  for (const k of [0, 1, 2]) expect(Math.abs(drawn[k] - Math.round(0.9 * reply.irradiance[k] * 255))).toBeLessThanOrEqual(2);
});

test('a link\'s pick=X,Y explains that pixel once the frame is drawn, and the address bar keeps it while it is shown', async ({ page }) => {
  await openDemo(page, `?paused&t=0&search=hierarchical&pick=${PIXEL.x},${PIXEL.y}`);
  await expect(page.locator('#pick')).toContainText(`pixel ${PIXEL.x},${PIXEL.y} of 800x600`);
  const shown = await page.evaluate(() => window.demo.lastPick());
  expect(shown.material).toBe('mirror');
  await expect(page).toHaveURL(new RegExp(`pick=${PIXEL.x},${PIXEL.y}`));
  await page.keyboard.press('p');
  await expect(page).not.toHaveURL(/pick=/);
  await expect(page.locator('#pick-box')).toBeHidden();
});

test('a pick= that is not a pixel is refused by name', async ({ page }) => {
  await openDemo(page, '?paused&pick=12');
  await expect(page.locator('#messages')).toContainText('pick=12: expected X,Y');
});

test('the panel\'s pick control turns pick a pixel on and off (a touch screen has no P key)', async ({ page }) => {
  await page.setViewportSize(PANEL_OPEN_VIEWPORT);
  await openDemo(page, '?paused&t=0');
  await page.locator('#control-pick button').click();
  await expect(page.locator('#pick-box')).toBeVisible();
  await expect(page.locator('#pick')).toContainText('pick a pixel');
  await page.locator('#control-pick button').click();
  await expect(page.locator('#pick-box')).toBeHidden();
});
