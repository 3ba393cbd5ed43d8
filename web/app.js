// The page: loads the wasm module, feeds it the models, runs the frame loop, turns pointer and
// key input into camera moves, shows stats and messages, and exposes window.demo for tests.
import { loadModels } from './models.js';
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
    meshNames: Module.cwrap('rf_mesh_names', 'string', []),
    loadMesh: Module.cwrap('rf_load_mesh', 'string', ['string', 'number', 'number', 'string']),
    initGraphics: Module.cwrap('rf_init_graphics', 'string', ['number']),
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

  const loadText = (name, bytes, source) => {
    const ptr = Module._malloc(bytes.length);
    Module.HEAPU8.set(bytes, ptr);
    try { return api.loadMesh(name, ptr, bytes.length, source); } finally { Module._free(ptr); }
  };
  await loadModels(JSON.parse(api.meshNames()), params.get('assets'), loadText);

  const cubeSize = Number(params.get('cube') || 256);
  const initError = api.initGraphics(cubeSize);
  if (initError) throw new Error(initError);

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
  const tick = (now) => {
    // Clamp the step so a tab that was hidden does not jump the animation.
    const dt = previous === null ? 0 : Math.min((now - previous) / 1000, 0.1);
    previous = now;
    lastStats = JSON.parse(api.frame(paused ? 0 : dt, 0));
    statsLine.update(now, lastStats, paused);
    requestAnimationFrame(tick);
  };
  requestAnimationFrame(tick);

  window.demo.frame = (dt) => { lastStats = JSON.parse(api.frame(dt, 1)); return lastStats; };
  window.demo.stats = () => ({ ...lastStats, fps: statsLine.fps });
  window.demo.setTime = (t) => api.setTime(t);
  window.demo.pause = (on = true) => { paused = on; };
  window.demo.camera = () => JSON.parse(api.camera());
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
