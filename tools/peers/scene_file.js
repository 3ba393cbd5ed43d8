// A project scene file (assets/scenes/NAME.json, served as scenes/NAME.json beside this folder)
// read into the numbers a peer draws, as src/core/scene_file.cpp reads it: placement
// T * R * S, an orbit R(axis, rate t) * placement, a spin placement * R(axis, rate t), mirrors'
// reflection, base and roughness with SceneObject's defaults. What the peers do not draw
// (skyboxes, cube-textured objects, shared probes, Fresnel mirrors; glass but for the frosted
// peer, which asks for it) is refused, not ignored.
import { MathUtils, Matrix4, Vector3 } from 'three';

const DEFAULTS = {
  camera: { eye: [0, 1, 7], fovY: 70, near: 1, far: 100 },
  light: { position: [5, 1, 7], ambient: 0.2, diffuse: 0.7, specular: 1.0, shininess: 10 },
  background: [0.4, 0.4, 0.4],
  capture: { faceSize: 256, near: 1, far: 100 },
  mirror: { reflection: 0.78, base: 0.3, roughness: 0 },
};

const scaleOf = (s) => (s === undefined ? [1, 1, 1] : typeof s === 'number' ? [s, s, s] : s);

function placementOf(o) {
  const m = new Matrix4().makeTranslation(...(o.translate || [0, 0, 0]));
  if (o.rotate) {
    const axis = new Vector3(...(o.rotate.axis || [0, 1, 0])).normalize();
    m.multiply(new Matrix4().makeRotationAxis(axis, MathUtils.degToRad(o.rotate.degrees || 0)));
  }
  return m.multiply(new Matrix4().makeScale(...scaleOf(o.scale)));
}

// One object: { mesh, placement, colour, motion: null | { orbit, axis, degreesPerSecond },
// mirror: null | { reflection, base, roughness }, ambient: 'constant' | 'probe' | 'own-probe' }.
function objectOf(o, index, acceptGlass) {
  const where = `objects[${index}] (${o.mesh})`;
  const material = typeof o.material === 'string' ? { type: o.material } : o.material || { type: 'phong' };
  const glass = material.type === 'glass' && acceptGlass;
  if (material.type !== 'phong' && material.type !== 'mirror' && !glass) {
    throw new Error(`${where}: a ${material.type} material is not drawn by the peers`);
  }
  if (o.probe !== undefined || o.probeCentre !== undefined) throw new Error(`${where}: shared or placed probes are not drawn by the peers`);
  if ((material.fresnel && !glass) || (material.environment && material.environment !== 'live')) {
    throw new Error(`${where}: Fresnel mirrors and skybox environments are not drawn by the peers`);
  }
  const a = o.animation;
  return {
    mesh: o.mesh,
    placement: placementOf(o),
    colour: o.colour || [1, 1, 1],
    motion: a ? { orbit: a.type === 'orbit', axis: new Vector3(...(a.axis || [0, 1, 0])).normalize(),
                  degreesPerSecond: a.degreesPerSecond ?? 27 } : null,
    mirror: material.type === 'mirror' ? { ...DEFAULTS.mirror, ...material } : null,
    glass: glass ? { ior: 1.52, roughness: 0, fresnel: false, ...material } : null,
    ambient: o.ambient || 'constant',
  };
}

// The model matrix at `seconds` into `out` (Scene::modelMatrix; the angle wrapped as it is there).
export function modelMatrixAt(object, seconds, out) {
  out.copy(object.placement);
  const m = object.motion;
  if (!m) return out;
  const turn = new Matrix4().makeRotationAxis(m.axis, MathUtils.degToRad((m.degreesPerSecond * seconds) % 360));
  return m.orbit ? out.premultiply(turn) : out.multiply(turn);
}

// { name, camera, light, background, capture, objects } from scenes/NAME.json.
// `acceptGlass`: glass objects are read (as `glass`), not refused (the frosted peer).
export async function loadSceneFile(name, base = new URL('../scenes/', import.meta.url),
                                    acceptGlass = false) {
  const url = new URL(`${name}.json`, base);
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: ${response.status} ${response.statusText}`);
  const file = await response.json();
  if (file.skybox) throw new Error(`${name}: a skybox is not drawn by the peers`);
  return {
    name,
    camera: { ...DEFAULTS.camera, ...file.camera },
    light: { ...DEFAULTS.light, ...file.light },
    background: file.background || DEFAULTS.background,
    capture: { ...DEFAULTS.capture, ...file.capture },
    objects: file.objects.map((o, i) => objectOf(o, i, acceptGlass)),
  };
}
