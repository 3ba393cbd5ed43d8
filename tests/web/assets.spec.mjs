// ?assets=PREFIX: the course's own OBJ files. Broken or missing files are reported on the page
// (naming the file and the problem) and the built-in model is kept; course quirks load silently.
import { test, expect } from '@playwright/test';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import {
  animationFrames, canvasScreenshot, colourSummary, expectedSphereBox, idle, measureGoldSphere, openDemo,
  readyOutcome,
  renderAndRead,
} from './helpers.mjs';

const MODELS = fileURLToPath(new URL('../../build/web/site/models/', import.meta.url));
const NAMES = ['mario.obj', 'sonic.obj', 'sphere.obj', 'quad.obj'];
const real = (name) => readFileSync(MODELS + name);

// Serves /course/NAME from `files`: a string or Buffer is a 200 body, a number an HTTP status,
// 'abort' a failed connection.
async function serveCourse(page, files) {
  const requested = [];
  await page.route((url) => url.pathname.startsWith('/course/'), (route) => {
    const name = new URL(route.request().url()).pathname.split('/').pop();
    requested.push(name);
    const file = files[name];
    if (file === undefined || typeof file === 'number') {
      return route.fulfill({ status: file || 404, contentType: 'text/plain', body: 'not found\n' });
    }
    if (file === 'abort') return route.abort('connectionrefused');
    return route.fulfill({ status: 200, contentType: 'text/plain', body: file });
  });
  return requested;
}

function trianglesOf(objText) {
  let count = 0;
  for (const line of objText.split(/\r*\n/)) {
    const tokens = line.trim().split(/\s+/);
    if (tokens[0] === 'f') count += tokens.length - 3;
  }
  return count;
}

// A sphere written the way course files often are: quads with v/vt/vn, CR CR LF line endings, a
// material library that does not exist, several objects and groups, smoothing and usemtl lines.
// Same place and size as the built-in sphere (centre (0, 0.5, 0), radius 2.5456 before scaling).
function courseLikeSphere(rings = 12, segments = 24) {
  const lines = ['# Blender-ish export', 'mtllib course_materials_missing.mtl'];
  const r = 2.5456, cy = 0.5;
  const ringVertex = (i, j) => 2 + (i - 1) * segments + (j % segments) + 1;  // 1-based, after 2 poles
  const point = (theta, phi) => [Math.sin(theta) * Math.cos(phi), Math.cos(theta), Math.sin(theta) * Math.sin(phi)];
  const v = [point(0, 0), point(Math.PI, 0)];
  for (let i = 1; i < rings; ++i) {
    for (let j = 0; j < segments; ++j) v.push(point((Math.PI * i) / rings, (2 * Math.PI * j) / segments));
  }
  for (const [x, y, z] of v) lines.push(`v ${(x * r).toFixed(6)} ${(y * r + cy).toFixed(6)} ${(z * r).toFixed(6)}`);
  for (const [x, y, z] of v) lines.push(`vn ${x.toFixed(6)} ${y.toFixed(6)} ${z.toFixed(6)}`);
  lines.push('vt 0 0', 'vt 1 0', 'vt 1 1', 'vt 0 1');
  const corner = (index, t) => `${index}/${t}/${index}`;
  const half = Math.floor(rings / 2);
  for (const [name, from, to] of [['SphereTop', 0, half], ['SphereBottom', half, rings]]) {
    lines.push(`o ${name}`, `g ${name}_mesh`, 'usemtl Material.001', 's 1');
    for (let i = from; i < to; ++i) {
      for (let j = 0; j < segments; ++j) {
        // Outward winding, counter-clockwise seen from outside.
        if (i === 0) {
          lines.push(`f ${corner(1, 1)} ${corner(ringVertex(1, j + 1), 2)} ${corner(ringVertex(1, j), 3)}`);
        } else if (i === rings - 1) {
          lines.push(`f ${corner(2, 1)} ${corner(ringVertex(i, j), 2)} ${corner(ringVertex(i, j + 1), 3)}`);
        } else {
          lines.push(`f ${corner(ringVertex(i, j), 1)} ${corner(ringVertex(i, j + 1), 2)} ` +
                     `${corner(ringVertex(i + 1, j + 1), 3)} ${corner(ringVertex(i + 1, j), 4)}`);
        }
      }
    }
  }
  return `${lines.join('\r\r\n')}\r\r\n`;
}

test('a broken mario.obj and a missing sonic.obj are named on the page; the scene still renders', async ({ page }) => {
  const requested = await serveCourse(page, {
    'mario.obj': 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n',
    'sphere.obj': real('sphere.obj'),
    'quad.obj': real('quad.obj'),
  });
  await page.goto('?paused&assets=/course/');
  expect(await readyOutcome(page)).toBe('resolved');
  expect(requested.sort()).toEqual([...NAMES].sort());

  const messages = page.locator('#messages .message');
  await expect(messages).toHaveCount(2);
  const mario = messages.filter({ hasText: 'mario.obj' });
  await expect(mario).toHaveCount(1);
  await expect(mario).toBeVisible();
  await expect(mario).toContainText('line 4');
  await expect(mario).toContainText(/vertex index 7 is out of range/);
  await expect(mario).toContainText('keeping the built-in mario.obj');
  const sonic = messages.filter({ hasText: 'sonic.obj' });
  await expect(sonic).toHaveCount(1);
  await expect(sonic).toBeVisible();
  await expect(sonic).toContainText('404');
  await expect(sonic).toContainText('keeping the built-in sonic.obj');

  // The built-in models stay: same triangles as without ?assets, a full picture, the gold sphere.
  const withAssets = await renderAndRead(page, 0);
  const image = await canvasScreenshot(page);
  const { distinct, greyFraction } = colourSummary(image);
  expect(distinct).toBeGreaterThan(500);
  expect(greyFraction).toBeLessThan(0.6);
  expect(measureGoldSphere(image, expectedSphereBox(image.width, image.height))).not.toBeNull();

  // A message can be dismissed.
  await mario.getByRole('button', { name: 'dismiss' }).click();
  await expect(messages).toHaveCount(1);

  await openDemo(page, '?paused');
  const builtIn = await renderAndRead(page, 0);
  expect(withAssets.stats.mainTriangles).toBe(builtIn.stats.mainTriangles);
  expect(Buffer.compare(Buffer.from(withAssets.data), Buffer.from(builtIn.data)), 'same picture as the built-in models').toBe(0);
});

test('a file whose request fails outright is named too', async ({ page }) => {
  await serveCourse(page, {
    'mario.obj': real('mario.obj'), 'sonic.obj': real('sonic.obj'), 'sphere.obj': real('sphere.obj'),
    'quad.obj': 'abort',
  });
  await page.goto('?paused&assets=/course/');
  expect(await readyOutcome(page)).toBe('resolved');
  const messages = page.locator('#messages .message');
  await expect(messages).toHaveCount(1);
  await expect(messages).toContainText('quad.obj');
  await expect(messages).toContainText('keeping the built-in quad.obj');
});

test('a course-like sphere.obj (quads v/vt/vn, CR CR LF, missing mtllib, several objects) loads silently', async ({ page }) => {
  const sphere = courseLikeSphere();
  expect(sphere).toContain('\r\r\n');
  const requested = await serveCourse(page, {
    'mario.obj': real('mario.obj'), 'sonic.obj': real('sonic.obj'), 'sphere.obj': sphere,
    'quad.obj': real('quad.obj'),
  });
  await page.goto('?paused&assets=/course/');
  expect(await readyOutcome(page)).toBe('resolved');
  expect(requested).not.toContain('course_materials_missing.mtl');
  await idle(page);
  await animationFrames(page, 5);
  await expect(page.locator('#messages .message')).toHaveCount(0);
  const course = await renderAndRead(page, 0);

  // The file was really used: the main view's triangle count changed by exactly the spheres'
  // difference. (Not the frame's total: that includes a capture only when the planner found
  // something changed, which depends on when the levels of detail arrived.)
  await openDemo(page, '?paused');
  const builtIn = await renderAndRead(page, 0);
  const delta = trianglesOf(sphere) - trianglesOf(real('sphere.obj').toString());
  expect(delta).not.toBe(0);
  expect(course.stats.mainTriangles - builtIn.stats.mainTriangles).toBe(delta);

  // And it is drawn as a round gold sphere in the same place.
  const expected = expectedSphereBox(course.width, course.height);
  const measured = measureGoldSphere(course, expected);
  expect(measured).not.toBeNull();
  expect(measured.width / measured.height).toBeGreaterThan(0.97);
  expect(measured.width / measured.height).toBeLessThan(1.03);
  expect(Math.abs(measured.height - (expected.y1 - expected.y0 + 1))).toBeLessThan(8);
});

// A model the loader lets pass with a warning (faces name normals the file has none of) is used,
// and the warning is shown as an info message naming the file; a reload of the same scene (cube
// size) does not repeat it.
test('an ?assets= model with undefined normals loads, its warning shown as an info message', async ({ page }) => {
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await serveCourse(page, {
    'mario.obj': real('mario.obj'), 'sonic.obj': 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//2 3//3\n',
    'sphere.obj': real('sphere.obj'), 'quad.obj': real('quad.obj'),
  });
  await openDemo(page, '?paused&assets=/course/');
  const warning = '/course/sonic.obj: faces name normals the file does not define (first on line 4); using computed normals';
  const shown = () => page.evaluate((w) => window.demo.messages().filter((m) => m.text === w), warning);
  expect(await shown()).toEqual([{ text: warning, kind: 'info' }]);
  await expect(page.locator('#messages .message.info', { hasText: warning })).toBeVisible();
  await expect(page.locator('#messages .message.error')).toHaveCount(0);
  // The file's one triangle is sonic now.
  await page.evaluate(() => window.demo.lodReady());
  expect(await page.evaluate(() => window.demo.lodLevels('sonic.obj')?.[0])).toBe(1);
  // A measured mode at another cube size reloads the same scene and its files.
  await page.evaluate(() => window.demo.setAccuracy('hierarchical-size-64'));
  await page.evaluate(() => window.demo.idle());
  expect((await page.evaluate(() => window.demo.frame(0))).cubeFaceSize).toBe(64);
  expect(await shown()).toHaveLength(1);
  expect(errors).toEqual([]);
});

// Paths as users write them: not ASCII, long, with quotes, backslashes and spaces. The page
// fetches them (the browser encodes them) and names them whole in its messages and its link.
const ODD_PREFIX = `/コース "ü" ${'long folder '.repeat(85)}\\ end/`;

test('an ?assets= path with odd characters is named whole in messages and kept in the link', async ({ page }) => {
  expect(ODD_PREFIX.length).toBeGreaterThan(1000);
  const requested = [];
  await page.route((url) => url.pathname.endsWith('.obj') && !url.pathname.startsWith('/models/'), (route) => {
    const name = new URL(route.request().url()).pathname.split('/').pop();
    requested.push(name);
    const body = name === 'mario.obj' ? 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n' : real(name);
    return route.fulfill({ status: 200, contentType: 'text/plain', body });
  });
  await page.goto(`?paused&assets=${encodeURIComponent(ODD_PREFIX)}`);
  expect(await readyOutcome(page)).toBe('resolved');
  expect(requested.sort()).toEqual([...NAMES].sort());
  const mario = page.locator('#messages .message', { hasText: `${ODD_PREFIX}mario.obj` });
  await expect(mario).toHaveCount(1);
  await expect(mario).toContainText('keeping the built-in mario.obj');
  const query = await page.evaluate(() => window.demo.query());
  expect(new URLSearchParams(query).get('assets')).toBe(ODD_PREFIX);
  await expect.poll(() => new URL(page.url()).searchParams.get('assets')).toBe(ODD_PREFIX);
});

test('a scene file at a URL with odd characters loads, and its errors and link name it whole', async ({ page }) => {
  const url = `user scenes/マリオ "1" ${'x'.repeat(1000)} ü.json`;
  const scene = readFileSync(fileURLToPath(new URL('../../assets/scenes/ex12-2.json', import.meta.url)), 'utf8');
  let body = '{ "objects": [ }';
  await page.route((u) => u.pathname.endsWith('.json') && decodeURIComponent(u.pathname).includes('マリオ'),
                   (route) => route.fulfill({ status: 200, contentType: 'application/json', body }));
  await openDemo(page, '?paused');
  // Broken: the error names the URL whole; the scene on screen stays.
  const error = await page.evaluate((u) => window.demo.loadScene(u).then(() => '', (e) => e.message), url);
  expect(error.startsWith(`${url}: not valid JSON: line 1`)).toBe(true);
  await expect(page.locator('#messages .message.error', { hasText: url })).toHaveCount(1);
  expect(await page.evaluate(() => window.demo.scene().name)).toBe('ex12-2');
  // Sound: it loads under the file's name, and the link carries the URL whole.
  body = scene;
  await page.evaluate((u) => window.demo.loadScene(u), url);
  expect(await page.evaluate(() => window.demo.scene().name)).toBe(`マリオ "1" ${'x'.repeat(1000)} ü`);
  const query = await page.evaluate(() => window.demo.query());
  expect(new URLSearchParams(query).get('scene')).toBe(url);
  const other = await page.context().newPage();
  await other.route((u) => u.pathname.endsWith('.json') && decodeURIComponent(u.pathname).includes('マリオ'),
                    (route) => route.fulfill({ status: 200, contentType: 'application/json', body: scene }));
  await openDemo(other, query);
  expect(await other.evaluate(() => window.demo.scene().name)).toBe(`マリオ "1" ${'x'.repeat(1000)} ü`);
  await other.close();
});

test('a scene file nested far deeper than any real one is refused, and the page keeps drawing', async ({ page }) => {
  // 200,000 levels: walking it a level a call would overflow the wasm stack (256 kB, CMakeLists.txt)
  // many times over; the reader refuses it past 64 levels instead (kMaxJsonDepth).
  const depth = 200_000;
  const body = `{"objects": [{"mesh": "mario.obj"}], "title": ${'['.repeat(depth)}${']'.repeat(depth)}}`;
  await page.route((u) => u.pathname.endsWith('/deep.json'),
                   (route) => route.fulfill({ status: 200, contentType: 'application/json', body }));
  await openDemo(page, '?paused');
  const error = await page.evaluate(() => window.demo.loadScene('deep.json').then(() => '', (e) => e.message));
  expect(error).toContain('nested deeper than 64 levels');
  expect(await page.evaluate(() => window.demo.scene().name)).toBe('ex12-2');
  expect((await page.evaluate(() => window.demo.frame(0))).mainTriangles).toBeGreaterThan(0);
  const stats = await page.evaluate(() => window.demo.stats());
  // The most stack ever used, from the start of the page through the loads, is a small part of it.
  expect(stats.stackBytes).toBe(256 * 1024);
  expect(stats.stackHighWaterBytes).toBeGreaterThan(0);
  expect(stats.stackHighWaterBytes).toBeLessThan(stats.stackBytes / 4);
});

test('a scene whose capture near plane lies outside a mirror loads, with a notice naming the mirror', async ({ page }) => {
  // A mirror of radius about 0.6 whose box reaches 0.509 from its centre (sphere.obj's 2.55, scaled 0.2)
  // inside a near plane of 1: its captures would leave out whatever passes closer
  // (core/capture_near.h).
  const body = JSON.stringify({
    capture: { faceSize: 64, near: 1, far: 100 },
    objects: [{ mesh: 'quad.obj', translate: [0, -2, 0], scale: [10, 1, 10] },
              { mesh: 'sphere.obj', scale: 0.2, material: { type: 'mirror' } }],
  });
  await page.route((u) => u.pathname.endsWith('/small-mirror.json'),
                   (route) => route.fulfill({ status: 200, contentType: 'application/json', body }));
  await openDemo(page, '?paused');
  const error = await page.evaluate(() => window.demo.loadScene('small-mirror.json').then(() => '', (e) => e.message));
  expect(error).toBe('');
  expect(await page.evaluate(() => window.demo.scene().name)).toBe('small-mirror');
  await expect(page.locator('#messages .message.info', { hasText: 'small-mirror: capture.near 1 lies outside object 1 (sphere.obj)' }))
    .toContainText('set capture.near to at most 0.509');
});
