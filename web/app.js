// The page: loads the wasm module, feeds it the scenes and models, runs the frame loop, turns
// pointer and key input into camera moves, shows the controls panel, live numbers and messages,
// mirrors its settings in the URL, and exposes window.demo for tests and tools.
import {
  describeAccuracy, fromUrlSetting, matchingRow, parseSweep, readout, toUrlSetting,
} from './accuracy.js';
import { runBench } from './bench.js';
import { filesFromDrop, filesFromList, sortFiles } from './drop.js';
import { attachInput, cameraBasis } from './input.js';
import { figureObject, freeAngle, takenAngles } from './figures.js';
import { buildLods } from './lod.js';
import { showMessage } from './messages.js';
import { buildPanel, materialRows } from './panel.js';
import {
  loadScene, MAX_MODEL_BYTES, readFileBytes, sceneUrl, tooLargeMessage, withBytes,
} from './scene_loader.js';
import { frameTimes, Progress, Sparkline, StatsLine } from './stats.js';
import { buildQuery, DEFAULT_SCENE, parseQuery } from './url_state.js';

const STEP = 0.1;  // scene units per key press (the C++ camera's move step)

const canvas = document.getElementById('canvas');
let resolveReady, rejectReady;
const ready = new Promise((resolve, reject) => { resolveReady = resolve; rejectReady = reject; });
ready.catch(() => {});  // failures are shown on the page; tests await it themselves

// The shipped scenes, in the picker's order: scenes/index.json, which the build writes from
// assets/scenes/*.json (cmake/SceneIndex.cmake). Without it the picker offers the default alone.
async function sceneTitles() {
  try {
    const response = await fetch('scenes/index.json');
    if (!response.ok) throw new Error(`${response.status}`);
    const list = await response.json();
    return list.map(({ name, title, description }) => ({ name, title: title || name, description: description || '' }));
  } catch {
    return [{ name: DEFAULT_SCENE, title: DEFAULT_SCENE, description: '' }];
  }
}

async function start() {
  if (typeof WebGL2RenderingContext === 'undefined') {
    throw new Error('WebGL2 is not available in this browser, so the demo cannot run.');
  }
  const { state: initial, problems } = parseQuery(location.search);
  for (const problem of problems) showMessage(problem);
  const titlesPromise = sceneTitles();
  const sweepPromise = fetch('sweep.csv').then((r) => (r.ok ? r.text() : '')).then(parseSweep, () => []);
  const guiPromise = import('./vendor/lil-gui.esm.js').then((m) => m.GUI, (e) => {
    showMessage(`The controls panel could not be loaded (vendor/lil-gui.esm.js: ${e.message}); ` +
                'keys and mouse still work.');
    return null;
  });

  const Module = await createReflectModule({ canvas });
  const api = {
    create: Module.cwrap('rf_create', 'string', []),
    beginScene: Module.cwrap('rf_begin_scene', 'string', ['number', 'number', 'string']),
    pendingFiles: Module.cwrap('rf_pending_files', 'string', []),
    loadMesh: Module.cwrap('rf_load_mesh', 'string', ['number', 'string', 'number', 'number', 'string']),
    skyboxImage: Module.cwrap('rf_pending_skybox_image', 'string', ['number', 'number', 'number', 'string']),
    commitScene: Module.cwrap('rf_commit_scene', 'string', ['number']),
    sceneJson: Module.cwrap('rf_scene_json', 'string', []),
    setPlanner: Module.cwrap('rf_set_planner', 'string', ['string', 'number', 'number', 'number', 'number']),
    planner: Module.cwrap('rf_planner_json', 'string', []),
    frame: Module.cwrap('rf_frame', 'string', ['number', 'number']),
    setTime: Module.cwrap('rf_set_time', null, ['number']),
    drag: Module.cwrap('rf_drag', null, ['number', 'number', 'number']),
    move: Module.cwrap('rf_move', null, ['number']),
    resetCamera: Module.cwrap('rf_reset_camera', null, []),
    setCamera: Module.cwrap('rf_set_camera', null, ['number', 'number', 'number', 'number', 'number']),
    camera: Module.cwrap('rf_camera_json', 'string', []),
    meshVertices: Module.cwrap('rf_mesh_vertices', 'number', ['string', 'number']),
    meshIndices: Module.cwrap('rf_mesh_indices', 'number', ['string', 'number']),
    lodSettings: Module.cwrap('rf_lod_settings_json', 'string', []),
    addLod: Module.cwrap('rf_add_lod', 'string', ['string', 'number', 'number']),
    addObject: Module.cwrap('rf_add_object', 'string', ['string']),
    meshBounds: Module.cwrap('rf_mesh_bounds_json', 'string', ['string']),
    setMaterial: Module.cwrap('rf_set_material', 'string', ['number', 'string']),
    objects: Module.cwrap('rf_objects_json', 'string', []),
    setAccuracy: Module.cwrap('rf_set_accuracy', 'string',
                              ['number', 'number', 'number', 'number', 'number', 'number']),
    accuracy: Module.cwrap('rf_accuracy_json', 'string', []),
  };
  const createError = api.create();
  if (createError) throw new Error(createError);

  sizeCanvasToDisplay();
  new ResizeObserver(sizeCanvasToDisplay).observe(canvas);

  // --- state ------------------------------------------------------------------------------
  const progress = new Progress(document.getElementById('progress'));
  const overrides = new Map();  // mesh file name -> { bytes, source }: the user's dropped models
  let cubeSize = initial.cube;  // 0: the scene's own capture.faceSize
  let paused = initial.paused;
  let sceneInfo = { name: initial.scene, title: '', json: null };
  let homeCamera = null;  // the scene's own camera: cam= stays out of the URL while it is there
  let lodLevels = {};
  let lodReady = Promise.resolve({});
  let suspended = false;  // the bench holds the frame loop
  let lastStats = {};
  let panel = null;
  const sweepRows = await sweepPromise;  // sweep.csv: the measured accuracy modes
  let chosenRow = null;  // the sweep row the user (or acc=) picked
  let defaultDescribe = null;  // the shipped accuracy settings (rf_accuracy_json's describe)
  // The user's added figures, { name, bytes, source, object }: re-added when the scene reloads
  // for a cube size or an accuracy mode; gone with another scene or the built-in-models button.
  let figures = [];
  const materialEdits = new Map();  // object index -> the material the user set
  let sceneMaterials = [];  // rf_objects_json's materials right after the scene loaded
  const settings = {
    scene: initial.scene, cube: 0, policy: 'when-changed', slice: 2, every: 4, lod: 0, viewLod: 0,
    staleness: '', lodLevels: '', paused, accuracy: '', accuracyReadout: '',
  };

  // Scene changes, model replacements and the bench run one at a time (one pending scene).
  let queue = Promise.resolve();
  const serial = (job) => {
    const run = queue.then(job);
    queue = run.catch(() => {});
    return run;
  };

  const camera = () => JSON.parse(api.camera());
  const planner = () => JSON.parse(api.planner());
  const objects = () => JSON.parse(api.objects());
  const accuracy = () => JSON.parse(api.accuracy());
  const faceSize = () => lastStats.cubeFaceSize || cubeSize;
  const currentRow = () => matchingRow(sweepRows, accuracy().describe, faceSize(), chosenRow);

  function syncSettings() {
    const p = planner();
    settings.scene = sceneInfo.name;
    settings.cube = lastStats.cubeFaceSize || cubeSize || settings.cube;
    settings.policy = p.policy;
    settings.slice = p.facesPerFrame;
    settings.every = p.everyN;
    settings.lod = p.lod;
    settings.viewLod = p.viewLod;
    settings.staleness = p.maxStalenessFrames > 0
      ? `up to ${p.maxStalenessFrames} frame${p.maxStalenessFrames > 1 ? 's' : ''} behind` : 'none: always current';
    settings.lodLevels = Object.entries(lodLevels).filter(([, t]) => t.length > 1)
      .map(([n, t]) => `${n.replace(/\.obj$/, '')} ${t.length}`).join(', ') || 'none built';
    settings.paused = paused;
    const row = currentRow();
    settings.accuracy = row ? row.name : '';
    settings.accuracyReadout = sweepRows.length ? readout(row, accuracy().describe, faceSize())
                                                : 'sweep.csv is not available: no measured modes';
    panel?.refresh();
  }

  function rebuildLods(names = null) {
    lodReady = buildLods(Module, api, names).then((built) => {
      lodLevels = names ? { ...lodLevels, ...built } : built;
      syncSettings();
      return lodLevels;
    });
    return lodReady;
  }

  // Loads scene `name` (keepView: the same camera and time, for a cube-size change or a model
  // reset). Throws with the message already shown; the old scene stays.
  async function switchScene(name, { keepView = false } = {}) {
    let view = null;
    const sameScene = keepView && name === sceneInfo.name;
    const beforeCommit = () => {
      if (keepView) view = { camera: camera(), time: lastStats.time };
    };
    let loaded;
    try {
      loaded = await loadScene(Module, api, sceneUrl(name),
                               { userPrefix: initial.assets, cubeSize, overrides, progress, beforeCommit });
    } catch (e) {
      showMessage(e.message);
      e.shown = true;
      syncSettings();
      throw e;
    }
    const scene = JSON.parse(api.sceneJson());
    sceneInfo = { name: scene.name, title: loaded.title, json: loaded.json };
    homeCamera = camera();
    if (view) {
      api.setCamera(...view.camera.eye, view.camera.yaw, view.camera.pitch);
      if (view.time !== undefined) api.setTime(view.time);
    }
    sceneMaterials = objects().map((o) => o.material);
    if (sameScene) {
      for (const f of figures) {
        const error = withBytes(Module, f.bytes, (ptr, n) => api.loadMesh(0, f.name, ptr, n, f.source)) ||
                      api.addObject(JSON.stringify(f.object));
        if (error) showMessage(`${f.source}: ${error}`);
      }
      for (const [index, material] of materialEdits) api.setMaterial(index, JSON.stringify(material));
    } else {
      figures = [];
      materialEdits.clear();
    }
    lastStats = JSON.parse(api.frame(0, 0));
    lodLevels = {};
    syncSettings();
    panel?.showMaterials();
    await rebuildLods();
    return loaded.title;
  }

  // Changes object `index`'s material: `changes` are scene-file material keys over what it has.
  function setMaterial(index, changes) {
    const current = objects()[index];
    let error;
    if (!current) {
      error = `no object ${index} in this scene (it has ${objects().length})`;
    } else if (!['mirror', 'glass'].includes(current.material.type)) {
      error = `object ${index} (${current.mesh}) is ${current.material.type}, not a mirror or glass`;
    } else {
      const material = { ...current.material, ...changes };
      error = api.setMaterial(index, JSON.stringify(material));
      if (!error) {
        const original = sceneMaterials[index];
        const same = original && ['type', 'fresnel', 'environment'].every((k) => original[k] === material[k]) &&
                     ['reflection', 'base', 'ior'].every((k) => Math.abs(original[k] - material[k]) < 5e-4);
        if (same) materialEdits.delete(index);
        else materialEdits.set(index, material);
      }
    }
    if (error) showMessage(error);
    panel?.updateMaterials();
    return error || '';
  }
  const changedMaterials = () => [...materialEdits].map(([index, m]) => ({ index, ...m }));

  // Accuracy settings (rf_accuracy_json's keys; missing keys keep their value). "" or the error.
  function setAccuracy(changes) {
    const a = { ...accuracy(), ...changes };
    const error = api.setAccuracy(a.distance, a.origin ? 1 : 0, a.depth, a.mipmaps ? 1 : 0,
                                  a.halfFloat ? 1 : 0, a.mediump ? 1 : 0);
    if (error) showMessage(error);
    syncSettings();
    return error || '';
  }

  // A row of sweep.csv: its accuracy settings and its cube size (reloading the scene if that
  // changes, keeping the view, the figures and the materials).
  function chooseAccuracy(name) {
    return serial(async () => {
      const row = sweepRows.find((r) => r.name === name);
      if (!row) {
        const error = `${name}: not a measured accuracy mode (sweep.csv has ${sweepRows.map((r) => r.name).join(', ')})`;
        showMessage(error);
        syncSettings();
        throw new Error(error);
      }
      chosenRow = row.name;
      const error = setAccuracy(row.accuracy);
      if (error) throw new Error(error);
      const reload = row.faceSize !== faceSize();
      cubeSize = row.faceSize;
      if (reload) await switchScene(sceneInfo.name, { keepView: true });
      syncSettings();
      return accuracy();
    });
  }
  // The acc= value for the URL: the picked row while its settings are current, else the first
  // row with the current settings; for settings no row measured, the settings themselves
  // (toUrlSetting); null for the shipped default.
  const accuracyName = () => {
    const describe = accuracy().describe;
    const picked = sweepRows.find((r) => r.name === chosenRow);
    if (picked && picked.setting === describe) return picked.name;
    if (describe === defaultDescribe) return null;
    const fallback = sweepRows.find((r) => r.setting === describe);
    return fallback ? fallback.name : toUrlSetting(describe);
  };

  function setPlanner(policy, slice, every, lod, viewLod) {
    const error = api.setPlanner(policy, slice, every, lod, viewLod);
    if (error) showMessage(error);
    syncSettings();
    return error;
  }

  // --- first scene, then the URL's settings -------------------------------------------------
  let initialRow = null;
  let initialSettings = null;  // acc= as settings no row measured
  if (initial.acc) {
    initialRow = sweepRows.find((r) => r.name === initial.acc) || null;
    initialSettings = initialRow ? null : fromUrlSetting(initial.acc);
    if (!initialRow && !initialSettings) {
      showMessage(`acc=${initial.acc}: not a measured accuracy mode` +
                  (sweepRows.length ? ` (sweep.csv has ${sweepRows.map((r) => r.name).join(', ')})` : ' (sweep.csv is not available)') +
                  ', nor settings such as centre,distance-x2,depth-24,mipmapped,RGBA8,highp; ignored');
    } else if (initialRow && !cubeSize) {
      cubeSize = initialRow.faceSize;
    }
  }
  await switchScene(initial.scene);
  defaultDescribe = accuracy().describe;
  if (initialRow) {
    chosenRow = initialRow.name;
    setAccuracy(initialRow.accuracy);
  } else if (initialSettings) {
    setAccuracy(initialSettings);
  }
  for (const m of initial.mat) {
    const { index, ...material } = m;
    setMaterial(index, material);
  }
  if (initial.policy !== null || initial.slice !== null || initial.every !== null || initial.lod !== null ||
      initial.vlod !== null) {
    const p = planner();
    setPlanner(initial.policy ?? p.policy, initial.slice ?? p.facesPerFrame, initial.every ?? p.everyN,
               initial.lod ?? p.lod, initial.vlod ?? p.viewLod);
  }
  if (initial.cam) api.setCamera(...initial.cam);
  if (initial.t !== null) api.setTime(initial.t);

  const statsLine = new StatsLine(document.getElementById('stats'));
  const sparkline = new Sparkline(document.getElementById('spark'));
  lastStats = JSON.parse(api.frame(0, 1));

  // --- actions -------------------------------------------------------------------------------
  const help = document.getElementById('help-overlay');
  const toggleHelp = (show = help.hidden) => { help.hidden = !show; };
  const setPaused = (on) => { paused = on; settings.paused = on; };
  const shift = (dx, dy, dz) => {
    const c = camera();
    api.setCamera(c.eye[0] + dx, c.eye[1] + dy, c.eye[2] + dz, c.yaw, c.pitch);
  };
  const strafe = (steps) => {
    const { right } = cameraBasis(camera().yaw, camera().pitch);
    shift(right[0] * STEP * steps, 0, right[2] * STEP * steps);
  };
  const rise = (steps) => shift(0, STEP * steps, 0);

  function readPixels() {
    const gl = canvas.getContext('webgl2');
    const readBinding = gl.getParameter(gl.READ_FRAMEBUFFER_BINDING);
    const packBinding = gl.getParameter(gl.PIXEL_PACK_BUFFER_BINDING);
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, null);
    gl.bindBuffer(gl.PIXEL_PACK_BUFFER, null);
    const width = gl.drawingBufferWidth, height = gl.drawingBufferHeight;
    const data = new Uint8Array(width * height * 4);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, data);
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, readBinding);
    gl.bindBuffer(gl.PIXEL_PACK_BUFFER, packBinding);
    return { width, height, data };
  }

  // Renders a frame and saves the canvas as a PNG (read in the same task: the drawing buffer is
  // not preserved). Resolves to the file name.
  function screenshot() {
    lastStats = JSON.parse(api.frame(0, 1));
    const copy = document.createElement('canvas');
    copy.width = canvas.width;
    copy.height = canvas.height;
    copy.getContext('2d').drawImage(canvas, 0, 0);
    const name = `reflect-${sceneInfo.name}-t${(lastStats.time ?? 0).toFixed(2)}.png`;
    return new Promise((resolve, reject) => copy.toBlob((blob) => {
      if (!blob) { reject(new Error('the canvas could not be encoded as PNG')); return; }
      const a = document.createElement('a');
      a.href = URL.createObjectURL(blob);
      a.download = name;
      document.body.appendChild(a);
      a.click();
      a.remove();
      setTimeout(() => URL.revokeObjectURL(a.href), 60_000);
      resolve(name);
    }, 'image/png'));
  }

  const currentQuery = () => buildQuery({
    scene: sceneInfo.name, cube: cubeSize, planner: planner(), paused, time: lastStats.time,
    camera: camera(), home: homeCamera, assets: initial.assets, acc: accuracyName(),
    materials: changedMaterials(), faceSize: faceSize(),
  });
  const syncUrl = () => {
    const query = currentQuery();
    if (query !== location.search) history.replaceState(null, '', location.pathname + query);
  };

  async function copyLink() {
    syncUrl();
    const link = location.href;
    try {
      if (!navigator.clipboard?.writeText) throw new Error('no clipboard');
      await navigator.clipboard.writeText(link);
      showMessage(`Link copied:\n${link}`, 'info', 5000);
    } catch {
      const box = showMessage('Copy this link (the clipboard is not available here):\n', 'info link');
      const field = document.createElement('input');
      field.value = link;
      field.readOnly = true;
      field.className = 'link-field';
      box.insertBefore(field, box.lastChild);
      field.select();
    }
    return link;
  }

  // Reads a dropped or picked file (size limit, progress). Resolves to its bytes or null (the
  // problem shown).
  async function readUserFile(f) {
    if (f.file.size > MAX_MODEL_BYTES) {
      showMessage(tooLargeMessage(f.path, f.file.size));
      return null;
    }
    try {
      return await readFileBytes(f.file, progress.track(f.path));
    } catch (e) {
      showMessage(`${f.path}: could not be read (${e.message})`);
      return null;
    } finally {
      progress.clear();
    }
  }

  // Mesh `mesh` of the scene from the user's file. The page keeps the bytes for scene reloads.
  function replaceMesh(f, mesh, bytes) {
    const error = withBytes(Module, bytes, (ptr, n) => api.loadMesh(0, mesh, ptr, n, f.path));
    if (error) {
      showMessage(`${error.includes(f.path) ? error : `${f.path}: ${error}`}\n(keeping the ${mesh} it had)`);
      return false;
    }
    const figure = figures.find((g) => g.name === mesh);
    if (figure) Object.assign(figure, { bytes, source: f.path });
    else overrides.set(mesh, { bytes, source: f.path });
    return true;
  }

  // A new orbiting figure from the user's file, scaled to fit on a ring around the reflector.
  function addFigure(f, name, bytes) {
    let error = withBytes(Module, bytes, (ptr, n) => api.loadMesh(0, name, ptr, n, f.path));
    if (error) {
      showMessage(`${error.includes(f.path) ? error : `${f.path}: ${error}`}\n(not added)`);
      return false;
    }
    const bounds = JSON.parse(api.meshBounds(name));
    if (!bounds.min) {
      showMessage(`${f.path}: no bounds for the loaded mesh; not added`);
      return false;
    }
    const angle = freeAngle(takenAngles(sceneInfo.json, figures.map((g) => g.object)));
    const object = figureObject(name, bounds, angle, figures.length);
    error = api.addObject(JSON.stringify(object));
    if (error) {
      showMessage(`${f.path}: ${error}; not added`);
      return false;
    }
    figures.push({ name, bytes, source: f.path, object });
    return true;
  }

  // The user's .obj files: those named like a model of the scene replace it; the others are
  // added as orbiting figures.
  function handleFiles(files) {
    return serial(async () => {
      const meshes = JSON.parse(api.sceneJson()).meshes || [];
      const { replace, extra, ignored } = sortFiles(files, meshes);
      const list = (fs) => fs.map((f) => f.path).join(', ');
      if (ignored.length) showMessage(`${list(ignored)}: not .obj files; ignored`, 'info', 8000);
      const replaced = [], added = [];
      for (const f of replace) {
        const bytes = await readUserFile(f);
        if (bytes && replaceMesh(f, f.mesh, bytes)) replaced.push(f);
      }
      for (const f of extra) {
        const bytes = await readUserFile(f);
        if (!bytes) continue;
        const base = f.path.split('/').pop();
        // A second file of the same name (another folder) replaces the figure added before.
        const known = (JSON.parse(api.sceneJson()).meshes || []).find((m) => m.toLowerCase() === base.toLowerCase());
        if (known) {
          if (replaceMesh(f, known, bytes)) replaced.push({ ...f, mesh: known });
        } else if (addFigure(f, base, bytes)) {
          added.push({ ...f, mesh: base });
        }
      }
      if (replaced.length || added.length) {
        lastStats = JSON.parse(api.frame(0, 0));
        showMessage([...replaced.map((f) => `${f.mesh} replaced by ${f.path}`),
                     ...added.map((f) => `added ${f.path} as an orbiting figure`)].join('\n'), 'info', 5000);
        syncSettings();
        panel?.showMaterials();
        await rebuildLods([...replaced, ...added].map((f) => f.mesh));
      }
      return { replaced: replaced.map((f) => f.mesh), added: added.map((f) => f.mesh),
               extra: added.map((f) => f.path), ignored: ignored.map((f) => f.path) };
    });
  }

  const filesInput = document.getElementById('file-input');
  const folderInput = document.getElementById('folder-input');
  for (const input of [filesInput, folderInput]) {
    input.addEventListener('change', () => {
      const files = filesFromList(input.files);
      input.value = '';
      handleFiles(files);
    });
  }
  const dropHint = document.getElementById('drop-hint');
  let dragDepth = 0;
  window.addEventListener('dragenter', (e) => {
    if (![...(e.dataTransfer?.types || [])].includes('Files')) return;
    ++dragDepth;
    dropHint.hidden = false;
  });
  window.addEventListener('dragleave', () => {
    dragDepth = Math.max(0, dragDepth - 1);
    if (!dragDepth) dropHint.hidden = true;
  });
  window.addEventListener('dragover', (e) => { e.preventDefault(); });
  window.addEventListener('drop', (e) => {
    e.preventDefault();
    dragDepth = 0;
    dropHint.hidden = true;
    filesFromDrop(e.dataTransfer).then(handleFiles);
  });

  let benchResults = null;
  const benchBox = document.getElementById('bench-box');
  function bench(frames = initial.frames || 60) {
    return serial(async () => {
      await lodReady;
      const saved = { planner: planner(), time: lastStats.time };
      suspended = true;
      const status = document.getElementById('progress');
      try {
        benchResults = await runBench({
          frame: (dt) => (lastStats = JSON.parse(api.frame(dt, 1))),
          setTime: (t) => api.setTime(t),
          setPlanner: (...args) => api.setPlanner(...args),
          readPixels,
          scene: () => JSON.parse(api.sceneJson()),
        }, { frames, onProgress: (text) => { status.hidden = false; status.textContent = text; } });
        document.getElementById('bench').textContent = benchResults.table;
        benchBox.hidden = false;
        console.info(benchResults.table);
        window.demo.benchResults = benchResults;
        return benchResults;
      } catch (e) {
        showMessage(e.message);
        throw e;
      } finally {
        status.hidden = true;
        status.textContent = '';
        api.setPlanner(saved.planner.policy, saved.planner.facesPerFrame, saved.planner.everyN, saved.planner.lod,
                       saved.planner.viewLod);
        if (saved.time !== undefined) api.setTime(saved.time);
        suspended = false;
        syncSettings();
      }
    });
  }
  document.getElementById('bench-close').onclick = () => { benchBox.hidden = true; };

  attachInput(canvas, {
    drag: (dx, dy) => api.drag(dx, dy, canvas.clientHeight),
    move: (steps) => api.move(steps),
    strafe,
    rise,
    reset: () => api.resetCamera(),
    togglePause: () => setPaused(!paused),
    toggleHelp: () => toggleHelp(),
    closeHelp: () => {
      if (help.hidden) return false;
      toggleHelp(false);
      return true;
    },
  });
  document.getElementById('help-close').onclick = () => toggleHelp(false);

  // --- the panel -----------------------------------------------------------------------------
  const scenes = await titlesPromise;
  const GUI = await guiPromise;
  const panelApp = {
    settings,
    scenes,
    materialRows: () => materialRows(objects()),
    // The environment objects (mirror, glass) with their index and material.
    environmentObjects: () => objects().map((o, index) => ({ index, ...o }))
      .filter((o) => ['mirror', 'glass'].includes(o.material.type)),
    hasSkybox: () => Boolean(sceneInfo.json?.skybox),
    setMaterial: (index, changes) => setMaterial(index, changes),
    sweepRows,
    chooseAccuracy: (name) => (name ? chooseAccuracy(name).catch(() => {}) : syncSettings()),
    setScene: (name) => serial(() => switchScene(name)).catch(() => {}),
    setCube: (size) => {
      cubeSize = size;
      serial(() => switchScene(sceneInfo.name, { keepView: true })).catch(() => {});
    },
    setPlanner: () => setPlanner(settings.policy, settings.slice, settings.every, settings.lod, settings.viewLod),
    setPaused,
    step: () => { lastStats = JSON.parse(api.frame(1 / 60, 1)); },
    resetCamera: () => api.resetCamera(),
    screenshot,
    copyLink,
    pickFiles: () => filesInput.click(),
    pickFolder: () => folderInput.click(),
    builtInModels: () => {
      if (!overrides.size && !figures.length) return;
      overrides.clear();
      figures = [];
      serial(() => switchScene(sceneInfo.name, { keepView: true })).catch(() => {});
    },
    bench: () => bench().catch(() => {}),
    toggleHelp: () => toggleHelp(),
  };
  if (GUI) {
    panel = buildPanel(GUI, panelApp);
    syncSettings();
  }
  const sceneDescription = document.getElementById('scene-description');
  const describe = () => {
    const s = scenes.find((x) => x.name === sceneInfo.name);
    sceneDescription.textContent = s ? `${s.title}: ${s.description}` : sceneInfo.title;
  };
  describe();

  // --- the frame loop ------------------------------------------------------------------------
  let previous = null;
  let lastError;
  let lastUrlSync = 0;
  const tick = (now) => {
    requestAnimationFrame(tick);
    // Clamp the step so a tab that was hidden does not jump the animation.
    const dt = previous === null ? 0 : Math.min((now - previous) / 1000, 0.1);
    previous = now;
    if (suspended) return;
    lastStats = JSON.parse(api.frame(paused ? 0 : dt, 0));
    if (lastStats.error && lastStats.error !== lastError) showMessage(lastStats.error);
    lastError = lastStats.error;
    const interval = statsLine.update(now, lastStats, paused);
    sparkline.push(interval, frameTimes(lastStats).frameMs);
    if (lastStats.cubeFaceSize && lastStats.cubeFaceSize !== settings.cube) syncSettings();
    if (now - lastUrlSync > 250) {
      lastUrlSync = now;
      syncUrl();
      describe();
    }
  };
  requestAnimationFrame(tick);

  Object.assign(window.demo, {
    frame: (dt) => { lastStats = JSON.parse(api.frame(dt, 1)); return lastStats; },
    stats: () => ({ ...lastStats, fps: statsLine.fps }),
    setTime: (t) => api.setTime(t),
    pause: (on = true) => setPaused(on),
    paused: () => paused,
    camera,
    setCamera: (x, y, z, yaw, pitch) => api.setCamera(x, y, z, yaw, pitch),
    scene: () => JSON.parse(api.sceneJson()),
    planner,
    setPlanner: (policy, slice = 2, every = 4, lod = 0, viewLod = 0) => setPlanner(policy, slice, every, lod, viewLod),
    // Loads another scene; the current one stays on screen if it fails (the error is shown and thrown).
    loadScene: (nameOrUrl) => serial(() => switchScene(nameOrUrl)),
    // Triangles of each level of detail of mesh `name` ([level 0] when none was built).
    lodLevels: (name) => lodLevels[name] || null,
    lodReady: () => lodReady,
    readPixels,
    screenshot,
    copyLink,
    loadFiles: (files) => handleFiles(filesFromList(files)),
    runBench: (frames) => bench(frames),
    benchResults: null,
    query: currentQuery,
    sparkSamples: () => sparkline.samples,
    progressHistory: () => [...progress.history],
    panel: () => panel?.gui || null,
    settings,
    // rf_objects_json: [{ mesh, material: { type, reflection, base, ior, fresnel, environment } }]
    objects,
    // Object `index`'s material: scene-file material keys over what it has. "" or the error.
    setMaterial: (index, changes) => setMaterial(index, changes),
    // rf_accuracy_json: { distance, origin, depth, mipmaps, halfFloat, mediump, describe }
    accuracy,
    // setAccuracy({ distance, origin, depth, mipmaps, halfFloat, mediump }) (missing keys keep
    // their value): "" or the error. setAccuracy('ROW'): a sweep.csv row with its cube size, as
    // the panel's selector (a promise of the new accuracy; rejects for an unknown row).
    setAccuracy: (settingsOrRow) => (typeof settingsOrRow === 'string'
      ? chooseAccuracy(settingsOrRow) : setAccuracy(settingsOrRow)),
    // The sweep.csv rows, and the row of the current combination (null: not measured).
    sweep: () => sweepRows,
    accuracyRow: () => currentRow(),
    figures: () => figures.map((f) => ({ name: f.name, source: f.source, object: f.object })),
  });
  resolveReady();
  if (initial.bench) bench().catch(() => {});
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
