// The page's start and its frame loop. The work is in modules with one job each:
//   wasm_bridge.js  the C++ exports as typed functions (the only file that knows their names)
//   session.js      the user's scene, models, settings, camera and time; the job queue
//   url_state.js    links, both ways        capture.js  read-back, screenshot, the address bar
//   drop.js         the user's files        panel.js    the controls     input.js  pointer and keys
//   test_api.js     window.demo             stats.js, messages.js, bench.js, lod.js, figures.js,
//   accuracy.js (the measured modes), scene_loader.js
import { parseSweep } from './accuracy.js';
import { benchPage } from './bench.js';
import { AddressBar, readPixels, screenshot } from './capture.js';
import { attachDrop } from './drop.js';
import { attachInput, helpOverlay } from './input.js';
import { showMessage } from './messages.js';
import { buildPanel } from './panel.js';
import { sceneTitles } from './scene_loader.js';
import { Session } from './session.js';
import { frameTimes, Progress, Sparkline, StatsLine } from './stats.js';
import { testApi } from './test_api.js';
import { parseQuery } from './url_state.js';
import { createBridge } from './wasm_bridge.js';

const canvas = document.getElementById('canvas');
let resolveReady, rejectReady;
const ready = new Promise((resolve, reject) => { resolveReady = resolve; rejectReady = reject; });
ready.catch(() => {});  // failures are shown on the page; tests await it themselves

// The link's settings: the first scene (at the link's cube size, or its accuracy mode's), then
// the accuracy mode and settings, materials, planner settings, camera, time and pause. A value
// that cannot be used is named in a message and the rest still applies.
async function applyLink(session, link) {
  const { bridge, modes, schema } = session;
  const row = link.acc ? modes.find(link.acc) : null;
  if (link.acc && !row) {
    showMessage(`acc=${link.acc}: not a measured accuracy mode ` +
                (modes.rows.length ? `(sweep.csv has ${modes.names()})` : '(sweep.csv is not available)') +
                `; settings go as keys of their own (${schema.accuracy.map((i) => i.name).join(', ')}); ignored`);
  }
  session.cubeSize = link.cube || row?.faceSize || 0;
  session.paused = link.paused;
  await session.switchScene(link.scene);
  // All at once (one GL rebuild for accuracy settings); when that fails, one by one.
  const each = (changes, set) => {
    if (!Object.keys(changes).length || !set(changes)) return;
    for (const [key, value] of Object.entries(changes)) {
      const error = set({ [key]: value });
      if (error) showMessage(`${error} (from the link; ignored)`);
    }
  };
  if (row) {
    modes.chosen = row.name;
    const error = bridge.setAccuracy(row.accuracy);
    if (error) showMessage(`acc=${row.name}: ${error}`);
  }
  each(link.accuracy, (c) => bridge.setAccuracy(c));
  for (const { index, changes, entry } of link.materials) {
    const error = bridge.setMaterial({ index, changes });
    if (error) showMessage(`mat=${entry}: ${error}; ignored`);
  }
  each(link.planner, (c) => bridge.setPlanner(c));
  session.startLevels();  // levels the link's LOD settings want
  if (link.cam) bridge.setCamera({ eye: link.cam.slice(0, 3), yaw: link.cam[3], pitch: link.cam[4] });
  if (link.t !== null) bridge.setTime(link.t);
  session.changed('settings');
}

async function start() {
  if (typeof WebGL2RenderingContext === 'undefined') {
    throw new Error('WebGL2 is not available in this browser, so the demo cannot run.');
  }
  const titlesPromise = sceneTitles();
  const sweepText = fetch('sweep.csv').then((r) => (r.ok ? r.text() : ''), () => '');
  const guiPromise = import('./vendor/lil-gui.esm.js').then((m) => m.GUI, (e) => {
    showMessage(`The controls panel could not be loaded (vendor/lil-gui.esm.js: ${e.message}); ` +
                'keys and mouse still work.');
    return null;
  });

  const bridge = await createBridge(canvas);
  const createError = bridge.create();
  if (createError) throw new Error(createError);
  sizeCanvasToDisplay();
  new ResizeObserver(sizeCanvasToDisplay).observe(canvas);

  const schema = bridge.schema();
  const { state: link, problems, notes } = parseQuery(location.search, schema);
  for (const problem of problems) showMessage(problem);
  for (const note of notes) showMessage(note, 'info');
  const progress = new Progress(document.getElementById('progress'));
  const sweepRows = parseSweep(await sweepText);
  const session = new Session(bridge, { schema, sweepRows, assets: link.assets, progress });
  await applyLink(session, link);
  const statsLine = new StatsLine(document.getElementById('stats'));
  const sparkline = new Sparkline(document.getElementById('spark'));
  session.frame(0, true);
  const addressBar = new AddressBar(session);
  addressBar.sync();

  let held = false;  // the bench holds the frame loop
  const bench = (frames = link.frames || 60) =>
    benchPage(session, { frames, readPixels: () => readPixels(canvas), hold: (on) => { held = on; } })
      .then((results) => { window.demo.benchResults = results; return results; });
  document.getElementById('bench-close').onclick = () => { document.getElementById('bench-box').hidden = true; };

  const help = helpOverlay();
  const camera = (change) => session.camera(change);
  attachInput(canvas, {
    drag: (dx, dy) => camera((b) => b.dragCamera({ dx, dy, height: canvas.clientHeight })),
    move: (steps) => camera((b) => b.moveCamera({ forward: steps })),
    strafe: (steps) => camera((b) => b.moveCamera({ right: steps })),
    rise: (steps) => camera((b) => b.moveCamera({ up: steps })),
    reset: () => camera((b) => b.resetCamera()),
    togglePause: () => session.setPaused(!session.paused),
    toggleHelp: () => help.toggle(),
    closeHelp: () => help.close(),
  });
  attachDrop(session);

  const scenes = await titlesPromise;
  const GUI = await guiPromise;
  const panel = GUI ? buildPanel(GUI, session, {
    scenes,
    screenshot: () => screenshot(session, canvas),
    copyLink: () => addressBar.copyLink(),
    pickFiles: () => document.getElementById('file-input').click(),
    pickFolder: () => document.getElementById('folder-input').click(),
    bench: () => bench().catch(() => {}),
    toggleHelp: () => help.toggle(),
  }) : null;
  const description = document.getElementById('scene-description');
  const describe = () => {
    const s = scenes.find((x) => x.name === session.scene.name);
    description.textContent = s ? `${s.title}: ${s.description}` : session.scene.title;
  };
  session.onChange((kind) => { if (kind === 'scene') describe(); });
  describe();

  // The frame loop: one frame per display frame, the stats line and the sparkline.
  let previous = null;
  let lastError;
  const tick = (now) => {
    requestAnimationFrame(tick);
    // Clamp the step so a tab that was hidden does not jump the animation.
    const dt = previous === null ? 0 : Math.min((now - previous) / 1000, 0.1);
    previous = now;
    if (held) return;
    const stats = session.frame(session.paused ? 0 : dt);
    if (stats.error && stats.error !== lastError) showMessage(stats.error);
    lastError = stats.error;
    sparkline.push(statsLine.update(now, stats, session.paused), frameTimes(stats).frameMs);
  };
  requestAnimationFrame(tick);

  Object.assign(window.demo, testApi({
    session, addressBar, sparkline, progress, fps: () => statsLine.fps, panel: () => panel,
    readPixels: () => readPixels(canvas), screenshot: () => screenshot(session, canvas), bench,
  }));
  resolveReady();
  if (link.bench) bench().catch(() => {});
}

function sizeCanvasToDisplay() {
  const dpr = window.devicePixelRatio || 1;
  const width = Math.max(0, Math.round(canvas.clientWidth * dpr));
  const height = Math.max(0, Math.round(canvas.clientHeight * dpr));
  if (canvas.width !== width || canvas.height !== height) {
    canvas.width = width;
    canvas.height = height;
  }
}

window.demo = { ready };
canvas.addEventListener('webglcontextlost', () => showMessage('WebGL context lost; restoring…', 'info'));
canvas.addEventListener('webglcontextrestored', () => showMessage('WebGL context restored.', 'info'));
start().catch((error) => {
  if (!error.shown) showMessage(error.message || String(error));
  document.getElementById('stats').textContent = 'not running';
  rejectReady(error);
});
