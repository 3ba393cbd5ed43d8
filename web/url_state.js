// The page's settings as a URL query, both ways: the address bar mirrors every control
// (history.replaceState), and opening such a link restores it.
//
//   scene=NAME  cube=PIXELS  policy=every-frame|when-changed|time-sliced|every-n  slice=FACES
//   every=N  lod=TRIANGLES_PER_PIXEL  paused  t=SECONDS (when paused)  cam=x,y,z,yaw,pitch
//   assets=PREFIX (the user's models by the scene's file names)
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
    cube: 0, policy: null, slice: null, every: null, lod: null,
    paused: params.has('paused'), t: null, cam: null,
    assets: params.get('assets'),
    bench: params.has('bench'),
    frames: null,
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
  return { state, problems };
}

// The query for the page as it is now. `planner` is rf_planner_json's, `camera` rf_camera_json's,
// `home` the scene's own camera (cam= is left out while the camera is there).
export function buildQuery({ scene, cube, planner, paused, time, camera, home, assets }) {
  const parts = [`scene=${encodeURIComponent(scene)}`];
  if (cube) parts.push(`cube=${cube}`);
  if (planner && planner.policy) {
    parts.push(`policy=${planner.policy}`);
    if (planner.policy === 'time-sliced') parts.push(`slice=${planner.facesPerFrame}`);
    if (planner.policy === 'every-n') parts.push(`every=${planner.everyN}`);
    if (planner.lod > 0) parts.push(`lod=${round(planner.lod, 3)}`);
  }
  if (paused) {
    parts.push('paused');
    if (time !== undefined && time !== null) parts.push(`t=${round(time, 4)}`);
  }
  if (camera && camera.eye && !sameCamera(camera, home)) {
    parts.push(`cam=${[...camera.eye.map((v) => round(v, 4)), round(camera.yaw, 3), round(camera.pitch, 3)].join(',')}`);
  }
  if (assets) parts.push(`assets=${encodeURIComponent(assets)}`);
  return `?${parts.join('&')}`;
}

export function sameCamera(a, b) {
  if (!a || !b || !a.eye || !b.eye) return false;
  const close = (x, y, e) => Math.abs(x - y) <= e;
  return a.eye.every((v, i) => close(v, b.eye[i], 5e-5)) && close(a.yaw, b.yaw, 5e-4) &&
         close(a.pitch, b.pitch, 5e-4);
}
