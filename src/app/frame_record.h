// One frame, planned once. Demo::record (demo_frame.cpp) makes it, the only place a frame is laid
// out: the objects at the frame's time (each with its model matrix), the planner's plan (probes,
// their faces and draws, the traced reflectors), the camera and the main pass's draws, and the
// error view's exact plan when that view is on. Everything that draws the frame or explains it
// reads this record: the frame itself, the steps view, the lookup-direction pass (accuracy, pick
// a pixel, the face-use view), the error view and the stats. Plain data: tests can assert on it.
#pragma once

#include <optional>
#include <vector>

#include "core/frame_planner.h"
#include "gfx/scene_renderer.h"

namespace reflect {

struct FrameRecord {
  // Before the first frame, or for a hidden canvas: nothing was laid out.
  bool empty() const { return width < 1 || height < 1; }

  double seconds = 0.0;
  int width = 0, height = 0;
  std::vector<PlannedObject> objects;  // in the scene's order
  CaptureContext context;              // what the captures depend on besides the objects
  FramePlan plan;
  ViewParams view;
  std::vector<DrawItem> mainDraws;  // every object in view, with its level of detail
  // The error view's frame: the same objects planned in the exact mode (show error only).
  std::optional<FramePlan> exactPlan;
  // Drawn by the course's own file (course/course_frame.cpp) rather than the general renderer.
  bool course = false;
};

}  // namespace reflect
