// Objects for the planner's tests, as the planner sees them: unit boxes placed in the world, and
// mirror boxes that need a live probe.
#pragma once

#include <glm/gtc/matrix_transform.hpp>

#include "core/frame_planner.h"

namespace reflect::testing {

inline const Bounds kUnitBox{{-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f}};

inline PlannedObject boxAt(glm::vec3 position) {
  PlannedObject o;
  o.localBounds = kUnitBox;
  o.model = glm::translate(glm::mat4(1.0f), position);
  return o;
}

inline PlannedObject mirrorAt(glm::vec3 position, float roughness = 0.0f) {
  PlannedObject o = boxAt(position);
  o.probed = true;
  o.look.material = Material::Mirror;
  o.look.roughness = roughness;
  return o;
}

}  // namespace reflect::testing
