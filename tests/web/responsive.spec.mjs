// Issue 12: moving, dropping files and switching scenes stay responsive while the levels of detail
// of the heavy figure are built. The page builds them in a Worker after the first frame that draws
// them (here view LOD's, which the main pass draws: the default traces its mirror and draws no
// level); the worker's answers are held at the page's gate (demo.holdLevels) until the test lets
// them in, so "levels not in yet" is a state the test waits for and acts in, not a race against
// the worker. Every check is a state or a count, never a duration.
import { test, expect } from '@playwright/test';
import { spawnSync } from 'node:child_process';
import { existsSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { canvasScreenshot, collectErrors, countChanged, expectMessage } from './helpers.mjs';

const REPO = fileURLToPath(new URL('../../', import.meta.url));
const MODELS = `${REPO}build/web/site/models/`;
const HEAVY = `${REPO}build/heavy/mario.obj`;

// The heavy figure of tools/web_bench.mjs --heavy (157k triangles), made as that tool makes it.
function heavyMario() {
  if (!existsSync(HEAVY)) {
    const made = spawnSync('python3', [`${REPO}tools/make_models.py`, '--heavy'], { stdio: 'inherit' });
    if (made.status !== 0) throw new Error('tools/make_models.py --heavy failed');
  }
  return readFileSync(HEAVY);
}

const CUBE = readFileSync(`${REPO}assets/models/cube.obj`, 'utf8');

// Drops a file on the canvas the way a browser does: a drop event carrying a DataTransfer.
async function drop(page, name, text) {
  const dataTransfer = await page.evaluateHandle(({ n, t }) => {
    const dt = new DataTransfer();
    dt.items.add(new File([t], n, { type: 'text/plain' }));
    return dt;
  }, { n: name, t: text });
  await page.dispatchEvent('#canvas', 'drop', { dataTransfer });
}

const state = (page) => page.evaluate(() => ({
  scene: window.demo.scene().name,
  lodReady: window.demo.stats().lodReady,
  waiting: window.demo.levelsWaiting(),
  mario: window.demo.lodLevels('mario.obj'),
  frames: window.demo.framesDrawn(),
}));

test('with the heavy figure, dragging, dropping a file and switching scenes work before its levels are in', async ({ page }) => {
  const errors = collectErrors(page);
  const mario = heavyMario();
  await page.route((url) => url.pathname.startsWith('/course/'), (route) => {
    const name = new URL(route.request().url()).pathname.split('/').pop();
    const body = name === 'mario.obj' ? mario : readFileSync(MODELS + name);
    return route.fulfill({ status: 200, contentType: 'text/plain', body });
  });
  await page.goto('?paused&assets=/course/&viewLod=0.05');
  await page.waitForFunction(() => window.demo !== undefined);
  await page.evaluate(() => window.demo.ready);
  const heavyTriangles = (await page.evaluate(() => window.demo.lodReady()))['mario.obj']?.[0];
  expect(heavyTriangles).toBeGreaterThan(150_000);  // the heavy figure stands in for mario

  // A fresh load of the scene (the heavy figure again) with its levels held.
  await page.evaluate(() => window.demo.holdLevels(true));
  await page.evaluate(() => window.demo.loadScene('ex12-2'));
  expect((await page.evaluate(() => window.demo.firstFrameStats())).lodReady).toBe(false);
  // The worker has built them: they wait at the gate, and the page draws without them.
  await expect.poll(async () => (await state(page)).waiting).toBeGreaterThan(0);
  const held = await state(page);
  expect(held.lodReady).toBe(false);
  expect(held.mario).toBeNull();

  // Moving: a mouse drag turns the view, the display loop draws it, and the picture changes.
  const before = { camera: await page.evaluate(() => window.demo.camera()), image: await canvasScreenshot(page) };
  const box = await page.locator('#canvas').boundingBox();
  const [x, y] = [box.x + box.width / 2, box.y + box.height / 2];
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.move(x + box.width / 8, y, { steps: 4 });
  await page.mouse.up();
  await expect.poll(async () => (await state(page)).frames).toBeGreaterThan(held.frames);
  const turned = await page.evaluate(() => window.demo.camera());
  expect(Math.abs(turned.yaw - before.camera.yaw)).toBeGreaterThan(5);
  await expect.poll(async () => countChanged(before.image, await canvasScreenshot(page), 16)).toBeGreaterThan(1000);
  expect((await state(page)).lodReady).toBe(false);  // all of it before the levels

  // Dropping a file: it joins as a figure while the levels are still held.
  const objects = await page.evaluate(() => window.demo.objects().length);
  await drop(page, 'box.obj', CUBE);
  await expectMessage(page, 'added box.obj as an orbiting figure', 'info');
  await expect.poll(() => page.evaluate(() => window.demo.objects().length)).toBe(objects + 1);
  expect((await state(page)).lodReady).toBe(false);

  // Switching scenes: the new scene is loaded and drawn, its levels held as well.
  const heavyImage = await canvasScreenshot(page);
  await page.evaluate(() => window.demo.loadScene('skybox'));
  const skybox = await state(page);
  expect(skybox.scene).toBe('skybox');
  expect(skybox.lodReady).toBe(false);
  expect(await page.evaluate(() => window.demo.scene().meshes)).not.toContain('box.obj');
  expect(countChanged(heavyImage, await canvasScreenshot(page), 16)).toBeGreaterThan(1000);

  // Back to the heavy figure, still before its levels; then they are let in and adopted.
  await page.evaluate(() => window.demo.loadScene('ex12-2'));
  expect((await page.evaluate(() => window.demo.firstFrameStats())).lodReady).toBe(false);
  await expect.poll(async () => (await state(page)).waiting).toBeGreaterThan(0);
  expect((await state(page)).lodReady).toBe(false);
  await page.evaluate(() => window.demo.holdLevels(false));
  const levels = await page.evaluate(() => window.demo.lodReady());
  expect(levels['mario.obj'][0]).toBe(heavyTriangles);
  expect(levels['mario.obj'].length).toBeGreaterThan(1);
  expect(levels['mario.obj'][1]).toBeLessThan(heavyTriangles * 0.75);
  expect((await page.evaluate(() => window.demo.frame(0))).lodReady).toBe(true);
  expect(await page.evaluate(() => window.demo.levelsWaiting())).toBe(0);
  expect(errors).toEqual([]);
});
