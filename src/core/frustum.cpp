#include "core/frustum.h"

#include <algorithm>

#include "core/cube_faces.h"

namespace reflect {

Bounds transformBounds(const Bounds& local, const glm::mat4& model) {
  Bounds out{glm::vec3(model * glm::vec4(local.min, 1.0f)), glm::vec3(0.0f)};
  out.max = out.min;
  for (int corner = 1; corner < 8; ++corner) {
    const glm::vec3 p((corner & 1) ? local.max.x : local.min.x,
                      (corner & 2) ? local.max.y : local.min.y,
                      (corner & 4) ? local.max.z : local.min.z);
    const glm::vec3 world(model * glm::vec4(p, 1.0f));
    out.min = glm::min(out.min, world);
    out.max = glm::max(out.max, world);
  }
  return out;
}

namespace {

// The largest value of dot(n, p - centre) over the box: its corner furthest along n.
float maxAlong(const glm::vec3& n, const glm::vec3& centre, const Bounds& box) {
  const glm::vec3 far(n.x >= 0 ? box.max.x : box.min.x, n.y >= 0 ? box.max.y : box.min.y,
                      n.z >= 0 ? box.max.z : box.min.z);
  return glm::dot(n, far - centre);
}

}  // namespace

bool faceMaySee(const glm::vec3& centre, int face, float near, float far, const Bounds& box) {
  const CubeFace& f = kCubeFaces.at(static_cast<size_t>(face));
  const glm::vec3 d = f.direction;
  const glm::vec3 u = f.up;
  const glm::vec3 r = glm::cross(d, u);
  // Inside the 90-degree pyramid means dot(p, d) >= |dot(p, u)| and >= |dot(p, r)|: four planes
  // through the centre with normals d -/+ u and d -/+ r (unnormalised; only the sign matters).
  const glm::vec3 sides[4] = {d - u, d + u, d - r, d + r};
  for (const glm::vec3& n : sides) {
    if (maxAlong(n, centre, box) < 0.0f) return false;
  }
  if (maxAlong(d, centre, box) < near) return false;   // wholly in front of the near plane
  if (maxAlong(-d, centre, box) < -far) return false;  // wholly beyond the far plane
  return true;
}

}  // namespace reflect
