// Pick a pixel's rays over the frame (the page shows them while a pick is shown; see
// app/pixel_explain.h for what they are). With no pick shown nothing here runs and nothing is
// allocated: the normal frame is untouched.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gfx/ray_lines.h"

namespace reflect {

class PickOverlay {
 public:
  // The segments to draw from the next frame on; none: the overlay is off.
  void show(std::vector<RaySegment> segments) {
    segments_ = std::move(segments);
    uploaded_ = false;
  }
  bool on() const { return !segments_.empty(); }
  const std::vector<RaySegment>& segments() const { return segments_; }
  // Draws them into `framebuffer` by the main camera. Returns "" or why not.
  std::string draw(const glm::mat4& viewProjection, unsigned framebuffer, int width, int height);
  // The GL objects are freed (the context stays).
  void release();

 private:
  std::vector<RaySegment> segments_;
  bool uploaded_ = false;
  std::unique_ptr<RayLines> lines_;  // made on the first draw
};

}  // namespace reflect
