#include "core/frustum.h"

#include <algorithm>
#include <cmath>

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

// The largest value of dot(n, M x + t - centre) over the local box: its corner furthest along n
// once n is taken into the box's space (M^T n).
float maxAlong(const glm::vec3& n, const glm::vec3& centre, const Bounds& local,
               const glm::mat4& model) {
  const glm::vec3 localN = glm::transpose(glm::mat3(model)) * n;
  const glm::vec3 far(localN.x >= 0 ? local.max.x : local.min.x,
                      localN.y >= 0 ? local.max.y : local.min.y,
                      localN.z >= 0 ? local.max.z : local.min.z);
  return glm::dot(localN, far) + glm::dot(n, glm::vec3(model[3]) - centre);
}

}  // namespace

bool faceMaySee(const glm::vec3& centre, int face, float near, float far, const Bounds& local,
                const glm::mat4& model) {
  const CubeFace& f = kCubeFaces.at(static_cast<size_t>(face));
  const glm::vec3 d = f.direction;
  const glm::vec3 u = f.up;
  const glm::vec3 r = glm::cross(d, u);
  // Inside the 90-degree pyramid means dot(p, d) >= |dot(p, u)| and >= |dot(p, r)|: four planes
  // through the centre with normals d -/+ u and d -/+ r (unnormalised; only the sign matters).
  const glm::vec3 sides[4] = {d - u, d + u, d - r, d + r};
  for (const glm::vec3& n : sides) {
    if (maxAlong(n, centre, local, model) < 0.0f) return false;
  }
  if (maxAlong(d, centre, local, model) < near) return false;   // wholly before the near plane
  if (maxAlong(-d, centre, local, model) < -far) return false;  // wholly beyond the far plane
  return true;
}

ScreenBox screenBox(const Bounds& local, const glm::mat4& model, const glm::mat4& viewProjection) {
  ScreenBox box;
  box.inFront = true;
  bool any = false;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p((corner & 1) ? local.max.x : local.min.x,
                      (corner & 2) ? local.max.y : local.min.y,
                      (corner & 4) ? local.max.z : local.min.z);
    const glm::vec4 clip = viewProjection * model * glm::vec4(p, 1.0f);
    if (!(clip.w > 0.0f)) {
      box.inFront = false;
      continue;
    }
    // Normalised device coordinates to fractions of the target, y from the top.
    const float x = 0.5f + 0.5f * clip.x / clip.w;
    const float y = 0.5f - 0.5f * clip.y / clip.w;
    if (!any) {
      box.x0 = box.x1 = x;
      box.y0 = box.y1 = y;
      any = true;
    }
    box.x0 = std::min(box.x0, x);
    box.x1 = std::max(box.x1, x);
    box.y0 = std::min(box.y0, y);
    box.y1 = std::max(box.y1, y);
  }
  return box;
}

float nearPlaneReach(const glm::mat4& projection) {
  // glm::perspective's layout: [0][0] = 1 / (aspect tan), [1][1] = 1 / tan, [2][3] = -1, the
  // third column's depth terms give near, and nothing off the diagonal shifts the view.
  const glm::mat4& p = projection;
  const bool symmetricPerspective = p[2][3] == -1.0f && p[3][3] == 0.0f && p[2][0] == 0.0f &&
                                    p[2][1] == 0.0f && p[0][0] > 0.0f && p[1][1] > 0.0f;
  if (!symmetricPerspective) return 0.0f;
  const float near = p[3][2] / (p[2][2] - 1.0f);
  if (!(near > 0.0f)) return 0.0f;
  const float tanX = 1.0f / p[0][0], tanY = 1.0f / p[1][1];
  return near * std::sqrt(1.0f + tanX * tanX + tanY * tanY);
}

float distanceToBox(const glm::vec3& point, const Bounds& box) {
  return glm::length(glm::max(glm::max(box.min - point, point - box.max), glm::vec3(0.0f)));
}

}  // namespace reflect
