#include "core/face_ages.h"

#include <algorithm>

namespace reflect {

void FaceAges::advance(const FramePlan& plan) {
  // In place: this runs every frame, views on or off, so a steady scene allocates nothing here
  // (a map node only when a probe first appears).
  std::erase_if(probes_, [&plan](const auto& entry) {
    return std::none_of(plan.probes.begin(), plan.probes.end(),
                        [&entry](const ProbePlan& p) { return p.reflector == entry.first; });
  });
  for (const ProbePlan& probe : plan.probes) {
    auto [it, added] = probes_.try_emplace(probe.reflector);
    std::array<FaceMark, 6>& marks = it->second;
    for (FaceMark& mark : marks) {
      if (added) mark.everCaptured = false;
      mark.captured = false;
      if (mark.everCaptured) ++mark.ageFrames;
    }
    for (const FacePlan& face : probe.faces) {
      marks[static_cast<size_t>(face.face)] = FaceMark{true, 0, true};
    }
  }
}

std::array<FaceMark, 6> FaceAges::marks(int reflector) const {
  if (const auto known = probes_.find(reflector); known != probes_.end()) return known->second;
  std::array<FaceMark, 6> empty;
  for (FaceMark& mark : empty) mark = FaceMark{false, 0, false};
  return empty;
}

}  // namespace reflect
