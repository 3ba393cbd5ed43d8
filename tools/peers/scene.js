// The default scene in three.js, shared by its two renditions (cubecamera, bvh): its models (one
// indexed mesh per file, as the project draws them; file_world.js loads a scene file's the same
// way), the Phong objects, the mirror (its material is the rendition's), the main camera, and
// where everything is at a time.
import { BufferGeometry, MathUtils, Matrix4, Mesh, PerspectiveCamera, Scene } from 'three';
import { OBJLoader } from 'three/addons/loaders/OBJLoader.js';
import { mergeGeometries, mergeVertices } from 'three/addons/utils/BufferGeometryUtils.js';
import { phongMaterial, setWorldNormalMatrix } from './phong.js';
import { SCENE } from './scene_facts.js';

// One file's objects and groups as one indexed geometry of positions and normals: one draw a
// file, and no texture coordinates (nothing reads them). Normals are computed only where the
// file has none; merging first makes them smooth across the file's objects.
export async function loadGeometry(url) {
  const group = await new OBJLoader().loadAsync(url);
  const parts = [];
  group.traverse((o) => { if (o.isMesh) parts.push(o.geometry); });
  if (!parts.length) throw new Error(`${url} has no triangles`);
  const hasNormals = parts.every((g) => g.hasAttribute('normal'));
  const kept = parts.map((g) => {
    const part = new BufferGeometry();
    part.setAttribute('position', g.getAttribute('position'));
    if (hasNormals) part.setAttribute('normal', g.getAttribute('normal'));
    return part;
  });
  const geometry = mergeVertices(kept.length === 1 ? kept[0] : mergeGeometries(kept));
  if (!hasNormals) geometry.computeVertexNormals();
  return geometry;
}

// The scene's models from `prefix` (a URL ending in '/'), by file name.
export async function loadModels(prefix) {
  const files = [...SCENE.objects.map((o) => o.mesh), SCENE.mirror.mesh];
  const geometries = await Promise.all(files.map((f) => loadGeometry(new URL(f, prefix).href)));
  return new Map(files.map((f, i) => [f, geometries[i]]));
}

// The scene with `mirrorMaterial` on the sphere. Returns { scene, camera, objects, mirror,
// pose(seconds) }; objects are the Phong meshes, each with its `fact` (scene_facts.js).
export function buildWorld(geometries, mirrorMaterial) {
  const scene = new Scene();
  const objects = SCENE.objects.map((fact) => {
    const mesh = new Mesh(geometries.get(fact.mesh), phongMaterial(fact.colour));
    mesh.fact = fact;
    return mesh;
  });
  const mirror = new Mesh(geometries.get(SCENE.mirror.mesh), mirrorMaterial);
  mirror.matrix.makeScale(...SCENE.mirror.scale);
  for (const mesh of [...objects, mirror]) {
    mesh.matrixAutoUpdate = false;  // the model matrices are the scene file's, set by pose()
    scene.add(mesh);
  }
  const { eye, fovY, near, far } = SCENE.camera;
  const camera = new PerspectiveCamera(fovY, 1, near, far);  // looks down -Z, up +Y
  camera.position.set(...eye);

  const rotation = new Matrix4(), translation = new Matrix4(), scale = new Matrix4();
  // Model matrix Ry(angle) * T * S, angle = 27 degrees a second for the orbiting figures.
  function pose(seconds) {
    const angle = MathUtils.degToRad(SCENE.orbitDegreesPerSecond * seconds);
    for (const mesh of objects) {
      const { translate, scale: s, orbits } = mesh.fact;
      rotation.makeRotationY(orbits ? angle : 0);
      mesh.matrix.multiplyMatrices(rotation, translation.makeTranslation(...translate)).multiply(scale.makeScale(...s));
      mesh.matrixWorldNeedsUpdate = true;
    }
    mirror.matrixWorldNeedsUpdate = true;
    scene.updateMatrixWorld();
    for (const mesh of [...objects, mirror]) setWorldNormalMatrix(mesh);
  }
  return { scene, camera, objects, mirror, pose };
}
