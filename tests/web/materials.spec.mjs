// The Materials folder: each mirror's and glass object's reflection weight, base weight, Fresnel,
// index of refraction and environment, applied to the renderer and mirrored in the URL (mat=).
import { test, expect } from '@playwright/test';
import {
  changedInSphere, collectErrors, expectedSphereBox, openDemo, PANEL_OPEN_VIEWPORT, renderAndRead,
} from './helpers.mjs';

// The panel's controls are used: a window where it starts open, the canvas 800x600 beside it.
test.use({ viewport: PANEL_OPEN_VIEWPORT });

// The link to what is on screen, as the page builds it (not the address bar, which is written
// as changes happen and read by the test runner a moment later).

const query = (page) => page.evaluate(() => window.demo.query());
const sphere = (page) => page.evaluate(() => window.demo.objects()[3].material);

test('the reflection weight and the Fresnel switch change the sphere and the URL', async ({ page }) => {
  const errors = collectErrors(page);
  await openDemo(page, '?paused&t=1&policy=every-frame');
  expect(await sphere(page)).toEqual({ type: 'mirror', reflection: 0.78, base: 0.3, ior: 1.52, fresnel: false, roughness: 0,
                                       environment: 'live' });
  const original = await renderAndRead(page);
  await page.locator('#materials > .lil-title').click();  // open the folder
  await expect(page.locator('#control-mat-3 input')).toHaveValue('mirror 0.78 refl + 0.3 base');

  await page.locator('#control-mat-3-reflection input').fill('0.3');
  await page.locator('#control-mat-3-reflection input').press('Enter');
  await expect.poll(async () => (await sphere(page)).reflection).toBeCloseTo(0.3, 5);
  await expect(page.locator('#control-mat-3 input')).toHaveValue('mirror 0.3 refl + 0.3 base');
  const weaker = await renderAndRead(page);
  const box = expectedSphereBox(original.width, original.height);
  const area = (box.x1 - box.x0 + 1) * (box.y1 - box.y0 + 1);
  expect(changedInSphere(original, weaker)).toBeGreaterThan(area * 0.4);
  await expect.poll(() => query(page)).toContain('&mat=3:reflection=0.3');

  await page.locator('#control-mat-3-fresnel input').check();
  await expect.poll(async () => (await sphere(page)).fresnel).toBe(true);
  await expect(page.locator('#control-mat-3 input')).toHaveValue('mirror, Fresnel (ior 1.52)');
  const fresnel = await renderAndRead(page);
  expect(changedInSphere(weaker, fresnel)).toBeGreaterThan(area * 0.2);
  await expect.poll(() => query(page)).toContain('&mat=3:reflection=0.3,fresnel=true');

  // The index of refraction (Fresnel on: it changes the reflectance).
  await page.locator('#control-mat-3-ior input').fill('2.4');
  await page.locator('#control-mat-3-ior input').press('Enter');
  await expect.poll(async () => (await sphere(page)).ior).toBeCloseTo(2.4, 5);
  expect(changedInSphere(fresnel, await renderAndRead(page))).toBeGreaterThan(area * 0.2);

  // The link restores the material; the address bar has it too.
  const link = await query(page);
  expect(link).toContain('&mat=3:reflection=0.3,ior=2.4,fresnel=true');
  await expect.poll(() => new URL(page.url()).search).toBe(link);
  const other = await page.context().newPage();
  await openDemo(other, link);
  expect(await sphere(other)).toMatchObject({ reflection: 0.3, fresnel: true, ior: 2.4 });
  await other.close();

  // Back to the scene file's values: mat= goes away.
  await page.locator('#control-mat-3-fresnel input').uncheck();
  for (const [key, value] of [['reflection', '0.78'], ['ior', '1.52']]) {
    await page.locator(`#control-mat-3-${key} input`).fill(value);
    await page.locator(`#control-mat-3-${key} input`).press('Enter');
  }
  await expect.poll(() => query(page)).not.toContain('mat=');
  expect(changedInSphere(original, await renderAndRead(page))).toBeLessThan(area * 0.01);
  expect(errors).toEqual([]);
});

test('glass and skybox scenes: environment and bad mat= entries', async ({ page }) => {
  await openDemo(page, '?scene=skybox&paused&mat=99:reflection=0.5;x');
  await expect(page.locator('#messages .message', { hasText: 'mat=x: expected INDEX:' })).toBeVisible();
  await expect(page.locator('#messages .message', { hasText: 'no object 99' })).toBeVisible();
  const objects = await page.evaluate(() => window.demo.objects());
  const index = objects.findIndex((o) => ['mirror', 'glass'].includes(o.material.type));
  expect(index).toBeGreaterThanOrEqual(0);
  const environment = objects[index].material.environment;
  const other = environment === 'live' ? 'skybox' : 'live';
  await page.locator('#materials > .lil-title').click();
  await page.locator(`#control-mat-${index}-environment select`).selectOption(other);
  await expect.poll(() => page.evaluate((i) => window.demo.objects()[i].material.environment, index)).toBe(other);
  await expect.poll(() => query(page)).toContain(`mat=${index}:`);
  // A phong object cannot take mirror settings.
  const phong = objects.findIndex((o) => o.material.type === 'phong');
  expect(await page.evaluate((i) => window.demo.setMaterial(i, { reflection: 0.5 }), phong)).toContain('not a mirror or glass');
});
