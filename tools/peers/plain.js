// Rendition P, the floor: the default scene with the mirror drawn as a plain Phong object of its
// base colour (no capture, no trace). What it costs is what any rendition of this scene pays to
// draw it once at this size; a reflection method's cost is what it adds on top.
import { phongMaterial } from './phong.js';
import { startPeer } from './peer_page.js';
import { SCENE } from './scene_facts.js';

startPeer({
  mirrorMaterial: phongMaterial(SCENE.mirror.colour),
  makeRendition({ renderer, world }) {
    return { draw: () => renderer.render(world.scene, world.camera) };
  },
});
