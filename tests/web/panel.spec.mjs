// The controls panel (lil-gui): every control changes the demo, and the scene picker loads every
// shipped scene without errors.
import { test, expect } from '@playwright/test';
import { readFileSync, readdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { decodePng } from './png.mjs';
import {
  animationFrames, collectErrors, colourSummary, idle, openDemo, PANEL_OPEN_VIEWPORT, renderAndRead,
} from './helpers.mjs';

// The panel's controls are used: a window where it starts open, the canvas 800x600 beside it.
test.use({ viewport: PANEL_OPEN_VIEWPORT });

const SCENE_DIR = fileURLToPath(new URL('../../assets/scenes/', import.meta.url));
const SHIPPED = readdirSync(SCENE_DIR).filter((f) => f.endsWith('.json')).map((f) => f.replace(/\.json$/, ''));

const select = (page, id) => page.locator(`#${id} select`);
const button = (page, id) => page.locator(`#${id} button`);
const planner = (page) => page.evaluate(() => window.demo.planner());

test('the update policy select, its parameters and the LOD slider set the planner', async ({ page }) => {
  // The policies are the capture's: the mirror captured (the default traces it here).
  await openDemo(page, '?paused&search=hierarchical');
  await expect(page.locator('#panel')).toBeVisible();
  expect((await planner(page)).policy).toBe('when-changed');
  await expect(page.locator('#control-staleness input')).toHaveValue('none: always current');
  // Parameters show only with their policy.
  await expect(page.locator('#control-facesPerFrame')).toBeHidden();
  await expect(page.locator('#control-everyN')).toBeHidden();

  await select(page, 'control-policy').selectOption('time-sliced');
  await expect.poll(async () => (await planner(page)).policy).toBe('time-sliced');
  await expect(page.locator('#control-facesPerFrame')).toBeVisible();
  await page.locator('#control-facesPerFrame input').fill('3');
  await page.locator('#control-facesPerFrame input').press('Enter');
  await expect.poll(async () => (await planner(page)).facesPerFrame).toBe(3);
  await expect(page.locator('#control-staleness input')).toHaveValue('up to 1 frame behind');
  let s = await page.evaluate(() => window.demo.frame(1 / 60));
  expect(s.facesCaptured).toBeLessThanOrEqual(3);

  await select(page, 'control-policy').selectOption('every-n');
  await expect.poll(async () => (await planner(page)).policy).toBe('every-n');
  await expect(page.locator('#control-facesPerFrame')).toBeHidden();
  await page.locator('#control-everyN input').fill('5');
  await page.locator('#control-everyN input').press('Enter');
  await expect.poll(async () => (await planner(page)).everyN).toBe(5);
  await expect(page.locator('#control-staleness input')).toHaveValue('up to 4 frames behind');
  // A value out of the schema's range is named, and the control shows the value kept.
  await page.locator('#control-everyN input').fill('5000');
  await page.locator('#control-everyN input').press('Enter');
  await expect(page.locator('#messages .message.error', { hasText: 'everyN: 5000 is not in 1..1000' })).toBeVisible();
  await expect(page.locator('#control-everyN input')).toHaveValue('5');
  expect((await planner(page)).everyN).toBe(5);

  await select(page, 'control-policy').selectOption('every-frame');
  await expect.poll(async () => (await planner(page)).policy).toBe('every-frame');
  s = await page.evaluate(() => window.demo.frame(1 / 60));
  expect(s.facesCaptured).toBe(6);

  await page.locator('#control-captureLod input').fill('0.5');
  await page.locator('#control-captureLod input').press('Enter');
  await expect.poll(async () => (await planner(page)).captureLod).toBe(0.5);
});

test('cube size reloads the scene with that face size and keeps the view and time', async ({ page }) => {
  await openDemo(page, '?paused&t=1.5');
  await page.evaluate(() => window.demo.setCamera(0.5, 1.2, 6, 10, -5));
  await select(page, 'control-cube').selectOption('128');
  await idle(page);
  expect((await page.evaluate(() => window.demo.frame(0))).cubeFaceSize).toBe(128);
  const after = await page.evaluate(() => ({ camera: window.demo.camera(), stats: window.demo.stats() }));
  expect(after.camera.eye[0]).toBeCloseTo(0.5, 4);
  expect(after.camera.yaw).toBeCloseTo(10, 3);
  expect(after.stats.time).toBeCloseTo(1.5, 6);
  await select(page, 'control-cube').selectOption('512');
  await idle(page);
  expect((await page.evaluate(() => window.demo.frame(0))).cubeFaceSize).toBe(512);
  await expect(select(page, 'control-cube')).toHaveValue('512');
});

test('the scene picker loads every shipped scene: its name, a picture, no errors', async ({ page }) => {
  test.setTimeout(90_000);
  const errors = collectErrors(page);
  await openDemo(page, '?paused');
  const options = await select(page, 'control-scene').locator('option').allTextContents();
  expect(options.length).toBe(SHIPPED.length);
  for (const name of SHIPPED) {
    const title = JSON.parse(readFileSync(`${SCENE_DIR}${name}.json`, 'utf8')).title;
    expect(options, `the picker lists "${title}"`).toContain(title);
    await select(page, 'control-scene').selectOption(title);
    await idle(page);
    expect(await page.evaluate(() => window.demo.scene().name)).toBe(name);
    const image = await renderAndRead(page, 1);
    const { distinct } = colourSummary(image);
    expect(distinct, `${name}: distinct colours`).toBeGreaterThan(100);
    expect(image.stats.drawCalls, `${name}: draw calls`).toBeGreaterThan(0);
    expect(image.stats.error, `${name}: capture error`).toBeUndefined();
    await expect(page.locator('#materials')).toBeAttached();
  }
  await expect(page.locator('#messages .message.error')).toHaveCount(0);
  expect(errors).toEqual([]);
});

test('the materials of the scene are listed, with controls for mirrors and glass', async ({ page }) => {
  await openDemo(page, '?paused');
  const materials = page.locator('#materials');
  await materials.locator('.lil-title').first().click();  // open the folder
  await expect(materials).toContainText('4 sphere.obj');
  await expect(materials.locator('input').first()).toHaveValue('mirror 0.78 refl + 0.3 base');
  await expect(materials.locator('.lil-controller').first()).toHaveClass(/lil-disabled/);
  await expect(page.locator('#control-mat-3-reflection input')).toHaveValue('0.78');
  await page.evaluate(() => window.demo.loadScene('glass-sphere'));
  await expect(page.locator('#materials input').first()).toHaveValue('glass ior 1.52, Fresnel');
  await expect(page.locator('#materials [id$="-fresnel"] input').first()).toBeChecked();
});

test('pause, single step and reset camera', async ({ page }) => {
  await openDemo(page, '?t=1');
  const paused = page.locator('#control-paused input');
  await expect(paused).not.toBeChecked();
  await paused.check();
  expect(await page.evaluate(() => window.demo.paused())).toBe(true);
  const t0 = (await page.evaluate(() => window.demo.stats())).time;
  await animationFrames(page, 10);
  expect((await page.evaluate(() => window.demo.stats())).time).toBe(t0);
  await button(page, 'control-step').click();
  expect((await page.evaluate(() => window.demo.stats())).time).toBeCloseTo(t0 + 1 / 60, 6);
  // Space (on the canvas) un-pauses, and the checkbox follows.
  await page.locator('#canvas').focus();
  await page.keyboard.press(' ');
  await expect(paused).not.toBeChecked();

  await page.evaluate(() => window.demo.setCamera(1, 2, 3, 40, 10));
  await button(page, 'control-reset').click();
  expect(await page.evaluate(() => window.demo.camera())).toEqual({ eye: [0, 1, 7], yaw: 0, pitch: 0 });
});

test('the screenshot button downloads a PNG of the canvas', async ({ page }) => {
  await openDemo(page, '?paused&t=2');
  const [download] = await Promise.all([
    page.waitForEvent('download'),
    button(page, 'control-screenshot').click(),
  ]);
  expect(download.suggestedFilename()).toBe('reflect-ex12-2-t2.00.png');
  const image = decodePng(readFileSync(await download.path()));
  expect([image.width, image.height]).toEqual([800, 600]);
  const { distinct, greyFraction } = colourSummary(image);
  expect(distinct).toBeGreaterThan(500);
  expect(greyFraction).toBeGreaterThan(0.2);  // the picture, not a blank (cleared) buffer
  expect(greyFraction).toBeLessThan(0.6);
  // Exactly the rendered pixels (no panel or numbers in it).
  const rendered = await renderAndRead(page, 2);
  let differ = 0;
  for (let i = 0; i < rendered.data.length; i += 4) {
    if (Math.abs(rendered.data[i] - image.data[i]) > 2) ++differ;
  }
  expect(differ).toBe(0);
});

test('help overlay: ? and H toggle it, Esc and its button close it', async ({ page }) => {
  await openDemo(page, '?paused');
  const overlay = page.locator('#help-overlay');
  await expect(overlay).toBeHidden();
  await page.locator('#canvas').focus();
  await page.keyboard.press('?');
  await expect(overlay).toBeVisible();
  await expect(overlay).toContainText('Q, E');
  await expect(overlay).toContainText('Ex12-2: dynamic reflection');  // the scene's description
  await page.keyboard.press('h');
  await expect(overlay).toBeHidden();
  await page.keyboard.press('H');
  await expect(overlay).toBeVisible();
  await page.keyboard.press('Escape');
  await expect(overlay).toBeHidden();
  await button(page, 'control-help').click();
  await expect(overlay).toBeVisible();
  await page.locator('#help-close').click();
  await expect(overlay).toBeHidden();
});
