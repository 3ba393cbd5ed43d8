// Which reflectors share a live probe, and where each probe captures from. One rule, used by the
// frame planner (what the raster captures) and by the reference (the true directions are
// measured from the same points).
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "core/mesh_data.h"
#include "core/scene.h"

namespace reflect {

// What the layout needs to know of one scene object.
struct ProbeCandidate {
  bool probed = false;  // samples a live probe (mirror, glass, cube-textured)
  int group = -1;       // objects with the same group >= 0 share one probe; -1: a probe of its own
  std::optional<glm::vec3> centre;  // an explicit capture point (scene file, or the course's mode)
  Bounds worldBounds;
};

struct ProbeLayout {
  int reflector = 0;         // the object that owns the probe: its first member
  std::vector<int> members;  // every object that samples it, the owner first
  glm::vec3 centre{0.0f};
};

// Probes in object order: one per ungrouped probed object, one per group. A probe captures from
// its owner's explicit centre when it has one, otherwise from the centre of its members' joint
// world bounds (for one member: its own bounds' centre).
std::vector<ProbeLayout> layoutProbes(const std::vector<ProbeCandidate>& objects);

// The probe (an index into `probes`) whose centre is nearest `point`, the first of equals; -1
// when there is none. A probe-lit object takes its diffuse light from it
// (ProbePlan::diffuseReaders).
int nearestProbe(const std::vector<ProbeLayout>& probes, const glm::vec3& point);

// The explicit capture point of an object: the course's origin when `captureAtOrigin`, otherwise
// the scene's own (nullopt: the bounds centre, as layoutProbes decides).
std::optional<glm::vec3> capturePoint(const std::optional<glm::vec3>& sceneCentre,
                                      bool captureAtOrigin);

// `scene` with every live probe's capture point as capturePoint() sets it.
Scene sceneAsCaptured(Scene scene, bool captureAtOrigin);

}  // namespace reflect
