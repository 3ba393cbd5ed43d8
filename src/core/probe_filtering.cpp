// Which prefiltered levels a captured probe keeps for its rough readers, and when they are
// filtered: the planner owns this decision as it owns the capture's. A probe read only by perfect
// mirrors (or polished glass, or a cube-textured object) keeps no level and is never filtered;
// nor is one whose rough readers take lobe taps from the capture itself (the default), which
// keeps its box chain instead. The static skybox's rough readers get the sky's levels the same
// way, filtered once. A probe read only by rough mirrors' lobe taps is captured at the face size
// their lobes need (lobeTapFaceSize), not the scene's.
#include <algorithm>
#include <cmath>

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

namespace {

// Adds the levels a reader of `look` needs, of a cube of faceSize, to `levels` (each once).
void addLevelsOf(const SceneObject::Look& look, int roughLevels, int faceSize,
                 std::vector<int>& levels) {
  for (float roughness : lobeRoughnesses(look)) {
    const RoughLevels needed = roughLevelsFor(roughness, usableRoughLevels(roughLevels, faceSize));
    for (int level : {needed.lower, needed.upper}) {
      if (level > 0 && !contains(levels, level)) levels.push_back(level);
    }
  }
}

}  // namespace

bool readsLobeTaps(const ProbeLayout& probe, const std::vector<PlannedObject>& objects,
                   const CaptureContext& context) {
  return context.accuracy.lobeTaps > 0 &&
         std::any_of(probe.members.begin(), probe.members.end(),
                     [&](int m) { return objects[static_cast<size_t>(m)].look.rough(); });
}

int lobeTapFaceSize(const ProbePlan& probe, const std::vector<PlannedObject>& objects,
                    const CaptureContext& context) {
  if (!probe.lobeTapReaders || !probe.diffuseReaders.empty()) return 0;
  // A tap's share of its lobe at the lobe's peak is 4 pi alpha^2 / taps steradians; a texel of
  // faces of N is 4 pi / (6 N^2): the tap covers N alpha sqrt(6 / taps) texels across, and the
  // narrowest lobe among the readers sets the size.
  float narrowest = 1.0f;
  for (int m : probe.members) {
    const SceneObject::Look& look = objects[static_cast<size_t>(m)].look;
    if (look.material != Material::Mirror || !look.rough()) return 0;
    narrowest = std::min(narrowest, ggxAlpha(look.roughness));
  }
  const float perTexel =
      narrowest * std::sqrt(6.0f / static_cast<float>(std::max(context.accuracy.lobeTaps, 1)));
  int size = context.faceSize;
  while (size / 2 >= kMinLobeTapFaceSize &&
         static_cast<float>(size / 2) * perTexel >= kMinTapFootprintTexels) {
    size /= 2;
  }
  return size == context.faceSize ? 0 : size;
}

std::vector<int> roughLevelsOf(const ProbeLayout& probe, const std::vector<PlannedObject>& objects,
                               const CaptureContext& context) {
  std::vector<int> levels;
  if (context.accuracy.lobeTaps > 0) return levels;  // its readers sample the capture itself
  for (int m : probe.members) {
    addLevelsOf(objects[static_cast<size_t>(m)].look, context.accuracy.roughLevels,
                context.faceSize, levels);
  }
  std::sort(levels.begin(), levels.end());
  return levels;
}

void decideFiltering(ProbePlan& probe, std::vector<int>& filtered) {
  const bool changed = probe.roughLevels != filtered;
  probe.filterFaces = !probe.roughLevels.empty() && (!probe.faces.empty() || changed) ? 0x3Fu : 0u;
  filtered = probe.roughLevels;
}

void decideSkyFiltering(FramePlan& plan, const std::vector<PlannedObject>& objects,
                        const CaptureContext& context, std::vector<int>& filtered,
                        uint64_t& filteredContent) {
  std::vector<int> levels;
  for (size_t i = 0; i < objects.size(); ++i) {
    const SceneObject::Look& look = objects[i].look;
    // A traced reader (search: exact) follows its lobe's rays to the sky itself.
    if (context.skyFaceSize <= 0 || look.environment != Environment::Skybox ||
        plan.traces(static_cast<int>(i))) {
      continue;
    }
    addLevelsOf(look, context.accuracy.roughLevels, context.skyFaceSize, levels);
  }
  std::sort(levels.begin(), levels.end());
  plan.skyRoughLevels = levels;
  plan.filterSky =
      !levels.empty() && (levels != filtered || context.skyboxContent != filteredContent);
  plan.skyFilterSamples =
      plan.filterSky ? filterSamplesFor(levels, context.skyFaceSize, context.accuracy.filterSamples)
                     : 0.0;
  filtered = std::move(levels);
  filteredContent = context.skyboxContent;
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
