// Capture levels of detail, built in the browser: the wasm build has no meshoptimizer, so after
// each scene commit (and each model replacement) the page simplifies every mesh with npm
// meshoptimizer's MeshoptSimplifier and hands each level to the renderer (rf_add_lod) as indices
// into the mesh's level-0 vertices. Same rules as the native build (src/core/mesh_lod.cpp):
// level k from level k-1 with target = indexCount * triangleRatio (a multiple of 3), stop below
// minTriangles or when the result is not below 3/4 of its input.

let simplifierPromise = null;
function simplifier() {
  if (!simplifierPromise) {
    simplifierPromise = import('./vendor/meshopt_simplifier.js').then(async ({ MeshoptSimplifier }) => {
      await MeshoptSimplifier.ready;
      return MeshoptSimplifier;
    });
  }
  return simplifierPromise;
}

const VERTEX_FLOATS = 6;  // position, normal

// Level 0 of `name` copied out of wasm memory: { positions: Float32Array (6 floats a vertex),
// indices: Uint32Array }, or null when the scene has no such mesh.
function levelZero(Module, api, name) {
  const countPtr = Module._malloc(4);
  try {
    const heapInt = () => new Int32Array(Module.HEAPU8.buffer, countPtr, 1)[0];
    const vertexPtr = api.meshVertices(name, countPtr);
    const vertexCount = heapInt();
    const indexPtr = api.meshIndices(name, countPtr);
    const indexCount = heapInt();
    if (!vertexPtr || !indexPtr || !vertexCount || !indexCount) return null;
    const buffer = Module.HEAPU8.buffer;
    return {
      positions: new Float32Array(buffer, vertexPtr, vertexCount * VERTEX_FLOATS).slice(),
      indices: new Uint32Array(buffer, indexPtr, indexCount).slice(),
    };
  } finally {
    Module._free(countPtr);
  }
}

// The index arrays of levels 1.. for one mesh (pure: no wasm of ours involved).
export function simplifyLevels(MeshoptSimplifier, positions, indices, settings) {
  const levels = [];
  let previous = indices;
  for (let level = 1; level < settings.maxLevels; ++level) {
    if (previous.length / 3 < settings.minTriangles) break;
    const target = Math.floor((previous.length * settings.triangleRatio) / 3) * 3;
    const [result] = MeshoptSimplifier.simplify(previous, positions, VERTEX_FLOATS, target,
                                                settings.targetError, ['Sparse']);
    if (result.length === 0 || result.length > (previous.length * 3) / 4) break;
    levels.push(result);
    previous = result;
  }
  return levels;
}

// Builds the levels of `names` (default: every mesh of the current scene). Returns
// { name: [triangles of level 0, level 1, ...] } for the meshes it handled.
export async function buildLods(Module, api, names = null) {
  let MeshoptSimplifier;
  try {
    MeshoptSimplifier = await simplifier();
  } catch (e) {
    console.warn(`capture LOD: the simplifier could not be loaded (${e.message}); no levels built`);
    return {};
  }
  const settings = JSON.parse(api.lodSettings());
  const scene = JSON.parse(api.sceneJson());
  const built = {};
  for (const name of names || scene.meshes || []) {
    const base = levelZero(Module, api, name);
    if (!base) continue;
    const triangles = [base.indices.length / 3];
    for (const indices of simplifyLevels(MeshoptSimplifier, base.positions, base.indices, settings)) {
      const ptr = Module._malloc(indices.byteLength);
      new Uint8Array(Module.HEAPU8.buffer, ptr, indices.byteLength).set(new Uint8Array(indices.buffer, indices.byteOffset, indices.byteLength));
      let error;
      try { error = api.addLod(name, ptr, indices.length); } finally { Module._free(ptr); }
      if (error) {
        console.warn(`capture LOD of ${name}: ${error}`);
        break;
      }
      triangles.push(indices.length / 3);
    }
    built[name] = triangles;
  }
  const summary = Object.entries(built).map(([n, t]) => `${n} ${t.join(' > ')}`).join(', ');
  console.info(`capture LOD levels (triangles): ${summary || 'none'}`);
  return built;
}
