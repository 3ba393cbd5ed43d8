#include "core/mesh_chunks.h"

#include <algorithm>
#include <numeric>

namespace reflect {
namespace {

struct Splitter {
  const MeshData& mesh;
  std::vector<glm::vec3> centres;  // per triangle
  std::vector<uint32_t> order;     // triangle ids, rearranged in place
  size_t maxTriangles;
  std::vector<MeshChunk> chunks;

  void split(size_t begin, size_t end) {
    Bounds box{centres[order[begin]], centres[order[begin]]};
    for (size_t i = begin; i < end; ++i) {
      box.min = glm::min(box.min, centres[order[i]]);
      box.max = glm::max(box.max, centres[order[i]]);
    }
    if (end - begin <= maxTriangles) {
      chunks.push_back(MeshChunk{
          {static_cast<uint32_t>(begin * 3), static_cast<uint32_t>((end - begin) * 3)}, {}});
      return;
    }
    const glm::vec3 extent = box.max - box.min;
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const size_t middle = begin + (end - begin) / 2;
    std::nth_element(order.begin() + static_cast<std::ptrdiff_t>(begin),
                     order.begin() + static_cast<std::ptrdiff_t>(middle),
                     order.begin() + static_cast<std::ptrdiff_t>(end),
                     [&](uint32_t a, uint32_t b) { return centres[a][axis] < centres[b][axis]; });
    split(begin, middle);
    split(middle, end);
  }
};

}  // namespace

void chunkMesh(MeshData& mesh, size_t maxTriangles) {
  const size_t triangles = mesh.triangleCount();
  mesh.chunks.clear();
  if (triangles == 0) return;
  Splitter s{mesh, {}, {}, std::max<size_t>(maxTriangles, 1), {}};
  s.centres.resize(triangles);
  for (size_t t = 0; t < triangles; ++t) {
    s.centres[t] = (mesh.vertices[mesh.indices[t * 3]].position +
                    mesh.vertices[mesh.indices[t * 3 + 1]].position +
                    mesh.vertices[mesh.indices[t * 3 + 2]].position) /
                   3.0f;
  }
  s.order.resize(triangles);
  std::iota(s.order.begin(), s.order.end(), 0u);
  s.split(0, triangles);

  std::vector<uint32_t> reordered(mesh.indices.size());
  for (size_t t = 0; t < triangles; ++t) {
    for (size_t k = 0; k < 3; ++k) reordered[t * 3 + k] = mesh.indices[s.order[t] * 3 + k];
  }
  mesh.indices = std::move(reordered);
  for (MeshChunk& chunk : s.chunks) {
    const Vertex& first = mesh.vertices[mesh.indices[chunk.range.first]];
    chunk.bounds = {first.position, first.position};
    for (uint32_t i = chunk.range.first; i < chunk.range.first + chunk.range.count; ++i) {
      const glm::vec3& p = mesh.vertices[mesh.indices[i]].position;
      chunk.bounds.min = glm::min(chunk.bounds.min, p);
      chunk.bounds.max = glm::max(chunk.bounds.max, p);
    }
  }
  mesh.chunks = std::move(s.chunks);
}

void appendRange(std::vector<IndexRange>& ranges, IndexRange range) {
  if (!ranges.empty() && ranges.back().first + ranges.back().count == range.first) {
    ranges.back().count += range.count;
  } else {
    ranges.push_back(range);
  }
}

}  // namespace reflect
