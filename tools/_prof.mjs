import { launchChromium } from '/work/main/tools/bench_lib.mjs';
const browser = await launchChromium();
const page = await browser.newPage({ viewport: { width: 800, height: 800 } });
const cdp = await page.context().newCDPSession(page);
await cdp.send('Profiler.enable');
await cdp.send('Profiler.setSamplingInterval', { interval: 200 });
await cdp.send('Profiler.start');
await page.goto(process.argv[2]);
await page.waitForFunction(() => window.demo && window.demo.ready !== undefined, null, { timeout: 30000 });
await page.evaluate(() => window.demo.ready);
const { profile } = await cdp.send('Profiler.stop');
const marks = await page.evaluate(() => performance.getEntriesByType('mark').map((m) => `${m.startTime.toFixed(0)} ${m.name}`));
console.log(marks.join('\n'));
const byId = new Map(profile.nodes.map((n) => [n.id, n]));
const self = new Map();
const total = new Map();
const parent = new Map();
for (const n of profile.nodes) for (const c of n.children || []) parent.set(c, n.id);
for (let i = 0; i < profile.samples.length; ++i) {
  const dt = (profile.timeDeltas[i + 1] ?? 0) / 1000;
  const n = byId.get(profile.samples[i]);
  const name = `${n.callFrame.functionName || '(anon)'} ${n.callFrame.url.split('/').pop()}`;
  self.set(name, (self.get(name) || 0) + dt);
  const seen = new Set();
  for (let id = n.id; id !== undefined; id = parent.get(id)) {
    const m = byId.get(id);
    const nm = `${m.callFrame.functionName || '(anon)'} ${m.callFrame.url.split('/').pop()}`;
    if (seen.has(nm)) continue;
    seen.add(nm);
    total.set(nm, (total.get(nm) || 0) + dt);
  }
}
const top = (m, k) => [...m.entries()].sort((a, b) => b[1] - a[1]).slice(0, k).map(([n, t]) => `${t.toFixed(1).padStart(7)} ${n}`).join('\n');
console.log('--- self ms\n' + top(self, 30));
console.log('--- total ms\n' + top(total, 45));
await browser.close();
