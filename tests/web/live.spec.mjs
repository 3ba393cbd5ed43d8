// The live numbers: the stats line (GPU or CPU timings, labelled), and the frame-time sparkline.
import { test, expect } from '@playwright/test';
import { openDemo } from './helpers.mjs';

test('the stats line and the sparkline follow the running demo', async ({ page }) => {
  await openDemo(page, '?t=0');
  const stats = page.locator('#stats');
  await expect(stats).toHaveText(/fps/);
  // Frames come as the display loop runs; how many in a given time depends on the machine, so
  // the test waits (with a long limit) for a couple more, not for a number in a time.
  const first = await page.evaluate(() => window.demo.sparkSamples());
  await expect.poll(() => page.evaluate(() => window.demo.sparkSamples()), { timeout: 30_000 })
    .toBeGreaterThanOrEqual(first + 2);
  // The line names which timer its numbers come from.
  const s = await page.evaluate(() => window.demo.stats());
  const label = s.gpuFrameMs >= 0 ? 'gpu' : 'cpu';
  await expect(stats).toContainText(` · ${label} `);
  expect(s.time).toBeGreaterThan(0);
  // The line changes as the demo runs (the triangle and face counts of a moving scene, the fps).
  const a = await stats.textContent();
  await expect.poll(() => stats.textContent(), { timeout: 30_000 }).not.toBe(a);
  // The sparkline has drawn something.
  const inked = await page.evaluate(() => {
    const c = document.getElementById('spark');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 3; i < d.length; i += 4) if (d[i] > 0) ++n;
    return { n, width: c.width, height: c.height };
  });
  expect(inked.width).toBeGreaterThan(100);
  expect(inked.n).toBeGreaterThan(100);
});
