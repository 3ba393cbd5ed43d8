// The page calls the wasm module only through exports the C++ defines: the table the build writes
// from src/platform/web/*.cpp (wasm_exports.js) holds every rf_ name the page's scripts use, and
// the module built beside it exports each one.
import { test, expect } from '@playwright/test';
import { readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import { openDemo } from './helpers.mjs';

const webDir = new URL('../../web/', import.meta.url).pathname;

test('every export the page names is in the table the build wrote from the C++', async ({ page }) => {
  await openDemo(page, '?paused&t=0');
  const table = await page.evaluate(async () => Object.keys((await import('./wasm_exports.js')).EXPORTS));
  expect(table.length).toBeGreaterThan(30);
  const used = new Set();
  for (const file of readdirSync(webDir).filter((f) => f.endsWith('.js'))) {
    for (const name of readFileSync(join(webDir, file), 'utf8').match(/\brf_[a-z_]+/g) || []) used.add(name);
  }
  expect([...used].filter((name) => !table.includes(name))).toEqual([]);
  // And the module has each of them (cwrap would otherwise fail only when first called).
  const missing = await page.evaluate(async (names) => {
    const module = await window.reflectModule;
    return names.filter((n) => typeof module['_' + n] !== 'function');
  }, table);
  expect(missing).toEqual([]);
});
