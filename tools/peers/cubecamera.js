// Rendition A: the course's method with three.js's own parts. Each frame a CubeCamera at the
// sphere's centre draws the scene (the sphere hidden) into a 256-pixel RGBA8 cube, linear
// filtering and no mipmaps, then the main pass looks the reflected view ray up in it.
import { CubeCamera, Vector3 } from 'three';
import { captureTarget } from './capture_target.js';
import { worldMaterial } from './phong.js';
import { startPeer } from './peer_page.js';
import { SCENE } from './scene_facts.js';

const { capture, mirror } = SCENE;
const target = captureTarget(capture.faceSize);

// three's cube cameras (negative field of view) leave a render target's faces in GL's cube-map
// convention, so the world direction is the lookup direction as it is: the x flip three applies
// to loaded cube textures (flipEnvMap) is not wanted here.
const MIRROR_FRAGMENT_GLSL = /* glsl */`
uniform vec3 eye;
uniform samplerCube environment;
uniform vec3 baseColour;
in vec3 worldPosition;
in vec3 worldNormal;
out vec4 fragColour;

void main() {
  vec3 N = normalize(worldNormal);
  vec3 I = normalize(worldPosition - eye);
  vec3 reflected = texture(environment, reflect(I, N)).rgb;
  fragColour = vec4(${mirror.reflection.toFixed(4)} * reflected + ${mirror.base.toFixed(4)} * baseColour, 1.0);
}
`;

const mirrorMaterial = worldMaterial(MIRROR_FRAGMENT_GLSL, {
  environment: { value: target.texture },
  baseColour: { value: new Vector3(...mirror.colour) },
});

startPeer({
  mirrorMaterial,
  makeRendition({ renderer, world }) {
    const probe = new CubeCamera(capture.near, capture.far, target);
    probe.position.set(...mirror.centre);
    return {
      draw(phase) {
        world.mirror.visible = false;
        probe.update(renderer, world.scene);
        world.mirror.visible = true;
        phase?.('capture');
        renderer.render(world.scene, world.camera);
      },
    };
  },
});
