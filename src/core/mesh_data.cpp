#include "core/mesh_data.h"

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

}  // namespace reflect
