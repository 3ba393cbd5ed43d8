// The page's settings as a URL query, both ways: the address bar follows every change
// (history.replaceState), and opening such a link restores it. Settings go by their names in the
// settings schema (rf_schema_json: the same names as the C++ fields and the CLI's options):
//
//   scene=NAME|URL  cube=PIXELS (the capture's face size; default: the scene file's)
//   policy=…&facesPerFrame=…&everyN=…&captureLod=…&viewLod=…   (the planner's settings)
//   preset=NAME (a named preset's planner and accuracy settings; the link's own keys override it)
//   acc=ROW (a measured accuracy mode: a row name of sweep.csv, with its cube size unless cube=)
//   captureAtOrigin=…&search=…&…   (accuracy settings, written when no row has them)
//   mat=INDEX:NAME=VALUE,…;…   (changed material settings; INDEX is the object's place from 0)
//   showError=true&auto=true&budget=MS   (the view settings, written when not at their default)
//   paused  t=SECONDS (while paused)  cam=x,y,z,yaw,pitch (unless the scene's own)  assets=PREFIX
//   pick=X,Y (pick a pixel: the drawing buffer's pixel explained, its rays drawn)
//   step=N (step N of the frame shown, from 1: step through a frame; it pauses)
// Not written (one-off actions): bench, frames.

export const DEFAULT_SCENE = 'ex12-2';

// Links written before each setting had one name: their keys, read as the new ones (with a
// message naming the new key).
const RENAMED = { slice: 'facesPerFrame', every: 'everyN', lod: 'captureLod', vlod: 'viewLod' };
// The old mat= entries' order: INDEX:REFLECTION,BASE,FRESNEL(0|1),IOR[,sky].
const OLD_MATERIAL_ORDER = ['reflection', 'base', 'fresnel', 'ior', 'environment'];

const round = (x, digits) => {
  const s = Number(x).toFixed(digits);
  return s.includes('.') ? s.replace(/\.?0+$/, '') : s;
};

// A link's text as the value the schema's kind wants; what is not one stays text, for the C++
// side to name in its message.
export function fromText(info, text) {
  if (!info) return text;
  if (info.kind === 'integer' || info.kind === 'number') {
    const v = Number(text);
    return text.trim() !== '' && Number.isFinite(v) ? v : text;
  }
  if (info.kind === 'flag') {
    if (['', 'true', '1'].includes(text)) return true;
    if (['false', '0'].includes(text)) return false;
  }
  return text;
}

function toText(info, value) {
  if (typeof value === 'number') return round(value, 4);
  if (typeof value === 'boolean') return value ? 'true' : 'false';
  return encodeURIComponent(String(value ?? (info ? info.default : '')));
}

const byName = (list, name) => list.find((info) => info.name === name);
const changesText = (changes, list) =>
  Object.entries(changes).map(([k, v]) => `${k}=${toText(byName(list, k), v)}`).join(',');

// An old link's acc=centre,distance-x2,depth-24,linear,RGBA8,highp as settings by the schema's
// names over their defaults, or null. (A distance search was the linear one then.)
function oldAccuracySettings(text, schema) {
  const settings = Object.fromEntries(schema.accuracy.map((i) => [i.name, i.default]));
  const words = {
    origin: { captureAtOrigin: true }, centre: { captureAtOrigin: false }, plain: { search: 'plain' },
    linear: { mipmaps: false }, mipmapped: { mipmaps: true }, RGBA8: { halfFloat: false },
    RGBA16F: { halfFloat: true }, highp: { mediump: false }, mediump: { mediump: true },
  };
  for (const word of text.split(',')) {
    const depth = /^depth-(16|24)$/.exec(word);
    if (words[word]) Object.assign(settings, words[word]);
    else if (/^distance-x\d+$/.test(word)) settings.search = 'linear';
    else if (depth) settings.depthBits = Number(depth[1]);
    else return null;
  }
  return settings;
}

// Returns { state, problems, notes }: state has every key (null or empty where the link has
// none); problems are values that cannot be used (shown as errors), notes the old keys read as
// new ones.
export function parseQuery(search, schema) {
  const params = new URLSearchParams(search);
  const problems = [], notes = [];
  const state = {
    scene: params.get('scene') || DEFAULT_SCENE, cube: 0, paused: params.has('paused'), t: null,
    cam: null, assets: params.get('assets'), bench: params.has('bench'), frames: null, acc: null,
    planner: {}, accuracy: {}, materials: [], view: {}, pick: null,
  };
  parsePageKeys(params, state, problems);
  for (const group of ['planner', 'accuracy', 'view']) {
    for (const info of schema[group] || []) {
      if (params.has(info.name)) state[group][info.name] = fromText(info, params.get(info.name));
    }
  }
  parsePreset(params, schema, state, problems);
  parseRenamedKeys(params, schema, state, notes);
  parseAccuracyRow(params, schema, state, problems, notes);
  for (const entry of (params.get('mat') || '').split(';').filter(Boolean)) {
    const material = parseMaterialEntry(entry, schema, problems, notes);
    if (material) state.materials.push(material);
  }
  return { state, problems, notes };
}

// The page's own keys (not settings): cube, t, frames, pick, step, cam.
function parsePageKeys(params, state, problems) {
  const number = (key, ok, expected) => {
    if (!params.has(key)) return null;
    const raw = params.get(key), v = Number(raw);
    if (raw.trim() === '' || !Number.isFinite(v) || !ok(v)) {
      problems.push(`${key}=${raw}: expected ${expected}; ignored`);
      return null;
    }
    return v;
  };
  // A comma-separated list of numbers, each passing `ok`, or null (and the problem).
  const list = (key, count, ok, problem) => {
    if (!params.has(key)) return null;
    const parts = params.get(key).split(',').map(Number);
    if (parts.length === count && parts.every(ok)) return parts;
    problems.push(`${key}=${params.get(key)}: ${problem}`);
    return null;
  };
  state.cube = number('cube', (v) => Number.isInteger(v) && v >= 1, "a whole number of pixels (the scene's size stays)") || 0;
  state.t = number('t', (v) => Math.abs(v) <= 1e9, 'a number of seconds');
  state.frames = number('frames', (v) => Number.isInteger(v) && v >= 1 && v <= 100000, 'a whole number from 1 to 100000');
  state.pick = list('pick', 2, (v) => Number.isInteger(v) && v >= 0,
    'expected X,Y, a pixel of the canvas from its top-left corner; no pixel picked');
  state.step = number('step', (v) => Number.isInteger(v) && v >= 1 && v <= 100000, 'a step of the frame, from 1');
  state.cam = list('cam', 5, Number.isFinite, "expected x,y,z,yaw,pitch; using the scene's camera");
}

// A preset's settings under the link's own: the keys the link gives win.
function parsePreset(params, schema, state, problems) {
  if (!params.has('preset')) return;
  const name = params.get('preset');
  const preset = (schema.presets || []).find((p) => p.name === name);
  if (!preset) {
    problems.push(`preset=${name}: not a preset (${(schema.presets || []).map((p) => p.name).join(', ')}); ignored`);
    return;
  }
  state.planner = { ...preset.planner, ...state.planner };
  state.accuracy = { ...preset.accuracy, ...state.accuracy };
}

// Links written before each setting had one name: read as the new keys, with a note.
function parseRenamedKeys(params, schema, state, notes) {
  for (const [old, name] of Object.entries(RENAMED)) {
    if (!params.has(old)) continue;
    const value = params.get(old);
    if (name in state.planner) {
      notes.push(`${old}=${value}: an old link's key, now ${name}; ignored (the link also has ${name})`);
      continue;
    }
    state.planner[name] = fromText(byName(schema.planner, name), value);
    notes.push(`${old}=${value}: an old link's key, now ${name}=${value} (applied)`);
  }
}

// acc=ROW (a measured mode, checked against sweep.csv by the page), or the old form of settings
// no row has: the words of the old description.
function parseAccuracyRow(params, schema, state, problems, notes) {
  const acc = params.get('acc');
  if (!acc) return;
  if (!acc.includes(',')) {
    state.acc = acc;
    return;
  }
  const settings = oldAccuracySettings(acc, schema);
  if (!settings) {
    problems.push(`acc=${acc}: neither a measured accuracy mode nor settings; ignored`);
    return;
  }
  const changed = Object.fromEntries(schema.accuracy.filter((i) => settings[i.name] !== i.default)
    .map((i) => [i.name, settings[i.name]]));
  state.accuracy = { ...changed, ...state.accuracy };
  notes.push(`acc=${acc}: an old link's form, now ${changesText(changed, schema.accuracy).replace(/,/g, '&') || 'the defaults'} (applied)`);
}

// One mat= entry, INDEX:NAME=VALUE,… (or the old positional form, with a note): { index, changes,
// entry }, or null (and the problem).
function parseMaterialEntry(entry, schema, problems, notes) {
  const m = /^(\d+):(.+)$/.exec(entry);
  if (!m) {
    problems.push(`mat=${entry}: expected INDEX:NAME=VALUE,… (${schema.material.map((i) => i.name).join(', ')}); ignored`);
    return null;
  }
  const fields = m[2].split(',');
  const changes = {};
  if (!m[2].includes('=')) {  // the old positional form
    fields.forEach((text, i) => {
      const name = OLD_MATERIAL_ORDER[i] || `value${i + 1}`;
      changes[name] = name === 'environment' ? (text === 'sky' ? 'skybox' : text) : fromText(byName(schema.material, name), text);
    });
    if (fields.length === 4) changes.environment = 'live';
    notes.push(`mat=${entry}: an old link's form, now mat=${m[1]}:${changesText(changes, schema.material)} (applied)`);
  } else {
    for (const field of fields) {
      const [name, ...rest] = field.split('=');
      changes[name] = fromText(byName(schema.material, name), rest.join('='));
    }
  }
  return { index: Number(m[1]), changes, entry };
}

// The query for the page as it is now (Session.linkState): planner settings are written when
// they are the policy or its parameters, or differ from their default (never a setting the
// policy does not read); accuracy settings as acc=ROW when a measured row has them (with the
// cube size), else those that differ from their default.
export function buildQuery(link, schema) {
  const parts = [`scene=${encodeURIComponent(link.scene)}`];
  if (link.cube || (link.acc && link.faceSize)) parts.push(`cube=${link.cube || link.faceSize}`);
  const planner = link.planner.settings || {};
  for (const info of schema.planner) {
    const value = planner[info.name];
    if (value === undefined || link.planner.unusedSettings?.includes(info.name)) continue;
    if (info.name === 'policy' || link.planner.policyParameters?.includes(info.name) || value !== info.default) {
      parts.push(`${info.name}=${toText(info, value)}`);
    }
  }
  if (link.paused) {
    parts.push('paused');
    if (Number.isFinite(link.time)) parts.push(`t=${round(link.time, 4)}`);
    if (link.step) parts.push(`step=${link.step}`);
  }
  if (link.pick) parts.push(`pick=${link.pick.join(',')}`);
  if (link.camera?.eye && !sameCamera(link.camera, link.home)) {
    const c = link.camera;
    parts.push(`cam=${[...c.eye.map((v) => round(v, 4)), round(c.yaw, 3), round(c.pitch, 3)].join(',')}`);
  }
  if (link.acc) {
    parts.push(`acc=${encodeURIComponent(link.acc)}`);
  } else {
    for (const info of schema.accuracy) {
      const value = link.accuracy?.[info.name];
      if (value !== undefined && value !== info.default) parts.push(`${info.name}=${toText(info, value)}`);
    }
  }
  if (link.materials?.length) {
    parts.push(`mat=${link.materials.map((m) => `${m.index}:${changesText(m.changes, schema.material)}`).join(';')}`);
  }
  for (const info of schema.view || []) {
    const value = link.view?.[info.name];
    if (value !== undefined && value !== info.default) parts.push(`${info.name}=${toText(info, value)}`);
  }
  if (link.assets) parts.push(`assets=${encodeURIComponent(link.assets)}`);
  return `?${parts.join('&')}`;
}

export function sameCamera(a, b) {
  if (!a || !b || !a.eye || !b.eye) return false;
  const close = (x, y, e) => Math.abs(x - y) <= e;
  return a.eye.every((v, i) => close(v, b.eye[i], 5e-5)) && close(a.yaw, b.yaw, 5e-4) &&
         close(a.pitch, b.pitch, 5e-4);
}
