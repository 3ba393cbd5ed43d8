#include "core/mesh_chunks.h"

#include <algorithm>
#include <numeric>
#include <string>

namespace reflect {
namespace {

struct Splitter {
  std::vector<glm::vec3> centres;  // per triangle
  std::vector<uint32_t> order;     // triangle ids, rearranged in place
  size_t maxTriangles;
  std::vector<uint32_t> counts;

  void split(size_t begin, size_t end) {
    if (end - begin <= maxTriangles) {
      // A chunk keeps its triangles in the mesh's order: with the total order below, the whole
      // reordering is canonical whatever the standard library (libstdc++ natively, libc++ in the
      // page's worker), and so are the levels simplified from it (mesh_simplify's result
      // depends on the input's order).
      std::sort(order.begin() + static_cast<std::ptrdiff_t>(begin),
                order.begin() + static_cast<std::ptrdiff_t>(end));
      counts.push_back(static_cast<uint32_t>(end - begin));
      return;
    }
    Bounds box{centres[order[begin]], centres[order[begin]]};
    for (size_t i = begin; i < end; ++i) {
      box.min = glm::min(box.min, centres[order[i]]);
      box.max = glm::max(box.max, centres[order[i]]);
    }
    const glm::vec3 extent = box.max - box.min;
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const size_t middle = begin + (end - begin) / 2;
    std::nth_element(order.begin() + static_cast<std::ptrdiff_t>(begin),
                     order.begin() + static_cast<std::ptrdiff_t>(middle),
                     order.begin() + static_cast<std::ptrdiff_t>(end), [&](uint32_t a, uint32_t b) {
                       // Ties broken by the triangle's number: which triangles fall below the
                       // median does not depend on nth_element's implementation.
                       const float ka = centres[a][axis], kb = centres[b][axis];
                       return ka < kb || (ka == kb && a < b);
                     });
    split(begin, middle);
    split(middle, end);
  }
};

}  // namespace

std::vector<uint32_t> chunkOrder(const std::vector<Vertex>& vertices,
                                 std::vector<uint32_t>& indices, size_t maxTriangles) {
  const size_t triangles = indices.size() / 3;
  if (triangles == 0) return {};
  Splitter s{{}, {}, std::max<size_t>(maxTriangles, 1), {}};
  s.centres.resize(triangles);
  for (size_t t = 0; t < triangles; ++t) {
    s.centres[t] = (vertices[indices[t * 3]].position + vertices[indices[t * 3 + 1]].position +
                    vertices[indices[t * 3 + 2]].position) /
                   3.0f;
  }
  s.order.resize(triangles);
  std::iota(s.order.begin(), s.order.end(), 0u);
  s.split(0, triangles);
  s.centres = {};

  std::vector<uint32_t> reordered(triangles * 3);
  for (size_t t = 0; t < triangles; ++t) {
    for (size_t k = 0; k < 3; ++k) reordered[t * 3 + k] = indices[s.order[t] * 3 + k];
  }
  indices = std::move(reordered);
  return std::move(s.counts);
}

Result<std::vector<MeshChunk>> chunksFromCounts(const std::vector<Vertex>& vertices,
                                                std::span<const uint32_t> indices,
                                                const std::vector<uint32_t>& triangleCounts) {
  using Out = Result<std::vector<MeshChunk>>;
  if (indices.size() % 3 != 0) return Out::failure("the indices are not whole triangles");
  std::vector<MeshChunk> chunks;
  chunks.reserve(triangleCounts.size());
  size_t first = 0;
  for (uint32_t count : triangleCounts) {
    if (count == 0 || count > (indices.size() - first) / 3) {
      return Out::failure("the chunks' triangle counts do not add up to the mesh's " +
                          std::to_string(indices.size() / 3) + " triangles");
    }
    MeshChunk chunk{{static_cast<uint32_t>(first), count * 3}, {}};
    for (size_t i = first; i < first + size_t{count} * 3; ++i) {
      if (indices[i] >= vertices.size()) return Out::failure("an index is out of range");
      const glm::vec3& p = vertices[indices[i]].position;
      if (i == first) chunk.bounds = {p, p};
      chunk.bounds.min = glm::min(chunk.bounds.min, p);
      chunk.bounds.max = glm::max(chunk.bounds.max, p);
    }
    first += size_t{count} * 3;
    chunks.push_back(chunk);
  }
  if (first != indices.size()) {
    return Out::failure("the chunks' triangle counts do not add up to the mesh's " +
                        std::to_string(indices.size() / 3) + " triangles");
  }
  return chunks;
}

void chunkMesh(MeshData& mesh, size_t maxTriangles) {
  mesh.chunks.clear();
  const std::vector<uint32_t> counts = chunkOrder(mesh.vertices, mesh.indices, maxTriangles);
  Result<std::vector<MeshChunk>> chunks = chunksFromCounts(mesh.vertices, mesh.indices, counts);
  if (chunks) mesh.chunks = chunks.take();
}

void appendRange(std::vector<IndexRange>& ranges, IndexRange range) {
  if (!ranges.empty() && ranges.back().first + ranges.back().count == range.first) {
    ranges.back().count += range.count;
  } else {
    ranges.push_back(range);
  }
}

}  // namespace reflect
