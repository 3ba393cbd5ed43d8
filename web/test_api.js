// window.demo: how tests and tools drive the page (docs/web.md describes each function). Settings
// go by the schema's names (demo.schema()); changes are objects whose absent keys keep their value.
import { filesFromList, handleFiles } from './drop.js';
import { messageHistory } from './messages.js';

// The clock, frames and the camera.
function timeAndCamera(page, session, bridge) {
  return {
    // One complete frame (dt seconds on), timed end to end; its stats.
    frame: (dt = 0) => session.frame(dt, true),
    // The same, with one wait for the GPU at its end and none between its passes (as the peer
    // pages' frame(dt) waits): what a frame costs end to end; its stats do not split the GPU's work.
    frameWaitedOnce: (dt = 0) => session.frame(dt, 'end'),
    // The last frame's stats, with the display rate.
    stats: () => ({ ...session.lastStats, ...bridge.memory(), fps: page.fps() }),
    setTime: (t) => session.setTime(t),
    pause: (on = true) => session.setPaused(on),
    paused: () => session.paused,
    camera: () => bridge.camera(),
    // setCamera(x, y, z, yaw, pitch) or setCamera({ eye, yaw, pitch }).
    setCamera: (x, y, z, yaw, pitch) =>
      session.camera((b) => b.setCamera(typeof x === 'object' ? x : { eye: [x, y, z], yaw, pitch })),
  };
}

// The scene, loading, and the levels of detail built after the first frame.
function sceneAndLevels(session, bridge) {
  return {
    // { name, title, meshes, cubeFaceSize, environments }
    scene: () => bridge.scene(),
    // Loads another scene (a name or a URL); the current one stays on screen if it fails (the
    // error is shown and thrown).
    loadScene: (nameOrUrl) => session.loadScene(nameOrUrl),
    // Triangles of each level of detail of mesh `name` (null before any was built).
    lodLevels: (name) => session.lodLevels[name] || null,
    // The levels the C++ side holds of mesh `name` now, triangles of each, level 0 first (null:
    // no such mesh).
    meshLevels: (name) => bridge.levelTriangles(name),
    // Resolves (to { mesh: [triangles a level] }) once every mesh's chunks and, while a LOD
    // setting is on, its levels are built and in use. It asks for them: the page itself builds
    // them only once a frame draws them (a capture, view LOD), after the first frame.
    lodReady: () => session.lodReady(),
    // Resolves (as lodReady) once what the frames drew wants is built, asking for nothing more.
    levelsSettled: () => session.levelsSettled(),
    // The stats of the first frame drawn after the last scene load (drawn before any level was
    // built: its lodReady is false), and the level builder's events ({ event, at }: 'start',
    // 'done', at performance.now()) with the first frame's time.
    firstFrameStats: () => session.firstFrameStats,
    levelEvents: () => [...session.levels.events],
    // holdLevels(true): built levels wait before they are handed in, until holdLevels(false)
    // (lod.js); levelsWaiting(): how many answers of the worker wait so.
    holdLevels: (on = true) => session.levels.hold(on),
    levelsWaiting: () => session.levels.waiting,
    // The longest main-thread task that handed a built piece in (ms).
    longestLevelHandOffMs: () => session.levels.longestHandOffMs,
  };
}

// The planner's and accuracy settings, the measured modes, the materials and the figures.
function settingsAndMaterials(session, bridge) {
  return {
    // The planner's settings by schema name, and maxStalenessFrames (read only).
    planner: () => {
      const state = bridge.plannerState();
      return { ...state.settings, maxStalenessFrames: state.maxStalenessFrames };
    },
    // setPlanner({ facesPerFrame: 3 }): "" or the error.
    setPlanner: (changes) => session.setPlanner(changes),
    // [{ mesh, material: { type, reflection, base, ior, fresnel, environment }, summary, ... }]
    objects: () => bridge.objects(),
    // Object `index`'s material settings (mirror and glass only): "" or the error.
    setMaterial: (index, changes) => session.setMaterial(index, changes),
    // The accuracy settings by schema name, and describe (the C++ description, read only).
    accuracy: () => ({ ...bridge.accuracy(), describe: bridge.accuracyDescription() }),
    // setAccuracy({ mipmaps: true }): "" or the error. setAccuracy('ROW'): a measured mode (a
    // sweep.csv row) with its cube size, as the panel: a promise of the settings.
    setAccuracy: (changesOrRow) => (typeof changesOrRow === 'string'
      ? session.chooseAccuracy(changesOrRow) : session.setAccuracy(changesOrRow)),
    sweep: () => session.modes.rows,
    accuracyRow: () => session.accuracyRow(),
    figures: () => session.figures.map((f) => ({ name: f.name, source: f.source, object: f.object })),
  };
}

// The page around the frame: pixels, the link, the bench, the panel, messages, drawing.
function pageParts(page, session) {
  const { addressBar } = page;
  return {
    readPixels: () => page.readPixels(),
    screenshot: () => page.screenshot(),
    copyLink: () => addressBar.copyLink(),
    loadFiles: (files) => handleFiles(session, filesFromList(files)),
    runBench: (frames) => page.bench(frames),
    benchResults: null,
    // The link to what is on screen, as the address bar has it.
    query: () => addressBar.query(),
    sparkSamples: () => page.sparkline.samples,
    progressHistory: () => [...page.progress.history],
    panel: () => page.panel()?.gui || null,
    // Resolves when no scene load, model change or bench is queued or running.
    idle: () => session.idle(),
    // Every message shown, [{ text, kind }], also those that have gone.
    messages: () => messageHistory(),
    // The settings schema: { planner, accuracy, material, view }.
    schema: () => session.schema,
    // Frames the display loop has drawn since the page started (none while idle), and whether it
    // draws none now (paused, nothing changed: the canvas keeps its picture).
    framesDrawn: () => page.framesDrawn(),
    drawingIdle: () => page.drawingIdle(),
  };
}

// The view settings, auto, and Inside the frame: stepping, pick a pixel.
function viewsAndPicks(page, session, bridge) {
  return {
    // The view settings { showError, auto, budget }; setView({ showError: true }): "" or the error.
    view: () => bridge.view(),
    setView: (changes) => session.setView(changes),
    // Step through a frame: stepFrame() draws the next step (pausing); frameStep() is the last
    // reply, { step, count, steps: [{ label, pass, face, objects, triangles }] }, or null.
    stepFrame: () => session.stepFrame(),
    frameStep: () => session.stepReply || null,
    // auto: measure now (a promise of { budget, pick: { index, fits, reason, table }, candidates:
    // [{ name, accuracy, frameMs, psnrDb }] }), and the last such result (or null).
    runAutoPick: () => page.autoPick.run(),
    autoPick: () => page.autoPick.last,
    // Pick a pixel: the mode (P) on or off; explainPixel(x, y): what a click on drawing-buffer
    // pixel (x, y) shows (rf_explain_pixel's reply); the readout's text; the last explanation.
    setPick: (on) => page.pick.toggle(on),
    explainPixel: (x, y) => page.pick.explain(x, y),
    pickReadout: () => page.pick.readout(),
    lastPick: () => page.pick.last,
  };
}

// page: { session, addressBar, canvas, readPixels, screenshot, bench, fps, sparkline, progress, panel,
// framesDrawn, idle, autoPick, pick }
export function testApi(page) {
  const { session } = page;
  const { bridge } = session;
  return {
    ...timeAndCamera(page, session, bridge),
    ...sceneAndLevels(session, bridge),
    ...settingsAndMaterials(session, bridge),
    ...pageParts(page, session),
    ...viewsAndPicks(page, session, bridge),
  };
}
