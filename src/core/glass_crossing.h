// The one rule for a ray refracted into glass crossing it, shared by pick a pixel (core's BVH,
// pixel_trace.cpp) and the Embree reference (reference_tracer.cpp): the ray meets the far surface
// and leaves by refract(D, N_in, n), or on total internal reflection reflects (reflect(D, N_in))
// and goes on, kMaxInternalReflections times at most. N_in is the surface's normal turned to face
// the ray (the inward normal at an exit). Only the search for the far surface differs.
#pragma once

#include <glm/glm.hpp>

#include "core/trace_limits.h"

namespace reflect {

struct GlassCrossing {
  glm::vec3 point{0.0f};      // the last surface point (the entry, if no far surface was met)
  glm::vec3 direction{0.0f};  // the ray that goes on from it
  int internalReflections = 0;
  bool exited = false;  // refracted out (false: still inside after the limit, or no far surface)
};

// What the far-surface search found: a point and its interpolated normal, or nothing.
struct FarSurface {
  bool found = false;
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f};
};

// From `entry` along the refracted direction `inside`, in glass of index `ior`.
// `findFarSurface(point, direction)` returns the glass's next surface along the ray.
template <typename FindFarSurface>
GlassCrossing crossGlassInterior(const glm::vec3& entry, const glm::vec3& inside, float ior,
                                 FindFarSurface findFarSurface) {
  GlassCrossing c;
  c.point = entry;
  c.direction = inside;
  for (;;) {
    const FarSurface far = findFarSurface(c.point, c.direction);
    if (!far.found) return c;  // no far surface (a ray along a silhouette): on from here
    const glm::vec3 facing = glm::dot(c.direction, far.normal) > 0.0f ? -far.normal : far.normal;
    const glm::vec3 out = glm::refract(c.direction, facing, ior);
    c.point = far.position;
    if (glm::dot(out, out) > 0.0f) {
      c.direction = glm::normalize(out);
      c.exited = true;
      return c;
    }
    c.direction = glm::reflect(c.direction, facing);
    if (++c.internalReflections == kMaxInternalReflections) return c;
  }
}

}  // namespace reflect
