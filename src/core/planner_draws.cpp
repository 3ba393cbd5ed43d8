// What the planner draws: each object's level of detail for a view or a cube face, culled to the
// face by its chunks; and the small rules on planned objects the planner's files share
// (core/planner_parts.h).
#include <algorithm>
#include <cmath>

#include "core/frame_planner.h"
#include "core/frustum.h"
#include "core/mesh_chunks.h"
#include "core/planner_parts.h"

namespace reflect {
namespace planner {

bool contains(const std::vector<int>& list, int value) {
  return std::find(list.begin(), list.end(), value) != list.end();
}

std::vector<ProbeLayout> probesOf(const std::vector<PlannedObject>& objects) {
  std::vector<ProbeCandidate> candidates;
  candidates.reserve(objects.size());
  for (const PlannedObject& o : objects) {
    // A probe-lit object with a probe of its own owns one, at its bounds' centre.
    candidates.push_back(ProbeCandidate{
        o.probed || o.ownsLightProbe, o.ownsLightProbe ? -1 : o.probeGroup,
        o.ownsLightProbe ? std::nullopt : o.probeCentre, transformBounds(o.localBounds, o.model)});
  }
  return layoutProbes(candidates);
}

std::vector<ProbePlan> probesWithReaders(const std::vector<PlannedObject>& objects) {
  std::vector<ProbeLayout> layouts = probesOf(objects);
  std::vector<ProbePlan> probes(layouts.size());
  for (size_t i = 0; i < objects.size(); ++i) {
    if (!objects[i].probeLit) continue;
    int nearest = nearestProbe(layouts, worldCentreOf(objects[i]));
    for (size_t p = 0; p < layouts.size() && objects[i].ownsLightProbe; ++p) {
      if (layouts[p].reflector == static_cast<int>(i)) nearest = static_cast<int>(p);
    }
    if (nearest >= 0)
      probes[static_cast<size_t>(nearest)].diffuseReaders.push_back(static_cast<int>(i));
  }
  for (size_t p = 0; p < layouts.size(); ++p) {
    static_cast<ProbeLayout&>(probes[p]) = std::move(layouts[p]);
  }
  return probes;
}

glm::vec3 worldCentreOf(const PlannedObject& o) {
  return glm::vec3(o.model * glm::vec4(o.localBounds.centre(), 1.0f));
}
float worldRadiusOf(const PlannedObject& o) {
  const glm::vec3 halfExtent = 0.5f * (o.localBounds.max - o.localBounds.min);
  const glm::mat3 m(o.model);
  return glm::length(glm::abs(m[0]) * halfExtent.x + glm::abs(m[1]) * halfExtent.y +
                     glm::abs(m[2]) * halfExtent.z);
}

bool traceable(const PlannedObject& o) {
  return o.look.material == Material::Mirror || o.look.material == Material::Glass;
}

bool needsGeneralTracer(const std::vector<PlannedObject>& objects, int object) {
  if (objects[static_cast<size_t>(object)].look.material == Material::Glass) return true;
  for (size_t i = 0; i < objects.size(); ++i) {
    if (i != static_cast<size_t>(object) && objects[i].look.material != Material::Phong) {
      return true;
    }
  }
  return false;
}

int chooseLevel(const PlannedObject& o, const glm::vec3& centre, float pixelsPerTangent,
                float trianglesPerPixel) {
  if (trianglesPerPixel <= 0.0f || o.levels.size() < 2) return 0;
  const glm::vec3 worldCentre = worldCentreOf(o);
  const float radius = worldRadiusOf(o);
  const float distance = glm::length(worldCentre - centre);
  if (distance <= radius) return 0;  // the probe is inside or touching it
  const float pixels = radius / distance * pixelsPerTangent;
  const float wanted = trianglesPerPixel * 3.14159265f * pixels * pixels;
  int level = 0;
  while (level + 1 < static_cast<int>(o.levels.size()) &&
         static_cast<float>(o.levels[static_cast<size_t>(level + 1)].triangles) >= wanted) {
    ++level;
  }
  return level;
}

}  // namespace planner

using planner::chooseLevel;
using planner::contains;

float screenPixels(const glm::vec3& centre, float radius, const PlannerView& view) {
  if (view.pixelsPerTangent <= 0.0f) return 0.0f;
  const float distance = glm::length(centre - view.eye);
  if (distance <= radius) return view.pixels;  // the camera is inside it
  const float tangent = radius / std::sqrt(distance * distance - radius * radius);
  const float pixels = tangent * view.pixelsPerTangent;
  return std::min(3.14159265f * pixels * pixels, view.pixels);
}

std::vector<DrawItem> planViewDraws(const std::vector<PlannedObject>& objects, const glm::vec3& eye,
                                    float pixelsPerTangent, const PlannerSettings& settings) {
  std::vector<DrawItem> draws;
  draws.reserve(objects.size());
  for (size_t i = 0; i < objects.size(); ++i) {
    const PlannedObject& o = objects[i];
    DrawItem item;
    item.object = static_cast<int>(i);
    item.lod = chooseLevel(o, eye, pixelsPerTangent, settings.viewLod);
    if (!o.levels.empty()) item.triangles = o.levels[static_cast<size_t>(item.lod)].triangles;
    draws.push_back(std::move(item));
  }
  return draws;
}

std::vector<DrawItem> FramePlanner::drawsFor(const std::vector<PlannedObject>& objects,
                                             const std::vector<int>& members,
                                             const glm::vec3& centre, int face,
                                             const CaptureContext& context, bool whole,
                                             float trianglesPerPixel) const {
  std::vector<DrawItem> draws;
  for (size_t i = 0; i < objects.size(); ++i) {
    // The probe's own reflectors are left out by identity: they surround the capture point.
    if (contains(members, static_cast<int>(i))) continue;
    const PlannedObject& o = objects[i];
    DrawItem item{static_cast<int>(i), 0, {}, 0};
    if (!o.levels.empty()) item.triangles = o.levels[0].triangles;
    if (whole) {  // the course draws every object whole into every face
      draws.push_back(std::move(item));
      continue;
    }
    if (!faceMaySee(centre, face, context.near, context.far, o.localBounds, o.model)) continue;
    // At 90 degrees one unit of tangent spans half the face.
    item.lod =
        chooseLevel(o, centre, 0.5f * static_cast<float>(context.faceSize), trianglesPerPixel);
    if (!o.levels.empty()) {
      const PlannedLevel& level = o.levels[static_cast<size_t>(item.lod)];
      item.triangles = level.triangles;
      if (level.chunks && !level.chunks->empty()) {
        item.triangles = 0;
        for (const MeshChunk& chunk : *level.chunks) {
          if (!faceMaySee(centre, face, context.near, context.far, chunk.bounds, o.model)) continue;
          appendRange(item.ranges, chunk.range);
          item.triangles += chunk.range.count / 3;
        }
        if (item.ranges.empty()) continue;  // the box reaches in, but no part of the mesh does
      }
    }
    draws.push_back(std::move(item));
  }
  return draws;
}

}  // namespace reflect
