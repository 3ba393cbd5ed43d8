// The live numbers: the stats line (fps from display-frame intervals, the renderer's own timings
// and counts), a sparkline of the last frame times, and the loading-progress line.
import { megabytes } from './scene_loader.js';

// Which timing the line shows: the GPU timer queries when the browser has them, otherwise the
// CPU-side times of the renderer. Returns { label, frameMs, captureMs }.
export function frameTimes(stats) {
  if (stats.gpuFrameMs !== undefined && stats.gpuFrameMs >= 0) {
    return { label: 'gpu', frameMs: stats.gpuFrameMs, captureMs: Math.max(stats.gpuCaptureMs, 0) };
  }
  return { label: 'cpu', frameMs: stats.frameMs || 0, captureMs: stats.captureMs || 0 };
}

export class StatsLine {
  constructor(element) {
    this.element = element;
    this.fps = 0;
    this.previous = null;
    this.lastShown = 0;
  }

  // Returns the display-frame interval in ms (null for the first frame).
  update(now, stats, paused) {
    let interval = null;
    if (this.previous !== null) {
      interval = Math.max(now - this.previous, 0.001);
      const instant = 1000 / interval;
      this.fps = this.fps === 0 ? instant : this.fps * 0.9 + instant * 0.1;
    }
    this.previous = now;
    // Nothing to show before the second frame gives an interval (fps 0 would read 1000000 ms).
    if (this.fps === 0 || now - this.lastShown < 250) return interval;  // readable, and cheap
    this.lastShown = now;
    this.element.textContent = formatStats(this.fps, stats, paused);
    return interval;
  }

  // Nothing is drawn while idle: the line says so, with the last frame's numbers.
  showIdle(stats) {
    this.element.textContent = formatStats(this.fps, stats, true, true);
    this.previous = null;  // the next interval starts with the next drawn frame
  }
}

// The error view's numbers (show error), or '' when it is off.
export function formatErrorView(stats) {
  const e = stats.errorView;
  if (!e) return '';
  const psnr = e.rmse === 0 ? '∞ dB (exact)' : `${e.psnrDb.toFixed(1)} dB`;
  return `\nerror vs exact: reflector PSNR ${psnr} · ${e.pixelsOver32} of ${e.reflectorPixels} px off by >32 · ` +
    `+${e.ms.toFixed(1)} ms`;
}

export function formatStats(fps, stats, paused, idle = false) {
  const triangles = stats.triangles >= 1000 ? `${(stats.triangles / 1000).toFixed(1)}k` : stats.triangles;
  const t = frameTimes(stats);
  const head = idle ? 'idle: no frame drawn until something changes · last frame'
                    : `${fps.toFixed(0)} fps · frame ${(1000 / Math.max(fps, 1e-3)).toFixed(1)} ms ·`;
  return `${head} ${t.label} ${(t.frameMs || 0).toFixed(2)} ms (capture ${(t.captureMs || 0).toFixed(2)})\n` +
    `${stats.facesCaptured ?? 0} faces · ${stats.drawCalls ?? 0} draws · ${triangles ?? 0} tris` +
    (paused ? ' · paused' : '') + (idle ? ' · idle' : '') + formatErrorView(stats);
}

// A tiny graph of the last `capacity` display-frame intervals (white) and the renderer's own
// frame times (orange), with guides at 16.7 and 33.3 ms.
export class Sparkline {
  constructor(canvas, capacity = 120) {
    this.canvas = canvas;
    this.capacity = capacity;
    this.intervals = [];
    this.renderMs = [];
    this.samples = 0;  // total pushed, for tests
  }

  push(intervalMs, renderMs) {
    if (intervalMs === null) return;
    this.intervals.push(intervalMs);
    this.renderMs.push(renderMs);
    if (this.intervals.length > this.capacity) {
      this.intervals.shift();
      this.renderMs.shift();
    }
    ++this.samples;
    this.draw();
  }

  draw() {
    const c = this.canvas;
    const dpr = window.devicePixelRatio || 1;
    const w = Math.round(c.clientWidth * dpr), h = Math.round(c.clientHeight * dpr);
    if (!w || !h) return;
    if (c.width !== w || c.height !== h) { c.width = w; c.height = h; }
    const g = c.getContext('2d');
    g.clearRect(0, 0, w, h);
    const top = Math.max(40, ...this.intervals, ...this.renderMs) * 1.1;
    const y = (ms) => h - (ms / top) * h;
    g.lineWidth = 1;
    g.strokeStyle = 'rgba(255,255,255,0.25)';
    for (const guide of [1000 / 60, 1000 / 30]) {
      g.beginPath();
      g.moveTo(0, Math.round(y(guide)) + 0.5);
      g.lineTo(w, Math.round(y(guide)) + 0.5);
      g.stroke();
    }
    const line = (values, colour) => {
      g.strokeStyle = colour;
      g.lineWidth = dpr;
      g.beginPath();
      const step = w / (this.capacity - 1);
      const x0 = w - (values.length - 1) * step;
      values.forEach((v, i) => (i ? g.lineTo(x0 + i * step, y(v)) : g.moveTo(x0, y(v))));
      g.stroke();
    };
    line(this.renderMs, '#f93');
    line(this.intervals, '#fff');
  }
}

// Bytes still coming in: one line for all files being fetched or read at once.
export class Progress {
  constructor(element) {
    this.element = element;
    this.files = new Map();  // name -> { loaded, total }
    this.history = [];       // every text shown (tests read it)
  }

  track(name) {
    return (loaded, total) => {
      this.files.set(name, { loaded, total });
      this.show();
    };
  }

  show() {
    let loaded = 0, total = 0, largest = null;
    for (const [name, f] of this.files) {
      loaded += f.loaded;
      total += Math.max(f.total, f.loaded);
      if (!largest || f.total > this.files.get(largest).total) largest = name;
    }
    if (!largest) return;
    const share = total ? Math.floor((100 * loaded) / total) : 0;
    const text = `loading ${largest}${this.files.size > 1 ? ` (+${this.files.size - 1} more)` : ''}: ` +
                 `${share}% of ${megabytes(total)} MB`;
    this.element.textContent = text;
    this.element.hidden = false;
    if (this.history[this.history.length - 1] !== text) this.history.push(text);
    if (this.history.length > 200) this.history.splice(0, 100);
  }

  clear() {
    this.files.clear();
    this.element.textContent = '';
    this.element.hidden = true;
  }
}
