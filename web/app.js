// The page: loads the wasm module, feeds it the models, runs the frame loop, turns pointer and
// key input into camera moves, shows stats and messages, and exposes window.demo for tests.
import { loadScene, sceneUrl } from './scene_loader.js';
import { attachInput } from './input.js';
import { showMessage } from './messages.js';
import { StatsLine } from './stats.js';

const params = new URLSearchParams(location.search);
const canvas = document.getElementById('canvas');
let resolveReady, rejectReady;
const ready = new Promise((resolve, reject) => { resolveReady = resolve; rejectReady = reject; });
ready.catch(() => {});  // failures are shown on the page; tests await it themselves

async function start() {
  if (typeof WebGL2RenderingContext === 'undefined') {
    throw new Error('WebGL2 is not available in this browser, so the demo cannot run.');
  }
  const Module = await createReflectModule({ canvas });
  const api = {
    create: Module.cwrap('rf_create', 'string', []),
    beginScene: Module.cwrap('rf_begin_scene', 'string', ['number', 'number', 'string']),
    pendingFiles: Module.cwrap('rf_pending_files', 'string', []),
    loadMesh: Module.cwrap('rf_load_mesh', 'string', ['number', 'string', 'number', 'number', 'string']),
    skyboxImage: Module.cwrap('rf_pending_skybox_image', 'string', ['number', 'number', 'number', 'string']),
    commitScene: Module.cwrap('rf_commit_scene', 'string', ['number']),
    sceneJson: Module.cwrap('rf_scene_json', 'string', []),
    setPlanner: Module.cwrap('rf_set_planner', 'string', ['string', 'number', 'number', 'number']),
    planner: Module.cwrap('rf_planner_json', 'string', []),
    frame: Module.cwrap('rf_frame', 'string', ['number', 'number']),
    setTime: Module.cwrap('rf_set_time', null, ['number']),
    drag: Module.cwrap('rf_drag', null, ['number', 'number', 'number']),
    move: Module.cwrap('rf_move', null, ['number']),
    resetCamera: Module.cwrap('rf_reset_camera', null, []),
    camera: Module.cwrap('rf_camera_json', 'string', []),
  };
  const createError = api.create();
  if (createError) throw new Error(createError);

  sizeCanvasToDisplay();
  new ResizeObserver(sizeCanvasToDisplay).observe(canvas);

  let cubeSize = 0;  // 0: the scene's own capture.faceSize
  if (params.has('cube')) {
    cubeSize = Number(params.get('cube'));
    if (!Number.isInteger(cubeSize) || cubeSize < 1) {
      showMessage(`cube=${params.get('cube')}: expected a whole number of pixels; using the scene's size`);
      cubeSize = 0;
    }
  }
  await loadScene(Module, api, sceneUrl(params.get('scene') || 'ex12-2'),
                  { userPrefix: params.get('assets'), cubeSize });
  if (params.has('policy')) {
    const error = api.setPlanner(params.get('policy'), Number(params.get('slice') || 2),
                                 Number(params.get('every') || 4), Number(params.get('lod') || 0));
    if (error) showMessage(error);
  }

  let paused = params.has('paused');
  if (params.has('t')) api.setTime(Number(params.get('t')));
  const statsLine = new StatsLine(document.getElementById('stats'));
  let lastStats = JSON.parse(api.frame(0, 1));

  attachInput(canvas, {
    drag: (dx, dy) => api.drag(dx, dy, canvas.clientHeight),
    move: (steps) => api.move(steps),
    reset: () => api.resetCamera(),
    togglePause: () => { paused = !paused; },
  });

  let previous = null;
  let lastError;
  const tick = (now) => {
    // Clamp the step so a tab that was hidden does not jump the animation.
    const dt = previous === null ? 0 : Math.min((now - previous) / 1000, 0.1);
    previous = now;
    lastStats = JSON.parse(api.frame(paused ? 0 : dt, 0));
    if (lastStats.error && lastStats.error !== lastError) showMessage(lastStats.error);
    lastError = lastStats.error;
    statsLine.update(now, lastStats, paused);
    requestAnimationFrame(tick);
  };
  requestAnimationFrame(tick);

  window.demo.frame = (dt) => { lastStats = JSON.parse(api.frame(dt, 1)); return lastStats; };
  window.demo.stats = () => ({ ...lastStats, fps: statsLine.fps });
  window.demo.setTime = (t) => api.setTime(t);
  window.demo.pause = (on = true) => { paused = on; };
  window.demo.camera = () => JSON.parse(api.camera());
  window.demo.scene = () => JSON.parse(api.sceneJson());
  window.demo.planner = () => JSON.parse(api.planner());
  window.demo.setPlanner = (policy, slice = 2, every = 4, lod = 0) => api.setPlanner(policy, slice, every, lod);
  // Loads another scene; the current one stays on screen if it fails (the error is shown and thrown).
  window.demo.loadScene = async (nameOrUrl) => {
    try {
      return await loadScene(Module, api, sceneUrl(nameOrUrl), { userPrefix: params.get('assets'), cubeSize });
    } catch (e) {
      showMessage(e.message);
      throw e;
    }
  };
  resolveReady();
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
  showMessage(error.message || String(error));
  document.getElementById('stats').textContent = 'not running';
  rejectReady(error);
});
