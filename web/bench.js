// Bench mode (?bench, or the panel's button): the same animation under each capture policy on
// the current scene, with the render cost and how far each policy's pictures are from
// re-capturing every frame. The page's own frame loop is held while it runs, so nothing else
// renders in between.
import { showMessage } from './messages.js';

// The planner settings of each run, by the schema's names (the rest stay the defaults below).
const BASE = { policy: 'when-changed', facesPerFrame: 2, everyN: 4, captureLod: 0, viewLod: 0 };
export const BENCH_CONFIGS = [
  { label: 'every-frame', settings: { ...BASE, policy: 'every-frame' } },
  { label: 'when-changed', settings: BASE },
  { label: 'when-changed+LOD 0.5', settings: { ...BASE, captureLod: 0.5 } },
  { label: 'when-changed+LOD+view 0.5', settings: { ...BASE, captureLod: 0.5, viewLod: 0.5 } },
  { label: 'time-sliced 2', settings: { ...BASE, policy: 'time-sliced' } },
  { label: 'every-n 4', settings: { ...BASE, policy: 'every-n' } },
];

function percentile(values, p) {
  const sorted = [...values].sort((a, b) => a - b);
  const index = (sorted.length - 1) * p;
  const lo = Math.floor(index), hi = Math.ceil(index);
  return sorted[lo] + (sorted[hi] - sorted[lo]) * (index - lo);
}
const mean = (values) => values.reduce((a, b) => a + b, 0) / Math.max(values.length, 1);

// Largest per-channel difference (RGB) between two RGBA frames, and how many pixels differ.
function compare(a, b) {
  let max = 0, differing = 0;
  for (let i = 0; i < a.length; i += 4) {
    const d = Math.max(Math.abs(a[i] - b[i]), Math.abs(a[i + 1] - b[i + 1]), Math.abs(a[i + 2] - b[i + 2]));
    if (d) {
      ++differing;
      if (d > max) max = d;
    }
  }
  return { max, differing };
}

// demo: { frame(dt) -> stats (waits for the GPU), setTime, setPlanner(settings) -> "" or the error,
// levels() -> a promise of the levels the settings need, readPixels() -> { width, height, data },
// scene() }.
// Returns { scene, frames, width, height, rows: [...], table }.
export async function runBench(demo, { frames = 60, onProgress = () => {} } = {}) {
  const memoryLimit = 512 * 1024 * 1024;  // reference frames kept for the comparison
  let reference = [];
  let compareEvery = 1;
  const rows = [];
  let size = null;
  for (const config of BENCH_CONFIGS) {
    onProgress(`bench: ${config.label} (${rows.length + 1}/${BENCH_CONFIGS.length}), ${frames} frames…`);
    await new Promise((r) => setTimeout(r, 0));  // let the progress line show
    const error = demo.setPlanner(config.settings);
    if (error) throw new Error(`bench: ${config.label}: ${error}`);
    await demo.levels?.();  // a LOD row starts with its levels built
    demo.setTime(0);
    const frameMs = [], faces = [], draws = [], triangles = [], captureTriangles = [];
    let maxDiff = 0, differingFrames = 0, compared = 0, gpuTiming = false;
    // All frames of one policy in one task; each read back in the task that drew it.
    for (let i = 0; i < frames; ++i) {
      const s = demo.frame(1 / 60);
      if (s.gpuFrameMs >= 0) gpuTiming = true;
      frameMs.push(s.gpuFrameMs >= 0 ? s.gpuFrameMs : s.frameMs);
      faces.push(s.facesCaptured);
      draws.push(s.drawCalls);
      triangles.push(s.triangles);
      captureTriangles.push(s.captureTriangles ?? 0);
      if (i % compareEvery) continue;
      const pixels = demo.readPixels();
      if (!size) {
        size = { width: pixels.width, height: pixels.height };
        const bytes = pixels.data.length * Math.ceil(frames);
        compareEvery = Math.max(1, Math.ceil(bytes / memoryLimit));
      }
      if (rows.length === 0) {  // the first run, every-frame: the reference
        reference.push(pixels.data);
      } else {
        const ref = reference[i / compareEvery];
        if (!ref) continue;
        const c = compare(ref, pixels.data);
        ++compared;
        if (c.max > maxDiff) maxDiff = c.max;
        if (c.differing) ++differingFrames;
      }
    }
    rows.push({
      label: config.label, settings: config.settings,
      timing: gpuTiming ? 'gpu' : 'cpu',
      frameMs: { median: percentile(frameMs, 0.5), p10: percentile(frameMs, 0.1), p90: percentile(frameMs, 0.9) },
      facesCapturedPerFrame: mean(faces), drawCallsPerFrame: mean(draws), trianglesPerFrame: mean(triangles),
      captureTrianglesPerFrame: mean(captureTriangles),
      maxDiff: rows.length === 0 ? 0 : maxDiff, differingFrames: rows.length === 0 ? 0 : differingFrames,
      comparedFrames: rows.length === 0 ? reference.length : compared,
    });
  }
  reference = null;
  const scene = demo.scene();
  const result = { scene: scene.name, title: scene.title, frames, width: size?.width, height: size?.height,
                   compareEvery, rows };
  result.table = formatTable(result);
  return result;
}

export function formatTable({ scene, frames, width, height, compareEvery, rows }) {
  const pad = (s, n) => String(s).padStart(n);
  const lines = [
    `bench: scene ${scene}, ${frames} frames of 1/60 s from t=0, ${width}x${height}` +
      (compareEvery > 1 ? `, every ${compareEvery}th frame compared` : ''),
    `${'policy'.padEnd(26)}${pad('ms med', 8)}${pad('p10', 8)}${pad('p90', 8)}${pad('faces', 7)}` +
      `${pad('draws', 7)}${pad('tris', 9)}${pad('cap tris', 10)}${pad('max diff', 10)}${pad('frames≠', 9)}`,
  ];
  for (const r of rows) {
    lines.push(`${r.label.padEnd(26)}${pad(r.frameMs.median.toFixed(2), 8)}${pad(r.frameMs.p10.toFixed(2), 8)}` +
               `${pad(r.frameMs.p90.toFixed(2), 8)}${pad(r.facesCapturedPerFrame.toFixed(2), 7)}` +
               `${pad(r.drawCallsPerFrame.toFixed(1), 7)}${pad(Math.round(r.trianglesPerFrame), 9)}` +
               `${pad(Math.round(r.captureTrianglesPerFrame), 10)}${pad(r.maxDiff, 10)}` +
               `${pad(`${r.differingFrames}/${r.comparedFrames}`, 9)}`);
  }
  lines.push('ms: frame time per demo.frame(1/60) (GPU timer where available, else CPU with a GPU wait); ' +
             'faces/draws/tris: per frame; max diff: largest RGB difference (0..255) from every-frame');
  return lines.join('\n');
}

// The bench on the page (?bench, the panel's button, demo.runBench): in the session's job queue,
// with the frame loop held (`hold(true)` ... `hold(false)`), the user's planner settings and time
// restored afterwards, and the table shown. Resolves to the results.
export function benchPage(session, { frames = 60, readPixels, hold }) {
  return session.serial(async () => {
    await session.lodReady();
    const { bridge } = session;
    const saved = { planner: bridge.planner(), time: bridge.time() };
    const status = document.getElementById('progress');
    hold(true);
    try {
      const results = await runBench({
        frame: (dt) => session.frame(dt, true),
        setTime: (t) => bridge.setTime(t),
        setPlanner: (settings) => bridge.setPlanner(settings),
        levels: () => { session.startLevels(); return session.lodReady(); },
        readPixels,
        scene: () => bridge.scene(),
      }, { frames, onProgress: (text) => { status.hidden = false; status.textContent = text; } });
      document.getElementById('bench').textContent = results.table;
      document.getElementById('bench-box').hidden = false;
      console.info(results.table);
      return results;
    } catch (e) {
      showMessage(e.message);
      throw e;
    } finally {
      status.hidden = true;
      status.textContent = '';
      bridge.setPlanner(saved.planner);
      bridge.setTime(saved.time);
      hold(false);
      session.changed('settings');
    }
  });
}
