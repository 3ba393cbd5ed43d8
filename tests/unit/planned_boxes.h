// Objects for the planner's tests, as the planner sees them: unit boxes placed in the world, and
// mirror boxes that need a live probe; and what a probe's plan draws, face by face.
#pragma once

#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "core/frame_planner.h"

namespace reflect::testing {

inline const Bounds kUnitBox{{-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f}};

inline PlannedObject boxAt(glm::vec3 position, float size = 1.0f) {
  PlannedObject o;
  o.localBounds = kUnitBox;
  o.model = glm::scale(glm::translate(glm::mat4(1.0f), position), glm::vec3(size));
  return o;
}

inline PlannedObject mirrorAt(glm::vec3 position, float roughness = 0.0f) {
  PlannedObject o = boxAt(position);
  o.probed = true;
  o.look.material = Material::Mirror;
  o.look.roughness = roughness;
  return o;
}

// The faces a probe plans to draw, in its order.
inline std::vector<int> facesOf(const ProbePlan& probe) {
  std::vector<int> faces;
  for (const FacePlan& f : probe.faces) faces.push_back(f.face);
  return faces;
}

// The objects face `face` of a probe draws (none when the face is not drawn).
inline std::vector<int> objectsIn(const ProbePlan& probe, int face) {
  for (const FacePlan& f : probe.faces) {
    if (f.face != face) continue;
    std::vector<int> objects;
    for (const DrawItem& d : f.draws) objects.push_back(d.object);
    return objects;
  }
  return {};
}

// The cube faces by name, in the GL order.
inline constexpr int kPX = 0, kNX = 1, kPY = 2, kNY = 3, kPZ = 4, kNZ = 5;

}  // namespace reflect::testing
