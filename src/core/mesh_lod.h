// Levels of detail: level 0 is the mesh itself, each next level has about a quarter of the
// triangles of the one before. A coarser level is kept as a list of triangles over level 0's
// vertices (no vertex copy); only the GPU gets a compact copy (meshFromIndices).
// Simplification is the project's own (core/mesh_simplify.h); the page's worker runs this same
// code compiled to wasm (src/platform/web/lod_worker_main.cpp), so both make the same levels.
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh_data.h"

namespace reflect {

struct LodSettings {
  int maxLevels = 3;            // including level 0
  float triangleRatio = 0.25f;  // target triangles of each level relative to the previous
  float targetError = 0.02f;    // the simplifier's error bound (a fraction of the extent)
  size_t minTriangles = 256;    // meshes this small get no coarser level
};

// A mesh made of `base`'s vertices that `indices` use (unused vertices dropped), the triangles in
// the same order.
MeshData meshFromIndices(const MeshData& base, const std::vector<uint32_t>& indices);
// How many distinct vertices `indices` use (what meshFromIndices would keep).
size_t verticesUsed(size_t vertexCount, const std::vector<uint32_t>& indices);

// A level's triangles (indices into the base mesh's vertices) in chunk order, with the chunks'
// triangle counts (core/mesh_chunks.h).
struct LevelIndices {
  std::vector<uint32_t> indices;
  std::vector<uint32_t> chunkTriangles;
};

// What a build makes of a base mesh: its own triangles in chunk order (when asked), and its
// coarser levels (when asked; none where the mesh is too small to gain).
struct BuiltLevels {
  bool chunked = false;
  LevelIndices base;
  bool coarse = false;
  std::vector<LevelIndices> coarser;
};
BuiltLevels buildLevels(const MeshData& base, bool chunkBase, bool coarser,
                        const LodSettings& settings = {});

}  // namespace reflect
