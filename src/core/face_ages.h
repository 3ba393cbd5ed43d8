// How old each face of each probe is, in frames: what the faces view marks (captured this frame,
// stale for N frames, never drawn). Fed one FramePlan a frame; it only watches the plans, so
// the planner's own rules for which faces to redraw stay in one place (core/frame_planner).
#pragma once

#include <array>
#include <map>

#include "core/cube_cross.h"
#include "core/frame_planner.h"

namespace reflect {

class FaceAges {
 public:
  // One frame's plan: its probes' redrawn faces become age 0, the others a frame older. A probe
  // missing from the plan (traced this frame, or gone) is forgotten: its cube is not read.
  void advance(const FramePlan& plan);
  // The marks of the probe owned by `reflector`; every face EMPTY when it has none.
  std::array<FaceMark, 6> marks(int reflector) const;
  // Forget everything (a lost context, a new scene: every cube starts empty).
  void clear() { probes_.clear(); }

 private:
  std::map<int, std::array<FaceMark, 6>> probes_;  // by owning reflector
};

}  // namespace reflect
