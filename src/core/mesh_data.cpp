#include "core/mesh_data.h"

#include <algorithm>
#include <cmath>

namespace reflect {

Bounds computeBounds(const std::vector<Vertex>& vertices) {
  if (vertices.empty()) return {};
  Bounds b{vertices.front().position, vertices.front().position};
  for (const Vertex& v : vertices) {
    b.min = glm::min(b.min, v.position);
    b.max = glm::max(b.max, v.position);
  }
  return b;
}

float sphereRadiusOf(const MeshData& mesh) {
  if (mesh.vertices.empty()) return 0.0f;
  const glm::vec3 centre = mesh.bounds.centre();
  float lo = INFINITY, hi = 0.0f;
  for (const Vertex& v : mesh.vertices) {
    const float r = glm::length(v.position - centre);
    lo = std::min(lo, r);
    hi = std::max(hi, r);
    // A cube's corners lie on a sphere too: a sphere's normals also point away from its centre
    // (within 8 degrees), a flat face's do not.
    const float n = glm::length(v.normal);
    if (!(n > 0.0f) || glm::dot(v.normal, v.position - centre) < 0.99f * n * r) return 0.0f;
  }
  if (!(lo > 0.0f) || hi > lo * 1.005f) return 0.0f;
  return 0.5f * (lo + hi);
}

}  // namespace reflect
