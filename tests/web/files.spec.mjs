// The user's own models: dropped files and folders, the file and folder pickers, size limits,
// broken files, and loading progress for large models.
import { test, expect } from '@playwright/test';
import { mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import {
  collectErrors, colourSummary, expectMessage, idle, messages, openDemo, PANEL_OPEN_VIEWPORT, readyOutcome,
  renderAndRead,
} from './helpers.mjs';

// The panel's controls are used: a window where it starts open, the canvas 800x600 beside it.
test.use({ viewport: PANEL_OPEN_VIEWPORT });

const MODELS = fileURLToPath(new URL('../../assets/models/', import.meta.url));
const real = (name) => readFileSync(MODELS + name, 'utf8');
const CUBE = real('cube.obj');  // 12 triangles

// The triangles the main view draws: what the scene holds (every object is in view, at full
// detail). Not the capture's: with the default when-changed policy a paused frame captures only
// when something changed, so a frame's total depends on what came before it.
const triangles = (page) => page.evaluate(() => window.demo.frame(0).mainTriangles);

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
  // The worker runs the native build's C++ (core's buildLevels, compiled to wasm): the same numbers
  // as natively, MeshChunks.ShippedMarioLevelsAreThePagesLevels (tests/unit/mesh_chunks_test.cpp)
  // expects these three too; a change to one is a change to both.
  expect(await page.evaluate(() => window.demo.lodLevels('mario.obj'))).toEqual([7258, 1814, 528]);
  // sonic's mesh under mario's name: a different, known triangle count.
  await drop(page, [{ name: 'mario.obj', text: real('sonic.obj') }]);
  await expectMessage(page, 'mario.obj replaced by mario.obj', 'info');
  await idle(page);
  const after = await triangles(page);
  expect(after).not.toBe(before);
  expect(await page.evaluate(() => window.demo.lodLevels('mario.obj')?.[0])).toBe(5288);
  expect((await page.evaluate(() => window.demo.lodLevels('mario.obj'))).length).toBeGreaterThan(1);
  // The replacement survives a cube-size reload (the page keeps the user's file).
  await page.locator('#control-cube select').selectOption('128');
  await idle(page);
  expect((await page.evaluate(() => window.demo.frame(0))).cubeFaceSize).toBe(128);
  expect(await triangles(page)).toBe(after);
  // And goes with the built-in-models button.
  await page.locator('#control-files').evaluate((e) => e.closest('.lil-gui').querySelector('.lil-title').click());
  await page.locator('#control-builtin button').click();
  await idle(page);
  expect(await triangles(page)).toBe(before);
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

// Faces that name normals the file does not define: the loader computes normals and says so; the
// page shows that as an info message (and keeps it in demo.messages()), for a new figure and for
// a replaced model alike.
test('a dropped OBJ with undefined normals loads, with its warning as an info message', async ({ page }) => {
  const errors = collectErrors(page);
  await openDemo(page, '?paused');
  const TRIANGLE = 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//2 3//3\n';
  const warning = (name) => `${name}: faces name normals the file does not define (first on line 4); using computed normals`;
  await drop(page, [{ name: 'triangle.obj', text: TRIANGLE }]);
  await expectMessage(page, 'added triangle.obj as an orbiting figure', 'info');
  await idle(page);
  expect(await page.evaluate(() => window.demo.figures().map((f) => f.name))).toEqual(['triangle.obj']);
  const history = await messages(page);
  expect(history.filter((m) => m.text === warning('triangle.obj'))).toEqual([{ text: warning('triangle.obj'), kind: 'info' }]);
  await expect(page.locator('#messages .message.info', { hasText: warning('triangle.obj') })).toBeVisible();

  await drop(page, [{ name: 'sonic.obj', text: TRIANGLE }]);
  await expectMessage(page, 'sonic.obj replaced by sonic.obj', 'info');
  await expectMessage(page, warning('sonic.obj'), 'info');
  await idle(page);
  expect((await messages(page)).filter((m) => m.kind === 'error')).toEqual([]);
  expect(errors).toEqual([]);
});

test('non-.obj files are reported, not loaded; files over 64 MB are refused unread', async ({ page }) => {
  await openDemo(page, '?paused');
  const before = await triangles(page);
  const objects = await page.evaluate(() => window.demo.objects().length);
  await drop(page, [{ name: 'notes.txt', text: 'hello' }]);
  await expectMessage(page, 'notes.txt: not .obj files');
  await drop(page, [{ name: 'Sonic.OBJ', size: 65 * 1024 * 1024 }]);
  await expect(page.locator('#messages .message.error', { hasText: 'Sonic.OBJ: 65.0 MB is over the 64 MB limit' })).toBeVisible();
  await drop(page, [{ name: 'teapot.obj', size: 65 * 1024 * 1024 }]);
  await expect(page.locator('#messages .message.error', { hasText: 'teapot.obj: 65.0 MB is over the 64 MB limit' })).toBeVisible();
  expect(await triangles(page)).toBe(before);
  expect(await page.evaluate(() => window.demo.objects().length)).toBe(objects);
});

// Orange pixels (the first added figure's colour is 0.95/0.55/0.15): red over green over blue by
// clear steps. Few others in the default scene look like that (some shading on the figures).
function orangePixels(image) {
  let n = 0;
  for (let i = 0; i < image.data.length; i += 4) {
    const r = image.data[i], g = image.data[i + 1], b = image.data[i + 2];
    if (r - g > 25 && g - b > 25) ++n;
  }
  return n;
}

test('dropping a new .obj adds it as an orbiting figure scaled to fit', async ({ page }) => {
  const errors = collectErrors(page);
  await openDemo(page, '?paused&policy=every-frame');
  const before = await page.evaluate(() => ({ objects: window.demo.objects(), stats: window.demo.frame(0) }));
  const imageBefore = await renderAndRead(page);
  await drop(page, [{ name: 'teapot.obj', text: CUBE }]);
  await expectMessage(page, 'added teapot.obj as an orbiting figure', 'info');
  await idle(page);
  const after = await page.evaluate(() => ({ objects: window.demo.objects(), figures: window.demo.figures() }));
  expect(after.objects.length).toBe(before.objects.length + 1);
  expect(after.objects.at(-1).mesh).toBe('teapot.obj');
  expect(await page.evaluate(() => window.demo.scene().meshes)).toContain('teapot.obj');
  // The cube is 2 units wide: scaled to 1.5, its bottom at y = -1.8, on the ring of radius 3.
  const object = after.figures[0].object;
  expect(object.scale).toBeCloseTo(0.75, 6);
  expect(object.translate[1]).toBeCloseTo(-1.05, 6);
  expect(Math.hypot(object.translate[0], object.translate[2])).toBeCloseTo(3, 6);
  expect(object.animation).toEqual({ type: 'orbit', degreesPerSecond: 27, axis: [0, 1, 0] });
  const image = await renderAndRead(page);
  expect(image.stats.triangles).toBeGreaterThan(before.stats.triangles);
  const { distinct, greyFraction } = colourSummary(image);
  expect(distinct).toBeGreaterThan(500);
  expect(greyFraction).toBeLessThan(0.6);
  // The figure is in view (directly and in the sphere).
  expect(orangePixels(image) - orangePixels(imageBefore)).toBeGreaterThan(300);

  // A second new file goes to another place on the ring; the figures stay through a cube-size
  // reload and go with the built-in-models button.
  await drop(page, [{ name: 'box.obj', text: CUBE }]);
  await expectMessage(page, 'added box.obj as an orbiting figure', 'info');
  await idle(page);
  const placed = (await page.evaluate(() => window.demo.figures())).map((f) => f.object.translate);
  expect(Math.hypot(placed[0][0] - placed[1][0], placed[0][2] - placed[1][2])).toBeGreaterThan(2);
  await page.locator('#control-cube select').selectOption('128');
  await idle(page);
  expect((await page.evaluate(() => window.demo.frame(0))).cubeFaceSize).toBe(128);
  expect(await page.evaluate(() => window.demo.objects().length)).toBe(before.objects.length + 2);
  await page.locator('#control-files').evaluate((e) => e.closest('.lil-gui').querySelector('.lil-title').click());
  await page.locator('#control-builtin button').click();
  await idle(page);
  expect(await page.evaluate(() => window.demo.objects().length)).toBe(before.objects.length);

  // A broken new file is named and nothing is added.
  await drop(page, [{ name: 'broken.obj', text: 'v 0 0 0\nf 1 2 3\n' }]);
  await expect(page.locator('#messages .message.error', { hasText: 'broken.obj' })).toContainText('not added');
  expect(await page.evaluate(() => window.demo.objects().length)).toBe(before.objects.length);
  expect(errors).toEqual([]);
});

test('the file picker and the folder picker (recursing into sub-folders) replace models', async ({ page }) => {
  await openDemo(page, '?paused');
  const base = await triangles(page);
  const dir = mkdtempSync(join(tmpdir(), 'reflect-models-'));
  try {
    writeFileSync(join(dir, 'sonic.obj'), CUBE);
    await page.setInputFiles('#file-input', join(dir, 'sonic.obj'));
    await expectMessage(page, 'sonic.obj replaced by sonic.obj', 'info');
    await idle(page);
    const sonicAsCube = await triangles(page);
    expect(sonicAsCube).toBeLessThan(base);

    const folder = join(dir, 'course');
    mkdirSync(join(folder, 'figures', 'red'), { recursive: true });
    writeFileSync(join(folder, 'figures', 'red', 'mario.obj'), CUBE);
    writeFileSync(join(folder, 'readme.txt'), 'not a model');
    await page.setInputFiles('#folder-input', folder);
    await expectMessage(page, 'mario.obj replaced by course/figures/red/mario.obj', 'info');
    await expectMessage(page, 'readme.txt: not .obj files');
    await idle(page);
    expect(await triangles(page)).toBeLessThan(sonicAsCube);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

// File names as users have them: not ASCII, over 1,000 characters, with quotes, backslashes and
// spaces. They go through the bridge as JSON strings, whole.
const ODD_NAMES = [
  'マリオ.obj',
  'ü.obj',
  `${'a long name '.repeat(90)}end.obj`,  // 1,087 characters
  'my "quoted" \\ back\\slashed name\'s file.obj',
];

test('dropped files keep their names intact: messages, figures and objects carry them whole', async ({ page }) => {
  const errors = collectErrors(page);
  expect(ODD_NAMES[2].length).toBeGreaterThan(1000);
  await openDemo(page, '?paused');
  const before = await page.evaluate(() => window.demo.objects().length);
  for (const name of ODD_NAMES) {
    await drop(page, [{ name, text: CUBE }]);
    await expectMessage(page, `added ${name} as an orbiting figure`, 'info');
    await idle(page);
  }
  const after = await page.evaluate(() => ({
    figures: window.demo.figures(), objects: window.demo.objects(), meshes: window.demo.scene().meshes,
  }));
  expect(after.figures.map((f) => f.name)).toEqual(ODD_NAMES);
  expect(after.figures.map((f) => f.source)).toEqual(ODD_NAMES);
  expect(after.figures.map((f) => f.object.mesh)).toEqual(ODD_NAMES);
  expect(after.objects.slice(before).map((o) => o.mesh)).toEqual(ODD_NAMES);
  for (const name of ODD_NAMES) expect(after.meshes).toContain(name);
  // Each is drawn (12 triangles more each), and the names survive a cube-size reload.
  await page.locator('#control-cube select').selectOption('128');
  await idle(page);
  expect((await page.evaluate(() => window.demo.objects())).slice(before).map((o) => o.mesh)).toEqual(ODD_NAMES);

  // A broken file of such a name is named whole in the error, and nothing is added.
  const broken = `ü "broken" \\ ${'x'.repeat(1000)}.obj`;
  await drop(page, [{ name: broken, text: 'v 0 0 0\nf 1 2 3\n' }]);
  await expectMessage(page, broken, 'error');
  const message = (await messages(page)).find((m) => m.text.includes(broken));
  expect(message.text).toContain('not added');
  expect(await page.evaluate(() => window.demo.objects().length)).toBe(before + ODD_NAMES.length);
  // Dropping a file of a name already added replaces that figure's mesh, found by its name.
  await drop(page, [{ name: ODD_NAMES[0], text: real('sonic.obj') }]);
  await expectMessage(page, `${ODD_NAMES[0]} replaced by ${ODD_NAMES[0]}`, 'info');
  expect(errors).toEqual([]);
});

test('picked files and folders keep their names intact', async ({ page }) => {
  await openDemo(page, '?paused');
  // The file picker, with names the file system does not hold (given as buffers).
  for (const name of ODD_NAMES) {
    await page.setInputFiles('#file-input', { name, mimeType: 'text/plain', buffer: Buffer.from(CUBE) });
    await expectMessage(page, `added ${name} as an orbiting figure`, 'info');
    await idle(page);
  }
  expect((await page.evaluate(() => window.demo.figures())).map((f) => f.name)).toEqual(ODD_NAMES);
  // A folder whose name has them: the path in the message is whole. (No backslash here: the
  // browser itself turns one in a folder name into a / in the file's relative path.)
  const dir = mkdtempSync(join(tmpdir(), 'reflect-names-'));
  try {
    const folder = join(dir, `コース "a" ü ${'f'.repeat(200)}`);
    mkdirSync(folder);
    writeFileSync(join(folder, 'mario.obj'), CUBE);
    await page.setInputFiles('#folder-input', folder);
    await expectMessage(page, `mario.obj replaced by コース "a" ü ${'f'.repeat(200)}/mario.obj`, 'info');
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

test('a large model shows loading progress while it streams in', async ({ page }) => {
  // The course's mario.obj is 11.5 MB: the built-in one padded with comments to that size. It
  // arrives as a stream of 16 padding chunks. (A routed response may arrive in one chunk, which
  // left this test to the browser's timing; the page's fetch is replaced for this one file.)
  await page.addInitScript(({ mario, paddingBytes }) => {
    const browserFetch = window.fetch.bind(window);
    window.fetch = async (input, init) => {
      const url = new URL(typeof input === 'string' ? input : input.url, location.href);
      if (url.pathname !== '/course/mario.obj') return browserFetch(input, init);
      const encoder = new TextEncoder();
      const line = `# ${'x'.repeat(78)}\n`;
      const chunk = encoder.encode(line.repeat(Math.ceil(paddingBytes / line.length / 16)));
      const chunks = [encoder.encode(mario), ...Array(16).fill(chunk)];
      const length = chunks.reduce((sum, c) => sum + c.length, 0);
      let next = 0;
      const body = new ReadableStream({
        pull(controller) {
          if (next < chunks.length) controller.enqueue(chunks[next++]);
          else controller.close();
        },
      });
      return new Response(body, { status: 200, headers: { 'Content-Type': 'text/plain', 'Content-Length': `${length}` } });
    };
  }, { mario: real('mario.obj'), paddingBytes: 11.5 * 1024 * 1024 });
  await page.route((url) => url.pathname.startsWith('/course/'), (route) => {
    const name = new URL(route.request().url()).pathname.split('/').pop();
    return route.fulfill({ status: 200, contentType: 'text/plain', body: real(name) });
  });
  await page.goto('?paused&assets=/course/');
  expect(await readyOutcome(page)).toBe('resolved');
  const history = await page.evaluate(() => window.demo.progressHistory());
  const mario = history.filter((line) => line.startsWith('loading /course/mario.obj'));
  expect(mario.length, history.join('\n')).toBeGreaterThan(10);  // a step per chunk, not one jump
  expect(mario[mario.length - 1]).toMatch(/100% of 1[1-3]\.\d MB/);
  await expect(page.locator('#progress')).toBeHidden();  // gone when done
  await expect(page.locator('#messages .message')).toHaveCount(0);
});
