// The wasm module's exports as typed functions. Their names and argument types come from
// wasm_exports.js, which the build writes from the C++ definitions (cmake/WebExports.cmake), so
// this file calls no export the module lacks (tests/web/exports.spec.mjs holds it). Everything
// crossing is JSON: each export takes one request object (plus a file's bytes where one goes)
// and returns JSON. Settings travel by the names of the
// settings schema (rf_schema_json), and changes are objects whose absent keys keep their value.
// Actions return "" or the error message (nothing changed then).

/* global createReflectModule */
import { EXPORTS } from './wasm_exports.js';

// An action's reply as "" or its error message.
const errorOf = (reply) => reply.error || '';

// The module's setup, its frames and its clock.
function frameCalls(call, fn) {
  return {
    // "" or why WebGL2 could not be set up.
    create: () => errorOf(call('rf_create')),
    // { planner: [INFO...], accuracy: [...], material: [...] }, INFO { name, label, help, kind,
    // default, min, max, choices }.
    schema: () => JSON.parse(fn.rf_schema_json()),

    // One frame into the canvas: its stats (FrameStats: frameMs, facesCaptured, time, ...).
    // waitForGpu: a read back after each pass (the stats time each); waitAtEnd: one after the frame.
    frame: ({ dt = 0, waitForGpu = false, waitAtEnd = false } = {}) =>
      call('rf_frame', { dt, waitForGpu, waitAtEnd }),
    // Step through a frame: step `step` of the frame now into the canvas; { step, count, steps:
    // [{ label, pass, face, objects, triangles }] } or { error }.
    frameStep: (step) => call('rf_frame_step', { step }),
    time: () => call('rf_clock').seconds,
    setTime: (seconds) => call('rf_clock', { seconds }).seconds,
  };
}

// The camera: each change returns the camera after it.
function cameraCalls(call) {
  return {
    // { eye: [x, y, z], yaw, pitch } (degrees).
    camera: () => call('rf_camera'),
    setCamera: ({ eye, yaw, pitch }) => call('rf_camera', { eye, yaw, pitch }),
    // Steps of 0.1 along the view (forward), to the right (level) and up.
    moveCamera: ({ forward = 0, right = 0, up = 0 }) => call('rf_camera', { forward, right, up }),
    // A pointer drag of (dx, dy) over a canvas `height` pixels tall.
    dragCamera: ({ dx, dy, height }) => call('rf_camera', { drag: { dx, dy, height } }),
    resetCamera: () => call('rf_camera', { reset: true }),
  };
}

// The planner's, accuracy and view settings (by the schema's names) and the frame-budget pick.
function settingsCalls(call) {
  return {
    // The planner's settings; plannerState adds what follows from them: { settings,
    // maxStalenessFrames, policyParameters, unusedSettings }.
    planner: () => call('rf_planner_json').settings || {},
    plannerState: () => call('rf_planner_json'),
    setPlanner: (changes) => errorOf(call('rf_set_planner', changes)),
    accuracy: () => call('rf_accuracy_json').settings || {},
    accuracyDescription: () => call('rf_accuracy_json').describe || '',
    setAccuracy: (changes) => errorOf(call('rf_set_accuracy', changes)),

    // The page's view settings { showError, auto, budget }; setView(changes): "" or the error.
    view: () => call('rf_view_json').settings || {},
    setView: (changes) => errorOf(call('rf_set_view', changes)),
    // "auto": the settings to time, [{ name, accuracy }], and the C++ rule's pick from their
    // measured { name, accuracy, frameMs, psnrDb }: { index, fits, reason, table }.
    budgetCandidates: () => call('rf_budget_candidates'),
    pickAccuracy: ({ budget, candidates }) => call('rf_pick_accuracy', { budget, candidates }),
  };
}

// The scene: its objects and materials, and loading one in stages (files, streamed models, skybox images).
function sceneCalls(call, callWithData, feedPiece) {
  return {
    // [{ mesh, material: { type, reflection, ... }, summary, reflective, editable, orbits, translate }]
    objects: () => call('rf_objects_json'),
    // { index: the object's place, changes: { reflection: 0.5, ... } }
    setMaterial: ({ index, changes }) => errorOf(call('rf_set_material', { index, changes })),
    // Adds a scene-file object entry (its mesh loaded first with loadMesh).
    addObject: (object) => errorOf(call('rf_add_object', object)),
    // { name, title, meshes, cubeFaceSize, environments }
    scene: () => call('rf_scene_json'),

    // Loading a scene in stages: begin (the scene file), every mesh and skybox image it names,
    // commit ({} or { error } or { notice }). `source` names a file in messages.
    beginScene: ({ source, bytes }) => errorOf(callWithData('rf_begin_scene', { source }, bytes)),
    pendingFiles: () => call('rf_pending_files'),
    // pending: for the scene being loaded; else the current scene's mesh `name` (replaced or new).
    // Returns "" or the error; what the loader let pass (undefined normals, texture indices
    // without vt lines: one line each, naming the file) goes to `warn(text)` when the load worked.
    loadMesh: ({ name, source, bytes, pending = false, warn = null }) => {
      const reply = callWithData('rf_load_mesh', { name, source, pending }, bytes);
      if (!reply.error && warn) for (const warning of reply.warnings || []) warn(warning);
      return errorOf(reply);
    },
    // A model parsed as it streams in: { feed(bytes) -> "" or the error (the stream is over then),
    // end() -> "" or the error (the mesh replaces the one of its name; its loader warnings go to
    // `warn(text)`), cancel() }, or { error }.
    streamMesh: ({ name, source, pending = false, warn = null }) => {
      const begun = call('rf_mesh_stream_begin', { name, source, pending });
      if (begun.error) return { error: begun.error };
      const stream = begun.stream;
      return {
        feed: (bytes) => feedPiece(stream, bytes),
        end: () => {
          const reply = call('rf_mesh_stream_end', { stream });
          if (!reply.error && warn) for (const warning of reply.warnings || []) warn(warning);
          return errorOf(reply);
        },
        cancel: () => { call('rf_mesh_stream_end', { stream, cancel: true }); },
      };
    },
    skyboxImage: ({ index, source, bytes }) =>
      errorOf(callWithData('rf_pending_skybox_image', { index, source }, bytes)),
    commitScene: ({ cubeSize = 0 } = {}) => call('rf_commit_scene', { cubeSize }),
  };
}

// The meshes' levels of detail for the page's worker, their arrays and bounds, wasm memory, and pick a pixel.
function meshCalls(call, callWithData, Module) {
  return {
    // Level 0 of mesh `name` copied out of wasm memory: { positions: Float32Array (6 floats a
    // vertex), indices: Uint32Array }, or null.
    meshLevelZero: (name) => {
      const a = call('rf_mesh_arrays', { name });
      if (!a.vertices || !a.indices || !a.vertexCount || !a.indexCount) return null;
      const buffer = Module.HEAPU8.buffer;
      return {
        positions: new Float32Array(buffer, a.vertices, a.vertexCount * a.vertexFloats).slice(),
        indices: new Uint32Array(buffer, a.indices, a.indexCount).slice(),
        vertexFloats: a.vertexFloats,
      };
    },
    lodSettings: () => call('rf_lod_settings_json'),
    // What is left to build: [{ name, revision, chunks, coarser }] (web/lod.js builds it): what
    // the frames drew wants (a frame's stats say levelsWanted), or everything after askForLevels.
    levelJobs: () => call('rf_level_jobs'),
    // From now on, every level the LOD settings could draw is wanted (demo.lodReady()).
    askForLevels: () => call('rf_ask_levels'),
    // Mesh `name`'s triangles in chunk order, the chunks' triangle counts. "" or the error.
    setMeshChunks: ({ name, revision, indices, chunkTriangles }) =>
      errorOf(callWithData('rf_set_mesh_chunks', { name, revision, chunkTriangles }, indices, indices.length)),
    // The next coarser level of mesh `name` (indices into its level-0 vertices, in chunk order).
    addLod: ({ name, revision, indices, chunkTriangles }) =>
      errorOf(callWithData('rf_add_lod', { name, revision, chunkTriangles }, indices, indices.length)),
    finishLevels: ({ name, revision }) => errorOf(call('rf_finish_levels', { name, revision })),
    // Triangles of each level of mesh `name`, level 0 first, or null.
    levelTriangles: (name) => call('rf_level_triangles', { name }).levels || null,
    // The wasm memory's size in bytes (it grows, and never shrinks).
    heapBytes: () => Module.HEAPU8.length,
    // What that memory is made of: malloc's use, the stack's size and high water (rf_memory_json).
    memory: () => call('rf_memory_json'),
    // Pick a pixel: the explanation of drawing-buffer pixel { x, y } of the frame on the canvas
    // (its numbers and `lines`, as `reflect explain` prints them; or { error }), its rays drawn
    // over the next frames; { clear: true } hides them.
    explainPixel: (request) => call('rf_explain_pixel', request),
    // { min: [x, y, z], max } of mesh `name`, or null.
    meshBounds: (name) => {
      const bounds = call('rf_mesh_bounds_json', { name });
      return bounds.min ? bounds : null;
    },
  };
}

export async function createBridge(canvas) {
  // index.html starts the module early, for this canvas; made here otherwise.
  const Module = await (window.reflectModule || createReflectModule({ canvas }));
  performance.mark('reflect:wasm-ready');
  const fn = Object.fromEntries(Object.entries(EXPORTS).map(([name, args]) => [name, Module.cwrap(name, 'string', args)]));

  const call = (name, request = {}) => JSON.parse(fn[name](JSON.stringify(request)));
  // `bytes` (a typed array) copied into wasm memory for the duration of the call.
  const callWithData = (name, request, bytes, count = bytes.length) => {
    const view = new Uint8Array(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    const ptr = Module._malloc(Math.max(view.length, 1));
    Module.HEAPU8.set(view, ptr);
    try {
      return JSON.parse(fn[name](JSON.stringify(request), ptr, count));
    } finally {
      Module._free(ptr);
    }
  };

  // The pieces of a streamed model go through one staging buffer in wasm memory, allocated once
  // (at the first piece, before any parse's arrays) and reused; larger pieces go in parts. It is
  // never reallocated: a new buffer would be placed among a parse's arrays, and split the space
  // they leave when freed (see core/block_array.h).
  const kStagingBytes = 64 * 1024;
  let staging = 0;
  const feedPiece = (stream, bytes) => {
    if (!staging) staging = Module._malloc(kStagingBytes);
    for (let at = 0; at < bytes.length; at += kStagingBytes) {
      const part = bytes.subarray(at, Math.min(at + kStagingBytes, bytes.length));
      Module.HEAPU8.set(part, staging);
      const error = errorOf(JSON.parse(fn.rf_mesh_stream_feed(JSON.stringify({ stream }), staging, part.length)));
      if (error) return error;
    }
    return '';
  };

  return {
    ...frameCalls(call, fn),
    ...cameraCalls(call),
    ...settingsCalls(call),
    ...sceneCalls(call, callWithData, feedPiece),
    ...meshCalls(call, callWithData, Module),
  };
}
