// The page's level-of-detail worker module: a wasm module of its own (lod_module.js/.wasm in the
// site), loaded by web/lod_worker.js in a Web Worker, off the page's main thread. It runs core's
// buildLevels, the code the native build runs, so the page's chunks and levels are native's,
// triangle for triangle. Its exports are not the page's module's (no rf_ prefix): the page never
// calls them, and cmake/WebExports.cmake does not list them.
#include <emscripten/emscripten.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "core/mesh_lod.h"

namespace {

// One mesh's vertices from the page's flat array: `stride` floats a vertex, the position first,
// then the normal where the stride holds one.
std::vector<reflect::Vertex> verticesFrom(const float* floats, int count, int stride) {
  std::vector<reflect::Vertex> vertices(static_cast<size_t>(count));
  for (size_t v = 0; v < vertices.size(); ++v) {
    const float* f = floats + v * static_cast<size_t>(stride);
    vertices[v].position = {f[0], f[1], f[2]};
    if (stride >= 6) vertices[v].normal = {f[3], f[4], f[5]};
  }
  return vertices;
}

void appendLevel(std::vector<uint32_t>& out, const reflect::LevelIndices& level) {
  out.push_back(static_cast<uint32_t>(level.indices.size()));
  out.push_back(static_cast<uint32_t>(level.chunkTriangles.size()));
  out.insert(out.end(), level.indices.begin(), level.indices.end());
  out.insert(out.end(), level.chunkTriangles.begin(), level.chunkTriangles.end());
}

}  // namespace

extern "C" {

// Builds one mesh's chunks (level 0 in chunk order, when `chunkBase`) and its coarser levels
// (when `coarser`) with buildLevels and the given LodSettings. Returns a block the caller frees
// with lod_free: [levels, then for each level (level 0 first when chunked): its index count, its
// chunk count, its indices, its chunks' triangle counts], or null when out of memory.
EMSCRIPTEN_KEEPALIVE uint32_t* lod_build(const float* vertexFloats, int vertexCount, int stride,
                                         const uint32_t* indices, int indexCount, int chunkBase,
                                         int coarser, int maxLevels, float triangleRatio,
                                         float targetError, int minTriangles) {
  if (vertexCount < 0 || indexCount < 0 || stride < 3) return nullptr;
  reflect::MeshData mesh;
  mesh.vertices = verticesFrom(vertexFloats, vertexCount, stride);
  mesh.indices.assign(indices, indices + indexCount);
  mesh.bounds = reflect::computeBounds(mesh.vertices);
  reflect::LodSettings settings;
  settings.maxLevels = maxLevels;
  settings.triangleRatio = triangleRatio;
  settings.targetError = targetError;
  settings.minTriangles = static_cast<size_t>(minTriangles < 0 ? 0 : minTriangles);
  const reflect::BuiltLevels built =
      reflect::buildLevels(mesh, chunkBase != 0, coarser != 0, settings);

  std::vector<uint32_t> out{0};
  if (built.chunked) appendLevel(out, built.base), ++out[0];
  for (const reflect::LevelIndices& level : built.coarser) appendLevel(out, level), ++out[0];
  auto* block = static_cast<uint32_t*>(std::malloc(out.size() * sizeof(uint32_t)));
  if (block) std::memcpy(block, out.data(), out.size() * sizeof(uint32_t));
  return block;
}

EMSCRIPTEN_KEEPALIVE void lod_free(uint32_t* block) {
  std::free(block);
}

}  // extern "C"
