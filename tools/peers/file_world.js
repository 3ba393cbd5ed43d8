// A scene file's world in three.js (scene_file.js reads the file): the same models, Phong and
// camera as the default scene's world (scene.js), for any number of mirrors, each with where its
// probe sits. Returns what startPeer's loadWorld wants: { scene, camera, background, capture,
// objects, mirrors, pose(seconds) }; objects are every mesh in the file's order, each with its `fact`;
// mirrors the mirror meshes, each with `probeCentre` (a Vector3 that pose() keeps current).
import { Mesh, PerspectiveCamera, Scene, Vector3 } from 'three';
import { lighting, phongMaterial, setWorldNormalMatrix } from './phong.js';
import { loadGeometry } from './scene.js';
import { modelMatrixAt } from './scene_file.js';

// `facts` from loadSceneFile; `prefix` the models' folder (a URL ending in '/');
// `mirrorMaterialFor(fact, index)` the rendition's material for each mirror (and glass, where the
// file was read with glass: `mirrors` holds both).
export async function buildFileWorld(facts, prefix, mirrorMaterialFor) {
  const names = [...new Set(facts.objects.map((o) => o.mesh))];
  const geometries = await Promise.all(names.map((n) => loadGeometry(new URL(n, prefix).href)));
  const geometryOf = new Map(names.map((n, i) => [n, geometries[i]]));
  // The shared lighting uniforms (phong.js) take this file's eye and light.
  lighting.eye.value.set(...facts.camera.eye);
  lighting.lightPosition.value.set(...facts.light.position);

  const scene = new Scene();
  const objects = facts.objects.map((fact, index) => {
    const reflector = fact.mirror || fact.glass;
    const material = reflector ? mirrorMaterialFor(fact, index) : phongMaterial(fact.colour, facts.light);
    const mesh = new Mesh(geometryOf.get(fact.mesh), material);
    mesh.fact = fact;
    mesh.matrixAutoUpdate = false;  // the file's model matrices, set by pose()
    scene.add(mesh);
    return mesh;
  });
  const mirrors = objects.filter((mesh) => mesh.fact.mirror || mesh.fact.glass);
  // The probe captures from the centre of the mirror's bounds, placed (as the project's
  // layoutProbes for a probe of one member).
  for (const mesh of mirrors) {
    mesh.geometry.computeBoundingBox();
    mesh.localCentre = mesh.geometry.boundingBox.getCenter(new Vector3());
    mesh.probeCentre = new Vector3();
  }
  const { eye, fovY, near, far } = facts.camera;
  const camera = new PerspectiveCamera(fovY, 1, near, far);  // looks down -Z, up +Y
  camera.position.set(...eye);

  function pose(seconds) {
    for (const mesh of objects) {
      modelMatrixAt(mesh.fact, seconds, mesh.matrix);
      mesh.matrixWorldNeedsUpdate = true;
    }
    scene.updateMatrixWorld();
    for (const mesh of objects) setWorldNormalMatrix(mesh);
    for (const mesh of mirrors) mesh.probeCentre.copy(mesh.localCentre).applyMatrix4(mesh.matrixWorld);
  }
  return { scene, camera, background: facts.background, capture: facts.capture, objects, mirrors, pose };
}
