// The page's settings as a URL query, both ways: the address bar mirrors every control
// (history.replaceState), and opening such a link restores it.
//
//   scene=NAME  cube=PIXELS  policy=every-frame|when-changed|time-sliced|every-n  slice=FACES
//   every=N  lod=TRIANGLES_PER_PIXEL  vlod=TRIANGLES_PER_PIXEL (view LOD)  paused  t=SECONDS (when paused)  cam=x,y,z,yaw,pitch
//   assets=PREFIX (the user's models by the scene's file names)
//   acc=ROW (an accuracy mode: a row name of sweep.csv; its cube size unless cube= is given)
//     or acc=SETTINGS for a combination no row measured: centre,distance-x2,depth-24,mipmapped,RGBA8,highp
//   mat=INDEX:REFLECTION,BASE,FRESNEL(0|1),IOR[,sky];... (changed materials; INDEX from 0)
// Not mirrored (one-off actions): bench, frames.

export const DEFAULT_SCENE = 'ex12-2';
export const POLICIES = ['every-frame', 'when-changed', 'time-sliced', 'every-n'];

const round = (x, digits) => {
  const s = Number(x).toFixed(digits);
  return s.includes('.') ? s.replace(/\.?0+$/, '') : s;
};

// Returns { state, problems }: state has every key (null where the URL has none), problems lists
// the values that could not be used (shown to the user).
export function parseQuery(search) {
  const params = new URLSearchParams(search);
  const problems = [];
  const state = {
    scene: params.get('scene') || DEFAULT_SCENE,
    cube: 0, policy: null, slice: null, every: null, lod: null, vlod: null,
    paused: params.has('paused'), t: null, cam: null,
    assets: params.get('assets'),
    bench: params.has('bench'),
    frames: null,
    acc: params.get('acc') || null,  // checked against sweep.csv by the page
    mat: [],
  };
  const integer = (key, min, max) => {
    if (!params.has(key)) return null;
    const v = Number(params.get(key));
    if (!Number.isInteger(v) || v < min || v > max) {
      problems.push(`${key}=${params.get(key)}: expected a whole number from ${min} to ${max}; ignored`);
      return null;
    }
    return v;
  };
  const number = (key, min, max) => {
    if (!params.has(key)) return null;
    const raw = params.get(key);
    const v = Number(raw);
    if (raw.trim() === '' || !Number.isFinite(v) || v < min || v > max) {
      problems.push(`${key}=${raw}: expected a number from ${min} to ${max}; ignored`);
      return null;
    }
    return v;
  };
  if (params.has('cube')) {
    const v = Number(params.get('cube'));
    if (!Number.isInteger(v) || v < 1) {
      problems.push(`cube=${params.get('cube')}: expected a whole number of pixels; using the scene's size`);
    } else {
      state.cube = v;
    }
  }
  if (params.has('policy')) state.policy = params.get('policy');  // the C side names bad ones
  state.slice = integer('slice', 1, 6);
  state.every = integer('every', 1, 1000);
  state.lod = number('lod', 0, 1000);
  state.vlod = number('vlod', 0, 1000);
  state.t = number('t', -1e9, 1e9);
  state.frames = integer('frames', 1, 100000);
  if (params.has('cam')) {
    const parts = params.get('cam').split(',').map(Number);
    if (parts.length !== 5 || parts.some((v) => !Number.isFinite(v))) {
      problems.push(`cam=${params.get('cam')}: expected x,y,z,yaw,pitch; using the scene's camera`);
    } else {
      state.cam = parts;
    }
  }
  if (params.has('mat')) {
    for (const entry of params.get('mat').split(';').filter(Boolean)) {
      const material = parseMaterialEntry(entry);
      if (material) state.mat.push(material);
      else problems.push(`mat=${entry}: expected INDEX:REFLECTION,BASE,FRESNEL(0|1),IOR[,sky]; ignored`);
    }
  }
  return { state, problems };
}

// "3:0.5,0.3,1,1.52[,sky]" -> { index, reflection, base, fresnel, ior, environment } or null.
export function parseMaterialEntry(entry) {
  const m = /^(\d+):(.*)$/.exec(entry);
  if (!m) return null;
  const parts = m[2].split(',');
  if (parts.length < 4 || parts.length > 5) return null;
  const [reflection, base, fresnel, ior] = parts.slice(0, 4).map(Number);
  const environment = parts[4] === undefined || parts[4] === 'live' ? 'live' : parts[4] === 'sky' ? 'skybox' : null;
  if (![reflection, base, ior].every(Number.isFinite) || reflection < 0 || reflection > 4 ||
      base < 0 || base > 4 || ior < 1 || ior > 4 || (fresnel !== 0 && fresnel !== 1) || !environment) {
    return null;
  }
  return { index: Number(m[1]), reflection, base, fresnel: fresnel === 1, ior, environment };
}

// { index, reflection, base, fresnel, ior, environment } -> "3:0.5,0.3,1,1.52[,sky]".
export function materialEntry(m) {
  return `${m.index}:${[round(m.reflection, 3), round(m.base, 3), m.fresnel ? 1 : 0, round(m.ior, 3)].join(',')}` +
         (m.environment === 'skybox' ? ',sky' : '');
}

// The query for the page as it is now. `planner` is rf_planner_json's, `camera` rf_camera_json's,
// `home` the scene's own camera (cam= is left out while the camera is there), `acc` a sweep row
// name (or null; with it the cube size `faceSize` is written even when the user did not set one,
// since acc= alone means the row's size), `materials` the changed materials (see materialEntry).
export function buildQuery({ scene, cube, planner, paused, time, camera, home, assets, acc = null,
                             materials = [], faceSize = 0 }) {
  const parts = [`scene=${encodeURIComponent(scene)}`];
  if (cube || (acc && faceSize)) parts.push(`cube=${cube || faceSize}`);
  if (planner && planner.policy) {
    parts.push(`policy=${planner.policy}`);
    if (planner.policy === 'time-sliced') parts.push(`slice=${planner.facesPerFrame}`);
    if (planner.policy === 'every-n') parts.push(`every=${planner.everyN}`);
    if (planner.lod > 0) parts.push(`lod=${round(planner.lod, 3)}`);
    if (planner.viewLod > 0) parts.push(`vlod=${round(planner.viewLod, 3)}`);
  }
  if (paused) {
    parts.push('paused');
    if (time !== undefined && time !== null) parts.push(`t=${round(time, 4)}`);
  }
  if (camera && camera.eye && !sameCamera(camera, home)) {
    parts.push(`cam=${[...camera.eye.map((v) => round(v, 4)), round(camera.yaw, 3), round(camera.pitch, 3)].join(',')}`);
  }
  if (acc) parts.push(`acc=${encodeURIComponent(acc)}`);
  if (materials.length) parts.push(`mat=${materials.map(materialEntry).join(';')}`);
  if (assets) parts.push(`assets=${encodeURIComponent(assets)}`);
  return `?${parts.join('&')}`;
}

export function sameCamera(a, b) {
  if (!a || !b || !a.eye || !b.eye) return false;
  const close = (x, y, e) => Math.abs(x - y) <= e;
  return a.eye.every((v, i) => close(v, b.eye[i], 5e-5)) && close(a.yaw, b.yaw, 5e-4) &&
         close(a.pitch, b.pitch, 5e-4);
}
