#include "core/face_ages.h"

namespace reflect {

void FaceAges::advance(const FramePlan& plan) {
  std::map<int, std::array<FaceMark, 6>> next;
  for (const ProbePlan& probe : plan.probes) {
    std::array<FaceMark, 6> marks;
    for (FaceMark& mark : marks) mark.everCaptured = false;
    if (const auto known = probes_.find(probe.reflector); known != probes_.end()) {
      marks = known->second;
    }
    for (FaceMark& mark : marks) {
      mark.captured = false;
      if (mark.everCaptured) ++mark.ageFrames;
    }
    for (const FacePlan& face : probe.faces) {
      marks[static_cast<size_t>(face.face)] = FaceMark{true, 0, true};
    }
    next[probe.reflector] = marks;
  }
  probes_ = std::move(next);
}

std::array<FaceMark, 6> FaceAges::marks(int reflector) const {
  if (const auto known = probes_.find(reflector); known != probes_.end()) return known->second;
  std::array<FaceMark, 6> empty;
  for (FaceMark& mark : empty) mark = FaceMark{false, 0, false};
  return empty;
}

}  // namespace reflect
