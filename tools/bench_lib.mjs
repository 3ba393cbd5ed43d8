// What the browser benches share: the repository's root, a free port, the static server
// (tools/serve.mjs) started on it, Debian's Chromium launched as playwright.config.mjs launches it,
// percentiles, and the renderer processes' memory.
import { readFileSync, readdirSync } from 'node:fs';
import { spawn } from 'node:child_process';
import { createServer } from 'node:net';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from '@playwright/test';

export const repo = resolve(dirname(fileURLToPath(import.meta.url)), '..');

// The same launch options as playwright.config.mjs; `extraArgs` for a bench's own flags
// (e.g. --js-flags=--expose-gc).
export function chromiumOptions(extraArgs = []) {
  return {
    executablePath: process.env.CHROMIUM_PATH || '/usr/bin/chromium',
    args: ['--no-sandbox', '--disable-background-networking', '--disable-component-update',
           '--disable-sync', '--no-first-run', '--disable-default-apps', ...extraArgs],
  };
}

export const launchChromium = (extraArgs = []) => chromium.launch(chromiumOptions(extraArgs));

export function freePort() {
  return new Promise((resolvePort, reject) => {
    const server = createServer();
    server.unref();
    server.on('error', reject);
    server.listen(0, '127.0.0.1', () => {
      const { port } = server.address();
      server.close(() => resolvePort(port));
    });
  });
}

// Serves `root` on 127.0.0.1:`port`; resolves once it answers, to { child, url }.
export async function startServer(port, root) {
  const child = spawn(process.execPath, [join(repo, 'tools/serve.mjs'), root, String(port)], {
    stdio: ['ignore', 'ignore', 'inherit'],
  });
  const url = `http://127.0.0.1:${port}/`;
  for (let attempt = 0; attempt < 100; ++attempt) {
    if (child.exitCode !== null) throw new Error(`serve.mjs exited with ${child.exitCode}`);
    try {
      if ((await fetch(url)).ok) return { child, url };
    } catch { /* not listening yet */ }
    await new Promise((r) => setTimeout(r, 100));
  }
  child.kill();
  throw new Error(`server did not answer at ${url}`);
}

// Linear interpolation between the nearest ranks (p in [0, 1]).
export function percentile(values, p) {
  const sorted = [...values].sort((a, b) => a - b);
  const index = (sorted.length - 1) * p;
  const lo = Math.floor(index), hi = Math.ceil(index);
  return sorted[lo] + (sorted[hi] - sorted[lo]) * (index - lo);
}

export function summary(values) {
  return { p10: percentile(values, 0.1), median: percentile(values, 0.5), p90: percentile(values, 0.9) };
}

// Resident memory (VmRSS) summed over the renderer processes among `pid`'s descendants.
export function rendererMemory(pid) {
  const parents = new Map();
  for (const entry of readdirSync('/proc')) {
    if (!/^\d+$/.test(entry)) continue;
    try {
      const stat = readFileSync(`/proc/${entry}/stat`, 'utf8');
      const fields = stat.slice(stat.lastIndexOf(')') + 2).split(' ');
      parents.set(Number(entry), Number(fields[1]));
    } catch { /* gone */ }
  }
  const descends = (p) => {
    for (let q = p, depth = 0; q && depth < 64; q = parents.get(q), ++depth) if (q === pid) return true;
    return false;
  };
  let kb = 0, count = 0;
  for (const p of parents.keys()) {
    if (!descends(p)) continue;
    try {
      if (!readFileSync(`/proc/${p}/cmdline`, 'utf8').includes('--type=renderer')) continue;
      const rss = /VmRSS:\s+(\d+) kB/.exec(readFileSync(`/proc/${p}/status`, 'utf8'));
      if (rss) { kb += Number(rss[1]); ++count; }
    } catch { /* gone */ }
  }
  return { mb: kb / 1024, processes: count };
}
