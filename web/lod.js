// Capture levels of detail, built in the browser: the wasm build has no meshoptimizer, so after
// each scene commit (and each model replacement) the page simplifies every mesh with npm
// meshoptimizer's MeshoptSimplifier and hands each level to the renderer (bridge.addLod) as indices
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

// The index arrays of levels 1.. for one mesh (pure: no wasm of ours involved).
export function simplifyLevels(MeshoptSimplifier, positions, indices, settings, vertexFloats = 6) {
  const levels = [];
  let previous = indices;
  for (let level = 1; level < settings.maxLevels; ++level) {
    if (previous.length / 3 < settings.minTriangles) break;
    const target = Math.floor((previous.length * settings.triangleRatio) / 3) * 3;
    const [result] = MeshoptSimplifier.simplify(previous, positions, vertexFloats, target,
                                                settings.targetError, ['Sparse']);
    if (result.length === 0 || result.length > (previous.length * 3) / 4) break;
    levels.push(result);
    previous = result;
  }
  return levels;
}

// Builds the levels of `names` (default: every mesh of the current scene) through the bridge
// (wasm_bridge.js). Returns { name: [triangles of level 0, level 1, ...] } for the meshes it
// handled.
export async function buildLods(bridge, names = null) {
  let MeshoptSimplifier;
  try {
    MeshoptSimplifier = await simplifier();
  } catch (e) {
    console.warn(`capture LOD: the simplifier could not be loaded (${e.message}); no levels built`);
    return {};
  }
  const settings = bridge.lodSettings();
  const built = {};
  for (const name of names || bridge.scene().meshes || []) {
    const base = bridge.meshLevelZero(name);
    if (!base) continue;
    const triangles = [base.indices.length / 3];
    for (const indices of simplifyLevels(MeshoptSimplifier, base.positions, base.indices, settings, base.vertexFloats)) {
      const error = bridge.addLod(name, indices);
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
