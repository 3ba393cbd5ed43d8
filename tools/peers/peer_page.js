// What every peer page does around its rendition: the renderer on #canvas, the models from
// ?assets=PREFIX (default: the site's models/ beside this folder), the animation clock and
// window.peer, the interface tools/peer_bench.mjs drives (as the project's window.demo):
//   ready                a promise: models loaded and the first frame drawn
//   frame(dt)            advance by dt seconds, render, wait for the GPU: { ms }
//   frameSplit(dt)       the same, with a wait for the GPU after each of the rendition's phases
//                        (the CubeCamera's capture): { ms, parts: { capture?, main } } in ms
//   setTime(t)           the animation time of the next frame
//   readPixels()         render and read the canvas: { width, height, data } (RGBA, bottom row first)
// With ?bench in the URL nothing else draws; otherwise the page animates itself with rAF.
import { Color, LinearSRGBColorSpace, WebGLRenderer } from 'three';
import { buildWorld, loadModels } from './scene.js';
import { SCENE } from './scene_facts.js';

// `mirrorMaterial`: the rendition's material for the sphere (made before the models are in; the
// rendition fills its uniforms). `makeRendition({ renderer, world })`, called once the world is
// built, returns { draw(phase) }, which renders the frame world.pose() has set up; a rendition
// that draws in passes calls phase('capture') after its capture (frameSplit times the passes
// apart). `loadWorld(prefix)`, if given, builds another world than the default scene's (a promise of { scene, camera,
// background, pose(seconds), ... }; the pmrem rendition's reads a scene file).
// One frame drawn by `draw(phase)` with a wait for the GPU (`sync`) after each phase it names and
// after the rest, the main pass: { ms, parts: { capture?, main } } in ms.
function drawInPhases(draw, sync) {
  const start = performance.now();
  const parts = {};
  let since = start;
  const phase = (name) => {
    sync();
    const now = performance.now();
    parts[name] = now - since;
    since = now;
  };
  draw(phase);
  phase('main');
  return { ms: performance.now() - start, parts };
}

function makeRenderer(canvas) {
  // As the project's context: no antialiasing, no alpha, a depth buffer.
  const renderer = new WebGLRenderer({ canvas, antialias: false, alpha: false, depth: true, stencil: false });
  // The shaders write final values, as the project's do; linear output also keeps three from
  // converting the clear colour to sRGB.
  renderer.outputColorSpace = LinearSRGBColorSpace;
  renderer.setClearColor(new Color(...SCENE.background), 1);
  return renderer;
}

export function startPeer({ mirrorMaterial, makeRendition, loadWorld }) {
  const params = new URLSearchParams(location.search);
  const prefix = new URL(params.get('assets') || '../models/', location.href).href;
  const canvas = document.getElementById('canvas');
  const renderer = makeRenderer(canvas);
  const gl = renderer.getContext();

  let time = 0, world = null, rendition = null;
  const render = () => {
    world.pose(time);
    rendition.draw();
  };
  const resize = () => {
    renderer.setPixelRatio(window.devicePixelRatio);
    renderer.setSize(canvas.clientWidth, canvas.clientHeight, false);
    world.camera.aspect = canvas.clientWidth / canvas.clientHeight;
    world.camera.updateProjectionMatrix();
  };
  const pixel = new Uint8Array(4);
  // A read-back waits for the GPU to finish the frame, so a frame's time includes its GPU work.
  const sync = () => gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);

  // Load to first frame in parts, as performance marks (tools/peer_bench.mjs reads them): the
  // scripts evaluated (three.js fetched and parsed), the models fetched and parsed into a world,
  // the rendition made (the bvh rendition's trees).
  performance.mark('peer:script-start');
  const ready = (async () => {
    world = loadWorld ? await loadWorld(prefix) : buildWorld(await loadModels(prefix), mirrorMaterial);
    performance.mark('peer:models-in');
    if (world.background) renderer.setClearColor(new Color(...world.background), 1);
    rendition = makeRendition({ renderer, world });
    performance.mark('peer:rendition-made');
    resize();
    render();
    sync();
  })();

  window.peer = {
    ready,
    frame(dt = 0) {
      const start = performance.now();
      time += dt;
      render();
      sync();
      return { ms: performance.now() - start };
    },
    frameSplit(dt = 0) {
      time += dt;
      world.pose(time);
      return drawInPhases((phase) => rendition.draw(phase), sync);
    },
    setTime(t) { time = t; },
    readPixels() {
      render();  // the drawing buffer is not preserved after the page is composited
      const { drawingBufferWidth: width, drawingBufferHeight: height } = gl;
      const data = new Uint8Array(width * height * 4);
      gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, data);
      return { width, height, data };
    },
  };

  ready.then(() => {
    if (params.has('bench')) return;
    window.addEventListener('resize', resize);
    let last = performance.now();
    const loop = (now) => {
      time += (now - last) / 1000;
      last = now;
      render();
      requestAnimationFrame(loop);
    };
    requestAnimationFrame(loop);
  }, (error) => {
    document.getElementById('message').textContent = `could not start: ${error.message}`;
    console.error(error);
  });
}
