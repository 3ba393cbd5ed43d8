// Inside the frame: the faces view replaces the picture with the probe's cube map unfolded
// (its pixels and marks are held natively: tests/gl/faces_view_test.cpp). Here: the link key, the
// panel's folder, the F key, and the message when the frame has no cube map; the face-use
// view (U) paints the mirror by the faces it reads.
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

// The view's own colours (core/cube_cross.cpp, core/bitmap_font.h): background, label text and
// the three face marks. Any other pixel is a face's texel.
const VIEW_COLOURS = [CROSS_BACKGROUND, [235, 235, 235], [70, 200, 100], [235, 165, 40], [110, 110, 110]];

function faceTexels(image) {
  const texels = [];
  for (let i = 0; i < image.data.length; i += 4) {
    const rgb = [image.data[i], image.data[i + 1], image.data[i + 2]];
    if (!VIEW_COLOURS.some((c) => c.every((v, k) => v === rgb[k]))) texels.push(rgb.join(','));
  }
  return texels;
}

test('the irradiance channel shows the light a probe-lit figure takes from its own probe', async ({ page }) => {
  // probe-lit: each figure has a 32-texel probe of its own; the second is mario's. Its six faces
  // are 6 x 32 x 32 texels, shown whole; the irradiance (held natively:
  // FacesView.TheIrradianceChannelShowsTheLightAProbeLitFigureTakes) is not the colours.
  await openDemo(page, '?scene=probe-lit&inside=faces&facesChannel=irradiance&facesProbe=2&paused');
  await expect(page.locator('#control-view-facesChannel select')).toHaveValue('irradiance');
  const light = faceTexels(await renderAndRead(page, 1.0));
  expect(light.length).toBe(6 * 32 * 32);
  await page.evaluate(() => window.demo.setView({ facesChannel: 'colour' }));
  const colours = faceTexels(await renderAndRead(page, 1.0));
  expect(colours.length).toBe(6 * 32 * 32);
  // Not the colours: they differ at nearly every texel, and the cosine-weighted average narrows
  // the range of each channel (the red wall's red, the grey wall's, the blue ground's blue).
  const differing = light.filter((rgb, i) => rgb !== colours[i]).length;
  expect(differing).toBeGreaterThan(0.9 * light.length);
  const range = (texels, k) => {
    const values = texels.map((rgb) => Number(rgb.split(',')[k]));
    return Math.max(...values) - Math.min(...values);
  };
  for (const k of [0, 1, 2]) expect(range(light, k)).toBeLessThan(range(colours, k));
});

// core/face_use.h, kFaceUseColours: +X, -X, +Y, -Y, +Z, -Z.
const FACE_COLOURS = [[230, 40, 40], [40, 210, 230], [50, 200, 60], [220, 60, 220], [50, 90, 240], [240, 220, 40]];

function pixelsOfEachFace(image) {
  const counts = FACE_COLOURS.map(() => 0);
  for (let i = 0; i < image.data.length; i += 4) {
    const face = FACE_COLOURS.findIndex(([r, g, b]) => image.data[i] === r && image.data[i + 1] === g && image.data[i + 2] === b);
    if (face >= 0) ++counts[face];
  }
  return counts;
}

test('?inside=faceuse paints the course\'s mirror by the faces it reads, and U gives the picture back', async ({ page }) => {
  await openDemo(page, '?preset=course&inside=faceuse&paused');
  expect((await page.evaluate(() => window.demo.view())).inside).toBe('faceuse');
  const shown = await renderAndRead(page, 1.0);
  // The camera looks at the sphere from +Z: its middle reads +Z (the ray comes back), the ring
  // around it +X, -X, +Y and -Y, and its rim -Z (behind the sphere). Where the view is exact is
  // held natively (tests/gl/face_use_view_test.cpp); here, that the page shows the view.
  const counts = pixelsOfEachFace(shown);
  for (let face = 0; face < 6; ++face) expect(counts[face], `face ${face}`).toBeGreaterThan(20);
  expect(counts[4]).toBeGreaterThan(counts[5]);

  await page.keyboard.press('u');
  await idle(page);
  expect((await page.evaluate(() => window.demo.view())).inside).toBe('off');
  const picture = await renderAndRead(page, 1.0);
  expect(pixelsOfEachFace(picture).reduce((a, b) => a + b, 0)).toBeLessThan(20);
});
