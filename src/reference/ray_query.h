// First hits from Embree, for checking the exact mode's own BVH (core/bvh.h) against it: the
// scene's objects placed at a time, world-space triangles as the reference traces them.
#pragma once

#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "core/result.h"
#include "core/scene.h"
#include "reference/reference_renderer.h"

namespace reflect {

struct QueryRay {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f};
  float tNear = 0.0f;
};

struct QueryHit {
  int object = -1;    // -1: nothing met
  int triangle = -1;  // the mesh's triangle index
  float t = std::numeric_limits<float>::infinity();
};

// Each ray's first hit among `scene`'s objects at `seconds` (level-0 meshes from `meshes`).
Result<std::vector<QueryHit>> embreeFirstHits(const Scene& scene, const MeshLookup& meshes,
                                              double seconds, const std::vector<QueryRay>& rays);

}  // namespace reflect
