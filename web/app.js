// The page's start and its frame loop. The work is in modules with one job each:
//   wasm_bridge.js  the C++ exports as typed functions (the only file that calls them)
//   session.js      the user's scene, models, settings, camera and time; the job queue
//   url_state.js    links, both ways        capture.js  read-back, screenshot, the address bar
//   drop.js         the user's files        panel.js    the controls     input.js  pointer and keys
//   test_api.js     window.demo             layout.js   the panel's place, hints for the device
//   frame_loop.js   frames on demand        apply_link.js  a link's settings, in order
//   stats.js, messages.js, bench.js, lod.js, figures.js, accuracy.js (the measured modes),
//   auto_pick.js (auto: the frame-budget pick), scene_loader.js
import { parseSweep } from './accuracy.js';
import { applyLink } from './apply_link.js';
import { AutoPick } from './auto_pick.js';
import { benchPage } from './bench.js';
import { AddressBar, readPixels, screenshot } from './capture.js';
import { attachDrop } from './drop.js';
import { attachInput, helpOverlay } from './input.js';
import { FrameLoop } from './frame_loop.js';
import { dockPanel, inputKinds, reservePanel, showHints } from './layout.js';
import { showMessage } from './messages.js';
import { buildPanel } from './panel.js';
import { sceneTitles } from './scene_loader.js';
import { Session } from './session.js';
import { Progress, Sparkline, StatsLine } from './stats.js';
import { testApi } from './test_api.js';
import { PickMode } from './pick.js';
import { parseQuery } from './url_state.js';
import { createBridge } from './wasm_bridge.js';

const canvas = document.getElementById('canvas');
let resolveReady, rejectReady;
const ready = new Promise((resolve, reject) => { resolveReady = resolve; rejectReady = reject; });
ready.catch(() => {});  // failures are shown on the page; tests await it themselves

async function start() {
  if (typeof WebGL2RenderingContext === 'undefined') {
    throw new Error('WebGL2 is not available in this browser, so the demo cannot run.');
  }
  const { titlesPromise, sweepText, guiPromise } = startLoads();

  const bridge = await createBridge(canvas);
  const createError = bridge.create();
  if (createError) throw new Error(createError);
  let onResize = () => {};
  let loop = null;
  // The canvas takes its displayed size; a new size draws a frame and re-times auto's candidates.
  const resizeCanvas = () => {
    if (sizeCanvasToDisplay()) {
      loop?.changed();
      onResize();
    }
  };
  sizeCanvasToDisplay();
  new ResizeObserver(resizeCanvas).observe(canvas);

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
  loop = new FrameLoop(session, statsLine, sparkline);
  session.onChange(() => loop.changed());
  canvas.addEventListener('webglcontextrestored', () => loop.changed());
  session.frame(0, true);
  if (link.step) session.showStep(link.step - 1);  // step through a frame, from a link
  const addressBar = new AddressBar(session);
  addressBar.sync();

  const autoPick = new AutoPick(session, {
    hold: (on) => loop.hold(on),
    displayInterval: () => loop.displayInterval(),
    canvasSize: () => `${canvas.width}x${canvas.height}`,
  });
  onResize = () => autoPick.schedule();
  const bench = (frames = link.frames || 60) =>
    benchPage(session, { frames, readPixels: () => readPixels(canvas), hold: (on) => loop.hold(on) })
      .then((results) => { window.demo.benchResults = results; return results; });
  document.getElementById('bench-close').onclick = () => { document.getElementById('bench-box').hidden = true; };

  const help = helpOverlay();
  const pick = new PickMode(bridge, canvas, () => loop.changed(), (pixel) => {
    session.pickedPixel = pixel;
    addressBar.changed();
  });
  attachControls(session, bridge, help, pick);

  const scenes = await titlesPromise;
  const GUI = await guiPromise;
  const panel = GUI ? buildPanel(GUI, session, {
    scenes, resized: resizeCanvas, ...panelActions(session, { addressBar, bench, help, autoPick, pick }),
  }) : null;
  if (!panel) dockPanel(null, resizeCanvas);
  describeScene(scenes, session);

  loop.start();
  autoPick.schedule();
  if (link.pick) pick.explainOnceDrawn(link.pick[0], link.pick[1], () => loop.framesDrawn);

  Object.assign(window.demo, testApi({
    session, addressBar, sparkline, progress, fps: () => statsLine.fps, panel: () => panel,
    readPixels: () => readPixels(canvas), screenshot: () => screenshot(session, canvas), bench,
    framesDrawn: () => loop.framesDrawn, drawingIdle: () => loop.idle, autoPick, pick,
  }));
  resolveReady();
  if (link.bench) bench().catch(() => {});
}

// What the page fetches while the module starts: the scenes' titles, the measured modes
// (sweep.csv) and the panel's library.
function startLoads() {
  const titlesPromise = sceneTitles();
  const sweepText = fetch('sweep.csv').then((r) => (r.ok ? r.text() : ''), () => '');
  const guiPromise = import('./vendor/lil-gui.esm.js').then((m) => m.GUI, (e) => {
    showMessage(`The controls panel could not be loaded (vendor/lil-gui.esm.js: ${e.message}); ` +
                'keys and mouse still work.');
    return null;
  });
  return { titlesPromise, sweepText, guiPromise };
}

// Keys, pointer and touch on the canvas, and dropped files.
function attachControls(session, bridge, help, pick) {
  const camera = (change) => session.camera(change);  // a change: the loop draws
  // One teaching view on, or the picture back when it is the one already on.
  const toggleInside = (view) => session.setView({ inside: bridge.view().inside === view ? 'off' : view });
  attachInput(canvas, {
    drag: (dx, dy) => camera((b) => b.dragCamera({ dx, dy, height: canvas.clientHeight })),
    move: (steps) => camera((b) => b.moveCamera({ forward: steps })),
    strafe: (steps) => camera((b) => b.moveCamera({ right: steps })),
    rise: (steps) => camera((b) => b.moveCamera({ up: steps })),
    pan: (right, up) => camera((b) => b.moveCamera({ right, up })),
    reset: () => camera((b) => b.resetCamera()),
    togglePause: () => session.setPaused(!session.paused),
    // Inside the frame: the faces view and the face-use view on and off (the panel's folder has
    // the faces view's channel).
    toggleFaces: () => toggleInside('faces'),
    toggleFaceUse: () => toggleInside('faceuse'),
    // Step through a frame: the next draw of the frame, paused.
    stepFrame: () => session.stepFrame(),
    toggleHelp: () => help.toggle(),
    closeHelp: () => help.close(),
    togglePick: () => pick.toggle(),
    click: (x, y) => pick.click(x, y),
  });
  attachDrop(session);
}

// What the panel's buttons do (beside its settings, which go to the session).
function panelActions(session, { addressBar, bench, help, autoPick, pick }) {
  return {
    screenshot: () => screenshot(session, canvas),
    copyLink: () => addressBar.copyLink(),
    pickFiles: () => document.getElementById('file-input').click(),
    pickFolder: () => document.getElementById('folder-input').click(),
    bench: () => bench().catch(() => {}),
    toggleHelp: () => help.toggle(),
    helpLabel: kinds.keys ? 'keys and mouse (?)' : 'touch gestures',
    autoReadout: () => autoPick.readout(),
    togglePick: () => pick.toggle(),
  };
}

// The scene's title and description under the canvas, following scene loads.
function describeScene(scenes, session) {
  const description = document.getElementById('scene-description');
  const describe = () => {
    const s = scenes.find((x) => x.name === session.scene.name);
    description.textContent = s ? `${s.title}: ${s.description}` : session.scene.title;
  };
  session.onChange((kind) => { if (kind === 'scene') describe(); });
  describe();
}

function sizeCanvasToDisplay() {
  const dpr = window.devicePixelRatio || 1;
  const width = Math.max(0, Math.round(canvas.clientWidth * dpr));
  const height = Math.max(0, Math.round(canvas.clientHeight * dpr));
  if (canvas.width !== width || canvas.height !== height) {
    canvas.width = width;
    canvas.height = height;
    return true;
  }
  return false;
}

const kinds = inputKinds();
showHints(kinds);
reservePanel();
window.demo = { ready };
canvas.addEventListener('webglcontextlost', () => showMessage('WebGL context lost; restoring…', 'info'));
canvas.addEventListener('webglcontextrestored', () => showMessage('WebGL context restored.', 'info'));
start().catch((error) => {
  if (!error.shown) showMessage(error.message || String(error));
  document.getElementById('stats').textContent = 'not running';
  rejectReady(error);
});
