// The URL mirrors every control (history.replaceState), and opening such a link restores the
// scene, the capture settings, the camera and the paused time.
import { test, expect } from '@playwright/test';
import { openDemo } from './helpers.mjs';

const query = (page) => new URL(page.url()).search;

test('the address bar follows the controls, the camera and the time', async ({ page }) => {
  await openDemo(page, '?paused&t=1');
  await expect.poll(() => query(page)).toBe('?scene=ex12-2&policy=when-changed&paused&t=1');

  await page.locator('#control-policy select').selectOption('time-sliced');
  await expect.poll(() => query(page)).toContain('policy=time-sliced&slice=2');
  await page.locator('#control-lod input').fill('0.25');
  await page.locator('#control-lod input').press('Enter');
  await expect.poll(() => query(page)).toContain('&lod=0.25');
  await page.locator('#control-cube select').selectOption('64');
  await expect.poll(() => query(page)).toContain('&cube=64&');
  await expect.poll(async () => (await page.evaluate(() => window.demo.frame(0))).cubeFaceSize).toBe(64);

  // A drag and a key press move the camera: cam=x,y,z,yaw,pitch appears.
  await page.mouse.move(300, 300);
  await page.mouse.down();
  await page.mouse.move(360, 300, { steps: 3 });  // 60 px = 10 degrees
  await page.mouse.up();
  await page.keyboard.press('w');
  await expect.poll(() => query(page)).toMatch(/&cam=-0\.0174,1,6\.9015,10,0(&|$)/);

  // Running: no t; paused again: t is the paused time.
  await page.locator('#control-paused input').uncheck();
  await expect.poll(() => query(page)).not.toContain('paused');
  expect(query(page)).not.toContain('t=');
  await page.locator('#control-paused input').check();
  await expect.poll(() => query(page)).toMatch(/&paused&t=\d+(\.\d+)?&cam=/);

  // Another scene: its own camera again, so no cam=.
  await page.evaluate(() => window.demo.loadScene('two-mirrors'));
  await expect.poll(() => query(page)).toMatch(/^\?scene=two-mirrors&cube=64&policy=time-sliced&slice=2&lod=0\.25&paused&t=0$/);
});

test('opening a copied link restores scene, cube, policy, camera and time', async ({ page, context }) => {
  await context.grantPermissions(['clipboard-read', 'clipboard-write']);
  await openDemo(page, '?scene=ex12-2');
  await page.evaluate(() => window.demo.loadScene('skybox'));
  await page.locator('#control-policy select').selectOption('every N frames');
  await page.locator('#control-every input').fill('3');
  await page.locator('#control-every input').press('Enter');
  await page.locator('#control-cube select').selectOption('128');
  await expect.poll(async () => (await page.evaluate(() => window.demo.frame(0))).cubeFaceSize).toBe(128);
  await page.evaluate(() => window.demo.setCamera(1.25, 1.5, 5, 20, -12.5));
  await page.locator('#control-paused input').check();
  await page.evaluate(() => window.demo.setTime(2.5));
  // The copy-link button (in its folder).
  await page.locator('#control-link button').click();
  await expect(page.locator('#messages .message.info', { hasText: 'Link copied' })).toBeVisible();
  const link = await page.evaluate(() => navigator.clipboard.readText());
  expect(link).toBe(page.url());
  expect(new URL(link).search).toBe('?scene=skybox&cube=128&policy=every-n&every=3&paused&t=2.5&cam=1.25,1.5,5,20,-12.5');

  const other = await context.newPage();
  await openDemo(other, new URL(link).search);
  const restored = await other.evaluate(() => ({
    scene: window.demo.scene().name, planner: window.demo.planner(), camera: window.demo.camera(),
    stats: window.demo.frame(0), paused: window.demo.paused(),
  }));
  expect(restored.scene).toBe('skybox');
  expect(restored.planner).toMatchObject({ policy: 'every-n', everyN: 3 });
  expect(restored.stats.cubeFaceSize).toBe(128);
  expect(restored.stats.time).toBeCloseTo(2.5, 6);
  expect(restored.paused).toBe(true);
  expect(restored.camera.eye[0]).toBeCloseTo(1.25, 4);
  expect(restored.camera.eye[1]).toBeCloseTo(1.5, 4);
  expect(restored.camera.eye[2]).toBeCloseTo(5, 4);
  expect(restored.camera.yaw).toBeCloseTo(20, 3);
  expect(restored.camera.pitch).toBeCloseTo(-12.5, 3);
  // The panel shows the restored settings.
  await expect(other.locator('#control-scene select')).toHaveValue('Skybox: static environment mapping');
  await expect(other.locator('#control-policy select')).toHaveValue('every N frames');
  await expect(other.locator('#control-paused input')).toBeChecked();
  await expect.poll(() => new URL(other.url()).search).toBe(new URL(link).search);
});

test('without a clipboard, copy link shows the link to copy by hand', async ({ page }) => {
  await page.addInitScript(() => { Object.defineProperty(navigator, 'clipboard', { value: undefined }); });
  await openDemo(page, '?paused&scene=glass-sphere');
  await page.locator('#control-link button').click();
  const field = page.locator('#messages .message .link-field');
  await expect(field).toBeVisible();
  expect(await field.inputValue()).toBe(page.url());
  expect(await field.inputValue()).toContain('scene=glass-sphere');
});

test('bad values in the URL are named and the rest still applies', async ({ page }) => {
  await openDemo(page, '?paused&scene=ex12-1&slice=9&cam=1,2&policy=every-frame');
  await expect(page.locator('#messages .message', { hasText: 'slice=9' })).toBeVisible();
  await expect(page.locator('#messages .message', { hasText: 'cam=1,2' })).toBeVisible();
  expect(await page.evaluate(() => window.demo.scene().name)).toBe('ex12-1');
  expect((await page.evaluate(() => window.demo.planner())).policy).toBe('every-frame');
});
