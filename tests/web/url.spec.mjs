// The URL mirrors every control (history.replaceState), and opening such a link restores the
// scene, the capture settings, the camera and the paused time.
import { test, expect } from '@playwright/test';
import { expectMessage, idle, messages, openDemo, PANEL_OPEN_VIEWPORT } from './helpers.mjs';

// The panel's controls are used: a window where it starts open, the canvas 800x600 beside it.
test.use({ viewport: PANEL_OPEN_VIEWPORT });

const query = (page) => new URL(page.url()).search;

test('the address bar follows the controls, the camera and the time', async ({ page }) => {
  await openDemo(page, '?paused&t=1');
  await expect.poll(() => query(page)).toBe('?scene=ex12-2&policy=when-changed&paused&t=1');

  await page.locator('#control-policy select').selectOption('time-sliced');
  await expect.poll(() => query(page)).toContain('policy=time-sliced&facesPerFrame=2');
  await page.locator('#control-captureLod input').fill('0.25');
  await page.locator('#control-captureLod input').press('Enter');
  await expect.poll(() => query(page)).toContain('&captureLod=0.25');
  await page.locator('#control-cube select').selectOption('64');
  await idle(page);
  expect((await page.evaluate(() => window.demo.frame(0))).cubeFaceSize).toBe(64);
  await expect.poll(() => query(page)).toContain('&cube=64&');

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
  await expect.poll(() => query(page)).toMatch(/^\?scene=two-mirrors&cube=64&policy=time-sliced&facesPerFrame=2&captureLod=0\.25&paused&t=0$/);
});

test('a link keeps a setting\'s four decimals when the page rewrites it', async ({ page }) => {
  // (The panel's field steps by 0.01; a link may hold finer values, and reloading must keep them.)
  await openDemo(page, '?captureLod=0.0625&paused&t=1');
  await expect.poll(() => query(page)).toBe('?scene=ex12-2&policy=when-changed&captureLod=0.0625&paused&t=1');
});

test('opening a copied link restores scene, cube, policy, camera and time', async ({ page, context }) => {
  // Two page loads, a scene switch and a cube reload, each followed by its levels of detail: more
  // than the default minute on a busy 2-core machine.
  test.setTimeout(150_000);
  await context.grantPermissions(['clipboard-read', 'clipboard-write']);
  await openDemo(page, '?scene=ex12-2');
  await page.evaluate(() => window.demo.loadScene('skybox'));
  await page.locator('#control-policy select').selectOption('every-n');
  await page.locator('#control-everyN input').fill('3');
  await page.locator('#control-everyN input').press('Enter');
  await page.locator('#control-cube select').selectOption('128');
  await idle(page);
  expect((await page.evaluate(() => window.demo.frame(0))).cubeFaceSize).toBe(128);
  await page.evaluate(() => window.demo.setCamera(1.25, 1.5, 5, 20, -12.5));
  await page.locator('#control-paused input').check();
  await page.evaluate(() => window.demo.setTime(2.5));
  // The copy-link button (in its folder). No frame has run since setTime: the link reads the clock.
  await page.locator('#control-link button').click();
  await expectMessage(page, 'Link copied', 'info');
  const link = await page.evaluate(() => navigator.clipboard.readText());
  await expect.poll(() => page.url()).toBe(link);
  expect(new URL(link).search).toBe('?scene=skybox&cube=128&policy=every-n&everyN=3&paused&t=2.5&cam=1.25,1.5,5,20,-12.5');

  const other = await context.newPage();
  // In front, as a link opened by the user is: the page parses and builds levels in steps between
  // tasks, which Chromium throttles to one a second in a page behind another.
  await other.bringToFront();
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
  await expect(other.locator('#control-policy select')).toHaveValue('every-n');
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
  await openDemo(page, '?paused&scene=ex12-1&facesPerFrame=9&cam=1,2&policy=every-frame&mipmaps=maybe');
  await expect(page.locator('#messages .message', { hasText: 'facesPerFrame: 9 is not in 1..6' })).toBeVisible();
  await expect(page.locator('#messages .message', { hasText: 'mipmaps: "maybe" is not true or false' })).toBeVisible();
  await expect(page.locator('#messages .message', { hasText: 'cam=1,2' })).toBeVisible();
  expect(await page.evaluate(() => window.demo.scene().name)).toBe('ex12-1');
  expect((await page.evaluate(() => window.demo.planner())).policy).toBe('every-frame');
});

test('every planner and accuracy setting goes by its schema name, both ways', async ({ page }) => {
  const schema = await (async () => {
    await openDemo(page, '?paused');
    return page.evaluate(() => window.demo.schema());
  })();
  expect(schema.planner.map((i) => i.name)).toEqual(['policy', 'facesPerFrame', 'everyN', 'captureLod', 'viewLod']);
  await openDemo(page, '?paused&policy=time-sliced&facesPerFrame=3&everyN=7&captureLod=0.25&viewLod=0.25' +
                       '&search=linear&layers=1&mipmaps=true&halfFloat');
  expect(await page.evaluate(() => window.demo.planner())).toMatchObject(
    { policy: 'time-sliced', facesPerFrame: 3, everyN: 7, captureLod: 0.25, viewLod: 0.25 });
  expect(await page.evaluate(() => window.demo.accuracy())).toMatchObject(
    { search: 'linear', layers: 1, mipmaps: true, halfFloat: true, captureAtOrigin: false, depthBits: 24 });
  // everyN does nothing under time-sliced: not in the link; settings at their defaults neither.
  expect(await page.evaluate(() => window.demo.query())).toBe(
    '?scene=ex12-2&policy=time-sliced&facesPerFrame=3&captureLod=0.25&viewLod=0.25&paused&t=0' +
    '&search=linear&layers=1&mipmaps=true&halfFloat=true');
  // The panel's labels are the schema's.
  for (const info of schema.planner) {
    await expect(page.locator(`#control-${info.name} .lil-name`)).toHaveText(info.label);
  }
  expect(await messages(page)).toEqual([]);
});

test("an old link's keys are read as the new ones, each with a message naming it", async ({ page }) => {
  await openDemo(page, '?paused&policy=time-sliced&slice=3&lod=0.25&vlod=0.25' +
                       '&acc=centre,distance-x2,depth-24,mipmapped,RGBA8,highp&mat=3:0.3,0.3,1,1.52');
  expect(await page.evaluate(() => window.demo.planner())).toMatchObject(
    { policy: 'time-sliced', facesPerFrame: 3, captureLod: 0.25, viewLod: 0.25 });
  expect(await page.evaluate(() => window.demo.accuracy())).toMatchObject({ search: 'linear', mipmaps: true });
  expect(await page.evaluate(() => window.demo.objects()[3].material)).toMatchObject(
    { reflection: 0.3, base: 0.3, fresnel: true, ior: 1.52, environment: 'live' });
  const notes = (await messages(page)).map((m) => m.text);
  for (const expected of ['slice=3: an old link\'s key, now facesPerFrame=3', 'lod=0.25: an old link\'s key, now captureLod=0.25',
                          'vlod=0.25: an old link\'s key, now viewLod=0.25',
                          'acc=centre,distance-x2,depth-24,mipmapped,RGBA8,highp: an old link\'s form, now search=linear&mipmaps=true',
                          'mat=3:0.3,0.3,1,1.52: an old link\'s form, now mat=3:reflection=0.3,base=0.3,fresnel=true,ior=1.52']) {
    expect(notes.filter((n) => n.startsWith(expected)), expected).toHaveLength(1);
  }
  for (const note of notes) expect(note).not.toContain('\n');  // one line each
  // The address bar has the new keys only.
  await expect.poll(() => query(page)).toBe(
    '?scene=ex12-2&policy=time-sliced&facesPerFrame=3&captureLod=0.25&viewLod=0.25&paused&t=0&search=linear&mipmaps=true' +
    '&mat=3:reflection=0.3,fresnel=true');
});
