// Which cube faces can see a box: the six planes of a 90-degree face frustum, tested against a
// world-space axis-aligned box (conservative: a box that might be visible is kept). And where a
// box lands on the main view's target.
#pragma once

#include <glm/glm.hpp>

#include "core/mesh_data.h"

namespace reflect {

// The world-space box around `local` transformed by `model` (all 8 corners).
Bounds transformBounds(const Bounds& local, const glm::mat4& model);

// True when the box `local` placed by `model` (an oriented box in the world) may intersect the
// frustum of cube face `face` seen from `centre` between `near` and `far`. Each plane is taken
// into the box's own space, so a rotated figure is not inflated to a world-aligned box.
bool faceMaySee(const glm::vec3& centre, int face, float near, float far, const Bounds& local,
                const glm::mat4& model = glm::mat4(1.0f));

// Where a box lands on a target: the rectangle around its 8 corners (the box `local` placed by
// `model`) projected by `viewProjection`, in fractions of the target (x to the right, y down;
// 0..1 is on the target). Conservative: the object inside the box covers at most this rectangle.
// `inFront` is false when some corner is not in front of the eye; the rectangle then spans only
// the corners that are (all zero when none is).
struct ScreenBox {
  float x0 = 0.0f, y0 = 0.0f, x1 = 0.0f, y1 = 0.0f;
  bool inFront = false;
};
ScreenBox screenBox(const Bounds& local, const glm::mat4& model, const glm::mat4& viewProjection);

// How far from the eye the near plane of a symmetric perspective `projection` reaches: the
// distance to its corners. A solid farther than this from the eye is seen from outside only, the
// near plane cutting nothing open. 0 for any other projection (nothing is taken to be outside).
float nearPlaneReach(const glm::mat4& projection);

// The distance from `point` to the box (0 inside it).
float distanceToBox(const glm::vec3& point, const Bounds& box);

}  // namespace reflect
