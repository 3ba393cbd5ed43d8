// The stats line: fps from display-frame intervals, and the renderer's own counts.
export class StatsLine {
  constructor(element) {
    this.element = element;
    this.fps = 0;
    this.previous = null;
    this.lastShown = 0;
  }

  update(now, stats, paused) {
    if (this.previous !== null) {
      const instant = 1000 / Math.max(now - this.previous, 0.001);
      this.fps = this.fps === 0 ? instant : this.fps * 0.9 + instant * 0.1;
    }
    this.previous = now;
    // Nothing to show before the second frame gives an interval (fps 0 would read 1000000 ms).
    if (this.fps === 0 || now - this.lastShown < 250) return;  // readable, and cheap
    this.lastShown = now;
    const triangles = stats.triangles >= 1000 ? `${(stats.triangles / 1000).toFixed(1)}k` : stats.triangles;
    this.element.textContent =
      `${this.fps.toFixed(0)} fps · frame ${(1000 / Math.max(this.fps, 1e-3)).toFixed(1)} ms` +
      ` · cpu ${stats.frameMs.toFixed(2)} ms (capture ${stats.captureMs.toFixed(2)})` +
      ` · ${stats.facesCaptured} faces · ${stats.drawCalls} draws · ${triangles} tris` +
      (paused ? ' · paused' : '');
  }
}
