// The controls panel (lil-gui). The session owns the state; the panel shows it and calls it. Every
// setting control is made from its entry in the settings schema (label, help, kind, range,
// choices), so a setting added on the C++ side appears here by itself: the planner's under
// Capture, the accuracy settings under Accuracy › settings, the material settings under Materials.
// Control ids: #control-NAME, #control-acc-NAME, #control-mat-INDEX-NAME.
import { dockPanel } from './layout.js';

export const CUBE_SIZES = [32, 64, 128, 256, 512, 1024];

// Step through a frame: a button that draws the frame's next step (pausing), and the step's name
// and triangles as the C++ side words them.
function addStepControl(folder, session) {
  if (!folder) return;
  const step = folder.add({ step: () => session.stepFrame() }, 'step').name('step through the frame (.)');
  step.domElement.id = 'control-frame-step';
  const readout = document.createElement('div');
  readout.id = 'step-readout';
  readout.className = 'readout';
  readout.title = 'each face\'s passes, then the main pass: reflect render --steps DIR writes the same steps';
  folder.$children.appendChild(readout);
  const show = (reply) => {
    const shown = reply?.steps?.[reply.step];
    readout.textContent = shown ? `step ${reply.step + 1} of ${reply.count}: ${shown.label}` : '';
  };
  session.onStep(show);
  show(session.stepReply);  // a link's step= is shown before the panel is made
}

// Pick a pixel: a button for the P key (touch has no keys): the mode on or off; a click or tap on
// the canvas then explains that pixel.
function addPickControl(folder, togglePick) {
  if (!folder || !togglePick) return;
  const pick = folder.add({ pick: togglePick }, 'pick').name('pick a pixel (P), then click');
  pick.domElement.id = 'control-pick';
}

// A control for schema entry `info` on target[info.name]; `apply(value)` is called with changes.
function addSetting(folder, target, info, apply, id) {
  let c;
  if (info.kind === 'choice') {
    c = folder.add(target, info.name, info.choices).onChange(apply);
  } else if (info.kind === 'flag') {
    c = folder.add(target, info.name).onChange(apply);
  } else {
    const step = info.kind === 'integer' ? 1 : 0.01;
    // A slider where the range is short enough to pick from; else a number field.
    c = info.max - info.min <= 64 ? folder.add(target, info.name, info.min, info.max, step)
                                   : folder.add(target, info.name).min(info.min).step(step);
    c.onFinishChange(apply);
  }
  c.name(info.label);
  c.domElement.title = info.help;
  c.domElement.id = id;
  return c;
}

// GUI: lil-gui's class. session: session.js. actions: { scenes, screenshot, copyLink, pickFiles,
// pickFolder, bench, toggleHelp, helpLabel, resized, autoReadout }. The panel goes in #dock; it
// starts open in a wide window only, and the layout makes room for it (layout.js). Returns
// { gui, refresh }.
export function buildPanel(GUI, session, actions) {
  const { bridge } = session;
  const gui = new GUI({ title: 'Controls', width: 260, container: document.getElementById('dock') });
  gui.domElement.id = 'panel';
  dockPanel(gui, actions.resized);
  const view = { scene: session.scene.name, cube: session.faceSize(), planner: bridge.planner(),
                 accuracy: bridge.accuracy(), view: bridge.view(), mode: '', staleness: '',
                 lodLevels: '', paused: session.paused };
  addScenePicker(gui, view, session, actions, () => refresh());
  const capture = addCaptureFolder(gui, view, session);
  const accuracy = addAccuracyFolder(gui, view, session, actions, () => refresh());
  const materials = materialsFolder(gui, session);
  addTimeAndShareFolders(gui, view, session, actions);

  // Reads everything shown back from the session.
  function refresh() {
    const state = bridge.plannerState();
    const stale = state.maxStalenessFrames;
    Object.assign(view, {
      scene: session.scene.name, cube: session.faceSize(), paused: session.paused,
      mode: session.accuracyRow()?.name || '',
      staleness: stale > 0 ? `up to ${stale} frame${stale > 1 ? 's' : ''} behind` : 'none: always current',
      lodLevels: Object.entries(session.lodLevels).filter(([, t]) => t.length > 1)
        .map(([n, t]) => `${n.replace(/\.obj$/i, '')} ${t.length}`).join(', ') || 'none built',
    });
    Object.assign(view.planner, state.settings);
    Object.assign(view.accuracy, bridge.accuracy());
    Object.assign(view.view, bridge.view());
    capture.refresh(state);
    materials.refresh();
    for (const c of gui.controllersRecursive()) c.updateDisplay();
    accuracy.refresh();
  }
  session.onChange((kind) => {
    if (kind === 'scene') materials.show();
    if (kind !== 'camera') refresh();
  });
  materials.show();
  refresh();
  return { gui, refresh };
}

// The scene picker, and the presets (the course's scheme one pick away: its settings then show in
// the folders). `refresh()`: the panel reads the session again.
function addScenePicker(gui, view, session, actions, refresh) {
  const { schema } = session;
  const sceneOptions = Object.fromEntries(actions.scenes.map((sc) => [sc.title || sc.name, sc.name]));
  if (!Object.values(sceneOptions).includes(view.scene)) sceneOptions[view.scene] = view.scene;
  gui.add(view, 'scene', sceneOptions).name('scene').onChange((v) => session.loadScene(v).catch(() => {}))
    .domElement.id = 'control-scene';
  const presetNames = (schema.presets || []).map((p) => p.name);
  if (!presetNames.length) return;
  // An action, not a state: the list always shows its prompt, and a pick applies that preset.
  const options = { 'apply a preset…': '' };
  for (const name of presetNames) options[name] = name;
  view.preset = '';
  const c = gui.add(view, 'preset', options).name('preset').onChange((v) => {
    if (v) session.applyPreset(v);
    view.preset = '';
    refresh();
  });
  c.domElement.id = 'control-preset';
  c.domElement.title = schema.presets.map((p) => `${p.name}: ${p.help}`).join('\n');
}

// Capture: the cube size, the planner's settings (those the policy does not read hidden), and what
// follows from them (staleness, LOD levels). { refresh(plannerState) }.
function addCaptureFolder(gui, view, session) {
  const capture = gui.addFolder('Capture');
  const cubeOptions = [...CUBE_SIZES];
  const addCube = () => {
    if (!cubeOptions.includes(view.cube)) cubeOptions.push(view.cube);
    cubeOptions.sort((a, b) => a - b);
    const c = capture.add(view, 'cube', cubeOptions).name('cube size')
      .onChange((v) => session.setCubeSize(Number(v)).catch(() => {}));
    c.domElement.id = 'control-cube';
    c.domElement.title = 'each probe\'s face size; a probe read only by rough mirrors\' lobe ' +
      'taps takes the smaller size its lobes need (pick a pixel on one names it)';
    return c;
  };
  let cube = addCube();
  const plannerControls = new Map();
  for (const info of session.schema.planner) {
    plannerControls.set(info.name, addSetting(capture, view.planner, info,
      (v) => session.setPlanner({ [info.name]: v }), `control-${info.name}`));
  }
  readOnly(capture, view, 'staleness', 'staleness', 'control-staleness');
  readOnly(capture, view, 'lodLevels', 'LOD levels', 'control-lod-levels');
  return {
    refresh: (state) => {
      for (const [name, c] of plannerControls) c.show(!state.unusedSettings?.includes(name));
      if (!cubeOptions.includes(view.cube)) {  // a size the list lacks (a scene file's own)
        cube.destroy();
        cube = addCube();
      }
    },
  };
}

function readOnly(folder, view, key, label, id) {
  const c = folder.add(view, key).name(label).disable();
  c.domElement.id = id;
  return c;
}

// Accuracy: a point on the measured speed/accuracy curve (sweep.csv) and what it costs, the view
// settings (show error, auto and its budget here; those the schema puts in a folder of their own,
// Inside the frame, in that folder, with the step and pick controls), and the accuracy settings one
// by one. `refresh()`: the panel reads the session again. { refresh() } rewrites the readouts.
function addAccuracyFolder(gui, view, session, actions, refresh) {
  const { schema } = session;
  const accuracy = gui.addFolder('Accuracy (measured modes)');
  accuracy.domElement.id = 'accuracy';
  const rowLabel = (r) => `${r.name}: ${r.psnr.toFixed(1)} dB, ${r.ms.toFixed(0)} ms${r.pareto ? ' ★' : ''}`;
  const modeOptions = { 'not measured': '' };
  for (const r of session.modes.rows) modeOptions[rowLabel(r)] = r.name;
  accuracy.add(view, 'mode', modeOptions).name('mode')
    .onChange((v) => (v ? session.chooseAccuracy(v).catch(() => {}) : refresh())).domElement.id = 'control-accuracy';
  const readout = addReadout(accuracy, 'accuracy-readout',
    'measured by reflect bench --sweep on the default scene, against the ray-traced reference');
  const viewFolders = new Map();
  const folderOf = (info) => {
    if (!info.folder) return accuracy;
    if (!viewFolders.has(info.folder)) viewFolders.set(info.folder, gui.addFolder(info.folder));
    return viewFolders.get(info.folder);
  };
  for (const info of schema.view || []) {
    addSetting(folderOf(info), view.view, info, (v) => session.setView({ [info.name]: v }), `control-view-${info.name}`);
  }
  addStepControl(viewFolders.get('Inside the frame'), session);
  addPickControl(viewFolders.get('Inside the frame'), actions.togglePick);
  const autoReadout = addReadout(accuracy, 'auto-readout',
    'auto: each search timed on this machine, its error measured against the exact mode on this scene');
  const accuracySettings = accuracy.addFolder('settings');
  for (const info of schema.accuracy) {
    addSetting(accuracySettings, view.accuracy, info, (v) => session.setAccuracy({ [info.name]: v }),
               `control-acc-${info.name}`);
  }
  accuracySettings.close();
  return {
    refresh: () => {
      readout.textContent = session.accuracyReadout();
      autoReadout.textContent = `auto: ${actions.autoReadout ? actions.autoReadout() : 'off'}`;
    },
  };
}

function addReadout(folder, id, title) {
  const readout = document.createElement('div');
  readout.id = id;
  readout.className = 'readout';
  readout.title = title;
  folder.$children.appendChild(readout);
  return readout;
}

// The reflective objects' materials: a summary line each, and for those the page may change
// (mirrors and glass) a control per material setting but the type. { show() (re)makes the folder
// for the scene now, refresh() reads the materials back }.
function materialsFolder(gui, session) {
  const { bridge, schema } = session;
  let materials = null;
  let materialViews = [];
  const show = () => {
    const wasOpen = materials ? !materials._closed : false;
    materials?.destroy();
    materials = gui.addFolder('Materials');
    materials.domElement.id = 'materials';
    materialViews = [];
    const objects = bridge.objects().map((o, index) => ({ ...o, index })).filter((o) => o.reflective);
    if (!objects.length) materials.add({ none: 'no reflective object' }, 'none').name('').disable();
    const environments = bridge.scene().environments || [];
    for (const o of objects) {
      const folder = materials.addFolder(`${o.index + 1} ${o.mesh}`);
      folder.domElement.id = `materials-${o.index}`;
      const line = { now: o.summary, material: { ...o.material } };
      folder.add(line, 'now').name('now').disable().domElement.id = `control-mat-${o.index}`;
      if (o.editable) {
        for (const info of schema.material.filter((i) => i.name !== 'type')) {
          const choices = info.name === 'environment'
            ? info.choices.filter((c) => environments.includes(c) || c === o.material.environment) : info.choices;
          addSetting(folder, line.material, { ...info, choices }, (v) => session.setMaterial(o.index, { [info.name]: v }),
                     `control-mat-${o.index}-${info.name}`);
        }
      }
      materialViews.push({ index: o.index, line });
    }
    if (!wasOpen) materials.close();
  };
  const refresh = () => {
    const objects = bridge.objects();
    for (const { index, line } of materialViews) {
      const o = objects[index];
      if (!o) continue;
      line.now = o.summary;
      Object.assign(line.material, o.material);
    }
  };
  return { show, refresh };
}

// Time and view (pause, a 1/60 s step, reset camera), your models, share and measure.
function addTimeAndShareFolders(gui, view, session, actions) {
  const time = gui.addFolder('Time and view');
  time.add(view, 'paused').name('paused (Space)').onChange((v) => session.setPaused(v)).domElement.id = 'control-paused';
  time.add({ step: () => session.step() }, 'step').name('step 1/60 s').domElement.id = 'control-step';
  time.add({ reset: () => session.camera((b) => b.resetCamera()) }, 'reset').name('reset camera (R)')
    .domElement.id = 'control-reset';

  const models = gui.addFolder('Your models');
  models.add(actions, 'pickFiles').name('load .obj files…').domElement.id = 'control-files';
  models.add(actions, 'pickFolder').name('load a folder…').domElement.id = 'control-folder';
  models.add({ builtIn: () => session.builtInModels().catch(() => {}) }, 'builtIn').name('back to built-in models')
    .domElement.id = 'control-builtin';
  models.close();

  const share = gui.addFolder('Share and measure');
  share.add(actions, 'screenshot').name('screenshot (PNG)').domElement.id = 'control-screenshot';
  share.add(actions, 'copyLink').name('copy link').domElement.id = 'control-link';
  share.add(actions, 'bench').name('run bench').domElement.id = 'control-bench';
  share.add(actions, 'toggleHelp').name(actions.helpLabel || 'keys and mouse (?)').domElement.id = 'control-help';
}
