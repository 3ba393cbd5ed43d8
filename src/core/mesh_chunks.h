// Spatial chunks of a mesh: its triangles reordered so that each chunk of nearby triangles is one
// contiguous index range with its own bounds. A cube face then draws only the chunks it can see:
// a figure standing across two faces costs each face about its own half, not the whole figure.
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh_data.h"

namespace reflect {

inline constexpr size_t kChunkTriangles = 1024;

// Reorders `mesh.indices` (the triangles, not the vertices) and fills `mesh.chunks`, each of at
// most `maxTriangles`, by recursive median splits of triangle centres along the longest axis.
void chunkMesh(MeshData& mesh, size_t maxTriangles = kChunkTriangles);

// Appends `range` to `ranges`, merging it with the last one when they touch.
void appendRange(std::vector<IndexRange>& ranges, IndexRange range);

}  // namespace reflect
