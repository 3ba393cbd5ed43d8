// What a captured probe stores: one depth layer or two, and whether its reflectors need the
// search at all or the plain lookup is within half a texel (core/frame_planner.h explains the
// bound).
#include <algorithm>
#include <array>
#include <cmath>

#include "core/frame_planner.h"
#include "core/frustum.h"
#include "core/planner_parts.h"

namespace reflect {
namespace {

float farthestInBox(const glm::vec3& p, const Bounds& box) {
  return glm::length(glm::max(glm::abs(box.min - p), glm::abs(box.max - p)));
}

}  // namespace

float halfTexelAngle(int faceSize) {
  return 0.4082f / static_cast<float>(std::max(faceSize, 1));
}

bool plainLookupWithinHalfTexel(float reach, float nearest, int faceSize) {
  return reach < nearest * std::sin(halfTexelAngle(faceSize));
}

namespace planner {

bool faceCanHide(size_t shown, const CaptureContext& context) {
  return shown >= 2 || (context.skyboxContent != 0 && shown >= 1);
}

void decideStorage(ProbePlan& probe, const std::vector<PlannedObject>& objects,
                   const CaptureContext& context) {
  const bool sky = context.skyboxContent != 0;
  float reach = 0.0f;
  bool searched = false;  // a member is a mirror or glass
  // Without a sky the clear background is stored at the far plane, at least `far` away.
  float nearest = sky ? INFINITY : context.far;
  bool occlusion = false;
  std::array<int, 6> visible{};
  for (size_t i = 0; i < objects.size(); ++i) {
    const PlannedObject& o = objects[i];
    const Bounds world = transformBounds(o.localBounds, o.model);
    if (contains(probe.members, static_cast<int>(i))) {
      reach = std::max(reach, farthestInBox(probe.centre, world));
      searched |= o.look.material == Material::Mirror || o.look.material == Material::Glass;
      continue;
    }
    bool seen = false;
    for (int face = 0; face < 6; ++face) {
      if (!faceMaySee(probe.centre, face, context.near, context.far, o.localBounds, o.model)) {
        continue;
      }
      seen = true;
      ++visible[static_cast<size_t>(face)];
    }
    if (seen) nearest = std::min(nearest, distanceToBox(probe.centre, world));
  }
  for (int count : visible) occlusion |= faceCanHide(static_cast<size_t>(count), context);
  const Search search = capturedSearch(context.accuracy.search);
  const bool searches = search != Search::Plain;
  probe.plainLookupSuffices =
      searches && (!searched || plainLookupWithinHalfTexel(reach, nearest, context.faceSize));
  probe.layers = search == Search::Hierarchical && context.accuracy.layers >= 2 && occlusion &&
                         !probe.plainLookupSuffices
                     ? 2
                     : 1;
}

}  // namespace planner
}  // namespace reflect
