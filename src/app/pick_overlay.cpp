#include "app/pick_overlay.h"

namespace reflect {

std::string PickOverlay::draw(const glm::mat4& viewProjection, unsigned framebuffer, int width,
                              int height) {
  if (!lines_) {
    Result<RayLines> lines = RayLines::create();
    if (!lines) return lines.error();
    lines_ = std::make_unique<RayLines>(lines.take());
    uploaded_ = false;
  }
  if (!uploaded_) {
    lines_->set(segments_);
    uploaded_ = true;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  lines_->draw(viewProjection, width, height);
  return {};
}

void PickOverlay::release() {
  lines_.reset();
}

}  // namespace reflect
