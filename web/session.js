// What the user has made of the demo: the scene (by the name or URL asked for), the cube size,
// the planner, accuracy and material settings, the added figures and replaced models, the
// camera, time and pause. Every change goes through here, to the C++ side through the bridge,
// and tells the listeners (the panel, the address bar) what changed. Scene loads, model changes
// and the bench run one at a time in a job queue; idle() resolves when it is empty and the levels
// of detail are built. Levels are built off the main thread (lod.js), after the first frame that
// draws them (session_levels.js), and never hold a job: a scene switch cancels the build under way.
import { AccuracyModes } from './accuracy.js';
import { showMessage } from './messages.js';
import { loadScene, readFileMesh, sceneUrl } from './scene_loader.js';
import { SessionLevels } from './session_levels.js';

// A model's loader warning (it loaded, with something let pass): an info message.
const warnInfo = (text) => showMessage(text, 'info');

export class Session {
  constructor(bridge, { schema, sweepRows, assets = null, progress = null }) {
    Object.assign(this, { bridge, schema, assets, progress });
    this.modes = new AccuracyModes(sweepRows);
    this.scene = { name: null, title: '' };  // name: as asked for (a shipped name or a URL)
    this.cubeSize = 0;  // the user's face size; 0: the scene file's
    this.paused = false;
    this.homeCamera = null;  // the scene's own camera (cam= stays out of links while it is there)
    this.sceneMaterials = [];  // the objects' materials as the scene file has them
    // Added figures { name, file, source, object }: kept through reloads of the same scene. The
    // user's files are kept as File objects (the browser's handle on the file), not their text.
    this.figures = [];
    this.overrides = new Map();  // mesh name -> { file, source }: the user's replacement models
    this.defaultAccuracy = Object.fromEntries(schema.accuracy.map((i) => [i.name, i.default]));
    this.levelState = new SessionLevels(bridge, () => this.changed('models'));
    this.lastStats = {};
    this.firstFrameStats = null;  // the stats of the first frame after the last scene load
    this.listeners = [];
    this.queue = Promise.resolve();
    this.pending = 0;
  }

  // listener(kind): kind is 'scene', 'settings', 'camera', 'time', 'models' or 'view'.
  onChange(listener) { this.listeners.push(listener); }
  changed(kind) { for (const listener of this.listeners) listener(kind); }

  // Runs `job` after the jobs before it; its promise is the job's.
  serial(job) {
    ++this.pending;
    const run = this.queue.then(job);
    this.queue = run.catch(() => {}).finally(() => { --this.pending; });
    return run;
  }

  // Resolves once no job is queued or running (jobs queued meanwhile included) and the levels of
  // detail are built.
  async idle() {
    for (;;) {
      while (this.pending) await this.queue;
      await this.lodReady();
      if (!this.pending) return;
    }
  }

  // Builds what the C++ side still lacks of what the frames drew (chunks and levels of a capture,
  // view LOD's levels), in the background (session_levels.js); resolves when that build is done.
  startLevels() { return this.levelState.start(); }
  // Asks for every chunk and level the LOD settings could draw, and resolves (to { mesh:
  // [triangles a level] }) once they are built.
  lodReady() { return this.levelState.ready(); }
  // Resolves once what the frames want is built, asking for nothing more.
  levelsSettled() { return this.levelState.settled(); }
  get lodLevels() { return this.levelState.lodLevels; }
  get levels() { return this.levelState.builder; }

  faceSize() { return this.bridge.scene().cubeFaceSize || this.cubeSize; }
  // wait: false (none), true (after each pass, which the stats then time) or 'end' (once, after
  // the frame).
  frame(dt, wait = false) {
    this.lastStats = this.bridge.frame({ dt, waitForGpu: wait === true, waitAtEnd: wait === 'end' });
    // The frame captured, and its meshes lack the chunks or levels a capture draws: built now.
    if (this.lastStats.levelsWanted && !this.levels.running) this.startLevels();
    this.redrawStep();
    return this.lastStats;
  }

  // --- scenes and models ---------------------------------------------------------------------

  // Loads scene `name` (keepView: the same camera and time, and for the same scene its figures
  // and material changes, as for a cube size). Throws with the message already shown; the old
  // scene stays then.
  async switchScene(name, { keepView = false } = {}) {
    const same = keepView && name === this.scene.name;
    const edits = same ? this.changedMaterials() : [];
    let view = null;
    const beforeCommit = () => {
      if (keepView) view = { camera: this.bridge.camera(), time: this.bridge.time() };
      this.levels.cancel();  // its meshes are about to go
    };
    let title;
    try {
      // A reload of the same scene (cube size, accuracy mode) loads the same files again: their
      // warnings were shown the first time.
      title = await loadScene(this.bridge, sceneUrl(name), {
        userPrefix: this.assets, cubeSize: this.cubeSize, overrides: this.overrides, progress: this.progress, beforeCommit,
        warn: same ? null : warnInfo,
      });
    } catch (e) {
      showMessage(e.message);
      e.shown = true;
      this.changed('settings');
      throw e;
    }
    this.scene = { name, title };
    this.homeCamera = this.bridge.camera();
    if (view) {
      this.bridge.setCamera(view.camera);
      this.bridge.setTime(view.time);
    }
    this.sceneMaterials = this.bridge.objects().map((o) => o.material);
    if (same) {
      for (const f of this.figures) {
        const error = (await readFileMesh(this.bridge, { name: f.name, source: f.source }, f.file)
          .catch((e) => e.message)) || this.bridge.addObject(f.object);
        if (error) showMessage(`${f.source}: ${error}`);
      }
      for (const edit of edits) this.bridge.setMaterial(edit);
    } else {
      this.figures = [];
    }
    this.levelState.lodLevels = {};
    // First frame first: the scene is drawn as parsed; its chunks and levels come after.
    this.firstFrameStats = this.frame(0);
    this.changed('scene');
    this.startLevels();
    return title;
  }

  loadScene(name) { return this.serial(() => this.switchScene(name)); }
  reload() { return this.serial(() => this.switchScene(this.scene.name, { keepView: true })); }
  setCubeSize(size) {
    this.cubeSize = size;
    return this.reload();
  }

  // Back to the scene's own models: no replacements, no added figures.
  builtInModels() {
    if (!this.overrides.size && !this.figures.length) return Promise.resolve();
    this.overrides.clear();
    this.figures = [];
    return this.reload();
  }

  // Mesh `mesh` of the scene from the user's file { file, path }, parsed as it is read (the File is
  // kept for reloads). Resolves to "" or the error; the
  // loader's warnings are shown as info messages.
  async replaceModel(f, mesh, onProgress = null) {
    const error = await readFileMesh(this.bridge, { name: mesh, source: f.path, warn: warnInfo }, f.file, onProgress)
      .catch((e) => e.message);
    if (error) return error;
    const figure = this.figures.find((g) => g.name === mesh);
    if (figure) Object.assign(figure, { file: f.file, source: f.path });
    else this.overrides.set(mesh, { file: f.file, source: f.path });
    return '';
  }

  // A new figure from the user's file { file, path }: `place(bounds, figures)` gives its
  // scene-file object. Resolves to "" or the error; the loader's
  // warnings are shown as info messages.
  async addFigure(f, name, place, onProgress = null) {
    const error = await readFileMesh(this.bridge, { name, source: f.path, warn: warnInfo }, f.file, onProgress)
      .catch((e) => e.message);
    if (error) return error;
    const bounds = this.bridge.meshBounds(name);
    if (!bounds) return 'no bounds for the loaded mesh';
    const object = place(bounds, this.figures.map((g) => g.object));
    const addError = this.bridge.addObject(object);
    if (addError) return addError;
    this.figures.push({ name, file: f.file, source: f.path, object });
    return '';
  }

  // After models changed: a frame, the listeners, and (in the background) their chunks and levels.
  modelsChanged() {
    this.frame(0);
    this.changed('models');
    return this.startLevels();
  }

  // --- settings --------------------------------------------------------------------------------

  // Each returns "" or the error (shown).
  report(error, kind = 'settings') {
    if (error) showMessage(error);
    this.changed(kind);
    return error || '';
  }
  setPlanner(changes) {
    const error = this.report(this.bridge.setPlanner(changes));
    if (!error) this.startLevels();  // a LOD setting turned on wants levels
    return error;
  }
  setAccuracy(changes) { return this.report(this.bridge.setAccuracy(changes)); }
  // A named preset (the schema's presets: the course's scheme, the shipped defaults): its planner
  // and accuracy settings at once. Returns "" or the problem.
  applyPreset(name) {
    const preset = (this.schema.presets || []).find((p) => p.name === name);
    if (!preset) return this.report(`${name}: not a preset (${(this.schema.presets || []).map((p) => p.name).join(', ')})`);
    this.modes.chosen = null;
    return this.setAccuracy(preset.accuracy) || this.setPlanner(preset.planner);
  }
  setMaterial(index, changes) { return this.report(this.bridge.setMaterial({ index, changes })); }
  // Show error, auto and its budget (the 'view' listeners: the panel, the address bar, auto).
  setView(changes) { return this.report(this.bridge.setView(changes), 'view'); }

  // The materials that differ from the scene file's: [{ index, changes }] by schema name.
  changedMaterials() {
    return this.bridge.objects().flatMap((o, index) => {
      const original = this.sceneMaterials[index];
      if (!original || !o.editable) return [];
      const changes = Object.fromEntries(this.schema.material.map((i) => i.name)
        .filter((name) => o.material[name] !== original[name]).map((name) => [name, o.material[name]]));
      return Object.keys(changes).length ? [{ index, changes }] : [];
    });
  }

  // A measured accuracy mode (a row of sweep.csv): its settings and its cube size (reloading
  // the scene when that changes).
  chooseAccuracy(name) {
    return this.serial(async () => {
      const row = this.modes.find(name);
      if (!row) {
        const error = `${name}: not a measured accuracy mode (sweep.csv has ${this.modes.names()})`;
        this.report(error);
        throw new Error(error);
      }
      this.modes.chosen = row.name;
      const error = this.setAccuracy(row.accuracy);
      if (error) throw new Error(error);
      const reload = row.faceSize !== this.faceSize();
      this.cubeSize = row.faceSize;
      if (reload) await this.switchScene(this.scene.name, { keepView: true });
      this.changed('settings');
      return this.bridge.accuracy();
    });
  }
  accuracyRow() { return this.modes.current(this.bridge.accuracy(), this.faceSize()); }
  accuracyReadout() {
    return this.modes.readout(this.accuracyRow(), this.bridge.accuracyDescription(), this.faceSize());
  }

  // --- camera, time, pause --------------------------------------------------------------------

  camera(change) {
    change(this.bridge);
    this.changed('camera');
  }
  setTime(seconds) {
    this.bridge.setTime(seconds);
    this.changed('time');
  }
  step(seconds = 1 / 60) {
    this.frame(seconds, true);
    this.changed('time');
  }
  setPaused(on) {
    this.paused = on;
    this.changed('time');
  }

  // --- step through a frame (Inside the frame) ---------------------------------------------------

  // Pauses, and draws the next step of the frame now (after the last, the first again): the canvas
  // shows it until the page runs again. Returns the C++ side's reply ({ step, count, steps } or
  // { error }); onStep listeners hear it.
  stepFrame() {
    if (!this.paused) this.setPaused(true);
    const count = this.stepReply?.count || 0;
    return this.showStep(this.shownStep === undefined || this.shownStep + 1 >= count ? 0 : this.shownStep + 1);
  }
  // Pauses and shows step `index` (from 0; past the last, the last): a link's step=.
  showStep(index) {
    if (!this.paused) this.setPaused(true);
    this.shownStep = index;
    return this.drawShownStep();
  }
  // A frame drawn while stepping is drawn over by the step shown (the camera may have moved); once
  // the page runs again, stepping ends.
  redrawStep() {
    if (this.shownStep === undefined) return;
    if (this.paused) {
      this.drawShownStep();
      return;
    }
    this.shownStep = undefined;
    this.stepReply = null;
    for (const listener of this.stepListeners || []) listener(null);
  }
  drawShownStep() {
    this.stepReply = this.bridge.frameStep(this.shownStep);
    if (this.stepReply.error) {
      showMessage(this.stepReply.error);
      this.shownStep = undefined;
    } else {
      this.shownStep = this.stepReply.step;  // clamped to the frame's steps
    }
    for (const listener of this.stepListeners || []) listener(this.stepReply);
    return this.stepReply;
  }
  onStep(listener) { (this.stepListeners ||= []).push(listener); }

}
