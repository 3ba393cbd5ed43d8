// The accuracy selector: a point on the measured speed/accuracy curve (assets/sweep.csv, copied to
// the site), its settings applied and its cube size, and a readout of the expected error from the
// CSV. Mirrored in the URL as acc=ROW, or, for settings no row has, as the settings' own keys.
import { test, expect } from '@playwright/test';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import {
  changedInSphere, collectErrors, expectedSphereBox, idle, messages, openDemo, PANEL_OPEN_VIEWPORT,
  renderAndRead,
} from './helpers.mjs';

// The panel's controls are used: a window where it starts open, the canvas 800x600 beside it.
test.use({ viewport: PANEL_OPEN_VIEWPORT });

const CSV = readFileSync(fileURLToPath(new URL('../../assets/sweep.csv', import.meta.url)), 'utf8');
// name -> { setting, faceSize, psnr, angular } from the CSV (the setting and settings columns
// are quoted and hold commas).
const ROWS = Object.fromEntries(CSV.trim().split('\n').slice(1).map((line) => {
  const [, name, setting, rest] = /^([^,]+),"([^"]*)","(?:[^"]|"")*",(.*)$/.exec(line);
  const f = rest.split(',');
  return [name, { setting, faceSize: Number(f[0]), psnr: Number(f[4]), angular: Number(f[8]) }];
}));

const query = (page) => new URL(page.url()).search;
const accuracy = (page) => page.evaluate(() => window.demo.accuracy());
const select = (page) => page.locator('#control-accuracy select');
async function choose(page, name) {
  const label = (await select(page).locator('option').allTextContents()).find((t) => t.startsWith(`${name}:`));
  expect(label, `an option for ${name}`).toBeTruthy();
  await select(page).selectOption({ label });
}

test('choosing "original" sets the course settings, changes the reflection and shows its error', async ({ page }) => {
  const errors = collectErrors(page);
  await openDemo(page, '?paused&t=1&policy=every-frame');
  const options = await select(page).locator('option').allTextContents();
  expect(options.length).toBe(Object.keys(ROWS).length + 1);  // every row, and "not measured"
  // The shipped default is a measured row.
  expect((await accuracy(page)).describe).toBe(ROWS.default.setting);
  await choose(page, 'default');
  await expect(page.locator('#accuracy-readout')).toContainText(`PSNR ${ROWS.default.psnr.toFixed(2)} dB`);
  const before = await renderAndRead(page);

  await choose(page, 'original');
  await idle(page);
  expect(await accuracy(page)).toMatchObject({ search: 'plain', captureAtOrigin: true, depthBits: 16,
                                               mipmaps: false, halfFloat: false, mediump: false,
                                               describe: ROWS.original.setting });
  const readout = page.locator('#accuracy-readout');
  await expect(readout).toContainText(`original: reflector PSNR ${ROWS.original.psnr.toFixed(2)} dB`);
  await expect(readout).toContainText(`mean angular error ${ROWS.original.angular.toFixed(2)}°`);
  await expect(readout).toContainText('not on the Pareto front');
  const after = await renderAndRead(page);
  expect(after.stats.cubeFaceSize).toBe(ROWS.original.faceSize);
  const box = expectedSphereBox(before.width, before.height);
  const area = (box.x1 - box.x0 + 1) * (box.y1 - box.y0 + 1);
  expect(changedInSphere(before, after)).toBeGreaterThan(area * 0.02);
  await expect.poll(() => query(page)).toContain('&acc=original');

  // A row with another cube size reloads the scene at that size.
  await choose(page, 'hierarchical-size-64');
  await idle(page);
  expect((await page.evaluate(() => window.demo.frame(0))).cubeFaceSize).toBe(64);
  expect((await accuracy(page)).describe).toBe(ROWS['hierarchical-size-64'].setting);
  // The default (traced here) is faster and more accurate than every cube-map row.
  await expect(readout).toContainText('not on the Pareto front');
  await expect.poll(() => query(page)).toContain('cube=64&');
  await expect.poll(() => query(page)).toContain('&acc=hierarchical-size-64');

  // A combination the sweep did not measure.
  expect(await page.evaluate(() => window.demo.setAccuracy({ mipmaps: true }))).toBe('');
  await expect(readout).toContainText('not measured');
  await expect.poll(() => select(page).evaluate((s) => s.options[s.selectedIndex].textContent)).toBe('not measured');
  // No row has these settings: the link carries the settings themselves (those not at their
  // defaults, by the schema's names), and opening it applies them.
  await expect.poll(() => query(page)).toBe('?scene=ex12-2&cube=64&policy=every-frame&paused&t=1&search=hierarchical&mipmaps=true');
  expect(errors).toEqual([]);

  await openDemo(page, query(page));
  expect(await accuracy(page)).toMatchObject({ search: 'hierarchical', captureAtOrigin: false, depthBits: 24,
                                               mipmaps: true, halfFloat: false, mediump: false });
  expect((await page.evaluate(() => window.demo.frame(0))).cubeFaceSize).toBe(64);
  await expect(readout).toContainText('not measured');
  await expect(page.locator('#messages .message')).toHaveCount(0);
  expect(await messages(page)).toEqual([]);
  expect(errors).toEqual([]);
});

test('acc= in a link applies the row; an unknown row is named', async ({ page }) => {
  await openDemo(page, '?paused&acc=original');
  expect(await accuracy(page)).toMatchObject({ search: 'plain', captureAtOrigin: true, depthBits: 16 });
  expect((await page.evaluate(() => window.demo.frame(0))).cubeFaceSize).toBe(256);
  await expect(page.locator('#accuracy-readout')).toContainText(`PSNR ${ROWS.original.psnr.toFixed(2)} dB`);
  await expect.poll(() => query(page)).toBe('?scene=ex12-2&cube=256&policy=when-changed&paused&t=0&acc=original');
  // Settings carry over to another scene.
  await page.evaluate(() => window.demo.loadScene('two-mirrors'));
  expect((await accuracy(page)).captureAtOrigin).toBe(true);

  await openDemo(page, '?paused&acc=nonsense');
  await expect(page.locator('#messages .message', { hasText: 'acc=nonsense: not a measured accuracy mode' })).toBeVisible();
  expect((await accuracy(page)).describe).toBe(ROWS.default.setting);
});

test('the accuracy settings have controls of their own, made from the schema', async ({ page }) => {
  await openDemo(page, '?paused');
  const schema = await page.evaluate(() => window.demo.schema().accuracy);
  for (const info of schema) {
    await expect(page.locator(`#control-acc-${info.name}`)).toBeAttached();
    await expect(page.locator(`#control-acc-${info.name} .lil-name`)).toHaveText(info.label);
  }
  await page.locator('#accuracy .lil-title', { hasText: 'settings' }).click();
  await page.locator('#control-acc-mipmaps input').check();
  await expect.poll(async () => (await accuracy(page)).mipmaps).toBe(true);
  await expect(page.locator('#accuracy-readout')).toContainText('not measured');
  await expect.poll(() => query(page)).toContain('&mipmaps=true');
  // A bad value is named by the C++ side and changes nothing.
  expect(await page.evaluate(() => window.demo.setAccuracy({ depthBits: 20 }))).toBe('depthBits: 20 is not one of 16, 24');
  expect((await accuracy(page)).depthBits).toBe(24);
});
