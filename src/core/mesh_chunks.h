// Spatial chunks of a mesh: its triangles reordered so that each chunk of nearby triangles is one
// contiguous index range with its own bounds. A cube face then draws only the chunks it can see:
// a figure standing across two faces costs each face about its own half, not the whole figure.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/mesh_data.h"
#include "core/result.h"

namespace reflect {

inline constexpr size_t kChunkTriangles = 1024;

// Reorders the triangles of `indices` (into `vertices`) by recursive median splits of triangle
// centres along the longest axis, until each piece has at most `maxTriangles`; returns the
// pieces' triangle counts in order (the chunks, without their bounds).
std::vector<uint32_t> chunkOrder(const std::vector<Vertex>& vertices,
                                 std::vector<uint32_t>& indices,
                                 size_t maxTriangles = kChunkTriangles);

// The chunks of `indices` from their consecutive triangle counts, each with the bounds of its
// vertices. Fails when the counts do not add up to the triangles or an index is out of range.
Result<std::vector<MeshChunk>> chunksFromCounts(const std::vector<Vertex>& vertices,
                                                std::span<const uint32_t> indices,
                                                const std::vector<uint32_t>& triangleCounts);

// Reorders `mesh.indices` (the triangles, not the vertices) and fills `mesh.chunks`, each of at
// most `maxTriangles` (chunkOrder, then chunksFromCounts).
void chunkMesh(MeshData& mesh, size_t maxTriangles = kChunkTriangles);

// Appends `range` to `ranges`, merging it with the last one when they touch.
void appendRange(std::vector<IndexRange>& ranges, IndexRange range);

}  // namespace reflect
