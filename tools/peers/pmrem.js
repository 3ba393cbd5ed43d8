// Rendition C: rough mirrors with three.js's own parts, for any scene file of Phong objects and
// mirrors (?scene=NAME, default ex12-2; rough-spheres is the one it was written for). Each frame:
//   1. every mirror's CubeCamera, at its probe centre, draws the scene (that mirror hidden) into
//      its own RGBA8 cube of the file's capture face size (128 for rough-spheres); the other
//      mirrors in view show the prefiltered maps of the frame before, seen from this probe's
//      centre (the project's one bounce: docs/architecture.md, the capture);
//   2. one PMREMGenerator turns each cube into a PMREM (fromCubemap). In three 0.187 a PMREM is a
//      half-float cube render target of at least 256 pixels a face (a 128 capture is upsampled)
//      whose mip levels 0..ENVMAP_MAX_LOD (5 at 256) hold the GGX lobe of roughness
//      1 - sqrt(1 - lod / max), alpha = roughness^2 as the project's, prefiltered with V = N;
//      each mirror's PMREM target is handed back to fromCubemap the next frame (no allocation a
//      frame; ?fresh instead allocates a new one each frame and disposes the old);
//   3. the main pass: each mirror reads its PMREM along the reflected view ray at its roughness
//      with three's own roughnessToMip (envmap_common_pars_fragment: lod = max r (2 - r)) and
//      mixes it as the project does, reflection * seen + base * colour (0.78 and 0.3).
// Not MeshStandardMaterial: its PBR (DFG split sum, Fresnel, the lookup bent towards the normal
// by roughness^4, the irradiance term) is another model than the project's fixed mix; this
// ShaderMaterial keeps three's prefilter and its level choice and nothing else of it.
// ?mask draws the mirrors white (told apart by their green) and everything else black: the
// reflector mask of tools/peer_bench.mjs --reference.
import { CubeCamera, PMREMGenerator, Vector3 } from 'three';
import { captureTarget } from './capture_target.js';
import { buildFileWorld } from './file_world.js';
import { worldMaterial } from './phong.js';
import { startPeer } from './peer_page.js';
import { loadSceneFile } from './scene_file.js';

const params = new URLSearchParams(location.search);
const sceneName = params.get('scene') || 'ex12-2';
const maskMode = params.has('mask');
const freshTargets = params.has('fresh');

// Three 0.187's PMREM size for a capture: the face size rounded down to a power of two, at
// least 256 (PMREMGenerator's MIN_SIZE); its last level is log2(size) - 3 (LOD_MIN). Checked
// against every PMREM made.
const pmremMaxLod = (faceSize) => Math.log2(Math.max(256, 2 ** Math.floor(Math.log2(faceSize)))) - 3;

// Where the mirrors look from: the main camera's eye in the main pass, a probe's centre while
// its faces are drawn. One object for every mirror material.
const viewPosition = { value: new Vector3() };

const MIRROR_FRAGMENT_GLSL = /* glsl */`
#include <envmap_common_pars_fragment>
uniform vec3 viewPosition;
uniform vec3 baseColour;
uniform float roughness;
uniform float reflectionWeight;
uniform float baseWeight;
in vec3 worldPosition;
in vec3 worldNormal;
out vec4 fragColour;

void main() {
  vec3 N = normalize(worldNormal);
  vec3 I = normalize(worldPosition - viewPosition);
  // The PMREM is a render target: its faces are in GL's convention, as the capture's (no flip).
  vec3 seen = textureLod(envMap, reflect(I, N), roughnessToMip(roughness)).rgb;
  fragColour = vec4(reflectionWeight * seen + baseWeight * baseColour, 1.0);
}
`;

const FLAT_FRAGMENT_GLSL = /* glsl */`
uniform vec3 flatColour;
out vec4 fragColour;
void main() { fragColour = vec4(flatColour, 1.0); }
`;

function mirrorMaterialFor(facts) {
  return (fact) => {
    const material = worldMaterial(MIRROR_FRAGMENT_GLSL, {
      envMap: { value: null },
      viewPosition,
      baseColour: { value: new Vector3(...fact.colour) },
      roughness: { value: fact.mirror.roughness },
      reflectionWeight: { value: fact.mirror.reflection },
      baseWeight: { value: fact.mirror.base },
    });
    material.defines = { USE_ENVMAP: '', ENVMAP_TYPE_PMREM: '',
                         ENVMAP_MAX_LOD: pmremMaxLod(facts.capture.faceSize).toFixed(1) };
    return material;
  };
}

// One mirror's probe: its cube, its camera and its PMREM.
function makeProbe(mesh, capture, generator) {
  const target = captureTarget(capture.faceSize);
  const camera = new CubeCamera(capture.near, capture.far, target);
  let pmrem = null;
  return {
    capture(renderer, scene) {
      viewPosition.value.copy(mesh.probeCentre);
      camera.position.copy(mesh.probeCentre);
      mesh.visible = false;
      camera.update(renderer, scene);
      mesh.visible = true;
    },
    prefilter() {
      const previous = pmrem;
      pmrem = generator.fromCubemap(target.texture, freshTargets ? null : previous);
      if (freshTargets && previous) previous.dispose();
      const maxLod = pmrem.texture.mipmaps.length - 1;
      if (maxLod !== Number(mesh.material.defines.ENVMAP_MAX_LOD)) {
        throw new Error(`the PMREM has ${maxLod + 1} levels, the shader expects ${mesh.material.defines.ENVMAP_MAX_LOD}`);
      }
      mesh.material.uniforms.envMap.value = pmrem.texture;
    },
  };
}

// ?mask: every object one flat colour (the same vertex shader, so the same pixels), on black:
// mirror k (0, 1, ... in the file's order) in (1, 1 - k / 255, 1), so white is the first and the
// green channel tells the mirrors apart.
function maskRendition(renderer, world) {
  renderer.setClearColor(0x000000, 1);
  for (const mesh of world.objects) {
    const k = world.mirrors.indexOf(mesh);
    const colour = k < 0 ? new Vector3(0, 0, 0) : new Vector3(1, 1 - k / 255, 1);
    mesh.material = worldMaterial(FLAT_FRAGMENT_GLSL, { flatColour: { value: colour } });
  }
  return { draw: () => renderer.render(world.scene, world.camera) };
}

startPeer({
  async loadWorld(prefix) {
    const facts = await loadSceneFile(sceneName);
    return buildFileWorld(facts, prefix, mirrorMaterialFor(facts));
  },
  makeRendition({ renderer, world }) {
    if (maskMode) return maskRendition(renderer, world);
    const generator = new PMREMGenerator(renderer);
    const probes = world.mirrors.map((mesh) => makeProbe(mesh, world.capture, generator));
    return {
      draw() {
        // Every capture before any prefilter: a probe sees the other mirrors as they were
        // before this frame's captures, whatever the order.
        for (const probe of probes) probe.capture(renderer, world.scene);
        for (const probe of probes) probe.prefilter();
        viewPosition.value.copy(world.camera.position);
        renderer.render(world.scene, world.camera);
      },
    };
  },
});
