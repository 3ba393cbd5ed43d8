// Which prefiltered levels a captured probe keeps for its rough readers, and when they are
// filtered: the planner owns this decision as it owns the capture's. A probe read only by perfect
// mirrors (or polished glass, or a cube-textured object) keeps no level and is never filtered.
#include <algorithm>

#include "core/frame_planner.h"
#include "core/ggx.h"
#include "core/planner_parts.h"

namespace reflect::planner {

std::vector<float> lobeRoughnesses(const SceneObject::Look& look) {
  if (!look.rough()) return {};
  if (look.material == Material::Glass) {
    return {look.roughness, transmissionRoughness(look.roughness, look.ior)};
  }
  return {look.roughness};
}

void decideFiltering(ProbePlan& probe, const std::vector<PlannedObject>& objects,
                     const CaptureContext& context, std::vector<int>& filtered) {
  std::vector<int> levels;
  for (int m : probe.members) {
    const SceneObject::Look& look = objects[static_cast<size_t>(m)].look;
    for (float roughness : lobeRoughnesses(look)) {
      const RoughLevels needed = roughLevelsFor(
          roughness, usableRoughLevels(context.accuracy.roughLevels, context.faceSize));
      for (int level : {needed.lower, needed.upper}) {
        if (level > 0 && !contains(levels, level)) levels.push_back(level);
      }
    }
  }
  std::sort(levels.begin(), levels.end());
  probe.roughLevels = levels;
  const bool changed = levels != filtered;
  probe.filterFaces = !levels.empty() && (!probe.faces.empty() || changed) ? 0x3Fu : 0u;
  filtered = std::move(levels);
}

double filterSamplesFor(const std::vector<int>& levels, int faceSize, int samples) {
  double texels = 0.0;
  for (int level : levels) {
    const double size = std::max(faceSize >> level, 1);
    texels += 6.0 * size * size;
  }
  return texels * samples;
}

}  // namespace reflect::planner
