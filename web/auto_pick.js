// "auto" accuracy with a frame budget: the page times each candidate setting on this machine
// (GPU timer queries where the browser has them, EXT_disjoint_timer_query_webgl2; elsewhere
// demo.frame with a read-back), measures each one's reflector error against the exact mode with
// the error view on the current scene, and lets the C++ rule (core/budget_pick.h, through
// bridge.pickAccuracy) pick the most accurate one that fits. It runs briefly once the page is
// idle after auto is turned on, and again when the scene, the canvas size or the budget changes.
import { showMessage } from './messages.js';

const WARMUP = 2;
const FRAMES = 5;
const SETTLE_MS = 300;  // quiet time before a run

// page: { hold(on), displayInterval() -> ms or null, canvasSize() -> "WxH" }
export class AutoPick {
  constructor(session, page) {
    Object.assign(this, { session, page });
    this.last = null;  // { budget, pick, candidates, reason, at }
    this.running = null;
    this.measuring = false;
    this.timer = null;
    this.measuredFor = null;  // what the last run measured: scene, size, budget
    session.onChange((kind) => {
      if (kind === 'scene' || kind === 'view') this.schedule();
    });
  }

  enabled() { return Boolean(this.session.bridge.view().auto); }

  // The budget in ms: the panel's (?budget=), else the display's frame interval.
  budget() {
    const set = Number(this.session.bridge.view().budget) || 0;
    if (set > 0) return set;
    return this.page.displayInterval() || 1000 / 60;
  }

  // What a run depends on: when it changes, auto measures again.
  key() {
    return `${this.session.scene.name}|${this.page.canvasSize()}|${this.budget().toFixed(2)}`;
  }

  // Measure again soon if auto is on and something it depends on changed.
  schedule() {
    clearTimeout(this.timer);
    if (!this.enabled()) return;
    this.timer = setTimeout(() => {
      if (this.running) return this.schedule();
      if (this.key() === this.measuredFor) return undefined;
      return this.run().catch((e) => showMessage(`auto: ${e.message}`));
    }, SETTLE_MS);
  }

  // Times and measures every candidate, applies the pick. Resolves to this.last.
  run() {
    const { session } = this;
    this.running = session.serial(async () => {
      // The captured candidates draw chunks and capture LOD's levels: built before any is timed,
      // so none is timed at full detail, nor while they arrive.
      await session.lodReady();
      const { bridge } = session;
      const budget = this.budget();
      const key = this.key();
      const saved = { time: bridge.time(), view: bridge.view(), accuracy: bridge.accuracy() };
      const dt = session.paused ? 0 : 1 / 60;
      const candidates = bridge.budgetCandidates();
      this.measuring = true;
      this.page.hold(true);
      try {
        if (saved.view.showError) bridge.setView({ showError: false });
        for (const c of candidates) {
          const error = bridge.setAccuracy(c.accuracy);
          if (error) throw new Error(`${c.name}: ${error}`);
          const ms = [];
          for (let i = 0; i < WARMUP + FRAMES; ++i) {
            bridge.setTime(saved.time);
            const s = session.frame(dt, true);
            const t = s.gpuFrameMs >= 0 ? s.gpuFrameMs : s.frameMs;
            if (i >= WARMUP) ms.push(t);
            // Far over the budget: it cannot fit, so a first measure will do.
            if (i === WARMUP && t > 4 * budget) break;
          }
          ms.sort((a, b) => a - b);
          c.frameMs = ms[Math.floor(ms.length / 2)];
          bridge.setView({ showError: true });
          bridge.setTime(saved.time);
          c.psnrDb = session.frame(0, true).errorView?.psnrDb ?? 0;
          bridge.setView({ showError: false });
          await new Promise((r) => setTimeout(r, 0));  // let the page breathe between settings
        }
        const pick = bridge.pickAccuracy({ budget, candidates });
        const chosen = candidates[pick.index];
        if (chosen) bridge.setAccuracy(chosen.accuracy);
        else bridge.setAccuracy(saved.accuracy);
        this.last = { budget, pick, candidates, reason: pick.reason, at: key };
        this.measuredFor = key;
        console.info(`auto (budget ${budget.toFixed(1)} ms):\n${pick.table}${pick.reason}`);
        return this.last;
      } catch (e) {
        bridge.setAccuracy(saved.accuracy);
        throw e;
      } finally {
        bridge.setView({ showError: saved.view.showError });
        bridge.setTime(saved.time);
        this.page.hold(false);
        this.measuring = false;
        session.changed('settings');
      }
    }).finally(() => { this.running = null; });
    return this.running;
  }

  // The panel's line: what auto picked and why.
  readout() {
    if (!this.enabled()) return 'off';
    if (this.measuring) return 'measuring…';
    return this.last ? this.last.reason : 'waiting for the page to be idle';
  }
}
