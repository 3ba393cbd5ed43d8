// The page and the native CLI share one renderer: the same scene at the same time and size must
// give the same picture. Each shipped scene with a reflector is drawn in the page (SwiftShader)
// and by build/native/reflect (llvmpipe; ./test.sh builds it before the web tests), and compared
// with the goldens' thresholds (tests/gl/golden_compare.h): over the frame, and inside the
// reflectors, which the page finds by drawing them once more as plain Phong (every pixel the
// reflection coloured changes).
import { test, expect } from '@playwright/test';
import { execFileSync } from 'node:child_process';
import { mkdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { openDemo, renderAndRead } from './helpers.mjs';
import { decodePng } from './png.mjs';

const REFLECT = 'build/native/reflect';
const OUTPUT = 'build/web-test-output';
const TOLERANCE = 16;                                   // levels a channel
const FRAME = { fractionOver: 0.002, mean: 0.5 };  // kMaxFractionOver, kMaxMeanDifference
// Inside the reflectors the goldens' mean (a mirror's mix of 0.78 changed to 0.70 moves it by 8
// or more), and 0.5% of pixels over the tolerance where the goldens allow 0.2%: two rasterisers
// filter a cube map and round a reflected silhouette differently, and that alone put 0.22% of
// skybox-grid's mirror pixels (along its grid lines, mirror-symmetric) and 0.27% of
// shared-probe's (single pixels on reflected outlines) over 16 levels, by 17 to 130.
const REFLECTORS = { fractionOver: 0.005, mean: 1.0 };
// rough-spheres' rough mirrors take 16 lobe taps a pixel from the capture's box chain at
// fractional levels; glGenerateMipmap's filter and trilinear cube filtering are the
// implementation's, so SwiftShader and llvmpipe part by a few levels over whole spheres. The taps
// also show each sphere's neighbours, drawn in its capture from their own probes: that second
// bounce depends on the frames drawn before (the page has drawn frames before t = 2 s,
// `reflect render` draws one), and the difference image puts the largest differences there.
// Measured at 800x600, t = 2 (lobe taps): frame 0.668% over 16 levels, mean 0.329; reflectors
// 7.50%, mean 3.56 (from the prefiltered levels it was 0.34%, 0.20; 3.78%, 2.13). Limits above
// those by about a third (loosened with lobe taps, for the reason above); the rough spheres drawn
// sharp (roughness ignored) are past them: 1.97% of the frame over, mean 0.78, natively.
const ROUGH = { frame: { fractionOver: 0.009, mean: 0.5 }, reflectors: { fractionOver: 0.10, mean: 4.75 } };
// frosted-glass takes lobe taps the same way, but parts far less (measured at 800x600, t = 2:
// frame 0.131% over 16 levels, mean 0.082; reflectors 1.735%, mean 1.033; from the prefiltered
// levels 0.051%, 0.063; 0.656%, 0.78): the sharp scenes' frame limits, its reflectors' above
// what it measured by about a third.
const FROSTED = { frame: FRAME, reflectors: { fractionOver: 0.025, mean: 1.4 } };

// Max channel difference per pixel of two RGBA images of one size.
function differences(a, b) {
  const out = new Uint8Array(a.width * a.height);
  for (let p = 0, i = 0; p < out.length; ++p, i += 4) {
    out[p] = Math.max(Math.abs(a.data[i] - b.data[i]), Math.abs(a.data[i + 1] - b.data[i + 1]),
                      Math.abs(a.data[i + 2] - b.data[i + 2]));
  }
  return out;
}

// Share of pixels over the tolerance and mean channel difference, where `mask` is set (all: null).
function summary(a, b, mask) {
  let count = 0, over = 0, sum = 0;
  for (let p = 0, i = 0; p < a.width * a.height; ++p, i += 4) {
    if (mask && !mask[p]) continue;
    ++count;
    let worst = 0;
    for (let c = 0; c < 3; ++c) {
      const d = Math.abs(a.data[i + c] - b.data[i + c]);
      sum += d;
      worst = Math.max(worst, d);
    }
    if (worst > TOLERANCE) ++over;
  }
  return { count, fractionOver: over / Math.max(count, 1), mean: sum / Math.max(3 * count, 1) };
}

const SCENES = ['ex12-2', 'ex12-2-fresnel', 'glass-sphere', 'two-mirrors', 'shared-probe', 'skybox-grid', 'skybox', 'rough-spheres', 'frosted-glass', 'probe-lit'];

for (const scene of SCENES) {
  test(`${scene}: the page draws what the native renderer draws`, async ({ page }) => {
    await openDemo(page, `?scene=${scene}&paused`);
    const shown = await renderAndRead(page, 2.0);
    // The reflectors: what changes when every mirror and glass is drawn as plain Phong.
    const objects = await page.evaluate(() => window.demo.objects());
    const reflectors = objects.map((o, i) => [o, i]).filter(([o]) => ['mirror', 'glass'].includes(o.material.type));
    expect(reflectors.length, 'the scene has a reflector').toBeGreaterThan(0);
    for (const [, i] of reflectors) await page.evaluate((k) => window.demo.setMaterial(k, { type: 'phong' }), i);
    const plain = await renderAndRead(page, 2.0);
    const mask = differences(shown, plain).map((d) => (d > 8 ? 1 : 0));

    mkdirSync(OUTPUT, { recursive: true });
    const file = join(OUTPUT, `native-${scene}.png`);
    execFileSync(REFLECT, ['render', '--scene', scene, '--time', '2', '--size', `${shown.width}x${shown.height}`,
                           '--out', file], { stdio: 'pipe' });
    const native = decodePng(readFileSync(file));
    expect([native.width, native.height]).toEqual([shown.width, shown.height]);

    const frame = summary(shown, native, null);
    const inside = summary(shown, native, mask);
    console.log(`${scene} ${shown.width}x${shown.height}: frame mean ${frame.mean.toFixed(3)}, over ` +
                `${(100 * frame.fractionOver).toFixed(3)}%; reflectors (${inside.count} px) mean ` +
                `${inside.mean.toFixed(3)}, over ${(100 * inside.fractionOver).toFixed(3)}%`);
    expect(inside.count, 'reflector pixels found').toBeGreaterThan(500);
    const limits = scene === 'rough-spheres' ? ROUGH
                 : scene === 'frosted-glass' ? FROSTED
                 : { frame: FRAME, reflectors: REFLECTORS };
    expect(frame.fractionOver).toBeLessThanOrEqual(limits.frame.fractionOver);
    expect(frame.mean).toBeLessThanOrEqual(limits.frame.mean);
    expect(inside.fractionOver).toBeLessThanOrEqual(limits.reflectors.fractionOver);
    expect(inside.mean).toBeLessThanOrEqual(limits.reflectors.mean);
  });
}
