// Which cube faces can see a box: the six planes of a 90-degree face frustum, tested against a
// world-space axis-aligned box (conservative: a box that might be visible is kept).
#pragma once

#include <glm/glm.hpp>

#include "core/mesh_data.h"

namespace reflect {

// The world-space box around `local` transformed by `model` (all 8 corners).
Bounds transformBounds(const Bounds& local, const glm::mat4& model);

// True when `box` may intersect the frustum of cube face `face` seen from `centre` between
// `near` and `far`.
bool faceMaySee(const glm::vec3& centre, int face, float near, float far, const Bounds& box);

}  // namespace reflect
