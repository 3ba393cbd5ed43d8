// The controls panel (lil-gui): scene, cube size, capture policy and LOD, the accuracy mode (a
// measured row of sweep.csv) with its expected error, the reflective objects' materials, time,
// camera, models, and the page's actions. app.js owns the state; the panel only shows it and
// calls back.

export const CUBE_SIZES = [32, 64, 128, 256, 512, 1024];
export const POLICY_LABELS = {
  'every-frame': 'every frame',
  'when-changed': 'when changed',
  'time-sliced': 'time-sliced',
  'every-n': 'every N frames',
};

// One line per reflective object (rf_objects_json's entries; phong objects are left out).
export function materialSummary(m) {
  const sky = m.environment === 'skybox' ? ', static sky' : '';
  if (m.type === 'mirror') {
    return m.fresnel ? `mirror, Fresnel (ior ${m.ior})${sky}` : `mirror ${m.reflection} refl + ${m.base} base${sky}`;
  }
  if (m.type === 'glass') return `glass ior ${m.ior}${m.fresnel ? ', Fresnel' : ''}${sky}`;
  return m.type;
}

export function materialRows(objects) {
  const rows = [];
  (objects || []).forEach((o, i) => {
    if (!o.material || o.material.type === 'phong') return;
    rows.push({ label: `${i + 1} ${o.mesh}`, text: materialSummary(o.material) });
  });
  return rows;
}

// GUI: lil-gui's class. app: see app.js (makePanelApp).
export function buildPanel(GUI, app) {
  const gui = new GUI({ title: 'Controls', width: 260 });
  gui.domElement.id = 'panel';
  // On a phone or a narrow window the open panel would hide the scene: start it closed there.
  if (matchMedia('(pointer: coarse)').matches || innerWidth < 640) gui.close();
  const s = app.settings;

  const sceneOptions = Object.fromEntries(app.scenes.map((sc) => [sc.title ? `${sc.title}` : sc.name, sc.name]));
  if (!Object.values(sceneOptions).includes(s.scene)) sceneOptions[s.scene] = s.scene;
  const scene = gui.add(s, 'scene', sceneOptions).name('scene').onChange((v) => app.setScene(v));
  scene.domElement.id = 'control-scene';

  const capture = gui.addFolder('Capture');
  const cubeOptions = [...CUBE_SIZES];
  const addCube = () => {
    if (!cubeOptions.includes(s.cube)) cubeOptions.push(s.cube);
    cubeOptions.sort((a, b) => a - b);
    const c = capture.add(s, 'cube', cubeOptions).name('cube size').onChange((v) => app.setCube(Number(v)));
    c.domElement.id = 'control-cube';
    return c;
  };
  let cube = addCube();
  const policy = capture.add(s, 'policy', Object.fromEntries(Object.entries(POLICY_LABELS).map(([k, v]) => [v, k])))
    .name('update policy').onChange(() => app.setPlanner());
  policy.domElement.id = 'control-policy';
  const slice = capture.add(s, 'slice', 1, 6, 1).name('faces per frame').onFinishChange(() => app.setPlanner());
  slice.domElement.id = 'control-slice';
  const every = capture.add(s, 'every', 2, 16, 1).name('every N').onFinishChange(() => app.setPlanner());
  every.domElement.id = 'control-every';
  capture.add(s, 'staleness').name('staleness').disable().listen().domElement.id = 'control-staleness';
  const lod = capture.add(s, 'lod', 0, 2, 0.05).name('LOD tris/pixel').onFinishChange(() => app.setPlanner());
  lod.domElement.id = 'control-lod';
  const viewLod = capture.add(s, 'viewLod', 0, 2, 0.05).name('view LOD tris/pixel')
    .onFinishChange(() => app.setPlanner());
  viewLod.domElement.id = 'control-view-lod';
  capture.add(s, 'lodLevels').name('LOD levels').disable().listen().domElement.id = 'control-lod-levels';

  // Accuracy: a point on the measured speed/accuracy curve (sweep.csv), and what it costs.
  const accuracyFolder = gui.addFolder('Accuracy (measured modes)');
  accuracyFolder.domElement.id = 'accuracy';
  const rowLabel = (r) => `${r.name}: ${r.psnr.toFixed(1)} dB, ${r.ms.toFixed(0)} ms${r.pareto ? ' ★' : ''}`;
  const accuracyOptions = { 'not measured': '' };
  for (const r of app.sweepRows) accuracyOptions[rowLabel(r)] = r.name;
  const accuracy = accuracyFolder.add(s, 'accuracy', accuracyOptions).name('mode')
    .onChange((v) => app.chooseAccuracy(v));
  accuracy.domElement.id = 'control-accuracy';
  const readout = document.createElement('div');
  readout.id = 'accuracy-readout';
  readout.className = 'readout';
  readout.title = 'measured by reflect bench --sweep on the default scene, against the ray-traced reference';
  accuracyFolder.$children.appendChild(readout);

  // The reflective objects' materials: a summary line each, and for mirrors and glass the
  // weights, Fresnel, index of refraction and environment, applied as they change.
  let materials = null;
  let materialControllers = [];
  const showMaterials = () => {
    const wasOpen = materials ? !materials._closed : false;
    materials?.destroy();
    materials = gui.addFolder('Materials');
    materials.domElement.id = 'materials';
    materialControllers = [];
    const rows = app.materialRows();
    if (!rows.length) {
      materials.add({ none: 'no reflective object' }, 'none').name('').disable();
    }
    const editable = new Map(app.environmentObjects().map((o) => [o.index, o]));
    for (const row of rows) {
      const index = Number(row.label.split(' ')[0]) - 1;
      const folder = materials.addFolder(row.label);
      folder.domElement.id = `materials-${index}`;
      const summary = { v: row.text };
      const line = folder.add(summary, 'v').name('now').disable();
      line.domElement.id = `control-mat-${index}`;
      const o = editable.get(index);
      if (!o) continue;
      const m = { ...o.material };
      const id = (key, c) => { c.domElement.id = `control-mat-${index}-${key}`; return c; };
      const apply = (key) => (v) => app.setMaterial(index, { [key]: v });
      const controls = [
        id('reflection', folder.add(m, 'reflection', 0, 2, 0.01).name('reflection').onFinishChange(apply('reflection'))),
        id('base', folder.add(m, 'base', 0, 2, 0.01).name('base').onFinishChange(apply('base'))),
        id('fresnel', folder.add(m, 'fresnel').name('Fresnel').onChange(apply('fresnel'))),
        id('ior', folder.add(m, 'ior', 1, 3, 0.01).name('index of refraction').onFinishChange(apply('ior'))),
      ];
      const environments = app.hasSkybox() || m.environment === 'skybox' ? ['live', 'skybox'] : ['live'];
      controls.push(id('environment', folder.add(m, 'environment', environments).name('environment')
        .onChange(apply('environment'))));
      materialControllers.push({ index, summary, line, m, controls });
    }
    if (!wasOpen) materials.close();
  };
  // After a material changed (here, from the URL or from demo.setMaterial): show what it is now.
  const updateMaterials = () => {
    const now = new Map(app.environmentObjects().map((o) => [o.index, o.material]));
    for (const c of materialControllers) {
      const material = now.get(c.index);
      if (!material) continue;
      Object.assign(c.m, material);
      c.summary.v = materialSummary(material);
      c.line.updateDisplay();
      for (const control of c.controls) control.updateDisplay();
    }
  };

  const view = gui.addFolder('Time and view');
  view.add(s, 'paused').name('paused (Space)').onChange((v) => app.setPaused(v)).listen().domElement.id = 'control-paused';
  view.add(app, 'step').name('step 1/60 s').domElement.id = 'control-step';
  view.add(app, 'resetCamera').name('reset camera (R)').domElement.id = 'control-reset';

  const models = gui.addFolder('Your models');
  models.add(app, 'pickFiles').name('load .obj files…').domElement.id = 'control-files';
  models.add(app, 'pickFolder').name('load a folder…').domElement.id = 'control-folder';
  models.add(app, 'builtInModels').name('back to built-in models').domElement.id = 'control-builtin';
  models.close();

  const actions = gui.addFolder('Share and measure');
  actions.add(app, 'screenshot').name('screenshot (PNG)').domElement.id = 'control-screenshot';
  actions.add(app, 'copyLink').name('copy link').domElement.id = 'control-link';
  actions.add(app, 'bench').name('run bench').domElement.id = 'control-bench';
  actions.add(app, 'toggleHelp').name('keys and mouse (?)').domElement.id = 'control-help';

  const refresh = () => {
    slice.show(s.policy === 'time-sliced');
    every.show(s.policy === 'every-n');
    if (!cubeOptions.includes(s.cube)) {
      cube.destroy();
      cube = addCube();
    }
    for (const c of gui.controllersRecursive()) c.updateDisplay();
    readout.textContent = s.accuracyReadout;
  };
  refresh();
  showMaterials();
  return { gui, refresh, showMaterials, updateMaterials };
}
