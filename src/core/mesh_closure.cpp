#include "core/mesh_closure.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace reflect {

namespace {

// One id per distinct position, by exact value: a seam's split vertices become one.
std::vector<uint32_t> weldedIds(const std::vector<Vertex>& vertices) {
  struct PositionHash {
    size_t operator()(const glm::vec3& p) const {
      const std::hash<float> h;
      return h(p.x) * 73856093u ^ h(p.y) * 19349663u ^ h(p.z) * 83492791u;
    }
  };
  std::unordered_map<glm::vec3, uint32_t, PositionHash> ids;
  ids.reserve(vertices.size());
  std::vector<uint32_t> welded;
  welded.reserve(vertices.size());
  for (const Vertex& v : vertices) {
    welded.push_back(ids.emplace(v.position, static_cast<uint32_t>(ids.size())).first->second);
  }
  return welded;
}

}  // namespace

bool isClosedOutward(const MeshData& mesh) {
  if (mesh.indices.size() < 3 || mesh.indices.size() % 3 != 0) return false;
  const std::vector<uint32_t> id = weldedIds(mesh.vertices);
  std::vector<uint64_t> edges;  // (from << 32 | to), directed as the triangles wind
  edges.reserve(mesh.indices.size());
  double volume = 0.0;  // six times the enclosed volume
  for (size_t i = 0; i < mesh.indices.size(); i += 3) {
    const uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
    if (a >= mesh.vertices.size() || b >= mesh.vertices.size() || c >= mesh.vertices.size()) {
      return false;
    }
    const uint32_t ia = id[a], ib = id[b], ic = id[c];
    if (ia == ib || ib == ic || ic == ia) continue;
    for (const auto& [from, to] : {std::pair{ia, ib}, std::pair{ib, ic}, std::pair{ic, ia}}) {
      edges.push_back(static_cast<uint64_t>(from) << 32 | to);
    }
    const glm::dvec3 pa(mesh.vertices[a].position), pb(mesh.vertices[b].position),
        pc(mesh.vertices[c].position);
    volume += glm::dot(pa, glm::cross(pb, pc));
  }
  if (edges.empty()) return false;
  std::sort(edges.begin(), edges.end());
  for (size_t i = 0; i < edges.size(); ++i) {
    if (i + 1 < edges.size() && edges[i + 1] == edges[i]) return false;  // met twice one way
    const uint64_t reversed = edges[i] << 32 | edges[i] >> 32;
    if (!std::binary_search(edges.begin(), edges.end(), reversed)) return false;  // an open edge
  }
  return volume > 0.0;
}

}  // namespace reflect
