// Rendition D: probe-lit figures with three.js's own parts, for a scene file of Phong objects,
// mirrors and probe-lit objects ("ambient": "probe" or "own-probe"; probe-lit is the one it was
// written for). Each frame:
//   1. every probe-lit object's CubeCamera, at its bounds' centre ("own-probe", the object hidden)
//      or at the nearest mirror's centre ("probe", every probe-lit object hidden), draws the scene
//      into its own RGBA8 cube (32 pixels a face for an own probe, the file's capture size
//      otherwise), probe-lit objects in it with the constant ambient (one bounce, as the project);
//   2. each cube is read back to the CPU (readRenderTargetPixels, a face at a time) and projected
//      on three's order-2 spherical harmonics (SphericalHarmonics3.getBasisAt: the same nine
//      basis functions as the project's core/irradiance.h), each texel weighed by its solid
//      angle, as LightProbeGenerator.fromCubeRenderTarget does; that one is asynchronous in three
//      0.187 (its read-back resolves after the frame), so the page does the same sum in the
//      frame, synchronously, with the faces in GL's cube-map convention (cubecamera.js);
//   3. every mirror's CubeCamera captures as the course does (cubecamera.js) and the main pass
//      draws the probe-lit objects with colour * (E(n) / pi + Kd N.L) + specular, E from the
//      coefficients with the cosine lobe's band factors (1, 2/3, 1/4 over pi), the project's
//      shaders/irradiance.glsl term by term.
// Not MeshLambertMaterial + LightProbe: three's lights would bring its own Phong and light units;
// this ShaderMaterial keeps three's capture and projection and the project's Phong.
import { CubeCamera, SphericalHarmonics3, Vector3 } from 'three';
import { captureTarget } from './capture_target.js';
import { buildFileWorld } from './file_world.js';
import { phongGlsl, phongMaterial, worldMaterial } from './phong.js';
import { startPeer } from './peer_page.js';
import { loadSceneFile } from './scene_file.js';

const params = new URLSearchParams(location.search);
const sceneName = params.get('scene') || 'probe-lit';
const OWN_PROBE_FACE = 32;  // core/irradiance.h kIrradianceFaceSize


const MIRROR_FRAGMENT_GLSL = /* glsl */`
uniform vec3 eye;
uniform samplerCube environment;
uniform vec3 baseColour;
uniform float reflectionWeight;
uniform float baseWeight;
in vec3 worldPosition;
in vec3 worldNormal;
out vec4 fragColour;

void main() {
  vec3 N = normalize(worldNormal);
  vec3 I = normalize(worldPosition - eye);
  vec3 seen = texture(environment, reflect(I, N)).rgb;
  fragColour = vec4(reflectionWeight * seen + baseWeight * baseColour, 1.0);
}
`;

// The project's phong() with the ambient term given (phongLit in shaders/shading.glsl).
const litFragmentGlsl = (light) => /* glsl */`
uniform vec3 colour;
uniform vec3 sh[9];
in vec3 worldPosition;
in vec3 worldNormal;
out vec4 fragColour;
${phongGlsl({ ...light, ambient: 0 })}

vec3 probeAmbient(vec3 n) {
  vec3 e = sh[0] * 0.282095;
  e += (2.0 / 3.0) * 0.488603 * (sh[1] * n.y + sh[2] * n.z + sh[3] * n.x);
  e += 0.25 * (1.092548 * (sh[4] * n.x * n.y + sh[5] * n.y * n.z + sh[7] * n.x * n.z) +
               0.315392 * sh[6] * (3.0 * n.z * n.z - 1.0) + 0.546274 * sh[8] * (n.x * n.x - n.y * n.y));
  return max(e, vec3(0.0));
}

void main() {
  vec3 N = normalize(worldNormal);
  fragColour = vec4(phong(colour, worldPosition, N) + colour * probeAmbient(N), 1.0);
}
`;

// GL's cube-map face table read backwards (GL ES 3.0 section 3.8.10): the direction of texel
// centre (s, t) of `face`, with sc = 2s - 1, tc = 2t - 1; rows as glReadPixels returns them.
function faceDirection(face, sc, tc, out) {
  switch (face) {
    case 0: return out.set(1, -tc, -sc);
    case 1: return out.set(-1, -tc, sc);
    case 2: return out.set(sc, 1, tc);
    case 3: return out.set(sc, -1, -tc);
    case 4: return out.set(sc, -tc, 1);
    default: return out.set(-sc, -tc, -1);
  }
}

// The nine coefficients (Vector3 each, into `out`) of the cube in `target`, read back.
function projectCube(renderer, target, out) {
  const size = target.width;
  const data = new Uint8Array(size * size * 4);
  const basis = new Array(9).fill(0);
  const dir = new Vector3();
  for (const c of out) c.set(0, 0, 0);
  let total = 0;
  for (let face = 0; face < 6; ++face) {
    renderer.readRenderTargetPixels(target, 0, 0, size, size, data, face);
    for (let j = 0; j < size; ++j) {
      for (let i = 0; i < size; ++i) {
        faceDirection(face, (2 * i + 1) / size - 1, (2 * j + 1) / size - 1, dir);
        const r2 = dir.lengthSq();
        const w = 1 / (r2 * Math.sqrt(r2));
        total += w;
        SphericalHarmonics3.getBasisAt(dir.normalize(), basis);
        const k = 4 * (j * size + i);
        for (let b = 0; b < 9; ++b) {
          out[b].x += w * basis[b] * data[k] / 255;
          out[b].y += w * basis[b] * data[k + 1] / 255;
          out[b].z += w * basis[b] * data[k + 2] / 255;
        }
      }
    }
  }
  for (const c of out) c.multiplyScalar((4 * Math.PI) / total);
}

function materialFor(facts) {
  return (fact) => worldMaterial(MIRROR_FRAGMENT_GLSL, {
    environment: { value: null },
    baseColour: { value: new Vector3(...fact.colour) },
    reflectionWeight: { value: fact.mirror.reflection },
    baseWeight: { value: fact.mirror.base },
  });
}

startPeer({
  async loadWorld(prefix) {
    const facts = await loadSceneFile(sceneName);
    const world = await buildFileWorld(facts, prefix, materialFor(facts));
    world.facts = facts;
    return world;
  },
  makeRendition({ renderer, world }) {
    const { capture, light } = world.facts;
    const lit = world.objects.filter((m) => m.fact.ambient !== 'constant' && !m.fact.mirror);
    for (const mesh of lit) {
      mesh.geometry.computeBoundingBox();
      mesh.localCentre = mesh.geometry.boundingBox.getCenter(new Vector3());
      mesh.constantMaterial = phongMaterial(mesh.fact.colour, light);
      mesh.litMaterial = worldMaterial(litFragmentGlsl(light), {
        colour: { value: new Vector3(...mesh.fact.colour) },
        sh: { value: Array.from({ length: 9 }, () => new Vector3()) },
      });
      mesh.material = mesh.litMaterial;
      const size = mesh.fact.ambient === 'own-probe' ? OWN_PROBE_FACE : capture.faceSize;
      mesh.probeTarget = captureTarget(size);
      mesh.probeCamera = new CubeCamera(capture.near, capture.far, mesh.probeTarget);
    }
    const mirrorProbes = world.mirrors.map((mesh) => {
      const target = captureTarget(capture.faceSize);
      mesh.material.uniforms.environment.value = target.texture;
      return { mesh, target, camera: new CubeCamera(capture.near, capture.far, target) };
    });
    const centre = new Vector3();
    const nearestMirror = (point) => {
      let best = null;
      for (const m of world.mirrors) {
        if (!best || m.probeCentre.distanceTo(point) < best.probeCentre.distanceTo(point)) best = m;
      }
      return best;
    };
    return {
      draw(phase) {
        // Captures show probe-lit objects with the constant ambient (one bounce).
        for (const mesh of lit) mesh.material = mesh.constantMaterial;
        for (const mesh of lit) {
          const own = mesh.fact.ambient === 'own-probe';
          centre.copy(mesh.localCentre).applyMatrix4(mesh.matrixWorld);
          const at = own ? centre : (nearestMirror(centre)?.probeCentre || centre);
          mesh.probeCamera.position.copy(at);
          const hidden = own ? [mesh] : [...lit, ...world.mirrors.filter((m) => m.probeCentre === at)];
          for (const h of hidden) h.visible = false;
          mesh.probeCamera.update(renderer, world.scene);
          for (const h of hidden) h.visible = true;
          projectCube(renderer, mesh.probeTarget, mesh.litMaterial.uniforms.sh.value);
        }
        for (const p of mirrorProbes) {
          p.camera.position.copy(p.mesh.probeCentre);
          p.mesh.visible = false;
          p.camera.update(renderer, world.scene);
          p.mesh.visible = true;
        }
        for (const mesh of lit) mesh.material = mesh.litMaterial;
        phase?.('capture');
        renderer.render(world.scene, world.camera);
      },
    };
  },
});
