// The controls panel (lil-gui): scene, cube size, capture policy and LOD, the scene's materials
// (read-only), time, camera, models, and the page's actions. app.js owns the state; the panel
// only shows it and calls back.

export const CUBE_SIZES = [32, 64, 128, 256, 512, 1024];
export const POLICY_LABELS = {
  'every-frame': 'every frame',
  'when-changed': 'when changed',
  'time-sliced': 'time-sliced',
  'every-n': 'every N frames',
};

// One line per object with a material, from the scene file (defaults as src/core/scene_file.cpp).
export function materialRows(json) {
  const rows = [];
  (json?.objects || []).forEach((o, i) => {
    const m = o.material;
    if (!m) return;
    const sky = m.environment === 'skybox' ? ', static sky' : '';
    const ior = m.ior ?? 1.52;
    let text;
    if (m.type === 'mirror') {
      text = m.fresnel ? `mirror, Fresnel (ior ${ior})${sky}`
                       : `mirror ${m.reflection ?? 0.78} refl + ${m.base ?? 0.3} base${sky}`;
    } else if (m.type === 'glass') {
      text = `glass ior ${ior}${m.fresnel ? ', Fresnel' : ''}${sky}`;
    } else {
      text = m.type;
    }
    rows.push({ label: `${i + 1} ${o.mesh}`, text });
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
  capture.add(s, 'lodLevels').name('LOD levels').disable().listen().domElement.id = 'control-lod-levels';

  let materials = null;
  const showMaterials = () => {
    materials?.destroy();
    materials = gui.addFolder('Reflection mix (read-only)');
    materials.domElement.id = 'materials';
    const rows = app.materialRows();
    if (!rows.length) {
      materials.add({ none: 'no reflective object' }, 'none').name('').disable();
    }
    for (const row of rows) materials.add({ v: row.text }, 'v').name(row.label).disable();
    materials.close();
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
  };
  refresh();
  showMaterials();
  return { gui, refresh, showMaterials };
}
