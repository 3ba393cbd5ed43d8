// Level-of-detail chains for capture passes: level 0 is the mesh itself, each next level has
// about a quarter of the triangles. Simplification is meshoptimizer's (natively from Debian's
// libmeshoptimizer; in the browser the page runs npm's build of the same library and hands the
// index lists back through meshFromIndices).
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh_data.h"

namespace reflect {

struct LodSettings {
  int maxLevels = 3;            // including level 0
  float triangleRatio = 0.25f;  // target triangles of each level relative to the previous
  float targetError = 0.02f;    // meshoptimizer's relative error bound (fraction of the extent)
  size_t minTriangles = 256;    // meshes this small get no coarser level
};

// A mesh made of `base`'s vertices that `indices` use (unused vertices dropped).
MeshData meshFromIndices(const MeshData& base, const std::vector<uint32_t>& indices);

// Levels 1.. of `base`, each simplified from the previous; empty where the library is missing
// (the web build) or the mesh is too small to gain.
std::vector<MeshData> buildLodLevels(const MeshData& base, const LodSettings& settings = {});

}  // namespace reflect
