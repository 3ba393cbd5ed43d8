// Rendition E: frosted glass with three.js's own material, for a scene file of Phong objects and
// glass (?scene=NAME, default frosted-glass). Each glass sphere is a MeshPhysicalMaterial with
// transmission 1, the file's index and roughness, thickness its diameter and a white colour (the
// project's Fresnel glass takes no base colour), and no lights (the project's glass shows its
// environment alone). Each frame:
//   1. every sphere's CubeCamera, at its centre, draws the scene (every sphere hidden: a
//      transmissive object in view makes three run its transmission pass for each cube face,
//      which took SwiftShader's GPU process down) into its own RGBA8 cube of the file's capture
//      face size, and one PMREMGenerator turns it into the sphere's envMap: its reflection,
//      blurred by roughness;
//   2. the main pass: three draws the opaque objects into its transmission target (mipmapped,
//      from the main camera) and each sphere reads what it lets through from there, refracted by
//      its index and thickness and blurred by its roughness: a screen-space refraction, not a
//      cube map or a ray through the sphere.
// The nearest three.js has to the project's frosted glass, not the same model: its reflection and
// transmission are three's physically based ones (GGX, split-sum DFG, Fresnel at the index).
import { CubeCamera, MeshPhysicalMaterial, PMREMGenerator } from 'three';
import { captureTarget } from './capture_target.js';
import { buildFileWorld } from './file_world.js';
import { startPeer } from './peer_page.js';
import { loadSceneFile } from './scene_file.js';

const params = new URLSearchParams(location.search);
const sceneName = params.get('scene') || 'frosted-glass';

function glassMaterialFor(fact) {
  if (!fact.glass) throw new Error(`${fact.mesh}: the frosted peer draws glass, not mirrors`);
  // A sphere.obj of radius 1 scaled uniformly: its diameter is twice the scale.
  const scale = fact.placement.getMaxScaleOnAxis();
  return new MeshPhysicalMaterial({
    color: 0xffffff, metalness: 0, roughness: fact.glass.roughness, ior: fact.glass.ior,
    transmission: 1, thickness: 2 * scale, specularIntensity: 1,
  });
}

function makeProbe(mesh, capture, generator, glass) {
  const target = captureTarget(capture.faceSize);
  const camera = new CubeCamera(capture.near, capture.far, target);
  let pmrem = null;
  return {
    capture(renderer, scene) {
      camera.position.copy(mesh.probeCentre);
      for (const g of glass) g.visible = false;
      camera.update(renderer, scene);
      for (const g of glass) g.visible = true;
    },
    prefilter() {
      const first = !pmrem;
      pmrem = generator.fromCubemap(target.texture, pmrem);  // the same target from then on
      mesh.material.envMap = pmrem.texture;
      if (first) mesh.material.needsUpdate = true;  // its program now reads an envMap
    },
  };
}

startPeer({
  async loadWorld(prefix) {
    const facts = await loadSceneFile(sceneName, undefined, true);
    return buildFileWorld(facts, prefix, glassMaterialFor);
  },
  makeRendition({ renderer, world }) {
    const generator = new PMREMGenerator(renderer);
    const probes = world.mirrors.map((mesh) => makeProbe(mesh, world.capture, generator, world.mirrors));
    return {
      draw(phase) {
        for (const probe of probes) probe.capture(renderer, world.scene);
        for (const probe of probes) probe.prefilter();
        phase?.('capture');
        renderer.render(world.scene, world.camera);
      },
    };
  },
});
