// The project's mesh simplifier: quadric error metric edge collapse (Garland and Heckbert,
// "Surface Simplification Using Quadric Error Metrics", 1997), for the levels of detail
// (core/mesh_lod.h). It is ours rather than a library's so that the native build and the page's
// worker (the same C++ compiled to wasm) make the same levels, triangle for triangle.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/mesh_data.h"

namespace reflect {

// Simplifies the triangles `indices` (into `vertices`) by collapsing edges, cheapest first, where
// an edge's cost is the mean squared distance (weighted by area) from the position it keeps to the
// planes of the original triangles the two merged vertices stood on.
//
// - Each collapse moves one vertex onto a neighbour (a half-edge collapse), so the result is a
//   list of triangles over the same `vertices`: a level needs no vertex of its own.
// - Vertices at the same position (seams of normals) are one vertex to the topology; a corner that
//   moves takes the vertex at its new position whose normal is nearest its own.
// - Stops when at most `targetIndexCount` indices are left, or when the next collapse would move
//   the surface by more than `targetError` times the mesh's extent (the largest side of its
//   bounds), or when no collapse is left that keeps the surface manifold and unflipped.
// - Vertices on an open border or a non-manifold edge never move: borders are kept.
// - Degenerate triangles (two corners at one position) and ones with an index out of range are
//   dropped. The triangles that remain keep their order in `indices`.
//
// Deterministic: the same input gives the same output on every platform (a total order for every
// choice, double arithmetic in a fixed order, compiled without FMA contraction).
std::vector<uint32_t> simplifyMesh(const std::vector<Vertex>& vertices,
                                   std::span<const uint32_t> indices, size_t targetIndexCount,
                                   float targetError);

}  // namespace reflect
