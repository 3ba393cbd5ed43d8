// The user's own models: dropped files and folders, the file and folder pickers, size limits,
// broken files, and loading progress for large models.
import { test, expect } from '@playwright/test';
import { mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { collectErrors, openDemo, readyOutcome } from './helpers.mjs';

const MODELS = fileURLToPath(new URL('../../assets/models/', import.meta.url));
const real = (name) => readFileSync(MODELS + name, 'utf8');
const CUBE = real('cube.obj');  // 12 triangles

const triangles = (page) => page.evaluate(() => window.demo.frame(0).triangles);

// Drops files on the canvas the way a browser does: a drop event carrying a DataTransfer.
async function drop(page, files) {
  const dataTransfer = await page.evaluateHandle((list) => {
    const dt = new DataTransfer();
    for (const f of list) {
      const body = f.size ? new Uint8Array(f.size) : f.text;
      dt.items.add(new File([body], f.name, { type: 'text/plain' }));
    }
    return dt;
  }, files);
  await page.dispatchEvent('#canvas', 'drop', { dataTransfer });
}

test('dropping mario.obj replaces the model; its levels of detail are rebuilt', async ({ page }) => {
  const errors = collectErrors(page);
  await openDemo(page, '?paused&policy=every-frame');
  const before = await triangles(page);
  expect(await page.evaluate(() => window.demo.lodLevels('mario.obj'))).toEqual([7258, 1814, 560]);
  // sonic's mesh under mario's name: a different, known triangle count.
  await drop(page, [{ name: 'mario.obj', text: real('sonic.obj') }]);
  await expect(page.locator('#messages .message.info', { hasText: 'mario.obj replaced by mario.obj' })).toBeVisible();
  const after = await triangles(page);
  expect(after).not.toBe(before);
  await expect.poll(() => page.evaluate(() => window.demo.lodLevels('mario.obj')?.[0])).toBe(5288);
  expect((await page.evaluate(() => window.demo.lodLevels('mario.obj'))).length).toBeGreaterThan(1);
  // The replacement survives a cube-size reload (the page keeps the user's file).
  await page.locator('#control-cube select').selectOption('128');
  await expect.poll(async () => (await page.evaluate(() => window.demo.frame(0))).cubeFaceSize).toBe(128);
  expect(await triangles(page)).toBe(after);
  // And goes with the built-in-models button.
  await page.locator('#control-files').evaluate((e) => e.closest('.lil-gui').querySelector('.lil-title').click());
  await page.locator('#control-builtin button').click();
  await expect.poll(() => triangles(page)).toBe(before);
  expect(errors).toEqual([]);
});

test('a broken file is named in a message and the scene keeps its model', async ({ page }) => {
  await openDemo(page, '?paused');
  const before = await triangles(page);
  await drop(page, [{ name: 'sonic.obj', text: 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' }]);
  const message = page.locator('#messages .message.error');
  await expect(message).toHaveCount(1);
  await expect(message).toContainText('sonic.obj');
  await expect(message).toContainText('line 4');
  await expect(message).toContainText('keeping the sonic.obj it had');
  expect(await triangles(page)).toBe(before);
  const image = await page.evaluate(() => window.demo.frame(0));
  expect(image.drawCalls).toBeGreaterThan(0);
});

test('other .obj files and non-.obj files are reported, not loaded; files over 64 MB are refused unread', async ({ page }) => {
  await openDemo(page, '?paused');
  const before = await triangles(page);
  await drop(page, [{ name: 'teapot.obj', text: CUBE }, { name: 'notes.txt', text: 'hello' }]);
  await expect(page.locator('#messages .message', { hasText: 'teapot.obj: no model of this scene has that name' })).toBeVisible();
  await expect(page.locator('#messages .message', { hasText: 'notes.txt: not .obj files' })).toBeVisible();
  await drop(page, [{ name: 'Sonic.OBJ', size: 65 * 1024 * 1024 }]);
  await expect(page.locator('#messages .message.error', { hasText: 'Sonic.OBJ: 65.0 MB is over the 64 MB limit' })).toBeVisible();
  expect(await triangles(page)).toBe(before);
});

test('the file picker and the folder picker (recursing into sub-folders) replace models', async ({ page }) => {
  await openDemo(page, '?paused');
  const base = await triangles(page);
  const dir = mkdtempSync(join(tmpdir(), 'reflect-models-'));
  try {
    writeFileSync(join(dir, 'sonic.obj'), CUBE);
    await page.setInputFiles('#file-input', join(dir, 'sonic.obj'));
    await expect(page.locator('#messages .message', { hasText: 'sonic.obj replaced by sonic.obj' })).toBeVisible();
    const sonicAsCube = await triangles(page);
    expect(sonicAsCube).toBeLessThan(base);

    const folder = join(dir, 'course');
    mkdirSync(join(folder, 'figures', 'red'), { recursive: true });
    writeFileSync(join(folder, 'figures', 'red', 'mario.obj'), CUBE);
    writeFileSync(join(folder, 'readme.txt'), 'not a model');
    await page.setInputFiles('#folder-input', folder);
    await expect(page.locator('#messages .message', { hasText: 'mario.obj replaced by course/figures/red/mario.obj' })).toBeVisible();
    await expect(page.locator('#messages .message', { hasText: 'readme.txt: not .obj files' })).toBeVisible();
    expect(await triangles(page)).toBeLessThan(sonicAsCube);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

test('a large model shows loading progress while it streams in', async ({ page }) => {
  // The course's mario.obj is 11.5 MB: the built-in one padded with comments to that size.
  const padding = `# ${'x'.repeat(78)}\n`.repeat(Math.ceil((11.5 * 1024 * 1024) / 81));
  const big = real('mario.obj') + padding;
  await page.route((url) => url.pathname.startsWith('/course/'), (route) => {
    const name = new URL(route.request().url()).pathname.split('/').pop();
    if (name === 'mario.obj') return route.fulfill({ status: 200, contentType: 'text/plain', body: big });
    return route.fulfill({ status: 200, contentType: 'text/plain', body: real(name) });
  });
  await page.goto('?paused&assets=/course/');
  expect(await readyOutcome(page)).toBe('resolved');
  const history = await page.evaluate(() => window.demo.progressHistory());
  const mario = history.filter((line) => line.startsWith('loading /course/mario.obj'));
  expect(mario.length, history.join('\n')).toBeGreaterThan(2);  // several steps, not one jump
  expect(mario[mario.length - 1]).toMatch(/100% of 1[1-3]\.\d MB/);
  await expect(page.locator('#progress')).toBeHidden();  // gone when done
  await expect(page.locator('#messages .message')).toHaveCount(0);
});
