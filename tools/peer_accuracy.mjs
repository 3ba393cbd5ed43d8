// The accuracy part of tools/peer_bench.mjs (--reference PNG): each page's frame at one scene time
// read back and compared with a reference image (the native CLI's `reflect render --reference`)
// over the reflector pixels, with the project's own measures (src/core/error_metrics.cpp): PSNR
// of the RGB error (capped at 99 dB) and pixels whose largest channel error is over 32 levels.
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { repo } from './bench_lib.mjs';
import { decodePng, encodePng } from './png.mjs';

// Frames drawn at the time before the read-back: a probe's capture shows the other mirrors as
// they were the frame before, so the first frame at T still has them at the previous time.
export const FRAMES_AT_TIME = 3;
const VISIBLE_LEVELS = 32;  // core/error_metrics.h kVisibleErrorLevels
const PSNR_CAP_DB = 99;

// The page's picture at scene time `t`: { width, height, data } (RGBA, top row first). The frames
// and the read-back run in one task, so the drawing buffer is still the frame's.
export async function pixelsAt(page, api, t) {
  const read = await page.evaluate(({ name, time, frames }) => {
    const driven = window[name];
    driven.setTime(time);
    for (let i = 0; i < frames; ++i) driven.frame(0);
    const { width, height, data } = driven.readPixels();
    let text = '';
    for (let i = 0; i < data.length; i += 0x8000) text += String.fromCharCode(...data.subarray(i, i + 0x8000));
    return { width, height, base64: btoa(text) };
  }, { name: api, time: t, frames: FRAMES_AT_TIME });
  const bottomFirst = Buffer.from(read.base64, 'base64');
  const stride = read.width * 4;
  const data = new Uint8Array(bottomFirst.length);
  for (let y = 0; y < read.height; ++y) {
    data.set(bottomFirst.subarray((read.height - 1 - y) * stride, (read.height - y) * stride), y * stride);
  }
  return { width: read.width, height: read.height, data };
}

export const readPng = (path) => decodePng(readFileSync(path), path);
export const writePng = (path, image) => writeFileSync(path, encodePng(image));

// A reflector pixel (red over half) holds 1 + its mirror's number, 255 - green (the pmrem peer's
// ?mask tells mirrors apart so; a white mask is all mirror 0); 0 elsewhere.
export function maskOf(image) {
  const mask = new Uint8Array(image.width * image.height);
  for (let p = 0; p < mask.length; ++p) mask[p] = image.data[p * 4] > 127 ? 256 - image.data[p * 4 + 1] : 0;
  return mask;
}

// The error of `image` against `reference` over the pixels `mask` marks (those of mirror `only`
// alone when given): { compared, rmse, psnrDb, over, maxError }, or { error } when the sizes differ.
export function compareImages(image, reference, mask, only = null) {
  if (image.width !== reference.width || image.height !== reference.height) {
    return { error: `the page is ${image.width}x${image.height}, the reference ${reference.width}x${reference.height}` };
  }
  let compared = 0, over = 0, maxError = 0, sumSquares = 0;
  for (let p = 0; p < mask.length; ++p) {
    if (!mask[p] || (only !== null && mask[p] !== only + 1)) continue;
    ++compared;
    let largest = 0;
    for (let c = 0; c < 3; ++c) {
      const d = Math.abs(image.data[p * 4 + c] - reference.data[p * 4 + c]);
      sumSquares += d * d;
      largest = Math.max(largest, d);
    }
    if (largest > VISIBLE_LEVELS) ++over;
    maxError = Math.max(maxError, largest);
  }
  const rmse = compared ? Math.sqrt(sumSquares / (3 * compared)) : 0;
  const psnrDb = rmse > 0 ? Math.min(PSNR_CAP_DB, 20 * Math.log10(255 / rmse)) : PSNR_CAP_DB;
  return { compared, rmse, psnrDb, over, maxError };
}

export function describeComparison(label, r) {
  if (r.error) return `${label.padEnd(28)} not compared: ${r.error}`;
  const share = r.compared ? (100 * r.over) / r.compared : 0;
  return `${label.padEnd(28)}${r.psnrDb.toFixed(2).padStart(9)}${r.rmse.toFixed(2).padStart(9)}` +
         `${String(r.over).padStart(10)} (${share.toFixed(2).padStart(5)}%)${String(r.maxError).padStart(6)}`;
}

export const COMPARISON_HEADER = `${'page'.padEnd(28)}${'PSNR dB'.padStart(9)}${'RMSE'.padStart(9)}` +
                                 `${`off >${VISIBLE_LEVELS}`.padStart(10)}${'share'.padStart(9)}${'max'.padStart(6)}`;

// After the timing: every page drawn at o.time and compared with o.reference over the reflector
// mask, o.mask's white pixels or, without it, the mirrors of `maskPage` (a scene-file peer) drawn
// in its ?mask mode (written to o.saveMask when asked). `openPage(browser, base, spec, o, extra)`
// is peer_bench's; `extraFor(spec)` the query parts that pause a page at o.time.
export async function runAccuracy(browser, base, pages, o, { openPage, extraFor, maskPage }) {
  const reference = readPng(o.reference);
  let mask;
  if (o.mask) mask = maskOf(readPng(o.mask));
  else {
    if (!maskPage) throw new Error('--reference without --mask needs the pmrem peer to draw the mask');
    const image = await drawnAt(browser, base, maskPage, o, openPage, [...extraFor(maskPage), 'mask']);
    if (o.saveMask) {
      writePng(o.saveMask, image);
      console.log(`wrote the reflector mask ${o.saveMask}`);
    }
    mask = maskOf(image);
  }
  if (mask.length !== reference.width * reference.height) {
    throw new Error(`the mask has ${mask.length} pixels, the reference ${reference.width}x${reference.height}`);
  }
  const reflectorPixels = mask.reduce((n, m) => n + (m ? 1 : 0), 0);
  const mirrors = [...new Set(mask)].filter(Boolean).sort((a, b) => a - b).map((m) => m - 1);
  const roughness = mirrorRoughness(o.scene);
  console.log('');
  console.log(`accuracy against ${o.reference} (${reference.width}x${reference.height}) at t = ${o.time} s ` +
              `(${FRAMES_AT_TIME} frames there), over ${reflectorPixels} reflector pixels ` +
              `(${o.mask ? o.mask : 'mask: the pmrem peer\'s mirrors'}):`);
  console.log(COMPARISON_HEADER);
  for (const spec of pages) {
    const image = await drawnAt(browser, base, spec, o, openPage, extraFor(spec));
    console.log(describeComparison(spec.label, compareImages(image, reference, mask)));
    if (mirrors.length < 2) continue;
    for (const k of mirrors) {
      const name = `  mirror ${k + 1}` + (roughness[k] !== undefined ? `, roughness ${roughness[k]}` : '');
      console.log(describeComparison(name, compareImages(image, reference, mask, k)));
    }
  }
}

// The roughness of each mirror of the shipped scene `name`, in the file's order (the pmrem peer's
// mask numbers them so); none without a scene (the default scene has one mirror).
function mirrorRoughness(name) {
  if (!name) return [];
  const file = JSON.parse(readFileSync(join(repo, 'assets/scenes', `${name}.json`), 'utf8'));
  return file.objects.filter((o) => o.material?.type === 'mirror').map((o) => o.material.roughness ?? 0);
}

async function drawnAt(browser, base, spec, o, openPage, extra) {
  const { context, page, api, problems } = await openPage(browser, base, spec, o, extra);
  try {
    const image = await pixelsAt(page, api, o.time);
    for (const p of problems) console.log(`  note (${spec.key}): ${p}`);
    return image;
  } finally {
    await context.close();
  }
}
