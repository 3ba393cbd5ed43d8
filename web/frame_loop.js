// The page's frame loop: one frame per display frame while something moves or changes, none at
// all while idle (paused, nothing changed, nothing loading): the canvas then keeps its last
// picture (the browser shows the last composited frame) and the stats line says idle. The bench
// and auto hold the loop while they draw frames of their own.
import { showMessage } from './messages.js';
import { frameTimes } from './stats.js';

export class FrameLoop {
  // session: session.js; statsLine, sparkline: stats.js.
  constructor(session, statsLine, sparkline) {
    this.session = session;
    this.statsLine = statsLine;
    this.sparkline = sparkline;
    this.needsFrame = true;  // something changed since the last drawn frame
    this.held = false;
    this.framesDrawn = 0;
    this.idle = false;
    this.intervals = [];  // the last 30 display frame intervals, ms
    this.previous = null;
    this.lastError = undefined;
  }

  // Something changed: the next display frame draws.
  changed() { this.needsFrame = true; }

  // The bench and auto draw their own frames while held; a frame follows their end.
  hold(on) {
    this.held = on;
    this.needsFrame = true;
  }

  // The display's frame interval, from the loop's own timestamps (the median of the last 30).
  displayInterval() {
    if (this.intervals.length < 5) return null;
    const sorted = [...this.intervals].sort((a, b) => a - b);
    return sorted[Math.floor(sorted.length / 2)];
  }

  start() { requestAnimationFrame((now) => this.tick(now)); }

  tick(now) {
    requestAnimationFrame((next) => this.tick(next));
    // Clamp the step so a tab that was hidden does not jump the animation.
    const dt = this.previous === null ? 0 : Math.min((now - this.previous) / 1000, 0.1);
    if (this.previous !== null) {
      this.intervals.push(now - this.previous);
      if (this.intervals.length > 30) this.intervals.shift();
    }
    this.previous = now;
    if (this.held) return;
    const { session } = this;
    if (session.paused && !this.needsFrame && !session.pending) {
      if (!this.idle) this.statsLine.showIdle(session.lastStats);
      this.idle = true;
      return;
    }
    this.idle = false;
    this.needsFrame = false;
    ++this.framesDrawn;
    const stats = session.frame(session.paused ? 0 : dt);
    if (stats.error && stats.error !== this.lastError) showMessage(stats.error);
    this.lastError = stats.error;
    this.sparkline.push(this.statsLine.update(now, stats, session.paused), frameTimes(stats).frameMs);
  }
}
